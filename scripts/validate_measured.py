#!/usr/bin/python3
"""The scoreboard: softglass's predictions against every public flow curve in
../shared/data/rheometry/, in every prediction mode the data support, with the
tabulated law and with its Herschel-Bulkley summary side by side.

Run by bench/validate_measured.sh, which also adds the castor-oil cell's
torques (macro compare). Every prediction is made by `bridge predict`; this
script only chooses the inputs each mode takes from the data and scores the
result:
  (b) E* from the measured G' (castor oil: 143 Pa, its amplitude sweep);
  (c) the measured yield stress, taken as the smallest stress of each curve
      (its low-rate plateau; an upper bound where a curve starts above it),
      with E* from (b) where G' is known, else from the (d) calibration;
  (d) E* fitted to one curve (phi = 0.80 of each series; the castor-oil curve
      itself, in sample), the other volume fractions predicted with it.
Mode (a) needs E* = 9.92 gamma_i/R, and no data set gives gamma_i: not scored.
Errors are pred/measured - 1 at each measured point; |.| medians and mean
(bias) per data set, mode and law form, overall and per branch: the yield
plateau (measured stress below 1.5 x the curve's smallest) and the flowing
branch above it.
"""
import argparse
import csv
import math
import os
import statistics
import subprocess
import sys
import tempfile

from result_table import read_rows

SIMULATED_PHI = (0.70, 0.90)  # the bundled law's range; other curves are listed, not scored
WATER = 0.89e-3  # Pa s at 25 C, every emulsion here
FORMS = ("tabulated", "herschel-bulkley")


def read_curves(path):
    """{label: (phi, rates, stresses)} of a paired (Dekker) or long (sample_id) file."""
    with open(path, newline="", encoding="utf-8-sig") as f:
        rows = [r for r in csv.reader(f) if r and not r[0].startswith("#")]
    header, body = rows[0], rows[1:]
    curves = {}
    if header[0] == "sample_id":
        for label, rate, stress in (r[:3] for r in body):
            curves.setdefault(label, ([], []))
            curves[label][0].append(float(rate))
            curves[label][1].append(float(stress))
        return {k: (float(k.split("_")[1]), *v) for k, v in curves.items()}
    if "Shear rate [1/s]" in header:  # an instrument export: one curve
        rc, sc = header.index("Shear rate [1/s]"), header.index("Stress [Pa]")
        points = sorted((float(r[rc]), float(r[sc])) for r in body)
        return {"castoroil85_couette_flow_sweep": (0.85, [p[0] for p in points],
                                                   [p[1] for p in points])}
    for c in range(0, len(header), 2):  # paired: a phi label over (rate, stress) columns
        points = [(float(r[c]), float(r[c + 1])) for r in body if len(r) > c + 1 and r[c] and r[c + 1]]
        curves[header[c]] = (float(header[c]), [p[0] for p in points], [p[1] for p in points])
    return curves


class Bridge:
    def __init__(self, executable, law, scratch):
        self.executable, self.law, self.scratch, self.runs = executable, law, scratch, 0

    def predict(self, phi, rates, form, *mode):
        """(stresses, extrapolated flags, header notes) from `bridge predict`."""
        self.runs += 1
        out = os.path.join(self.scratch, f"prediction_{self.runs}.csv")
        command = [self.executable, "predict", self.law, "--phi", str(phi), "--viscosity",
                   str(WATER), "--rates", ",".join(repr(r) for r in rates), "--law-form", form,
                   "--rate-unit", "1/s", "--stress-unit", "Pa", "-o", out, "-f", *mode]
        subprocess.run(command, check=True, stdout=subprocess.DEVNULL)
        with open(out) as f:
            table, notes = read_rows(f.read().splitlines())
        return ([float(r["shear_stress [Pa]"]) for r in table],
                [r["extrapolated [1]"] == "1" for r in table], notes)

    def fitted_modulus(self, phi, curve_file, label, form):
        mode = ["--fit-to", curve_file] + (["--fit-curve", label] if label else [])
        _, _, notes = self.predict(phi, [1.0], form, *mode)
        note = next(n for n in notes if n.startswith("E* = ") and "fitted" in n)
        return float(note.split()[2])


def score(errors):
    if not errors:
        return None
    return (statistics.median(abs(e) for e in errors), statistics.fmean(errors), len(errors))


def main():
    p = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    p.add_argument("bridge", help="the bridge executable")
    p.add_argument("law", help="the law file (its _points.csv and _phi.csv beside it)")
    p.add_argument("data", help="the folder of the measured files")
    p.add_argument("--model-error",
                   help="write the pooled error per mode, law form and branch (CSV) here: the "
                        "model's systematic error that `bridge predict` states beside its band")
    p.add_argument("--torques", action="append", default=[],
                   help="a row of macro compare's torques: 'mode|law|median|bias|points'")
    p.add_argument("--castoroil-plateau-modulus", type=float, default=143.0)
    args = p.parse_args()
    sets = [  # name, file, calibration curve of mode (d), measured G' (or None)
        ("castor oil 85 % (flow sweep)", "castoroil85_couette_flow_sweep.csv", None,
         args.castoroil_plateau_modulus),
        ("Dekker 2018", "dekker2018_emulsion_flow_curves_digitized.csv", "0.80", None),
        ("Paredes 2013", "paredes2013_emulsion_flow_curves_digitized.csv", "phi_0.8", None),
        ("Dinkgreve 2015", "dinkgreve2015_emulsion_flow_curves_digitized.csv", "phi_0.8", None),
    ]
    rows, details = [], []
    pooled = {}  # (mode letter, form, branch) -> ([errors], {data sets})
    with tempfile.TemporaryDirectory() as scratch:
        bridge = Bridge(args.bridge, args.law, scratch)
        for name, filename, calibration, plateau in sets:
            path = os.path.join(args.data, filename)
            curves = read_curves(path)
            scored = {k: v for k, v in curves.items()
                      if SIMULATED_PHI[0] - 1e-9 <= v[0] <= SIMULATED_PHI[1] + 1e-9}
            skipped = sorted(v[0] for k, v in curves.items() if k not in scored)
            for form in FORMS:
                modes = {}
                if plateau:
                    modes["(b) E* from G'"] = {k: ["--plateau-modulus", str(plateau)]
                                                for k in scored}
                label = calibration if calibration else next(iter(scored))
                e_star = bridge.fitted_modulus(curves[label][0], path, calibration or "", form)
                modes["(c) measured yield stress"] = {
                    k: ["--yield-stress", repr(min(v[2]))] +
                       (["--plateau-modulus", str(plateau)] if plateau else ["--modulus", repr(e_star)])
                    for k, v in scored.items()}
                fitted = "(d) E* fitted to phi = %s" % curves[label][0] if calibration \
                    else "(d) E* fitted, in sample"
                modes[fitted] = {k: ["--modulus", repr(e_star)] for k in scored
                                 if k != calibration}
                for mode, inputs in modes.items():
                    errors = {"all": [], "plateau": [], "flowing": []}
                    extrapolated = 0
                    for k, extra in inputs.items():
                        phi, rates, measured = scored[k]
                        predicted, outside, _ = bridge.predict(phi, rates, form, *extra)
                        plateau_level = 1.5 * min(measured)
                        curve_errors = []
                        for i, (r, m, q) in enumerate(zip(rates, measured, predicted)):
                            if mode.startswith("(c)") and m == min(measured):
                                continue  # the point that gave the yield stress
                            e = q / m - 1.0
                            curve_errors.append(e)
                            errors["all"].append(e)
                            errors["plateau" if m < plateau_level else "flowing"].append(e)
                            extrapolated += outside[i]
                        s = score(curve_errors)
                        details.append(f"| {name} | {mode} | {form} | {phi:g} | {s[0]:.1%} | "
                                       f"{s[1]:+.1%} | {s[2]} |")
                    if "in sample" not in mode:  # a calibration says nothing of the model
                        for branch in ("all", "plateau", "flowing"):
                            entry = pooled.setdefault((mode[1], form, branch), ([], set()))
                            entry[0].extend(errors[branch])
                            entry[1].add(name)
                    total = score(errors["all"])
                    rows.append((name, mode, form, total, score(errors["plateau"]),
                                 score(errors["flowing"]), extrapolated / total[2],
                                 "E* from G'" if plateau and not mode.startswith("(d)")
                                 else f"E* = {e_star:.4g} Pa (fitted, d)",
                                 ", ".join(f"{x:g}" for x in sorted(scored[k][0] for k in inputs)),
                                 ", ".join(f"{x:g}" for x in skipped)))

    if args.model_error:
        with open(args.model_error, "w") as f:
            f.write("# The model's systematic error per prediction mode: predicted/measured - 1 "
                    "pooled over the\n# public flow curves of ../shared/data/rheometry "
                    "(scripts/validate_measured.py). Written by\n# bench/validate_measured.sh; "
                    "read by `bridge predict` beside its law file.\n")
            f.write("mode,law_form,branch,median_abs_error [1],bias [1],points [1],data_sets\n")
            for (mode, form, branch), (errs, names) in sorted(pooled.items()):
                if errs:
                    s = score(errs)
                    f.write(f"{mode},{form},{branch},{s[0]:.4f},{s[1]:+.4f},{s[2]},"
                            f"\"{'; '.join(sorted(names))}\"\n")

    def cell(s):
        return "–" if s is None else f"{s[0]:.0%} / {s[1]:+.0%}"

    print("| data set | mode | law | median abs error / bias | yield plateau | flowing branch | "
          "points (outside window) | phi scored | notes |")
    print("|---|---|---|---|---|---|---|---|---|")
    for line in args.torques:
        mode, form, median, bias, points = line.split("|")
        print(f"| castor oil 85 % (Couette torques, macro compare) | {mode} | {form} | "
              f"{float(median):.0f}% / {float(bias):+.0f}% | – | – | {points} | 0.85 | "
              f"the instrument's torques, finite elements of the cell with its bottom |")
    for name, mode, form, total, plat, flow, outside, note, phis, skipped in rows:
        notes = "; ".join(x for x in (note, f"not scored (outside the law's phi): {skipped}"
                                      if skipped else "") if x)
        print(f"| {name} | {mode} | {form} | {cell(total)} | {cell(plat)} | {cell(flow)} | "
              f"{total[2]} ({outside:.0%}) | {phis} | {notes} |")
    print()
    print("<details><summary>per volume fraction</summary>\n")
    print("| data set | mode | law | phi | median abs error | bias | points |")
    print("|---|---|---|---|---|---|---|")
    print("\n".join(details))
    print("\n</details>")


if __name__ == "__main__":
    sys.exit(main())

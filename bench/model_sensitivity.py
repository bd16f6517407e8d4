#!/usr/bin/python3
"""Model sensitivity study: which modelling choice sets the flow laws.

Each *variant* is a set of parameter-file entries on top of the engine's
defaults (contact law, drag, mobility, polydispersity, ...). Every variant is
sheared with the same cheap protocol — the same φ, rates, packings (seeds) and
run length — by `micro sweep`, fitted by `bridge fit` with the packing
bootstrap, and summarised per φ:

  m          Herschel–Bulkley exponent of σ (paper 0.50 ± 0.02)
  σ_y        HB yield stress and the quasi-static (AQS) one
  G0, γ_y    static linear modulus and σ_y/G0 (paper γ_y 0.02 … 0.04)
  k k' k''   each φ's own universal-law constants (paper 80, 20, 26)
  σe/σv      smallest elastic/viscous ratio at γ̃ ≤ 1e-5 (paper ≥ 100)
  G0/Mason   G0 against compressed emulsions, G′ ≈ 1.7 (γ_i/R) φ (φ − φ_c)
             with E* = 9.92 γ_i/R (the paper's relation), φ_c = 0.635
  σy/Mason   σ_y against τ_y ≈ 0.51 (γ_i/R)(φ − φ_c)² (Mason et al. 1996)

and per variant: k, k', k'' fitted over all φ with their collapse statistic
(Cochran Q/dof), the mean m, and the wall time. Variants that differ only in
the mobility factor f_r are compared point by point (the paper's claim: σ does
not change for f_r < 0.1).

With --static, only the packings are made (`micro pack`, no shear): G0/E*,
Π/E* and ⟨ε⟩ per φ and variant against compressed emulsions — the check of the
contact law that does not involve the dynamics (default φ 0.66 … 0.90). Mason
et al. also found the osmotic pressure Π about equal to G′ over a wide range
of φ, which Π/G0 shows.

Usage (bench/model_sensitivity.sh wraps it):
  model_sensitivity.py --bin BUILD --out DIR [--variants a,b,...] [--phis ...]
                       [--rates ...] [--particles N] [--packings P] [--strain S]
                       [--ranks R] [--static] [--list]
Finished sweeps are not rerun (micro sweep resumes), so the study can be grown
one variant at a time into the same DIR.
"""
import argparse
import csv
import math
import os
import subprocess
import sys
import time

# Mason, Bibette & Weitz, PRL 75, 2051 (1995): G′ ≈ 1.7 (γ_i/R) φ (φ − φ_c);
# Mason, Bibette & Weitz, J. Colloid Interface Sci. 179, 439 (1996):
# τ_y ≈ 0.51 (γ_i/R)(φ − φ_c)²; E* = 9.92 γ_i/R (Seth et al. 2006, the paper).
PHI_C = 0.635
E_STAR_PER_LAPLACE = 9.92
ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))


def mason_g0(phi):
    return 1.7 * phi * (phi - PHI_C) / E_STAR_PER_LAPLACE


def mason_yield(phi):
    return 0.51 * (phi - PHI_C) ** 2 / E_STAR_PER_LAPLACE


def piecewise(breakpoints, exponents):
    return {("contact law", "law"): "piecewise",
            ("contact law", "piecewise breakpoints"): ", ".join(str(b) for b in breakpoints),
            ("contact law", "piecewise exponents"): ", ".join(str(n) for n in exponents)}


# name -> (entries {(subsection, entry): value}, one-line description)
VARIANTS = {
    "literal": ({}, "the paper read literally: seth2011, f_r = 0.01, tangential EHD"),
    # The model presets (micro/input/model_preset.h); softglass = nominal+neighbours.
    "softglass": ({("model", "preset"): "softglass"}, "the softglass model preset"),
    # Any other mobility factor: fr<value> (fr0.05, softglass+fr0.0625), see part().
    "ehd_off": ({("drag", "ehd"): "false"}, "literal without EHD drag"),
    "hertz": ({("contact law", "law"): "hertz"}, "Hertz at every ε"),
    "hertz_fr1": ({("contact law", "law"): "hertz", ("shear", "mobility factor"): "1"},
                  "Hertz, f_r = 1"),
    # seth2011's breakpoints read as nominal strain δ/2R = ε/4 of a sphere
    # between plates (Liu et al.'s measure: Hertz to 10 %, stiffer beyond).
    "nominal": (piecewise([0.4, 0.8], [1.5, 2, 3]),
                "seth2011's branches at eps = 0.4, 0.8 (10 %, 20 % nominal strain)"),
    "half_nominal": (piecewise([0.2, 0.4], [1.5, 2, 3]),
                     "seth2011's branches at eps = 0.2, 0.4 (between seth2011 and nominal)"),
    # The contact law of an elastic (neo-Hookean, nearly incompressible) sphere
    # between frictionless plates, computed by finite elements
    # (macro/particle/sphere_compression.h, written by `sphere_compression`).
    "neohookean": ({("contact law", "law"): "table",
                    ("contact law", "table file"): os.path.join(
                        ROOT, "cases", "contact_law_neohookean.dat")},
                   "the finite-element law of a neo-Hookean sphere (table)"),
    "poly20": ({("particles", "polydispersity"): "0.2"}, "literal, 20 % polydispersity"),
    # The shape of the radius distribution at the same 10 %: flat (the LAMMPS
    # peer's) and skewed (emulsions' size distributions) against the Gaussian.
    "uniform": ({("particles", "distribution"): "uniform"}, "radii uniform on 1 ± √3·0.1"),
    "lognormal": ({("particles", "distribution"): "lognormal"}, "radii lognormal, 10 %"),
    # The film-dominated limit: friction against the affine flow below a free
    # sphere's Stokes drag. The explicit step scales like γ̃/f_r, so these run
    # implicit at every rate.
    "fr20": ({("shear", "mobility factor"): "20", ("integrator", "scheme"): "implicit"},
             "literal, f_r = 20 (implicit at every rate)"),
    "fr100": ({("shear", "mobility factor"): "100", ("integrator", "scheme"): "implicit"},
              "literal, f_r = 100 (implicit at every rate)"),
    "full_fr20": ({("drag", "velocity"): "full", ("shear", "mobility factor"): "20",
                   ("integrator", "scheme"): "implicit"},
                  "EHD on the full relative velocity, f_r = 20"),
    "full_fr100": ({("drag", "velocity"): "full", ("shear", "mobility factor"): "100",
                    ("integrator", "scheme"): "implicit"},
                   "EHD on the full relative velocity, f_r = 100"),
    "full": ({("drag", "velocity"): "full"}, "EHD on the full relative velocity, f_r = 0.01"),
    "neighbours": ({("drag", "stokes reference"): "neighbours"},
                   "Stokes friction against the neighbours (pair dashpots), f_r = 0.01"),
    "neighbours_fr0.05": ({("drag", "stokes reference"): "neighbours",
                           ("shear", "mobility factor"): "0.05"},
                          "Stokes friction against the neighbours, f_r = 0.05"),
    "nonaffine": ({("drag", "velocity"): "nonaffine"}, "EHD on the non-affine sliding only"),
    # Modifiers of the neighbours friction (compose: nominal+neighbours+share0.3):
    # the share kappa of each particle's friction kept against the affine flow,
    # from the default 0.01 towards 1 (all of it: the affine reference).
    "share0.1": ({("drag", "stokes reservoir share"): "0.1"},
                 "a share 0.1 of the Stokes friction against the affine flow"),
    "share0.3": ({("drag", "stokes reservoir share"): "0.3"},
                 "a share 0.3 of the Stokes friction against the affine flow"),
    # Films of finite rest thickness h0 (units of R): linear drag below the
    # sliding speed at which the EHD film would be thinner (micro/model/film.h);
    # 2e-3 and 6e-3 are 6 and 20 nm for R = 3 um (docs/oscillation.md).
    "h0_0.002": ({("drag", "film rest thickness"): "0.002"}, "films of rest thickness 0.002 R"),
    "h0_0.006": ({("drag", "film rest thickness"): "0.006"}, "films of rest thickness 0.006 R"),
}


def part(name):
    """One part of a variant: a listed name, or fr<value>, the mobility factor
    f_r = value (fr0.05, fr1: the friction's strength is the one continuous
    knob the study scans)."""
    if name in VARIANTS:
        return VARIANTS[name]
    if name.startswith("fr"):
        try:
            value = float(name[2:])
        except ValueError:
            return None
        return {("shear", "mobility factor"): name[2:]}, f"f_r = {value:g}"
    return None


def resolve(name):
    """A variant's entries: a listed name, or names joined by '+' (their
    entries together, later ones winning), e.g. nominal+neighbours. Every
    variant starts from the `literal` model preset, the paper as stated (not
    from the default, which is one of the variants: softglass)."""
    parts = [part(p) for p in name.split("+")]
    if None in parts:
        return None
    entries, texts = {("model", "preset"): "literal"}, []
    for part_entries, text in parts:
        entries.update(part_entries)
        texts.append(text)
    return entries, "; ".join(texts)


def variant_file(path, name, entries, sweep):
    by_section = {}
    for (section, key), value in list(sweep.items()) + list(entries.items()):
        by_section.setdefault(section, []).append((key, value))
    with open(path, "w") as f:
        f.write(f"# model sensitivity study, variant '{name}': {resolve(name)[1]}\n")
        for section, items in by_section.items():
            f.write(f"subsection {section}\n")
            for key, value in items:
                f.write(f"  set {key} = {value}\n")
            f.write("end\n")


def read_csv(path):
    with open(path) as f:
        rows = [line for line in f if not line.startswith("#")]
    return list(csv.DictReader(rows))


def run_variant(args, name):
    entries, _ = resolve(name)
    folder = os.path.join(args.out, name)
    os.makedirs(folder, exist_ok=True)
    sweep = {("sweep", "preset"): "custom",
             ("sweep", "particles"): str(args.particles),
             ("sweep", "volume fractions"): ", ".join(args.phis),
             ("sweep", "gamma dot tildes"): ", ".join(args.rates),
             ("sweep", "packings"): str(args.packings),
             ("sweep", "output directory"): "out",
             ("shear", "min strain"): str(args.strain),
             ("shear", "max strain"): str(args.strain),
             ("shear", "min stationary strain"): str(0.6 * args.strain)}
    prm = os.path.join(folder, "sweep.prm")
    variant_file(prm, name, entries, sweep)
    micro = os.path.join(args.bin, "micro")
    command = [micro, "--threads", "1", "sweep", "sweep.prm", "-q"]
    if args.ranks > 1:
        command = ["mpirun", "--allow-run-as-root", "-n", str(args.ranks)] + command
    start = time.time()
    with open(os.path.join(folder, "sweep.log"), "a") as log:
        status = subprocess.run(command, cwd=folder, stdout=log, stderr=subprocess.STDOUT,
                                env=dict(os.environ, OMP_NUM_THREADS="1"))
    wall = time.time() - start
    if status.returncode != 0:
        sys.exit(f"variant {name}: micro sweep failed (exit {status.returncode}), see {folder}/sweep.log")
    # Wall time of the sweep's own runs (a resumed study reports the first run's).
    timing = os.path.join(folder, "wall_seconds")
    if not os.path.exists(timing):
        with open(timing, "w") as f:
            f.write(f"{wall:.0f}\n")
    bridge = os.path.join(args.bin, "bridge")
    with open(os.path.join(folder, "fit.txt"), "w") as log:
        status = subprocess.run([bridge, "fit", "out/flow_curve.csv", "--packings",
                                 "out/flow_curve_packings.csv", "-o", "law.prm", "--force"],
                                cwd=folder, stdout=log, stderr=subprocess.STDOUT)
    if status.returncode != 0:
        sys.exit(f"variant {name}: bridge fit failed, see {folder}/fit.txt")
    return folder


def fmt(value, error=None, digits=3):
    if value is None or (isinstance(value, float) and math.isnan(value)):
        return "-"
    text = f"{value:.{digits}g}"
    if error is not None and not math.isnan(error):
        text += f"±{error:.2g}"
    return text


def number(row, key):
    try:
        return float(row[key])
    except (KeyError, ValueError):
        return math.nan


def summarise(args, name, folder, table):
    phis = read_csv(os.path.join(folder, "law_phi.csv"))
    constants = {r["constant"]: r for r in read_csv(os.path.join(folder, "law_constants.csv"))}
    points = read_csv(os.path.join(folder, "out", "flow_curve.csv"))
    with open(os.path.join(folder, "wall_seconds")) as f:
        wall = float(f.read())
    for row in phis:
        phi = float(row["phi [1]"])
        ratios = [number(p, "sigma_elastic [E*]") / number(p, "sigma_viscous [E*]")
                  for p in points if abs(float(p["phi [1]"]) - phi) < 1e-9
                  and 0 < float(p["gamma_tilde [1]"]) <= 1e-5 and number(p, "sigma_viscous [E*]") > 0]
        # The paper's σ^v is the EHD films' part alone ("due to the EHD drag force").
        film_ratios = [number(p, "sigma_elastic [E*]") / number(p, "sigma_film [E*]")
                       for p in points if abs(float(p["phi [1]"]) - phi) < 1e-9
                       and 0 < float(p["gamma_tilde [1]"]) <= 1e-5 and number(p, "sigma_film [E*]") > 0]
        g0 = number(row, "G0 [E*]")
        sy_aqs = number(row, "sigma_yield_quasi_static [E*]")
        m_aqs, m_aqs_se = anchored_exponent(points, phi)
        table.append({
            "variant": name, "phi": phi,
            "m": number(row, "sigma_exponent [1]"), "m_se": number(row, "sigma_exponent_se [1]"),
            "m_aqs": m_aqs, "m_aqs_se": m_aqs_se,
            "sigma_y": number(row, "sigma_yield [E*]"), "sigma_y_aqs": sy_aqs,
            "G0": g0, "G0_se": number(row, "G0_se [E*]"),
            "gamma_y": number(row, "gamma_y [1]"), "gamma_y_se": number(row, "gamma_y_se [1]"),
            "k": number(row, "sigma_own_k [1]"), "k_se": number(row, "sigma_own_k_se [1]"),
            "k1": number(row, "N1_own_k [1]"), "k1_se": number(row, "N1_own_k_se [1]"),
            "k2": number(row, "N2_own_k [1]"), "k2_se": number(row, "N2_own_k_se [1]"),
            "ev_ratio": min(ratios) if ratios else math.nan,
            "ef_ratio": min(film_ratios) if film_ratios else math.nan,
            "G0_mason": g0 / mason_g0(phi), "sy_mason": sy_aqs / mason_yield(phi),
            "K": constants["k"], "K1": constants["k_N1"], "K2": constants["k_N2"],
            "mean_m": constants["mean_exponent"], "wall": wall})


def anchored_exponent(points, phi):
    """m of σ = σ_y + K γ̃^m with σ_y the quasi-static (AQS) yield stress, by
    weighted least squares over the rates (scipy's curve_fit): the exponent of
    the rate-dependent part alone, free of the trade between σ_y and m that a
    free Herschel–Bulkley fit makes when the curve bends."""
    import numpy as np
    from scipy.optimize import curve_fit
    rows = [p for p in points if abs(float(p["phi [1]"]) - phi) < 1e-9]
    yield_rows = [p for p in rows if float(p["gamma_tilde [1]"]) == 0.0]
    curve = [p for p in rows if float(p["gamma_tilde [1]"]) > 0.0]
    if not yield_rows or len(curve) < 3:
        return math.nan, math.nan
    sy = number(yield_rows[0], "sigma [E*]")
    g = np.array([float(p["gamma_tilde [1]"]) for p in curve])
    s = np.array([number(p, "sigma [E*]") for p in curve])
    se = np.array([number(p, "sigma_se [E*]") for p in curve])
    se = np.hypot(se, number(yield_rows[0], "sigma_se [E*]"))
    try:
        (k, m), cov = curve_fit(lambda x, k, m: sy + k * x ** m, g, s, p0=(1.0, 0.5), sigma=se,
                                absolute_sigma=True, maxfev=20000)
    except RuntimeError:
        return math.nan, math.nan
    return m, math.sqrt(cov[1, 1])


def sigma_by_point(folder):
    points = read_csv(os.path.join(folder, "out", "flow_curve.csv"))
    return {(float(p["phi [1]"]), float(p["gamma_tilde [1]"])):
            (number(p, "sigma [E*]"), number(p, "sigma_se [E*]")) for p in points}


def mobility_sensitivity(args, done):
    """Largest |σ(f_r) / σ(f_r = 0.01) − 1| over the rates, per φ, for variants
    that differ from another only in the mobility factor."""
    lines = []
    for name in done:
        entries = resolve(name)[0]
        if ("shear", "mobility factor") not in entries:
            continue
        base = {k: v for k, v in entries.items() if k != ("shear", "mobility factor")}
        partner = next((n for n in done if resolve(n)[0] == base), None)
        if partner is None:
            continue
        a = sigma_by_point(os.path.join(args.out, name))
        b = sigma_by_point(os.path.join(args.out, partner))
        for phi in sorted({p for p, _ in a}):
            worst, where = 0.0, None
            for (p, rate), (s, se) in a.items():
                if p != phi or rate == 0 or (p, rate) not in b:
                    continue
                change = s / b[(p, rate)][0] - 1.0
                if abs(change) > abs(worst):
                    worst, where = change, rate
            lines.append(f"  {name:<12} vs {partner:<12} phi {phi:.2f}: largest change of sigma "
                         f"{100 * worst:+.1f} % (at gamma~ = {where:g})")
    return lines


def write_csv(path, rows):
    """Rows (dicts with the same keys) as CSV, for scripts/plot_fidelity.py."""
    import csv
    with open(path + ".tmp", "w", newline="") as f:
        writer = csv.DictWriter(f, fieldnames=list(rows[0]))
        writer.writeheader()
        writer.writerows(rows)
    os.replace(path + ".tmp", path)


def static_scan(args, names):
    """G0, Π, ⟨ε⟩ of relaxed packings per variant and φ (micro pack)."""
    import h5py  # Debian's python3-h5py
    phis = args.phis if args.phis_given else ["0.66", "0.70", "0.75", "0.80", "0.85", "0.90"]
    print(f"# static packings: N = {args.particles}, {args.packings} packings per phi; "
          f"Mason: G' = 1.7 (gamma_i/R) phi (phi - {PHI_C}), E* = {E_STAR_PER_LAPLACE} gamma_i/R")
    print(" ".join(f"{h:>13}" for h in ("variant", "phi", "G0 [E*]", "G0/Mason", "Pi [E*]",
                                          "Pi/G0", "<eps>", "Z", "seconds")))
    rows = []
    for name in names:
        entries = {k: v for k, v in resolve(name)[0].items()
                   if k[0] in ("model", "contact law", "particles")}
        folder = os.path.join(args.out, "static", name)
        os.makedirs(folder, exist_ok=True)
        for phi in phis:
            g0, pressure, eps, z, seconds = [], [], [], [], 0.0
            for seed in range(1, args.packings + 1):
                out = os.path.join(folder, f"phi{phi}_seed{seed}.h5")
                if not os.path.exists(out):
                    prm = os.path.join(folder, f"phi{phi}_seed{seed}.prm")
                    sweep = {("particles", "number"): str(args.particles),
                             ("particles", "volume fraction"): phi,
                             ("particles", "seed"): str(seed),
                             ("output", "file"): out}
                    variant_file(prm, name, entries, sweep)
                    start = time.time()
                    status = subprocess.run([os.path.join(args.bin, "micro"), "--threads", "1",
                                             "pack", "-q", prm], capture_output=True, text=True)
                    seconds += time.time() - start
                    if status.returncode != 0:
                        sys.exit(f"variant {name}, phi {phi}: micro pack failed: {status.stderr}")
                with h5py.File(out) as f:
                    p = f["packing"]
                    g0.append(float(p["shear_modulus"][()]))
                    pressure.append(float(p["pressure"][()]))
                    eps.append(float(p["mean_deformation"][()]))
                    z.append(float(p["coordination"][()]))
            mean = sum(g0) / len(g0)
            se = (sum((g - mean) ** 2 for g in g0) / max(1, len(g0) - 1) / len(g0)) ** 0.5
            cells = (name, phi, fmt(mean, se), fmt(mean / mason_g0(float(phi))),
                     fmt(sum(pressure) / len(pressure)), fmt(sum(pressure) / len(pressure) / mean),
                     fmt(sum(eps) / len(eps)),
                     fmt(sum(z) / len(z)), f"{seconds:.0f}")
            print(" ".join(f"{c:>13}" for c in cells), flush=True)
            rows.append({"variant": name, "phi": phi, "G0": mean, "G0_se": se,
                         "G0_mason": mean / mason_g0(float(phi))})
    write_csv(os.path.join(args.out, "static.csv"), rows)


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    parser.add_argument("--bin", default="build/bin")
    parser.add_argument("--out", default="out/model_sensitivity")
    parser.add_argument("--variants", default=",".join(VARIANTS))
    parser.add_argument("--phis", default="0.75,0.85,0.90")
    parser.add_argument("--rates", default="1e-8,1e-7,1e-6,1e-5,1e-4")
    parser.add_argument("--particles", type=int, default=250)
    parser.add_argument("--packings", type=int, default=2)
    parser.add_argument("--strain", type=float, default=5.0)
    parser.add_argument("--ranks", type=int, default=2)
    parser.add_argument("--static", action="store_true",
                        help="packings only: G0 against compressed emulsions")
    parser.add_argument("--list", action="store_true", help="print the variants and stop")
    args = parser.parse_args()
    args.phis_given = args.phis != parser.get_default("phis")
    if args.list:
        for name, (_, text) in VARIANTS.items():
            print(f"{name:<14} {text}")
        print(f"{'fr<value>':<14} the mobility factor f_r = value (fr0.05, softglass+fr0.0625)")
        return
    args.phis = [p.strip() for p in args.phis.split(",")]
    args.rates = [r.strip() for r in args.rates.split(",")]
    names = [v.strip() for v in args.variants.split(",")]
    unknown = [n for n in names if resolve(n) is None]
    if unknown:
        sys.exit(f"unknown variant(s) {', '.join(unknown)}; --list shows them")
    args.out = os.path.abspath(args.out)
    args.bin = os.path.abspath(args.bin)
    if args.static:
        static_scan(args, names)
        return
    table = []
    for name in names:
        folder = run_variant(args, name)
        summarise(args, name, folder, table)
        print(f"# {name}: done", file=sys.stderr, flush=True)

    print(f"# model sensitivity: N = {args.particles}, phi = {', '.join(args.phis)}, "
          f"gamma~ = {', '.join(args.rates)} + AQS, {args.packings} packings, "
          f"{args.strain:g} strain per run")
    header = ("variant", "phi", "m", "m (AQS yield)", "sigma_y HB", "sigma_y AQS", "G0",
              "gamma_y", "own k", "own k'", "own k''", "se/sv", "se/s_film", "G0/Mason", "sy/Mason")
    print(" ".join(f"{h:>13}" for h in header))
    for r in table:
        cells = (r["variant"], f"{r['phi']:.2f}", fmt(r["m"], r["m_se"]),
                 fmt(r["m_aqs"], r["m_aqs_se"]), fmt(r["sigma_y"]),
                 fmt(r["sigma_y_aqs"]), fmt(r["G0"], r["G0_se"]), fmt(r["gamma_y"], r["gamma_y_se"]),
                 fmt(r["k"], r["k_se"]), fmt(r["k1"], r["k1_se"]), fmt(r["k2"], r["k2_se"]),
                 fmt(r["ev_ratio"]), fmt(r["ef_ratio"]), fmt(r["G0_mason"]), fmt(r["sy_mason"]))
        print(" ".join(f"{c:>13}" for c in cells))
    write_csv(os.path.join(args.out, "summary.csv"),
              [{k: v for k, v in r.items() if not isinstance(v, dict)} for r in table])
    print("# over all phi: universal constants (collapse Q/dof), mean m, wall time")
    seen = set()
    for r in table:
        if r["variant"] in seen:
            continue
        seen.add(r["variant"])
        parts = []
        for key, label in (("K", "k"), ("K1", "k'"), ("K2", "k''")):
            c = r[key]
            parts.append(f"{label} {fmt(float(c['value [1]']), float(c['error [1]']))} "
                         f"(Q/dof {fmt(float(c['collapse_chi2_dof [1]']), digits=2)})")
        m = r["mean_m"]
        parts.append(f"m {fmt(float(m['value [1]']), float(m['error [1]']))}")
        print(f"  {r['variant']:<12} " + ", ".join(parts) + f", {r['wall']:.0f} s")
    sensitivity = mobility_sensitivity(args, list(dict.fromkeys(r["variant"] for r in table)))
    if sensitivity:
        print("# mobility factor: sigma against the same model at f_r = 0.01")
        print("\n".join(sensitivity))


if __name__ == "__main__":
    main()

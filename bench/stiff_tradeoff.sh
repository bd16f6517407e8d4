#!/usr/bin/env bash
# The speed/accuracy trade of the integrators across γ̃ (issue 4, docs/integrators.md).
#
# For γ̃ ∈ {1e-11, 1e-9, 1e-8, 1e-7, 1e-6, 1e-5, 1e-4}: every integrator and fidelity setting
# from the same start (N particles at φ, pre-sheared quasi-statically by
# PRESHEAR strain so that the window sees steady-state-like plastic activity),
# sheared over WINDOW strain. Per run: σ, N1, N2 (window means, sampled every
# 0.01) and their relative error against the reference of that γ̃ from the same
# start — the explicit scheme with a small step (tolerance 1e-5, half the
# default stability fraction) where affordable (γ̃ ≥ 1e-7), else the implicit
# scheme at tolerance 1e-4 (step-size convergence: compare its 1e-3 row) — and
# the wall time per strain unit. Over a window of a few tenths of strain two
# runs of a small system that take different branches at a plastic event
# (chaos) differ by several per cent whatever their accuracy, so the table
# gives, over SEEDS packings, the mean signed error ± its standard error (the
# bias, which is what discretisation adds) and the largest |error| (bias plus
# scatter). A run slower than TIME_LIMIT seconds is cut short: its cost is
# extrapolated, its stresses not compared ("-"); the explicit scheme at
# γ̃ = 1e-9 runs for the first seed only (cost only).
#
# Per γ̃ ≤ 1e-6, `cost_vs_aqs_<Δγ>_<γ̃>`: that cheapest setting's cost per
# strain against quasi-static shear at strain step Δγ (2e-4, the sweep's, and
# 1e-3). Over many packings no setting keeps every packing within 2 % (each
# run either follows the reference's sequence of plastic events, within
# 0.03 %, or takes another branch and differs by ~20 %: docs/integrators.md,
# "1e-11 over 256 packings"), so the issue's rule — σ within 2 % in the mean
# over packings — is applied too: the cheapest setting whose Σ(σ − σ_ref)/Σσ_ref
# is within 2 % at two standard errors, `cost_vs_aqs_mean_rule_<Δγ>_<γ̃>`.
# Ends with `cost_ratio_1e-9_vs_1e-5 <ratio>`: the cheapest setting at γ̃ = 1e-9
# whose σ is within 2 % of the reference for every packing, against the same at
# γ̃ = 1e-5 (and the same for 1e-11); also the ratio against the explicit
# default at 1e-5.
#
# Usage: bench/stiff_tradeoff.sh [build dir]   (env: N, PHI, SEEDS, WINDOW,
#        PRESHEAR, TIME_LIMIT, OUT, GAMMAS; BIN: the program, default BUILD's).
#        The defaults run for minutes on 2 cores; the logs
#        bench/results/stiff_tradeoff*.md give the times.
set -euo pipefail
BUILD=${1:-build}
BIN="${BIN:-$BUILD/bench/stiff_tradeoff}"
N=${N:-256}
PHI=${PHI:-0.80}
SEEDS=${SEEDS:-"1 2 3 4"}
WINDOW=${WINDOW:-0.2}
PRESHEAR=${PRESHEAR:-1.0}
TIME_LIMIT=${TIME_LIMIT:-60}
GAMMAS=${GAMMAS:-"1e-4 1e-5 1e-6 1e-7 1e-8 1e-9 1e-11"}
FIRST=${SEEDS%% *}
OUT=${OUT:-$(mktemp -d)/stiff_tradeoff.txt}
[[ -x "$BIN" ]] || { echo "build $BIN first (cmake --build $BUILD --target stiff_tradeoff)" >&2; exit 1; }

: > "$OUT"
for seed in $SEEDS; do
  for g in $GAMMAS; do
    runs=(--run implicit:1e-1 --run implicit:3e-2 --run implicit:1e-2 --run implicit:3e-3 --run implicit:1e-3)
    runs+=(--run bdf2:1e-2 --run bdf2:3e-3 --run bdf2:1e-3)
    case $g in
      # euler at its default tolerance (what `auto` runs at 1e-5 and 1e-4);
      # reference; the implicit scheme with its step capped (its first-order
      # error at the 0.01 sampling step is ~1 % here)
      1e-4|1e-5|1e-6|1e-7) runs+=(--run euler:1e-4 --run euler:1e-5:0.4
                                  --run implicit:1e-3:1e-3 --run implicit:1e-3:2.5e-4) ;;
      1e-8|1e-9) runs+=(--run implicit:1e-4)                               # reference
            [[ $g == 1e-9 && $seed == "$FIRST" ]] && runs+=(--run euler:1e-4) ;;  # explicit: cost only
      1e-11) runs+=(--run implicit:1e-4) ;;
    esac
    # quasi-static shear at the sweep's strain step and at 1e-3: the cost floor
    # of the low rates (its stresses are compared with the 1e-11 reference)
    [[ $g == 1e-11 ]] && runs+=(--run aqs:2e-4 --run aqs:1e-3)
    echo "seed $seed gamma $g" >&2
    "$BIN" --particles "$N" --phi "$PHI" --seed "$seed" --gamma-tilde "$g" --strain "$WINDOW" \
      --preshear "$PRESHEAR" --time-limit "$TIME_LIMIT" "${runs[@]}" | sed "s/^/seed $seed /" >> "$OUT"
  done
done

python3 - "$OUT" "$N" "$PHI" "$WINDOW" "$PRESHEAR" "$SEEDS" <<'PY'
import sys, collections, math
path, n, phi, window, preshear, seeds = sys.argv[1:7]
rows = collections.defaultdict(dict)   # (gamma, setting) -> seed -> fields
for line in open(path):
    w = line.split()
    if len(w) < 4 or w[2] != "run" or "failed" in w: continue
    seed, setting = w[1], f"{w[3]}:{w[4]}"
    f = dict(zip(w[5::2], w[6::2]))
    rows[(float(f["gamma"]), setting)][seed] = f
def ref_setting(g):
    return "euler:1e-05:0.4" if g >= 1e-7 else "implicit:1e-04:0.05"
def label(s):
    scheme, tol, third = s.split(":")
    if scheme == "aqs": return f"aqs step {tol}"
    if scheme == "euler": return f"euler tol {tol}" + (f" stab {third}" if third != "0.8" else "")
    return f"{scheme} tol {tol}" + (f" max step {third}" if third != "0.05" else "")
def stats(v):
    m = sum(v) / len(v)
    se = math.sqrt(sum((x - m) ** 2 for x in v) / (len(v) - 1) / len(v)) if len(v) > 1 else float("nan")
    return m, se
print(f"# N = {n}, phi = {phi}, window {window} strain after {preshear} strain of AQS pre-shear; "
      f"seeds {seeds}; errors: mean signed ± SE over seeds [largest |error|]")
print("| gamma~ | setting | sigma (E*) | err sigma | err N1 | err N2 | s / strain | steps / strain |")
print("|---|---|---|---|---|---|---|---|")
best, best_mean, explicit, aqs = {}, {}, {}, {}
for g in sorted({k[0] for k in rows}, reverse=True):
    ref = rows.get((g, ref_setting(g)), {})
    for (gg, s), per_seed in sorted(rows.items(), key=lambda kv: kv[0][1]):
        if gg != g: continue
        cost = sum(float(f["per_strain"]) for f in per_seed.values()) / len(per_seed)
        steps = sum(float(f["steps"]) / max(float(f["strain"]), 1e-12) for f in per_seed.values()) / len(per_seed)
        complete = [seed for seed, f in per_seed.items() if f["complete"] == "1" and seed in ref]
        sig = (sum(float(per_seed[x]["sigma"]) for x in complete) / len(complete)) if complete else float("nan")
        errs = {q: [(float(per_seed[x][q]) - float(ref[x][q])) / abs(float(ref[x][q])) for x in complete]
                for q in ("sigma", "N1", "N2")}
        is_ref = s == ref_setting(g)
        def cell(q):
            if is_ref: return "ref"
            if not complete: return "-"
            m, se = stats(errs[q])
            return f"{100*m:+.2f} ± {100*se:.2f} % [{100*max(abs(e) for e in errs[q]):.2f}]"
        sig_txt = f"{sig:.4e}" if complete else "-"
        print(f"| {g:.0e} | {label(s)} | {sig_txt} | {cell('sigma')} | {cell('N1')} | {cell('N2')} | {cost:.3g} | {steps:.3g} |")
        if s.startswith("aqs"): aqs[s.split(":")[1]] = cost
        elif complete and not is_ref and len(complete) == len(per_seed):
            if max(abs(e) for e in errs["sigma"]) <= 0.02 and (g not in best or cost < best[g][0]):
                best[g] = (cost, label(s))
            # the mean over packings: Σ(σ − σ_ref)/Σσ_ref, within 2 % at two standard errors
            if len(complete) > 1:
                d = [float(per_seed[x]["sigma"]) - float(ref[x]["sigma"]) for x in complete]
                scale = sum(float(ref[x]["sigma"]) for x in complete) / len(complete)
                m, se = stats(d)
                if abs(m) / scale + 2 * se / scale <= 0.02 and (g not in best_mean or cost < best_mean[g][0]):
                    best_mean[g] = (cost, label(s), m / scale, se / scale)
        if s == "euler:1e-04:0.8": explicit[g] = cost
print()
for g in sorted(best, reverse=True):
    print(f"cheapest with sigma within 2 % of the reference for every packing: gamma {g:.0e}: {best[g][1]}, {best[g][0]:.3g} s/strain")
for g in sorted(best_mean, reverse=True):
    c, name, m, se = best_mean[g]
    print(f"cheapest with the mean sigma over packings within 2 % of the reference's at two SE: "
          f"gamma {g:.0e}: {name} ({100*m:+.2f} ± {100*se:.2f} %), {c:.3g} s/strain")
def ratio(a, b):
    return best[a][0] / best[b][0] if a in best and b in best else float("nan")
for g in (1e-9, 1e-11):
    if g in best and 1e-5 in explicit:
        print(f"cost_ratio_{g:.0e}_vs_explicit_default_1e-05 {best[g][0] / explicit[1e-5]:.3g}".replace("e-09", "e-9"))
for step, c in sorted(aqs.items()):
    for g in sorted(best, reverse=True):
        if g <= 1e-6:
            print(f"cost_vs_aqs_{step}_{g:.0e} {best[g][0] / c:.3g}")
    for g in sorted(best_mean, reverse=True):
        if g <= 1e-6:
            print(f"cost_vs_aqs_mean_rule_{step}_{g:.0e} {best_mean[g][0] / c:.3g}")
print(f"cost_ratio_1e-11_vs_1e-5 {ratio(1e-11, 1e-5):.3g}")
print(f"cost_ratio_1e-9_vs_1e-5 {ratio(1e-9, 1e-5):.3g}")
PY

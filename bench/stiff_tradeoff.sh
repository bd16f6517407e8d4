#!/usr/bin/env bash
# The speed/accuracy trade of the integrators across γ̃ (issue 4, docs/integrators.md).
#
# For γ̃ ∈ {1e-11, 1e-9, 1e-7, 1e-5, 1e-4}: every integrator and fidelity setting
# from the same start (N particles at φ, pre-sheared quasi-statically by
# PRESHEAR strain so that the window sees steady-state-like plastic activity),
# sheared over WINDOW strain. Reported per run: σ, N1, N2 (means over the
# window, sampled every 0.01) and their relative error against the reference
# of that γ̃ — the explicit scheme with a small step (tolerance 1e-5, half the
# default stability fraction) where affordable (γ̃ ≥ 1e-7), else the implicit
# scheme at tolerance 1e-4 (step-size convergence: compare its 1e-3 row) —
# and the wall time per strain unit. A run slower than TIME_LIMIT seconds is
# cut short: its cost is extrapolated, its stresses not compared ("-").
# Worst errors and mean costs are over SEEDS packings.
#
# Ends with `cost_ratio_1e-9_vs_1e-5 <ratio>`: the cheapest setting at γ̃ = 1e-9
# whose σ is within 2 % of the reference for every seed, against the same at
# γ̃ = 1e-5 (and the same figure for 1e-11).
#
# Usage: bench/stiff_tradeoff.sh [build dir]   (env: N, PHI, SEEDS, WINDOW,
#        PRESHEAR, TIME_LIMIT, OUT). Defaults take ≈ 10 min on 2 cores.
set -euo pipefail
BUILD=${1:-build}
BIN="$BUILD/bench/stiff_tradeoff"
N=${N:-256}
PHI=${PHI:-0.80}
SEEDS=${SEEDS:-"1 2"}
WINDOW=${WINDOW:-0.3}
PRESHEAR=${PRESHEAR:-1.0}
TIME_LIMIT=${TIME_LIMIT:-60}
OUT=${OUT:-$(mktemp -d)/stiff_tradeoff.txt}
[[ -x "$BIN" ]] || { echo "build $BIN first (cmake --build $BUILD --target stiff_tradeoff)" >&2; exit 1; }

: > "$OUT"
for seed in $SEEDS; do
  for g in 1e-4 1e-5 1e-7 1e-9 1e-11; do
    runs=(--run implicit:1e-1 --run implicit:3e-2 --run implicit:1e-2 --run implicit:1e-3)
    case $g in
      1e-4|1e-5|1e-7) runs+=(--run euler:1e-4 --run euler:1e-5:0.4) ;;   # default; reference
      1e-9) runs+=(--run implicit:1e-4 --run euler:1e-4) ;;               # reference; explicit (cut)
      1e-11) runs+=(--run implicit:1e-4 --run aqs:1e-3 --run aqs:2e-4) ;;
    esac
    echo "seed $seed gamma $g" >&2
    "$BIN" --particles "$N" --phi "$PHI" --seed "$seed" --gamma-tilde "$g" --strain "$WINDOW" \
      --preshear "$PRESHEAR" --time-limit "$TIME_LIMIT" "${runs[@]}" | sed "s/^/seed $seed /" >> "$OUT"
  done
done

python3 - "$OUT" "$N" "$PHI" "$WINDOW" "$PRESHEAR" <<'PY'
import sys, collections
path, n, phi, window, preshear = sys.argv[1:6]
rows = collections.defaultdict(dict)   # (gamma, setting) -> seed -> fields
for line in open(path):
    w = line.split()
    if len(w) < 4 or w[2] != "run" or "failed" in w: continue
    seed, setting = w[1], f"{w[3]}:{w[4]}"
    f = dict(zip(w[5::2], w[6::2]))
    rows[(float(f["gamma"]), setting)][seed] = f
def ref_setting(g):
    return "euler:1e-05:0.4" if g >= 1e-7 else "implicit:1e-04:0.8"
def label(s):
    scheme, tol, stab = s.split(":")
    if scheme == "aqs": return f"aqs step {tol}"
    if scheme == "euler": return f"euler tol {tol}" + (f" stab {stab}" if stab != "0.8" else "")
    return f"implicit tol {tol}"
print(f"# N = {n}, phi = {phi}, window {window} strain after {preshear} strain of AQS pre-shear")
print("| gamma~ | setting | sigma (E*) | err sigma | err N1 | err N2 | s / strain | steps / strain |")
print("|---|---|---|---|---|---|---|---|")
best = {}
for g in sorted({k[0] for k in rows}, reverse=True):
    ref = rows.get((g, ref_setting(g)), {})
    for (gg, s), per_seed in sorted(rows.items(), key=lambda kv: (kv[0][0] != g, kv[0][1])):
        if gg != g: continue
        errs = {"sigma": 0.0, "N1": 0.0, "N2": 0.0}; comparable = True
        cost = sum(float(f["per_strain"]) for f in per_seed.values()) / len(per_seed)
        steps = sum(float(f["steps"]) / max(float(f["strain"]), 1e-12) for f in per_seed.values()) / len(per_seed)
        sig = sum(float(f["sigma"]) for f in per_seed.values()) / len(per_seed)
        for seed, f in per_seed.items():
            if f["complete"] != "1" or seed not in ref: comparable = False; continue
            for q in errs:
                r = float(ref[seed][q]); errs[q] = max(errs[q], abs(float(f[q]) - r) / abs(r))
        is_ref = s == ref_setting(g)
        fmt = lambda q: "ref" if is_ref else (f"{100*errs[q]:.2f} %" if comparable else "-")
        print(f"| {g:.0e} | {label(s)} | {sig:.4e} | {fmt('sigma')} | {fmt('N1')} | {fmt('N2')} | {cost:.3g} | {steps:.3g} |")
        if comparable and not is_ref and errs["sigma"] <= 0.02:
            if g not in best or cost < best[g][0]: best[g] = (cost, label(s))
print()
for g in sorted(best, reverse=True):
    print(f"cheapest within 2 %: gamma {g:.0e}: {best[g][1]}, {best[g][0]:.3g} s/strain")
def ratio(a, b):
    return best[a][0] / best[b][0] if a in best and b in best else float("nan")
print(f"cost_ratio_1e-11_vs_1e-5 {ratio(1e-11, 1e-5):.3g}")
print(f"cost_ratio_1e-9_vs_1e-5 {ratio(1e-9, 1e-5):.3g}")
PY

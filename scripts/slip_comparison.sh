#!/usr/bin/env bash
# The castor-oil Couette cell predicted with and without wall slip
# (docs/macro.md, "Wall slip: the castor-oil cell"): the slip law of a
# `micro slip` table (bridge slip-law, rows below the bundled law's yield
# stress), the bundled predicted material, the measured flow sweep of
# ../shared/data/rheometry/, `macro compare` without slip and with slip on bob
# and cup for each droplet radius R, and the error per branch.
#
# Usage: scripts/slip_comparison.sh BUILD_DIR SLIP_TABLE [OUTPUT_DIR] [R ...]
#   SLIP_TABLE  slip.csv of `micro slip` (several joined: one header)
#   R           droplet radii [m] (default 3.4e-6; beta is proportional to R)
# Environment: ROWS (below-yield: the rows below the bundled law's yield
# stress, the sliding plug; all: every row, the flowing bulk too), PHI (0.85), EXTRAPOLATE (empty; "--extrapolate" to use a
# table without phi = PHI), PRESET (fast), SPLIT (1: the shear rate [1/s]
# between the low and the high branch).
set -euo pipefail
build=${1:?usage: scripts/slip_comparison.sh BUILD_DIR SLIP_TABLE [OUTPUT_DIR] [R ...]}
table=${2:?usage: scripts/slip_comparison.sh BUILD_DIR SLIP_TABLE [OUTPUT_DIR] [R ...]}
out=${3:-out/slip_comparison}
shift $(( $# < 3 ? $# : 3 ))
radii=("${@:-3.4e-6}")
root=$(cd "$(dirname "$0")/.." && pwd)
data="$root/../shared/data/rheometry/castoroil85_couette_flow_sweep.csv"
[ -f "$data" ] || { echo "no castor-oil data at $data: nothing to compare" >&2; exit 0; }
phi=${PHI:-0.85} preset=${PRESET:-fast} split=${SPLIT:-1}
# E* and eta_s of the bundled predicted material (its header records them), so
# the slip law is made dimensional with the same E* the bulk law was.
material="$root/cases/material_castoroil85_predicted.prm"
read -r modulus viscosity < <(sed -n 's/^# phi = [^,]*, E\* = \([^ ]*\) Pa, eta_s = \([^ ]*\) Pa s.*/\1 \2/p' "$material") || true
[ -n "${modulus:-}" ] && [ -n "${viscosity:-}" ] ||
  { echo "slip_comparison: no 'E* = ... Pa, eta_s = ... Pa s' line in $material" >&2; exit 2; }
rows_option=(--below-yield "$root/cases/bridge_law_paper_sweep.prm")
[ "${ROWS:-below-yield}" = all ] && rows_option=()
out=$(mkdir -p "$out" && cd "$out" && pwd)   # the scenes' includes are taken from there

# Per branch: mean, rms and median |.| of predicted/measured - 1.
branches() {
  python3 - "$1" "$split" <<'PY'
import csv, math, sys
rows = [r for r in csv.reader(l for l in open(sys.argv[1]) if not l.startswith('#'))]
head, rows = rows[0], rows[1:]
rate, err = head.index('shear_rate [1/s]'), head.index('relative_error [1]')
split = float(sys.argv[2])
def stats(name, e):
    if not e: return
    e = sorted(e, key=abs); m = sum(e) / len(e)
    rms = math.sqrt(sum(x * x for x in e) / len(e)); med = abs(e[len(e) // 2]) if len(e) % 2 else 0.5 * (abs(e[len(e) // 2 - 1]) + abs(e[len(e) // 2]))
    print(f"  {name:<28} {len(e):3d} points  mean {100*m:+6.1f} %  rms {100*rms:5.1f} %  median |.| {100*med:5.1f} %  max |.| {100*abs(e[-1]):5.1f} %")
all_e = [float(r[err]) for r in rows]
stats('all', all_e)
stats(f'low (shear rate < {split:g} 1/s)', [float(r[err]) for r in rows if float(r[rate]) < split])
stats(f'high (shear rate >= {split:g} 1/s)', [float(r[err]) for r in rows if float(r[rate]) >= split])
PY
}

"$build/macro/macro" compare "$root/cases/castoroil_couette.prm" "$data" --preset "$preset" \
  -o "$out/no_slip" -f -q > /dev/null
echo "no slip:"; branches "$out/no_slip/comparison.csv"
for r in "${radii[@]}"; do
  "$build/bridge/bridge" slip-law "$table" ${rows_option[@]+"${rows_option[@]}"} \
    --phi "$phi" ${EXTRAPOLATE:-} --modulus "$modulus" --viscosity "$viscosity" --radius "$r" \
    -o "$out/slip_R$r.prm" -f > "$out/slip_R$r.txt"
  # The bundled slip case with this radius's law (includes made absolute).
  sed -e "s|^include material_|include $root/cases/material_|" \
      -e "s|^include slip_castoroil85.prm|include $out/slip_R$r.prm|" \
      "$root/cases/castoroil_couette_slip.prm" > "$out/castoroil_couette_slip_R$r.prm"
  "$build/macro/macro" compare "$out/castoroil_couette_slip_R$r.prm" "$data" --preset "$preset" \
    -o "$out/slip_R$r" -f -q > /dev/null
  echo "slip on bob and cup, R = $r m ($(grep -o 'beta = A R E[^,]*= [^ ]* m/s/Pa^p' "$out/slip_R$r.txt" | sed 's/.*= //'), p = $(awk '/set exponent/ {print $4}' "$out/slip_R$r.prm")):"
  branches "$out/slip_R$r/comparison.csv"
done

# One figure: measured and predicted torques against Omega, and the errors.
if command -v gnuplot > /dev/null; then
  plots="'$out/no_slip/comparison.csv' using 1:3 with points pt 7 ps 0.6 lc rgb 'black' title 'measured', "
  plots+="'$out/no_slip/comparison.csv' using 1:4 with lines lw 2 lc rgb 'black' title 'no slip'"
  errors="'$out/no_slip/comparison.csv' using 1:(100*\$5) with lines lw 2 lc rgb 'black' notitle"
  k=0
  for r in "${radii[@]}"; do
    k=$((k + 1))
    plots+=", '$out/slip_R$r/comparison.csv' using 1:4 with lines lw 2 lc $k title 'slip, R = $r m'"
    errors+=", '$out/slip_R$r/comparison.csv' using 1:(100*\$5) with lines lw 2 lc $k notitle"
  done
  gnuplot <<GP
set terminal pngcairo size 900,900 font ',11'
set output '$out/slip_comparison.png'
set datafile separator ','
set multiplot layout 2,1 title 'castor-oil emulsion, Couette cell (smooth aluminium): bundled law with and without EHD wall slip'
set logscale xy
set format x '10^{%T}'; set format y '10^{%T}'
set xlabel 'angular velocity {/Symbol W} [rad/s]'; set ylabel 'torque [N m]'
set key left top
plot $plots
unset logscale y; set format y '%g'
set ylabel 'predicted/measured - 1 [%]'
set yrange [-100:100]
plot $errors, 0 with lines lc rgb 'gray' notitle
unset multiplot
GP
  echo "figure: $out/slip_comparison.png"
fi

#!/usr/bin/env bash
# `make demo`: the whole workflow on built-in defaults, from particles to a
# rheometer torque compared with a measurement, in a few minutes on 2 cores.
#
#   1. micro sweep    flow curves of N = 200 soft spheres (cases/demo_sweep.prm)
#   2. bridge fit     Herschel-Bulkley and universal-law fits -> a law file
#   3. bridge material  the law at the paper's emulsion (phi 0.80, E* 40 kPa,
#                     eta_s 1 mPa s) and at the castor-oil emulsion (phi 0.85,
#                     water, E* from its measured G' plateau of 143 Pa), the
#                     latter as the simulated flow curve itself (tabulated)
#   4. macro run      the paper's cone and plate (cases/cone_plate.prm)
#   5. macro compare  the castor-oil Couette measurement, when
#                     ../shared/data/rheometry/ is present; otherwise the
#                     Couette torques of the bundled law only
#   5b. bridge predict  the castor-oil flow curve with its bands from the
#                     bundled law of the paper sweep, E* from G' (mode b) and
#                     from the measured yield stress (mode c)
#   6. micro oscillate  the castor-oil emulsion's amplitude sweep at 1 rad/s
#                     (cases/demo_oscillation.prm), added to the law
#   7. bridge amplitude-sweep  predicted against its measured amplitude sweep
#                     (when present), E* by the flow-curve route as in 3
# The terminal shows each step on one line, a short table where one helps,
# the warnings folded (one line per kind, with a count) and a summary; the
# tools' full reports and the full tables go to OUTPUT_DIR/demo.log. On a
# terminal the particle simulations draw their progress line.
# Usage: scripts/demo.sh BUILD_DIR [OUTPUT_DIR]   (default out/demo)
set -euo pipefail

build=${1:?usage: scripts/demo.sh BUILD_DIR [OUTPUT_DIR]}
out=${2:-out/demo}
root=$(cd "$(dirname "$0")/.." && pwd)
micro="$build/micro/micro" bridge="$build/bridge/bridge" macro="$build/macro/macro"
data="$root/../shared/data/rheometry/castoroil85_couette_flow_sweep.csv"
amplitude_data="$root/../shared/data/rheometry/castoroil85_couette_amplitude_sweep.csv"
start=$SECONDS
source "$root/scripts/bundled_materials.sh"

mkdir -p "$out"
log="$out/demo.log"
: > "$log"
step_output="$out/.step_output"
trap 'rm -f "$step_output"' EXIT

step() {
  printf '\n== %s  (%d s)\n' "$1" $((SECONDS - start))
  printf '\n== %s  (%d s)\n' "$1" $((SECONDS - start)) >> "$log"
}
# Chosen columns of a result table, by name (scripts/show_table.py); `show`
# prints them on the terminal and in the log, `record` in the log only.
show() { /usr/bin/python3 "$root/scripts/show_table.py" "$@" | tee -a "$log"; }
record() { /usr/bin/python3 "$root/scripts/show_table.py" "$@" >> "$log"; }
# Runs a tool with its whole output in the log. On failure the output's last
# lines are shown; otherwise only its warnings, one line per distinct warning
# (repeats counted), at most 3 on the terminal and the rest in the log.
run() {
  printf '$ %s\n' "$*" >> "$log"
  local status=0
  if [ -n "${progress_on_terminal:-}" ]; then
    "$@" > "$step_output" || status=$?
  else
    "$@" > "$step_output" 2>&1 || status=$?
  fi
  cat "$step_output" >> "$log"
  if [ $status -ne 0 ]; then
    echo "failed (exit $status): $*" >&2
    tail -n 20 "$step_output" >&2
    echo "the whole output: $log" >&2
    exit $status
  fi
  # Warnings of one kind differ in their place ("line 11 (phi = 0.85, ...): "):
  # without it they fold into one line with a count.
  { grep -i 'warning' "$step_output" | grep -v -x -i ' *warnings' || true; } |
    sed -E 's/^ *//; s/line [0-9]+ \([^)]*\): //' | sort | uniq -c | sort -rn |
    awk -v logfile="$log" '{ n = $1; sub(/^ *[0-9]+ /, "") }
      NR <= 3 { w = length($0) > 110 ? substr($0, 1, 107) "..." : $0
                print "   " w (n > 1 ? "  (" n " times)" : "") }
      NR > 3 { more++ }
      END { if (more) print "   and " more " more warning(s) in " logfile }'
}
# The long simulations draw their progress line on a terminal; in a pipe or
# a file they keep quiet (-q) and say nothing until done.
quiet=(-q)
[ -t 2 ] && quiet=()
with_progress() {
  progress_on_terminal=
  [ ${#quiet[@]} -eq 0 ] && progress_on_terminal=1
  run "$@"
  progress_on_terminal=
}

# The sweep spreads its cases over one MPI rank per core when mpirun is there.
cores=$(nproc)
launcher=()
if command -v mpirun >/dev/null && [ "$cores" -gt 1 ]; then
  export OMPI_ALLOW_RUN_AS_ROOT=1 OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1 OMP_NUM_THREADS=1
  launcher=(mpirun -n "$cores")
fi

# A fresh demo each time: the sweep folders would otherwise be resumed as done.
rm -rf "${out:?}/sweep" "${out:?}/oscillation"
sweep_file="$out/demo_sweep.prm" oscillation_file="$out/demo_oscillation.prm"
sed "s|out/demo/sweep|$out/sweep|" "$root/cases/demo_sweep.prm" > "$sweep_file"
sed "s|out/demo/oscillation|$out/oscillation|" "$root/cases/demo_oscillation.prm" > "$oscillation_file"
echo "softglass demo: particles -> flow laws -> rheometer (details: $log)"

step "1. micro sweep: 3 volume fractions x 5 rates, N = 200 ($cores worker(s))"
with_progress "${launcher[@]}" "$micro" sweep "$sweep_file" "${quiet[@]}"
record "$out/sweep/flow_curve.csv" phi gamma_tilde sigma sigma_se N1 N1_se

step "2. bridge fit: Herschel-Bulkley and universal laws, bootstrap errors"
run "$bridge" fit "$out/sweep/flow_curve.csv" -o "$out/law.prm" -f -q
# The fit report's warnings, one line per kind (bridge folds the repeats).
awk -v logfile="$log" '/^warnings$/ { on = 1; next } on && /^  / { n++ } on && !/^  / { on = 0 }
  END { if (n) print "   " n " kind(s) of warning (each once, repeats counted): see " logfile }' "$step_output"
{ grep -E '^  k    ' "$log" || true; } | tail -n 1 | sed -E 's/^  /   /'

step "3. bridge material: the paper's emulsion and the castor-oil emulsion"
run paper_emulsion "$bridge" "$out/law.prm" "$out/material_paper_emulsion.prm"
run castoroil85 "$bridge" "$out/law.prm" "$out/material_castoroil85.prm" --tabulated

step "4. macro run: the paper's cone and plate, 20 speeds"
with_progress "$macro" run "$root/cases/cone_plate.prm" --material "$out/material_paper_emulsion.prm" \
  -o "$out/cone_plate" -f "${quiet[@]}"
record "$out/cone_plate/results.csv" rotation_rate torque torque_discretisation_error
show "$out/cone_plate/results.csv" rotation_rate torque torque_discretisation_error --every 5

if [ -f "$data" ]; then
  step "5. macro compare: the castor-oil emulsion in its Couette cell (no fitted parameter)"
  with_progress "$macro" compare "$root/cases/castoroil_couette.prm" "$data" \
    --material "$out/material_castoroil85.prm" -o "$out/compare_castoroil" -f
  { grep -E '^torque: ' "$step_output" || true; } | sed 's/^/   /'
  compared="$out/compare_castoroil/comparison.csv"
else
  step "5. no measured data (../shared/data/rheometry/ absent): Couette torques of the bundled law"
  run "$macro" run "$root/cases/castoroil_couette.prm" -o "$out/couette" -f -q
  record "$out/couette/results.csv" rotation_rate torque
  compared=""
fi

# The castor-oil flow curve from the bundled law (the paper sweep: 5 phi,
# 11 rates, 2 packings), with the band of each stress.
predict_castoroil() {
  local file=$1
  shift
  run "$bridge" predict "$root/cases/bridge_law_paper_sweep.prm" --phi 0.85 --viscosity 0.89e-3 \
    --rates 0.01,0.1,1,10,100,1000 "$@" -o "$file" -f
  # extrapolated: 1 outside the simulated rates
  show "$file" shear_rate shear_stress shear_stress_band extrapolated
}
step "5b. bridge predict: the castor-oil flow curve, (b) E* from G' = 143 Pa"
predict_castoroil "$out/predicted.csv" --plateau-modulus 143
predicted="$out/predicted.csv"
if [ -f "$data" ]; then
  # The measured yield stress: the flow sweep's low-rate plateau, its smallest stress.
  yield=$(awk -F, 'NR > 1 && (min == "" || $1 < min) { min = $1 } END { print min }' "$data")
  step "5b. bridge predict: (c) the measured yield stress ($yield Pa) and G' = 143 Pa"
  predict_castoroil "$out/predicted_yield_stress.csv" --plateau-modulus 143 --yield-stress "$yield"
  predicted="$predicted, $out/predicted_yield_stress.csv"
fi

step "6. micro oscillate: the castor-oil emulsion's amplitude sweep, 6 amplitudes, N = 200"
with_progress "${launcher[@]}" "$micro" oscillate "$oscillation_file" "${quiet[@]}"
# G' and G'' (storage, loss) with their standard errors, and I3/I1.
record "$out/oscillation/oscillation.csv" gamma0 storage storage_se loss loss_se intensity_3
run "$bridge" fit --law "$out/law.prm" --oscillation "$out/oscillation/oscillation.csv" \
  -o "$out/law_with_amplitude_sweep.prm" -f

if [ -f "$amplitude_data" ]; then
  step "7. bridge amplitude-sweep: predicted against the measured one (E* by the flow-curve route)"
  run "$bridge" amplitude-sweep "$out/law_with_amplitude_sweep.prm" --phi 0.85 --plateau-modulus 143 \
    --viscosity 0.89e-3 --data "$amplitude_data" -o "$out/amplitude_castoroil" -f
else
  step "7. no measured amplitude sweep: the predicted one only"
  run "$bridge" amplitude-sweep "$out/law_with_amplitude_sweep.prm" --phi 0.85 --plateau-modulus 143 \
    --viscosity 0.89e-3 -o "$out/amplitude_castoroil" -f
fi
{ grep -E '^amplitude sweep at omega = ' "$step_output" || true; } | head -n 1 | fold -s -w 100 | sed 's/^/   /'

step "done"
# The summary: the prediction with its band, and where the files are; on the
# terminal and at the end of the log.
{
  /usr/bin/python3 - "$root/scripts" "$out/predicted.csv" <<'PY'
import sys
sys.path.insert(0, sys.argv[1])
from result_table import read_rows

rows, _ = read_rows(open(sys.argv[2], encoding="utf-8").read().splitlines())
def value(row, name):
    return float(next(v for k, v in row.items() if k == name or k.startswith(name + " [")))
row = min(rows, key=lambda r: abs(value(r, "shear_rate") - 1.0))
tau, band = value(row, "shear_stress"), value(row, "shear_stress_band")
print(f"prediction:      castor-oil emulsion (phi 0.85, E* from G' = 143 Pa): "
      f"tau = {tau:.3g} Pa at {value(row, 'shear_rate'):g} 1/s, band +- {band:.2g} Pa")
PY
  echo "flow curve:      $predicted"
  echo "law:             $out/law.prm (its tables: $out/law_phi.csv, _points.csv, _constants.csv)"
  echo "materials:       $out/material_paper_emulsion.prm, $out/material_castoroil85.prm"
  echo "cone and plate:  $out/cone_plate/results.csv, $out/cone_plate/solution_019.vtu (ParaView)"
  if [ -n "$compared" ]; then
    echo "comparison:      $compared"
    [ -f "$out/compare_castoroil/comparison.png" ] && echo "plot:            $out/compare_castoroil/comparison.png"
  fi
  echo "amplitude sweep: $out/amplitude_castoroil/amplitude_sweep.csv"
  [ -f "$out/amplitude_castoroil/comparison.png" ] && echo "plot:            $out/amplitude_castoroil/comparison.png"
  echo "details:         $log (every tool's full report and the full tables)"
} | tee -a "$log"

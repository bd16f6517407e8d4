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

step() { printf '\n== %s  (%d s)\n' "$1" $((SECONDS - start)); }
# Chosen columns of a result table, by name (scripts/show_table.py).
show() { /usr/bin/python3 "$root/scripts/show_table.py" "$@"; }

# The sweep spreads its cases over one MPI rank per core when mpirun is there.
cores=$(nproc)
launcher=()
if command -v mpirun >/dev/null && [ "$cores" -gt 1 ]; then
  export OMPI_ALLOW_RUN_AS_ROOT=1 OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1 OMP_NUM_THREADS=1
  launcher=(mpirun -n "$cores")
fi

mkdir -p "$out"
# A fresh demo each time: the sweep folders would otherwise be resumed as done.
rm -rf "${out:?}/sweep" "${out:?}/oscillation"
sweep_file="$out/demo_sweep.prm" oscillation_file="$out/demo_oscillation.prm"
sed "s|out/demo/sweep|$out/sweep|" "$root/cases/demo_sweep.prm" > "$sweep_file"
sed "s|out/demo/oscillation|$out/oscillation|" "$root/cases/demo_oscillation.prm" > "$oscillation_file"

step "1. micro sweep: 3 volume fractions x 5 rates, N = 200 ($cores worker(s))"
"${launcher[@]}" "$micro" sweep "$sweep_file" -q
show "$out/sweep/flow_curve.csv" phi gamma_tilde sigma sigma_se N1 N1_se

step "2. bridge fit"
"$bridge" fit "$out/sweep/flow_curve.csv" -o "$out/law.prm" -f -q

step "3. bridge material"
paper_emulsion "$bridge" "$out/law.prm" "$out/material_paper_emulsion.prm"
castoroil85 "$bridge" "$out/law.prm" "$out/material_castoroil85.prm" --tabulated

step "4. macro run: the paper's cone and plate, 20 speeds"
"$macro" run "$root/cases/cone_plate.prm" --material "$out/material_paper_emulsion.prm" \
  -o "$out/cone_plate" -f -q
show "$out/cone_plate/results.csv" rotation_rate torque torque_discretisation_error

if [ -f "$data" ]; then
  step "5. macro compare: the castor-oil emulsion in its Couette cell (no fitted parameter)"
  "$macro" compare "$root/cases/castoroil_couette.prm" "$data" \
    --material "$out/material_castoroil85.prm" -o "$out/compare_castoroil" -f
  compared="$out/compare_castoroil/comparison.csv"
else
  step "5. no measured data (../shared/data/rheometry/ absent): Couette torques of the bundled law"
  "$macro" run "$root/cases/castoroil_couette.prm" -o "$out/couette" -f -q
  show "$out/couette/results.csv" rotation_rate torque
  compared=""
fi

# The castor-oil flow curve from the bundled law (the paper sweep: 5 phi,
# 11 rates, 2 packings), with the band of each stress.
predict_castoroil() {
  "$bridge" predict "$root/cases/bridge_law_paper_sweep.prm" --phi 0.85 --viscosity 0.89e-3 \
    --rates 0.01,0.1,1,10,100,1000 "$@" -o "$out/predicted.csv" -f > /dev/null
  # extrapolated: 1 outside the simulated rates
  show "$out/predicted.csv" shear_rate shear_stress shear_stress_band extrapolated
}
step "5b. bridge predict: the castor-oil flow curve, (b) E* from G' = 143 Pa"
predict_castoroil --plateau-modulus 143
if [ -f "$data" ]; then
  # The measured yield stress: the flow sweep's low-rate plateau, its smallest stress.
  yield=$(awk -F, 'NR > 1 && (min == "" || $1 < min) { min = $1 } END { print min }' "$data")
  step "5b. bridge predict: (c) the measured yield stress ($yield Pa) and G' = 143 Pa"
  predict_castoroil --plateau-modulus 143 --yield-stress "$yield"
fi

step "6. micro oscillate: the castor-oil emulsion's amplitude sweep, 6 amplitudes, N = 200"
"${launcher[@]}" "$micro" oscillate "$oscillation_file" -q
# G' and G'' (storage, loss) with their standard errors, and I3/I1.
show "$out/oscillation/oscillation.csv" gamma0 storage storage_se loss loss_se intensity_3
"$bridge" fit --law "$out/law.prm" --oscillation "$out/oscillation/oscillation.csv" \
  -o "$out/law_with_amplitude_sweep.prm" -f

if [ -f "$amplitude_data" ]; then
  step "7. bridge amplitude-sweep: predicted against the measured one (E* by the flow-curve route)"
  "$bridge" amplitude-sweep "$out/law_with_amplitude_sweep.prm" --phi 0.85 --plateau-modulus 143 \
    --viscosity 0.89e-3 --data "$amplitude_data" -o "$out/amplitude_castoroil" -f
else
  step "7. no measured amplitude sweep: the predicted one only"
  "$bridge" amplitude-sweep "$out/law_with_amplitude_sweep.prm" --phi 0.85 --plateau-modulus 143 \
    --viscosity 0.89e-3 -o "$out/amplitude_castoroil" -f
fi

step "done"
echo "law:            $out/law.prm"
echo "materials:      $out/material_paper_emulsion.prm, $out/material_castoroil85.prm"
echo "cone and plate: $out/cone_plate/results.csv, $out/cone_plate/solution_019.vtu (ParaView)"
if [ -n "$compared" ]; then
  echo "comparison:     $compared"
  [ -f "$out/compare_castoroil/comparison.png" ] && echo "plot:           $out/compare_castoroil/comparison.png"
fi
echo "amplitude sweep: $out/amplitude_castoroil/amplitude_sweep.csv"
[ -f "$out/amplitude_castoroil/comparison.png" ] && echo "                 $out/amplitude_castoroil/comparison.png"
echo "total:          $((SECONDS - start)) s"

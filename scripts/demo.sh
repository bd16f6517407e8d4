#!/usr/bin/env bash
# `make demo`: the whole workflow on built-in defaults, from particles to a
# rheometer torque compared with a measurement, in a few minutes on 2 cores.
#
#   1. micro sweep    flow curves of N = 200 soft spheres (cases/demo_sweep.prm)
#   2. bridge fit     Herschel-Bulkley and universal-law fits -> a law file
#   3. bridge material  the law at the paper's emulsion (phi 0.80, E* 40 kPa,
#                     eta_s 1 mPa s) and at the castor-oil emulsion (phi 0.85,
#                     water, E* from its measured G' plateau of 143 Pa)
#   4. macro run      the paper's cone and plate (cases/cone_plate.prm)
#   5. macro compare  the castor-oil Couette measurement, when
#                     ../shared/data/rheometry/ is present; otherwise the
#                     Couette torques of the bundled law only
# Usage: scripts/demo.sh BUILD_DIR [OUTPUT_DIR]   (default out/demo)
set -euo pipefail

build=${1:?usage: scripts/demo.sh BUILD_DIR [OUTPUT_DIR]}
out=${2:-out/demo}
root=$(cd "$(dirname "$0")/.." && pwd)
micro="$build/micro/micro" bridge="$build/bridge/bridge" macro="$build/macro/macro"
data="$root/../shared/data/rheometry/castoroil85_couette_flow_sweep.csv"
start=$SECONDS
source "$root/scripts/bundled_materials.sh"

step() { printf '\n== %s  (%d s)\n' "$1" $((SECONDS - start)); }

# The sweep spreads its cases over one MPI rank per core when mpirun is there.
cores=$(nproc)
launcher=()
if command -v mpirun >/dev/null && [ "$cores" -gt 1 ]; then
  export OMPI_ALLOW_RUN_AS_ROOT=1 OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1 OMP_NUM_THREADS=1
  launcher=(mpirun -n "$cores")
fi

mkdir -p "$out"
# A fresh demo each time: the sweep folder would otherwise be resumed as done.
rm -rf "${out:?}/sweep"
sweep_file="$out/demo_sweep.prm"
sed "s|out/demo/sweep|$out/sweep|" "$root/cases/demo_sweep.prm" > "$sweep_file"

step "1. micro sweep: 3 volume fractions x 5 rates, N = 200 ($cores worker(s))"
"${launcher[@]}" "$micro" sweep "$sweep_file" -q
# phi, gamma~, sigma and its standard error, N1 and its standard error.
grep -v '^#' "$out/sweep/flow_curve.csv" | cut -d, -f1,2,4,5,10,11 | column -t -s,

step "2. bridge fit"
"$bridge" fit "$out/sweep/flow_curve.csv" -o "$out/law.prm" -f -q

step "3. bridge material"
paper_emulsion "$bridge" "$out/law.prm" "$out/material_paper_emulsion.prm"
castoroil85 "$bridge" "$out/law.prm" "$out/material_castoroil85.prm"

step "4. macro run: the paper's cone and plate, 20 speeds"
"$macro" run "$root/cases/cone_plate.prm" --material "$out/material_paper_emulsion.prm" \
  -o "$out/cone_plate" -f -q
grep -v '^#' "$out/cone_plate/results.csv" | cut -d, -f1,2 | column -t -s, | sed -n '1,21p'

if [ -f "$data" ]; then
  step "5. macro compare: the castor-oil emulsion in its Couette cell (no fitted parameter)"
  "$macro" compare "$root/cases/castoroil_couette.prm" "$data" \
    --material "$out/material_castoroil85.prm" -o "$out/compare_castoroil" -f
  compared="$out/compare_castoroil/comparison.csv"
else
  step "5. no measured data (../shared/data/rheometry/ absent): Couette torques of the bundled law"
  "$macro" run "$root/cases/castoroil_couette.prm" -o "$out/couette" -f -q
  grep -v '^#' "$out/couette/results.csv" | cut -d, -f1,2 | column -t -s,
  compared=""
fi

step "done"
echo "law:            $out/law.prm"
echo "materials:      $out/material_paper_emulsion.prm, $out/material_castoroil85.prm"
echo "cone and plate: $out/cone_plate/results.csv, $out/cone_plate/solution_019.vtu (ParaView)"
if [ -n "$compared" ]; then
  echo "comparison:     $compared"
  [ -f "$out/compare_castoroil/comparison.png" ] && echo "plot:           $out/compare_castoroil/comparison.png"
fi
echo "total:          $((SECONDS - start)) s"

#!/usr/bin/env bash
# Predicted against measured torques with the bundled law
# (cases/bridge_law_paper_sweep.prm, or the law file named by LAW), for
# docs/validation.md:
#
#  1. the 85 % castor-oil emulsion in its Couette cell (TA HR-3, DIN cylinders):
#     phi = 0.85, water (0.89 mPa s), E* from the measured G' plateau (143 Pa,
#     castoroil85_couette_amplitude_sweep.csv) - no parameter fitted to the
#     flow curve;
#  2. Dekker et al. 2018 (castor oil in water, phi = 0.70 ... 0.80, stress
#     against shear rate): E* fitted to the phi = 0.80 curve alone by `bridge
#     rescale`, the other volume fractions predicted; no geometry is reported,
#     so their stresses are compared as torques of the paper's cone and plate
#     (cases/cone_plate.prm, stress = 3M/(2 pi R^3)).
# Usage: bench/compare_measured.sh BUILD_DIR [OUTPUT_DIR]   (needs ../shared/data/rheometry)
set -euo pipefail
build=${1:?usage: bench/compare_measured.sh BUILD_DIR [OUTPUT_DIR]}
out=${2:-out/compare_measured}
root=$(cd "$(dirname "$0")/.." && pwd)
data="$root/../shared/data/rheometry"
law=${LAW:-"$root/cases/bridge_law_paper_sweep.prm"}
bridge="$build/bridge/bridge" macro="$build/macro/macro"
[ -d "$data" ] || { echo "compare_measured: $data is absent; nothing to compare" >&2; exit 2; }
mkdir -p "$out"
source "$root/scripts/bundled_materials.sh"

echo "== castor-oil emulsion, Couette cell, E* from G' = 143 Pa"
castoroil85 "$bridge" "$law" "$out/material_castoroil85.prm" > /dev/null
"$macro" compare "$root/cases/castoroil_couette.prm" "$data/castoroil85_couette_flow_sweep.csv" \
  --material "$out/material_castoroil85.prm" -o "$out/castoroil" -f -q
grep -E "^(torque|material)" "$out/castoroil/summary.txt"
# The flowing branch alone (below ~1 1/s the measured stress keeps falling: slip).
"$macro" compare "$root/cases/castoroil_couette.prm" "$data/castoroil85_couette_flow_sweep.csv" \
  --material "$out/material_castoroil85.prm" -o "$out/castoroil_above_1" --min-rate 1 -f -q
echo "shear rates >= 1 1/s: $(grep '^torque' "$out/castoroil_above_1/summary.txt")"

echo "== Dekker 2018, E* fitted to phi = 0.80 only"
dekker="$data/dekker2018_emulsion_flow_curves_digitized.csv"
"$bridge" rescale "$dekker" --rate-unit 1/s --stress-unit Pa --viscosity 0.89e-3 --law "$law" \
  --phi-from-labels --extrapolate -o "$out/dekker_rescaled.csv" -f > "$out/dekker_rescale.txt"
e_star=$(awk '/^curve .0.80./ {found = 1} found && /E\* =/ {sub(/.*E\* = /, ""); print $1; exit}' \
  "$out/dekker_rescale.txt")
echo "E* = $e_star Pa (universal-law fit of the phi = 0.80 curve)"
for phi in 0.70 0.72 0.74 0.76 0.78 0.80; do
  "$bridge" material "$law" --phi "$phi" --modulus "$e_star" --viscosity 0.89e-3 \
    -o "$out/material_dekker_$phi.prm" -f > /dev/null
  "$macro" compare "$root/cases/cone_plate.prm" "$dekker" --sample "$phi" \
    --rate-unit 1/s --stress-unit Pa --material "$out/material_dekker_$phi.prm" \
    -o "$out/dekker_$phi" -f -q
  echo "phi $phi: $(grep '^torque' "$out/dekker_$phi/summary.txt")"
done

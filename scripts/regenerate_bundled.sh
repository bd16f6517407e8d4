#!/usr/bin/env bash
# Everything the project bundles from its default model's `paper` sweep,
# regenerated from one finished sweep folder (cases/sweep_paper.prm):
#
#   1. bridge fit       cases/bridge_law_paper_sweep.prm and its three tables
#                       (the bundled law; the figures are drawn from the tables)
#   2. bridge material  cases/material_paper_emulsion.prm (phi 0.80, E* 40 kPa,
#                       water: the cone and plate's material) and
#                       cases/material_castoroil85_predicted.prm (phi 0.85,
#                       E* from the measured G' plateau of 143 Pa)
#   3. figures          docs/img/paper_sweep_n1000_*.png: the stresses and
#                       their parts (plot_flow_curve.py), the Herschel-Bulkley
#                       fits and the collapse (plot_bridge.py; Figs. 2a, 4)
#
# Each file is written by the tool that owns it, so its header records the
# command, software version and inputs. Afterwards: the numbers quoted in
# docs/bridge.md, docs/macro.md and docs/validation.md, and
# `bash bench/compare_measured.sh BUILD` for the comparison with measurements.
# Usage: scripts/regenerate_bundled.sh BUILD_DIR SWEEP_DIR
set -euo pipefail
build=${1:?usage: scripts/regenerate_bundled.sh BUILD_DIR SWEEP_DIR}
sweep=${2:?usage: scripts/regenerate_bundled.sh BUILD_DIR SWEEP_DIR}
root=$(cd "$(dirname "$0")/.." && pwd)
bridge="$build/bridge/bridge"
for f in flow_curve.csv flow_curve_packings.csv; do
  [ -f "$sweep/$f" ] || { echo "regenerate_bundled: $sweep/$f is missing (is the sweep finished?)" >&2; exit 2; }
done
cd "$root"

"$bridge" fit "$sweep/flow_curve.csv" --packings "$sweep/flow_curve_packings.csv" \
  -o cases/bridge_law_paper_sweep.prm --force

law=cases/bridge_law_paper_sweep.prm
source scripts/bundled_materials.sh
paper_emulsion "$bridge" "$law" cases/material_paper_emulsion.prm
castoroil85 "$bridge" "$law" cases/material_castoroil85_predicted.prm

figures=$(mktemp -d)
trap 'rm -rf "$figures"' EXIT
/usr/bin/python3 scripts/plot_flow_curve.py "$sweep/flow_curve.csv" docs/img/paper_sweep_n1000
/usr/bin/python3 scripts/plot_bridge.py fit "$law" -o "$figures"
mv "$figures/bridge_law_paper_sweep_flow_curves.png" docs/img/paper_sweep_n1000_hb_fits.png
mv "$figures/bridge_law_paper_sweep_collapse.png" docs/img/paper_sweep_n1000_collapse.png

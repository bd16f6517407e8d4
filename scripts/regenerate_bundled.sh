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
# command, software version and inputs. Afterwards, by hand (nothing below is
# redone here):
#   - cases/slip_castoroil85.prm: its rows are those below the law's yield
#     stress, `bridge slip-law cases/slip_phi080_085.csv --below-yield LAW
#     --phi 0.85 --modulus E* ...` (the command is in its header and in
#     docs/macro.md, "Wall slip: the castor-oil cell");
#   - `bash bench/compare_measured.sh BUILD [OUT]` (the comparison with
#     measurements) and `bash scripts/slip_comparison.sh BUILD
#     cases/slip_phi080_085.csv OUT R ...` (the castor-oil cell with slip; it
#     reads E* and eta_s from the castor-oil material's header), and the
#     figures they draw that docs/img holds: compare_castoroil_couette.png,
#     compare_dekker_phi074.png, compare_castoroil_couette_slip.png;
#   - the numbers the docs quote from the law, the materials and those
#     comparisons: docs/bridge.md, macro.md, validation.md, fidelity.md,
#     oscillation.md (yield strains, k, the crossover estimate),
#     bench/results/wall_slip_micro-2026-11-26.md (sigma_w/sigma_y of the wall
#     tables), tutorial.md, sweeps.md (the sweep's
#     cost);
#   - if the law's G0 at phi 0.85 moves, the castor-oil E* moves and with it
#     omega~ = 2.31e-7, at which the amplitude sweeps of docs/oscillation.md
#     (and compare_castoroil_amplitude_sweep.png) were simulated.
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

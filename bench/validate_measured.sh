#!/usr/bin/env bash
# The scoreboard of docs/validation.md: softglass against every public data set
# in ../shared/data/rheometry, in every prediction mode each supports, with the
# tabulated law and its Herschel-Bulkley summary side by side
# (scripts/validate_measured.py; the castor-oil cell's torques by macro compare
# in modes (b), (c), (d)). Not in CI.
#   bench/validate_measured.sh BUILD_DIR [LAW]
# Writes bench/results/validate_measured-DATE.md (the whole table, per phi
# too), replaces the scoreboard block of docs/validation.md with it, and
# writes LAW_model_error.csv beside the law: the pooled error per mode, which
# `bridge predict` states as the model's systematic error.
set -euo pipefail
build=${1:?usage: bench/validate_measured.sh BUILD_DIR [LAW]}
root=$(cd "$(dirname "$0")/.." && pwd)
law=${2:-"$root/cases/bridge_law_paper_sweep.prm"}
data="$root/../shared/data/rheometry"
bridge="$build/bridge/bridge" macro="$build/macro/macro"
[ -d "$data" ] || { echo "validate_measured: $data is absent; nothing to score" >&2; exit 2; }
scratch=$(mktemp -d)
trap 'rm -rf "$scratch"' EXIT

# The castor-oil cell's torques by macro compare: mode (b) (E* from G' = 143 Pa)
# with both law forms, and with the tabulated law modes (c) (the flow sweep's
# smallest stress as the measured yield stress, as in the flow-curve rows) and
# (d) (E* fitted to the flow sweep, in sample).
sweep="$data/castoroil85_couette_flow_sweep.csv"
yield=$(awk -F, 'NR > 1 && (min == "" || $1 < min) { min = $1 } END { print min }' "$sweep")
torques=()
score_torques() {  # name, mode label, law form, then bridge material's mode arguments
  local name=$1 mode=$2 form=$3
  shift 3
  "$bridge" material "$law" --phi 0.85 --viscosity 0.89e-3 "$@" -o "$scratch/$name.prm" -f \
    > /dev/null
  "$macro" compare "$root/cases/castoroil_couette.prm" "$sweep" --material "$scratch/$name.prm" \
    -o "$scratch/compare_$name" -f -q
  local line points bias median
  line=$(grep '^torque:' "$scratch/compare_$name/summary.txt")
  # "torque: 71 points, predicted/measured - 1: mean +2.7 %, rms 51.6 %, median |.| 40.4 %, ..."
  points=$(sed -E 's/^torque: ([0-9]+) points.*/\1/' <<< "$line")
  bias=$(sed -E 's/.*mean ([-+0-9.]+) %.*/\1/' <<< "$line")
  median=$(sed -E 's/.*median \|\.\| ([0-9.]+) %.*/\1/' <<< "$line")
  torques+=(--torques "$mode|$form|$median|$bias|$points")
}
score_torques b_tabulated "(b) E* from G'" tabulated --plateau-modulus 143 --tabulated
score_torques b_hb "(b) E* from G'" herschel-bulkley --plateau-modulus 143
score_torques c_tabulated "(c) measured yield stress" tabulated --plateau-modulus 143 \
  --yield-stress "$yield" --tabulated
score_torques d_tabulated "(d) E* fitted, in sample" tabulated --fit-to "$sweep" --tabulated

date=$(date -u +%Y-%m-%d)
commit=$(git -C "$root" rev-parse --short HEAD)
log="$root/bench/results/validate_measured-$date.md"
mkdir -p "$(dirname "$log")"
{
  echo "Scoreboard of $date, commit $commit, law $(basename "$law") (bench/validate_measured.sh)."
  echo
  /usr/bin/python3 "$root/scripts/validate_measured.py" "$bridge" "$law" "$data" "${torques[@]}" \
    --model-error "${law%.prm}_model_error.csv"
} > "$scratch/table.md"
cp "$scratch/table.md" "$log"

# docs/validation.md: the block between the two markers is the table.
doc="$root/docs/validation.md"
/usr/bin/python3 - "$doc" "$scratch/table.md" <<'PY'
import sys
doc, table = sys.argv[1], open(sys.argv[2]).read()
text = open(doc).read()
begin, end = "<!-- scoreboard: begin -->", "<!-- scoreboard: end -->"
if begin not in text or end not in text:
    sys.exit(f"validate_measured: {doc} has no {begin} ... {end} block")
head, rest = text.split(begin, 1)
_, tail = rest.split(end, 1)
open(doc, "w").write(head + begin + "\n" + table + end + tail)
PY
cat "$scratch/table.md"
echo "written  $log and the scoreboard of $doc"

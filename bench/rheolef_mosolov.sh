#!/usr/bin/env bash
# Rheolef's Mosolov solver against `macro run` on the same unit-square duct
# (Bi = 0.2, n = 0.5, Rheolef's scaling; bench/macro_rheolef_square.prm).
#   usage: bench/rheolef_mosolov.sh [BUILD_DIR]
# Reference values: macro at the accurate preset with one more uniform
# refinements. Prints both solvers' u_max and flow rate with their errors
# against it, the wall times, and a last line `speedup_vs_rheolef <ratio>`
# (Rheolef's wall time at its 20x20 P1 grid / macro's at the standard preset).
# Needs Rheolef (apt-get install rheolef librheolef-dev rheolef-doc).
set -euo pipefail
here=$(cd "$(dirname "$0")" && pwd)
build=${1:-$here/../build}
macro=$build/macro/macro
scene=$here/macro_rheolef_square.prm
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT

run_macro() {  # preset, extra solver lines -> "u_max Q seconds"
  sed -e "s/set preset = standard/set preset = $1\n$2/" "$scene" > "$work/scene.prm"
  local start end
  start=$(date +%s.%N)
  "$macro" run "$work/scene.prm" -o "$work/out_$1" -q --force
  end=$(date +%s.%N)
  # columns: G, Q, Q errors (2), u_max, ...
  tail -1 "$work/out_$1/results.csv" | awk -F, -v t="$(echo "$end - $start" | bc)" '{print $5, $2, t}'
}

read -r ref_u ref_q _ < <(run_macro accurate "  set global refinements = 3")
read -r u q t < <(run_macro standard "")
echo "reference (macro accurate, 3 refinements): u_max=$ref_u Q=$ref_q"
echo "macro standard: u_max=$u Q=$q seconds=$t" \
     "u_max_error=$(echo "scale=10; ($u - $ref_u)/$ref_u" | bc)" \
     "Q_error=$(echo "scale=10; ($q - $ref_q)/$ref_q" | bc)"
line=$(/work/shared/peers/rheolef/run_mosolov.sh 20 P1 0.2 0.5 10000)
echo "$line"
r_u=$(echo "$line" | sed -n 's/.*u_max=\([^ ]*\).*/\1/p')
r_t=$(echo "$line" | sed -n 's/.*seconds=\([^ ]*\).*/\1/p')
echo "rheolef u_max_error=$(echo "scale=10; ($r_u - $ref_u)/$ref_u" | bc)"
echo "speedup_vs_rheolef $(echo "scale=2; $r_t / $t" | bc)"

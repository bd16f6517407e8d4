#!/usr/bin/env bash
# Rheolef's Mosolov solver against `macro run` on the same unit-square duct
# (Bi = 0.2, n = 0.5, Rheolef's scaling; bench/macro_rheolef_square.prm).
#   usage: bench/rheolef_mosolov.sh [BUILD_DIR]
# Reference values: macro at the accurate preset with three uniform refinements
# (instead of two). Prints both solvers' u_max and flow rate with their errors
# against it, the wall times, and a last line `speedup_vs_rheolef <ratio>`
# (Rheolef's wall time at its 20x20 P1 grid / macro's cheapest run at least as
# accurate in u_max).
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

rel() { echo "scale=10; ($1 - $2)/$2" | bc; }
abs() { local v=$1; echo "${v#-}"; }

read -r ref_u ref_q _ < <(run_macro accurate "  set global refinements = 3")
echo "reference (macro accurate, 3 refinements): u_max=$ref_u Q=$ref_q"
line=$(/work/shared/peers/rheolef/run_mosolov.sh 20 P1 0.2 0.5 10000)
echo "$line"
r_u=$(echo "$line" | sed -n 's/.*u_max=\([^ ]*\).*/\1/p')
r_t=$(echo "$line" | sed -n 's/.*seconds=\([^ ]*\).*/\1/p')
r_err=$(rel "$r_u" "$ref_u")
echo "rheolef 20x20 P1: u_max_error=$r_err seconds=$r_t"

# macro, cheapest first; the speedup is taken against the cheapest run whose
# u_max is at least as accurate as Rheolef's.
speedup=""
for candidate in "fast|  set relative rate scale = 1e-3" "standard|"; do
  preset=${candidate%%|*}; extra=${candidate#*|}
  read -r u q t < <(run_macro "$preset" "$extra")
  u_err=$(rel "$u" "$ref_u"); q_err=$(rel "$q" "$ref_q")
  echo "macro $preset ${extra# }: u_max=$u u_max_error=$u_err Q=$q Q_error=$q_err seconds=$t"
  if [ -z "$speedup" ] && (( $(echo "$(abs "$u_err") <= $(abs "$r_err")" | bc) )); then
    speedup=$(echo "scale=2; $r_t / $t" | bc)
    echo "accuracy: macro u_max error $u_err, flow rate error $q_err; rheolef u_max error $r_err"
  fi
done
echo "speedup_vs_rheolef ${speedup:-none}"

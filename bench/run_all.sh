#!/usr/bin/env bash
# The peer comparisons (LAMMPS, scaling with N, LAMMPS' scaling with N); `make
# bench` runs this. The other benches (stiff_tradeoff.sh, contact_law_exponent.sh,
# phi080_packings.sh, compare_measured.sh, …) each answer one question and are
# run by hand; the docs page that quotes a bench names its command.
set -euo pipefail
here=$(cd "$(dirname "$0")" && pwd)
build=${1:-$here/../build}
"$here/lammps_comparison.sh" "$build"
"$here/scaling.sh" "$build"
"$here/lammps_scaling.sh" "$build"

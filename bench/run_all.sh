#!/usr/bin/env bash
# Every benchmark, in order; `make bench` runs this.
set -euo pipefail
here=$(cd "$(dirname "$0")" && pwd)
build=${1:-$here/../build}
"$here/lammps_comparison.sh" "$build"
"$here/scaling.sh" "$build"

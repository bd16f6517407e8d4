#!/usr/bin/env bash
# The microstructure issue's check: phi = 0.80, N = 1000, gamma~ = 1e-6, 1e-5,
# 1e-4, one packing, snapshots every 0.1 strain; the structure of the stationary
# part (written by `micro run` into each result file), its CSV tables, and the
# figures of docs/structure.md. The `literal` model (whose results they show).
#   usage: bench/structure_phi080.sh [BUILD_DIR] [OUT_DIR]
set -euo pipefail
here=$(cd "$(dirname "$0")" && pwd)
build=$(cd "${1:-$here/../build}" && pwd)
out=${2:-$here/../out/structure_phi080}
mkdir -p "$out"
micro="$build/micro/micro"

for spec in "1e-4 20" "1e-5 20" "1e-6 12"; do
  read -r rate strain <<< "$spec"
  cat > "$out/run_$rate.prm" <<PRM
subsection model
  set preset = literal
end
subsection particles
  set number          = 1000
  set volume fraction = 0.80
  set seed            = 1
end
subsection shear
  set gamma dot tilde       = $rate
  set min strain            = $strain
  set max strain            = $strain
  set min stationary strain = 5
  set snapshot interval     = 0.1
end
subsection output
  set file = $out/run_$rate.h5
end
PRM
done

ls "$out"/run_*.prm | xargs -P "$(nproc)" -I{} sh -c \
  'OMP_NUM_THREADS=1 "$0" run "$1" --force --quiet > "${1%.prm}.log" 2>&1 || echo "FAILED: $1"' "$micro" {}

for rate in 1e-4 1e-5 1e-6; do
  "$micro" analyze "$out/run_$rate.h5" --csv "$out/structure_$rate" --force | grep -v written
  grep -h -E "shear |converged|CONVERGED|layering" "$out/run_$rate.log"
done
/usr/bin/python3 "$here/../scripts/plot_structure.py" "$out/structure" "$out"/run_1e-*.h5

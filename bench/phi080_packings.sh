#!/usr/bin/env bash
# The foundation issue's check: phi = 0.80, N = 1000, three packings, at
# gamma~ = 1e-4 and 1e-5, each run until sigma, N1 and N2 are known to 5 %;
# then the packing averages (micro summary). One run per core at a time.
#   usage: bench/phi080_packings.sh [BUILD_DIR] [OUT_DIR]
set -euo pipefail
here=$(cd "$(dirname "$0")" && pwd)
build=$(cd "${1:-$here/../build}" && pwd)
out=${2:-$here/../out/phi080_packings}
mkdir -p "$out"
micro="$build/micro/micro"

for rate in 1e-4 1e-5; do
  for seed in 1 2 3; do
    cat > "$out/run_${rate}_seed${seed}.prm" <<PRM
subsection particles
  set number          = 1000
  set volume fraction = 0.80
  set seed            = $seed
end
subsection shear
  set gamma dot tilde       = $rate
  set target relative error = 0.05
  set min stationary strain = 10
  set max strain            = 400
end
subsection output
  set file = $out/run_${rate}_seed${seed}.h5
end
PRM
  done
done

ls "$out"/run_*.prm | xargs -P "$(nproc)" -I{} sh -c \
  'OMP_NUM_THREADS=1 "$0" run "$1" --force --quiet > "${1%.prm}.log" 2>&1 || echo "FAILED: $1"' "$micro" {}

for rate in 1e-4 1e-5; do
  echo "=== gamma~ = $rate"
  "$micro" summary "$out"/run_${rate}_seed*.h5 --csv "$out/summary_${rate}.csv" --force
  grep -h "cost" "$out"/run_${rate}_seed*.log
done

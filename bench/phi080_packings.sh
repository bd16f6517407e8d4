#!/usr/bin/env bash
# The foundation issue's check: phi = 0.80, N = 1000, three packings, at
# gamma~ = 1e-4 and 1e-5, each run until sigma, N1 and N2 are known to 5 %;
# then the packing averages (micro summary). One run per core at a time.
# Two polydispersities: the default 0.10, with which the samples layer under
# shear at 1e-4 (runs stop and say so), and 0.15, with which they stay glassy.
# The `literal` model (whose results docs/validation.md shows).
#   usage: bench/phi080_packings.sh [BUILD_DIR] [OUT_DIR]
set -euo pipefail
here=$(cd "$(dirname "$0")" && pwd)
build=$(cd "${1:-$here/../build}" && pwd)
out=${2:-$here/../out/phi080_packings}
mkdir -p "$out"
micro="$build/micro/micro"

cases="1e-4:0.10 1e-5:0.10 1e-4:0.15 1e-5:0.15"
for case in $cases; do
  rate=${case%:*}; delta=${case#*:}
  for seed in 1 2 3; do
    cat > "$out/run_${rate}_d${delta}_seed${seed}.prm" <<PRM
subsection model
  set preset = literal
end
subsection particles
  set number          = 1000
  set volume fraction = 0.80
  set polydispersity  = $delta
  set seed            = $seed
end
subsection shear
  set gamma dot tilde       = $rate
  set target relative error = 0.05
  set min stationary strain = 10
  set max strain            = 400
end
subsection output
  set file = $out/run_${rate}_d${delta}_seed${seed}.h5
end
PRM
  done
done

ls "$out"/run_*.prm | xargs -P "$(nproc)" -I{} sh -c \
  'OMP_NUM_THREADS=1 "$0" run "$1" --force --quiet > "${1%.prm}.log" 2>&1 || echo "FAILED: $1"' "$micro" {}

for case in $cases; do
  rate=${case%:*}; delta=${case#*:}
  echo "=== gamma~ = $rate, polydispersity $delta"
  grep -h -E "converged|NOT CONVERGED|layering" "$out"/run_${rate}_d${delta}_seed*.log
  "$micro" summary "$out"/run_${rate}_d${delta}_seed*.h5 --csv "$out/summary_${rate}_d${delta}.csv" --force
  grep -h "cost" "$out"/run_${rate}_d${delta}_seed*.log
done

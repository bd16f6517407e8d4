#!/usr/bin/env bash
# Time per particle-step and memory per particle for N = 1e3, 1e4, 1e5, 1e6
# (Hertz, phi = 0.80, no drag, fixed strain step 2e-6), one thread and all
# threads. Large N tiles a relaxed base packing k×k×k times (see engine_bench.cpp):
#   1e3 = 1000·1³, 1e4 = 1250·2³, 1e5 = 800·5³, 1e6 = 1000·10³.
# Then the roof for the sizes beyond the caches: one core's memory bandwidth
# with k concurrent streams (memory_streams.cpp), measured in the same run.
#   usage: bench/scaling.sh [BUILD_DIR]
set -euo pipefail
here=$(cd "$(dirname "$0")" && pwd)
build=$(cd "${1:-$here/../build}" && pwd)
threads_all=$(nproc)
printf "%-9s %-8s %-17s %-18s %-18s %-18s\n" N threads ns/particle-step particle-steps/s engine_B/particle peakRSS_B/particle
for spec in "1000 1 2000" "1250 2 1000" "800 5 200" "1000 10 40"; do
  read -r base tile steps <<< "$spec"
  for t in 1 "$threads_all"; do
    out=$("$build/bench/engine_bench" --base "$base" --tile "$tile" --phi 0.80 --law hertz --skin 0.6 \
          --steps "$steps" --strain-per-step 2e-6 --threads "$t")
    get() { awk -v k="$1" '$1==k{print $2}' <<< "$out"; }
    printf "%-9s %-8s %-17s %-18s %-18s %-18s\n" "$(get particles)" "$t" "$(get ns_per_particle_step)" \
      "$(get particle_steps_per_second)" "$(get engine_bytes_per_particle)" "$(get peak_rss_bytes_per_particle)"
  done
done
"$build/bench/memory_streams" --streams 1 6 12 24

#!/usr/bin/env bash
# Time per particle-step and memory per particle for N = 1e3, 1e4, 1e5, 1e6
# (Hertz, phi = 0.80, no drag, fixed strain step 2e-6), one thread and all
# threads. Large N tiles a relaxed base packing k×k×k times (see engine_bench.cpp):
#   1e3 = 1000·1³, 1e4 = 1250·2³, 1e5 = 800·5³, 1e6 = 1000·10³.
# Each timed loop is 4e7 particle-steps, long enough to time, short enough to
# repeat. The sizes are measured in turn, `rounds` times (default 5), and the
# best round of each is printed: on a shared host single runs of a size
# scatter widely (docs/validation.md §2; bench/results/scaling_against_198b852-2026-12-02-zen5.md),
# enough to move the growth from 1e3 to 1e6 by as much, and a slow phase hits
# one size in one round, not all rounds of it.
# Then the roof for the sizes beyond the caches: one core's memory bandwidth
# with k concurrent streams (memory_streams.cpp), measured in the same run.
# Last line: growth_1e3_to_1e6_one_thread <ratio of the best ns per particle-step>.
#   usage: bench/scaling.sh [BUILD_DIR] [ROUNDS]
set -euo pipefail
here=$(cd "$(dirname "$0")" && pwd)
build=$(cd "${1:-$here/../build}" && pwd)
rounds=${2:-5}
threads_all=$(nproc)
work=$(mktemp -d); trap 'rm -rf "$work"' EXIT

# base tile steps: steps × N = 4e7 particle-steps.
specs=("1000 1 40000" "1250 2 4000" "800 5 400" "1000 10 40")
for round in $(seq "$rounds"); do
  for spec in "${specs[@]}"; do
    read -r base tile steps <<< "$spec"
    for t in 1 "$threads_all"; do
      "$build/bench/engine_bench" --base "$base" --tile "$tile" --phi 0.80 --law hertz --skin 0.6 \
        --steps "$steps" --strain-per-step 2e-6 --threads "$t" > "$work/$base.$tile.$t.$round"
    done
  done
done

printf "%-9s %-8s %-17s %-18s %-18s %-18s\n" N threads ns/particle-step particle-steps/s engine_B/particle peakRSS_B/particle
for spec in "${specs[@]}"; do
  read -r base tile steps <<< "$spec"
  for t in 1 "$threads_all"; do
    # The round with the fewest ns per particle-step, whole.
    best=$(awk '$1=="ns_per_particle_step"{print $2, FILENAME}' "$work/$base.$tile.$t".* |
           sort -g | head -1 | cut -d' ' -f2)
    get() { awk -v k="$1" '$1==k{print $2}' "$best"; }
    printf "%-9s %-8s %-17s %-18s %-18s %-18s\n" "$(get particles)" "$t" "$(get ns_per_particle_step)" \
      "$(get particle_steps_per_second)" "$(get engine_bytes_per_particle)" "$(get peak_rss_bytes_per_particle)"
  done
done | tee "$work/table"
"$build/bench/memory_streams" --streams 1 6 12 24
awk '$2==1 && $1==1000{a=$3} $2==1 && $1==1000000{b=$3}
     END{printf "growth_1e3_to_1e6_one_thread %.2f\n", b/a}' "$work/table"

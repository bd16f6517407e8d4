#!/usr/bin/env bash
# How the time per particle-step grows with N, for softglass and for LAMMPS on
# the same work (bench/lammps_comparison.sh's: Hertz, phi = 0.80, no drag, skin
# 0.3 diameters, strain 2e-6 per step), on one core, the two in turn at each
# N. A rise from 1e3 to 1e5 particles that both codes show is the memory
# hierarchy's (the data leave the caches), not one code's; scaling.sh gives
# ours alone, up to 1e6 (LAMMPS' compression stage alone would take hours
# there). softglass tiles a relaxed base packing (scaling.sh's sizes); LAMMPS
# makes a packing of N at each size (its input's 25 000 compression steps are
# not timed: only its last run, the shear).
# Last lines: growth_1e3_to_<N>_softglass / _lammps <ratio of ns per particle-step>.
# The defaults run for tens of minutes, most of it LAMMPS' compression at the
# largest N (bench/results/lammps_scaling-*.md).
#   usage: bench/lammps_scaling.sh [BUILD_DIR]   (env: SIZES, default "1000 10000 100000")
set -euo pipefail
here=$(cd "$(dirname "$0")" && pwd)
build=$(cd "${1:-$here/../build}" && pwd)
source "$here/lammps_peer.sh"
require_lammps
work=$(mktemp -d); trap 'rm -rf "$work"' EXIT
sizes=${SIZES:-"1000 10000 100000"}

# base × tile³ = N as in scaling.sh; the shear's steps for about 2e7…2e8
# particle-steps per run.
layout() {
  case $1 in
    1000) echo "1000 1 20000" ;;
    10000) echo "1250 2 5000" ;;
    100000) echo "800 5 2000" ;;
    1000000) echo "1000 10 200" ;;
    *) echo "size $1: one of 1000 10000 100000 1000000" >&2; exit 2 ;;
  esac
}

printf "%-9s %-22s %-22s %s\n" N softglass_ns_per_step lammps_ns_per_step lammps/softglass
declare -A ours lammps
for n in $sizes; do
  read -r base tile steps <<< "$(layout "$n")"
  out=$(OMP_NUM_THREADS=1 "$build/bench/engine_bench" --base "$base" --tile "$tile" --phi 0.80 \
        --law hertz --skin 0.6 --steps "$steps" --strain-per-step 2e-6 --threads 1)
  ours[$n]=$(awk '$1=="ns_per_particle_step"{print $2}' <<< "$out")
  lammps_shear "$n" "$steps" "$work"
  loop=$(lammps_shear_seconds "$work")
  lammps[$n]=$(awk -v t="$loop" -v n="$n" -v s="$steps" 'BEGIN{printf "%.2f", 1e9*t/(n*s)}')
  printf "%-9s %-22s %-22s %.2f\n" "$n" "${ours[$n]}" "${lammps[$n]}" \
    "$(awk -v a="${lammps[$n]}" -v b="${ours[$n]}" 'BEGIN{print a/b}')"
done
first=${sizes%% *}
power() { awk -v n="$1" 'BEGIN{printf "1e%d", int(log(n)/log(10) + 0.5)}'; }
for n in $sizes; do
  [ "$n" = "$first" ] && continue
  for code in softglass lammps; do
    if [ $code = softglass ]; then a=${ours[$n]} b=${ours[$first]}; else a=${lammps[$n]} b=${lammps[$first]}; fi
    awk -v a="$a" -v b="$b" -v name="growth_$(power "$first")_to_$(power "$n")_$code" \
      'BEGIN{printf "%s %.2f\n", name, a/b}'
  done
done

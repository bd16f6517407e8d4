#!/usr/bin/env bash
# One `micro run` timed side by side for two builds (issue 18): the same packing
# sheared by a candidate and a base build, alternating A, B, A, B, ... so that
# both see the same load on a shared machine. Prints per repetition each
# build's wall time and the ratio candidate/base, then the median ratio, and
# each build's sigma, N1, N2 and step counts from its last run (a change meant
# to be exact must give the same numbers; a faster one, a ratio below 1).
#
# Usage: bench/run_side_by_side.sh CANDIDATE_BUILD BASE_BUILD [output dir]
#   env: MODEL (softglass), GAMMA (1e-9), N (1000), PHI (0.80), SEED (1),
#        STRAIN (0.2), REPS (3), CANDIDATE_SCHEME and BASE_SCHEME (the
#        integrator's `scheme`, auto: two schemes of one build side by side)
# Example (docs/integrators.md, "The assembly written entry by entry"):
#   bash bench/run_side_by_side.sh build /tmp/base/build
set -euo pipefail
shopt -s inherit_errexit
candidate=${1:?usage: bench/run_side_by_side.sh CANDIDATE_BUILD BASE_BUILD [output dir]}
base=${2:?usage: bench/run_side_by_side.sh CANDIDATE_BUILD BASE_BUILD [output dir]}
out=${3:-out/run_side_by_side}
model=${MODEL:-softglass} gamma=${GAMMA:-1e-9} n=${N:-1000} phi=${PHI:-0.80}
seed=${SEED:-1} strain=${STRAIN:-0.2} reps=${REPS:-3}
candidate_scheme=${CANDIDATE_SCHEME:-auto} base_scheme=${BASE_SCHEME:-auto}
for b in "$candidate" "$base"; do
  [ -x "$b/micro/micro" ] || { echo "run_side_by_side: no micro in $b/micro" >&2; exit 2; }
done
mkdir -p "$out"
cd "$out"

common="subsection model
  set preset = $model
end
subsection particles
  set number = $n
  set volume fraction = $phi
  set seed = $seed
end"
printf '%s\nsubsection output\n  set file = pack.h5\n  set overwrite = true\nend\n' \
  "$common" > pack.prm
OMP_NUM_THREADS=1 "$base/micro/micro" --threads 1 pack pack.prm > pack.log 2>&1 ||
  { tail -n 3 pack.log >&2; exit 1; }

run_file() {  # $1: output file, $2: scheme
  printf '%s\nsubsection packing\n  set input file = pack.h5\nend\n' "$common"
  printf 'subsection integrator\n  set scheme = %s\nend\n' "$2"
  printf 'subsection shear\n  set gamma dot tilde = %s\n  set min strain = %s\n' "$gamma" "$strain"
  printf '  set max strain = %s\n  set min stationary strain = %s\n' "$strain" "$strain"
  printf '  set snapshot interval = 0\nend\n'
  printf 'subsection output\n  set file = %s\n  set overwrite = true\nend\n' "$1"
}

timed_run() {  # $1: label, $2: build, $3: scheme; prints the wall time in seconds
  run_file "$1.h5" "$3" > "$1.prm"
  local start end
  start=$(date +%s.%N)
  OMP_NUM_THREADS=1 "$2/micro/micro" --threads 1 run "$1.prm" > "$1.log" 2>&1 ||
    { tail -n 3 "$1.log" >&2; exit 1; }
  end=$(date +%s.%N)
  echo "$end - $start" | bc
}

echo "# micro run side by side: $model, N = $n, phi = $phi, seed $seed, gamma~ = $gamma, $strain strain, $reps repetitions"
ratios=()
for r in $(seq 1 "$reps"); do
  t_candidate=$(timed_run candidate "$candidate" "$candidate_scheme")
  t_base=$(timed_run base "$base" "$base_scheme")
  ratio=$(printf '%.3f' "$(echo "scale=6; $t_candidate / $t_base" | bc)")
  ratios+=("$ratio")
  printf 'rep %d  candidate %.1f s  base %.1f s  ratio %s\n' "$r" "$t_candidate" "$t_base" "$ratio"
done
for label in candidate base; do
  printf '%-9s' "$label"
  awk '$1 == "sigma" || $1 == "N1" || $1 == "N2" {printf "  %s %s", $1, $2}
       $1 == "cost" {printf "  steps %s rejected %s", $2, substr($4, 2)}' "$label.log"
  echo
done
echo "median_ratio $(printf '%s\n' "${ratios[@]}" | sort -g | awk '{v[NR] = $1} END {printf "%.3f\n", NR % 2 ? v[(NR + 1) / 2] : (v[NR / 2] + v[NR / 2 + 1]) / 2}')"

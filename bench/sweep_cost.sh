#!/usr/bin/env bash
# What the paper's sweep costs, from a slice of it timed side by side with a
# baseline build (issue 18), and whether the two builds agree on its stresses.
#
# The slice: one packing at φ = 0.80 and 0.90, every rate of the `paper` sweep
# preset (1e-9 … 1e-4, two per decade) plus the quasi-static case, N = 1000,
# the preset's run length (5 strain). The baseline and the candidate run the
# same cases at the same time, one core each, case after case in the same
# order, so that both see the same load on a shared machine. Per case: the
# wall time of each, their ratio, and the difference of σ, N1, N2 (candidate
# − baseline) with its standard error (the two runs' errors combined). Last
# lines:
#   paper_slice_speedup <Σ baseline time / Σ candidate time>
#   paper_sweep_hours_estimate <h>   the whole `paper` sweep (five packings)
#       on two cores with the candidate: the slice's measured time scaled by
#       the ratio of the sweep's cost model for the whole sweep to the slice
#       (`micro sweep --list`, docs/sweeps.md).
#
# Usage: bench/sweep_cost.sh BUILD [BASE_BUILD]
#   Without BASE_BUILD, BASE_COMMIT (default: main) is built (micro only) in a
#   temporary git worktree.
#   env: MODEL (the model preset, default softglass, the default model), N (particles, default the
#   preset's 1000), PHIS (default "0.80, 0.90"), RATES (default the preset's),
#   QUASI_STATIC (true|false, default true), OUT (kept results).
#   A quick check of the script itself: N=250 RATES="1e-4, 1e-5" QUASI_STATIC=false.
#   At the defaults expect tens of minutes with softglass (the two builds'
#   slices side by side on two cores).
set -euo pipefail
export LC_ALL=C OMP_NUM_THREADS=1
build=$(realpath "${1:?usage: bench/sweep_cost.sh BUILD [BASE_BUILD]}")
root=$(cd "$(dirname "$0")/.." && pwd)
out=$(realpath -m "${OUT:-$(mktemp -d)/sweep_cost}")
mkdir -p "$out"

if [ $# -ge 2 ]; then
  base=$(realpath "$2")
else
  commit=$(git -C "$root" rev-parse "${BASE_COMMIT:-main}")
  tree="$out/baseline-src"
  git -C "$root" worktree add -f --detach "$tree" "$commit" > /dev/null
  trap 'git -C "$root" worktree remove --force "$tree"' EXIT
  base="$out/baseline-build"
  launcher=$(command -v ccache > /dev/null && echo "-DCMAKE_CXX_COMPILER_LAUNCHER=ccache" || true)
  cmake -S "$tree" -B "$base" -DCMAKE_BUILD_TYPE=Release $launcher > /dev/null
  cmake --build "$base" -j 2 --target micro > /dev/null
fi

sweep_file() {  # folder packings volume-fractions
  {
    echo "subsection model"
    echo "  set preset = ${MODEL:-softglass}"
    echo "end"
    echo "subsection sweep"
    echo "  set preset = paper"
    echo "  set packings = $2"
    [ -n "$3" ] && echo "  set volume fractions = $3"
    [ -n "${N:-}" ] && echo "  set particles = $N"
    [ -n "${RATES:-}" ] && echo "  set gamma dot tildes = $RATES"
    echo "  set quasi-static = ${QUASI_STATIC:-true}"
    echo "  set output directory = sweep"
    echo "end"
  } > "$1/sweep.prm"
}

model_hours() {  # folder -> the cost model's core hours for all its cases
  (cd "$1" && "$build/micro/micro" sweep sweep.prm --list) | awk '$1 == "cost" { print $2 }'
}

for side in baseline candidate; do
  mkdir -p "$out/$side"
  sweep_file "$out/$side" 1 "${PHIS:-0.80, 0.90}"
done
mkdir -p "$out/whole"
sweep_file "$out/whole" 5 ""
(cd "$out/candidate" && "$build/micro/micro" sweep sweep.prm --list) > "$out/cases.txt"
cases=$(grep -c '^case' "$out/cases.txt")

# One case on each side at once; the wall time of each.
run_case() {  # side executable case
  local start end
  start=$(date +%s.%N)
  (cd "$out/$1" && "$2" --threads 1 sweep sweep.prm --case "$3" -q > /dev/null)
  end=$(date +%s.%N)
  awk -v k="$3" -v a="$start" -v b="$end" 'BEGIN { print k, b - a }' >> "$out/$1/times"
}
rm -f "$out"/{baseline,candidate}/times
for ((k = 0; k < cases; ++k)); do
  run_case baseline "$base/micro/micro" "$k" &
  first=$!
  run_case candidate "$build/micro/micro" "$k" &
  wait "$first" && wait $! || { echo "sweep_cost: case $k failed" >&2; exit 1; }
done
for side in baseline candidate; do
  (cd "$out/$side" && "$build/micro/micro" sweep sweep.prm --gather -q > /dev/null)
done

/usr/bin/python3 - "$out" "$(model_hours "$out/candidate")" "$(model_hours "$out/whole")" <<'EOF'
import csv, math, sys
out, slice_model, whole_model = sys.argv[1], float(sys.argv[2]), float(sys.argv[3])

def table(side):
    with open(f"{out}/{side}/sweep/flow_curve.csv") as f:
        rows = csv.DictReader(line for line in f if not line.startswith("#"))
        return {(r["phi [1]"], r["gamma_tilde [1]"]): r for r in rows}

def times(side):
    with open(f"{out}/{side}/times") as f:
        return dict((int(k), float(t)) for k, t in (line.split() for line in f))

# The state point of case k, from `micro sweep --list`: "case k phi X gamma~ Y ...".
def state_points():
    points = {}
    with open(f"{out}/cases.txt") as f:
        for line in f:
            words = line.split()
            if words and words[0] == "case":
                points[int(words[1])] = (float(words[3]), float(words[5]))
    return points

def row(table, point):
    for (phi, gamma), r in table.items():
        if math.isclose(float(phi), point[0], rel_tol=1e-6) and \
           math.isclose(float(gamma), point[1], rel_tol=1e-3, abs_tol=1e-300):
            return r
    raise SystemExit(f"sweep_cost: no row for phi {point[0]}, gamma~ {point[1]}")

base, cand = table("baseline"), table("candidate")
t_base, t_cand = times("baseline"), times("candidate")
points = state_points()
print(f"{'phi':>5} {'gamma~':>9} {'t_base':>8} {'t_cand':>8} {'ratio':>6}"
      f" {'d_sigma':>20} {'d_N1':>20} {'d_N2':>20}   [s; E*, candidate - baseline +- se]")
for k in sorted(points):
    b, c = row(base, points[k]), row(cand, points[k])
    diffs = []
    for q in ("sigma", "N1", "N2"):
        d = float(c[f"{q} [E*]"]) - float(b[f"{q} [E*]"])
        se = math.hypot(float(c[f"{q}_se [E*]"]), float(b[f"{q}_se [E*]"]))
        diffs.append(f"{d:+.2e} +- {se:.1e}")
    print(f"{points[k][0]:5.2f} {points[k][1]:9.2e} {t_base[k]:8.1f} {t_cand[k]:8.1f}"
          f" {t_base[k] / t_cand[k]:6.2f} " + " ".join(f"{d:>20}" for d in diffs))
total_base, total_cand = sum(t_base.values()), sum(t_cand.values())
print(f"slice: {len(t_cand)} cases, baseline {total_base:.0f} s, candidate {total_cand:.0f} s;"
      f" cost model {slice_model:.3g} core h for the slice, {whole_model:.3g} for the whole sweep")
print(f"paper_slice_speedup {total_base / total_cand:.3f}")
print(f"paper_sweep_hours_estimate {total_cand * whole_model / slice_model / 2 / 3600:.2f}")
EOF

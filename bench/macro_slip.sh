#!/usr/bin/env bash
# Wall slip in macro against the exact solutions (docs/macro.md, "Wall slip").
#
# 1. The finite-element torque or flow rate of the 1D scenes with slip at the
#    standard preset against exact/couette.h, channel.h and pipe.h (the
#    results' relative_deviation_from_ideal): macro.md's Couette cell
#    (R1 = 20 mm, R2 = 30 mm, L = 1 m; τ_y = 10 Pa, K = 5 Pa s^½, n = ½) with
#    the fixed-load law V_s = β σ_w² (β = 2e-5 m/s/Pa²) on the bob, the cup and
#    both, and with a slip yield stress of 3 Pa on both, at Ω = 0.01, 1, 30
#    rad/s; the plane channel (H = 10 mm; τ_y = 5 Pa, K = 2 Pa s^½, n = ½) and
#    the pipe (R = 10 mm) with β = 2e-6 m/s/Pa², from a sliding plug (τ_w below
#    τ_y) to τ_w = 40 τ_y. Per case: the largest |deviation| and the largest
#    reported regularisation estimate (relative).
# 2. The convergence order of the torque with slip: the Newtonian Couette cell
#    (μ = 3 Pa s) with Navier slip (β = 5e-4 m/s/Pa, slip length 1.5 mm) on both
#    cylinders, Q1 and Q2, 1, 2, 3 uniform refinements of a one-cell gap then
#    one adaptive cycle (as tests/macro/fe_convergence_test.cpp), against
#    T = Ω / [(1/R1² − 1/R2²)/(4πμL) + β/(2πL)(1/R1³ + 1/R2³)].
#
# Usage: bench/macro_slip.sh [build dir]   (each run well under a second)
set -euo pipefail
BUILD=${1:-build}
MACRO="$BUILD/macro/macro"
WORK=$(mktemp -d)
trap 'rm -rf "$WORK"' EXIT

# scene_text: the scene's lines; prints "max|deviation| max regularisation/value"
run() {  # name scene_text sweep [solver lines]
  printf '%s\nsubsection sweep\n set values = %s\nend\nsubsection solver\n%s\nend\n' \
    "$2" "$3" "${4:-}" > "$WORK/$1.prm"
  "$MACRO" run "$WORK/$1.prm" -o "$WORK/$1" -q --force
  awk -F, '!/^#/ && !/^rotation|^pressure/ {
      d = $6 < 0 ? -$6 : $6; if (d > dev) dev = d
      r = $4 / $2; if (r > reg) reg = r }
    END { printf "%-34s max|deviation| %.2e   regularisation estimate %.2e\n", name, dev, reg }' \
    name="$1" "$WORK/$1/results.csv"
}

hb_couette='set scene = couette
subsection material
 set model = herschel-bulkley
 set yield stress = 10
 set consistency = 5
 set flow index = 0.5
end
subsection couette
 set inner radius = 0.02
 set outer radius = 0.03
 set length = 1'
slip() {  # beta p [yield stress]
  printf 'subsection slip\n set coefficient = %s\n set exponent = %s\n set yield stress = %s\nend' \
    "$1" "$2" "${3:-0}"
}
echo "# 1. against the exact solutions, standard preset"
for walls in bob cup "bob, cup"; do
  run "couette_${walls/, /_}" "$hb_couette
 set slip walls = $walls
end
$(slip 2e-5 2)" "0.01, 1, 30"
done
run couette_both_yield "$hb_couette
 set slip walls = bob, cup
end
$(slip 2e-5 2 3)" "0.01, 1, 30"
for scene in channel pipe; do
  [ $scene = channel ] && size="half height" walls=walls drives="400, 2000, 20000, 80000"
  [ $scene = pipe ] && size=radius walls=wall drives="800, 4000, 40000, 160000"
  run "$scene" "set scene = $scene
subsection material
 set model = herschel-bulkley
 set yield stress = 5
 set consistency = 2
 set flow index = 0.5
end
subsection $scene
 set $size = 0.01
 set slip walls = $walls
end
$(slip 2e-6 2)" "$drives"
done

echo "# 2. convergence of the torque with Navier slip on both cylinders"
for degree in 1 2; do
  errors=()
  for refinements in 1 2 3; do
    run "convergence_${degree}_$refinements" "set scene = couette
subsection material
 set model = newtonian
 set yield stress = 0
 set consistency = 3
 set flow index = 1
end
subsection couette
 set inner radius = 0.02
 set outer radius = 0.03
 set length = 1
 set gap cells = 1
 set slip walls = bob, cup
end
$(slip 5e-4 1)" 2 " set degree = $degree
 set global refinements = $refinements
 set adaptive cycles = 1" > /dev/null
    errors+=("$(awk -F, '!/^#/ && !/^rotation/ {
        pi = 3.141592653589793; mu = 3; b = 5e-4; R1 = 0.02; R2 = 0.03
        c = (1/R1^2 - 1/R2^2)/(4*pi*mu) + b/(2*pi)*(1/R1^3 + 1/R2^3)
        e = $2*c/$1 - 1; printf "%.3e", e < 0 ? -e : e }' "$WORK/convergence_${degree}_$refinements/results.csv")")
  done
  awk -v p="$degree" -v e0="${errors[0]}" -v e1="${errors[1]}" -v e2="${errors[2]}" 'BEGIN {
    printf "Q%d: errors %s %s %s, order log2 sqrt(e0/e2) = %.2f (nominal 2p = %d)\n",
      p, e0, e1, e2, log(sqrt(e0/e2))/log(2), 2*p }'
done

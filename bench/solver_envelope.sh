#!/usr/bin/env bash
# Where the macro solver converges: the Bingham number and flow index scan
# behind the input check of macro/app/input_scales.h (issue 19, class 3).
#
# The castor-oil Couette cell of cases/couette.prm (R1 = 14 mm, R2 = 15.2 mm,
# τ_y = 15.36 Pa) in its one-dimensional form, at each preset, for flow
# indices N_VALUES and consistencies K_VALUES, at the two ends of the
# rheometer's range (Ω = 1e-3 and 50 rad/s). Per run: the Bingham number
# Bi = τ_y/(K γ̇_cⁿ) at the low end, and the outcome: ok (exit 0), warn (exit 0
# with the estimated error above 10 % on stderr), refused (exit 2: beyond the
# checked envelope) or FAIL (exit 1: the solve failed inside the envelope, a
# defect). Then a flow-index scan with a thin bob (R1 = 1e-4 m), where the
# rate (Δτ/K)^{1/n} overflows first.
#
# Ends with `envelope_failures <count>` (0 is the claim) and
# `largest_bingham_solved <Bi>`. Each run takes well under a second.
#
# Usage: bench/solver_envelope.sh [build dir]   (env: PRESETS, N_VALUES, K_VALUES)
set -euo pipefail
BUILD=${1:-build}
MACRO="$BUILD/macro/macro"
PRESETS=${PRESETS:-"fast standard accurate"}
N_VALUES=${N_VALUES:-"1 0.568 0.3 0.1 0.03"}
K_VALUES=${K_VALUES:-"10 1 1e-1 1e-2 1e-3 1e-4 1e-5 1e-6 1e-7 1e-8 1e-9 1e-10"}
TAU_Y=15.36
WORK=$(mktemp -d)
trap 'rm -rf "$WORK"' EXIT

# One run; prints its outcome.
run() {  # preset n K R1 omegas
  cat > "$WORK/scene.prm" <<EOF
set scene = couette
subsection material
  set model        = herschel-bulkley
  set yield stress = $TAU_Y
  set consistency  = $3
  set flow index   = $2
end
subsection couette
  set inner radius = $4
  set outer radius = 0.0152
  set length       = 0.042
  set end effects  = false
  set gap cells    = 4
end
subsection solver
  set preset = $1
end
subsection sweep
  set values = $5
end
EOF
  local code=0
  "$MACRO" run "$WORK/scene.prm" -o "$WORK/out" -q --force > "$WORK/log" 2>&1 || code=$?
  case $code in
    0) grep -q "warning" "$WORK/log" && echo warn || echo ok ;;
    2) echo refused ;;
    *) echo FAIL ;;
  esac
}

# Bi at the low end, from the scene's characteristic rate γ̇_c = 2Ω R2²/(R2² − R1²).
bingham() {  # n K R1 omega
  awk -v n="$1" -v K="$2" -v r1="$3" -v w="$4" -v ty=$TAU_Y \
    'BEGIN { r2 = 0.0152; g = 2 * w * r2 * r2 / (r2 * r2 - r1 * r1); printf "%.2g", ty / (K * g ^ n) }'
}

failures=0
largest=0
printf "%-9s %-6s %-7s %-9s %-8s %-8s\n" preset n K "Bi(1e-3)" "1e-3" "50"
for preset in $PRESETS; do
  for n in $N_VALUES; do
    for K in $K_VALUES; do
      low=$(run "$preset" "$n" "$K" 0.014 1e-3)
      high=$(run "$preset" "$n" "$K" 0.014 50)
      bi=$(bingham "$n" "$K" 0.014 1e-3)
      printf "%-9s %-6s %-7s %-9s %-8s %-8s\n" "$preset" "$n" "$K" "$bi" "$low" "$high"
      [[ $low == FAIL || $high == FAIL ]] && failures=$((failures + 1))
      if [[ $low == ok || $low == warn ]]; then
        largest=$(awk -v a="$largest" -v b="$bi" 'BEGIN { print (b > a ? b : a) }')
      fi
    done
  done
done

echo
echo "flow index, thin bob (R1 = 1e-4 m), K = 4.72, Omega = 1e-3 and 50:"
for preset in $PRESETS; do
  for n in 0.1 0.03 0.01 0.003; do
    outcome=$(run "$preset" "$n" 4.72 1e-4 "1e-3, 50")
    printf "%-9s n = %-6s %s\n" "$preset" "$n" "$outcome"
    [[ $outcome == FAIL ]] && failures=$((failures + 1))
  done
done
echo
echo "envelope_failures $failures"
echo "largest_bingham_solved $largest"

#!/usr/bin/env bash
# The Bingham lid-driven cavity benchmark of macro.md (Bleyer et al. 2015):
# unit square, lid speed 1, mu = 1, Bi = tau_y. Prints the Newtonian
# reference of an independent streamfunction computation, then, for each Bi, the
# minimum of u_x on the vertical centreline and its height against the
# published values, for tau_y = Bi (macro.md's convention, yielded where
# sqrt(tau:tau/2) > tau_y) and for tau_y = sqrt(2) Bi (the other convention,
# macro.md "Conventions").
#   usage: bench/macro_cavity.sh [BUILD_DIR] [PRESET] [CELLS]
set -euo pipefail
here=$(cd "$(dirname "$0")" && pwd)
build=${1:-$here/../build}; preset=${2:-fast}; cells=${3:-16}
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
# The Newtonian value from the streamfunction on 128², 256², 512² grids
# (bench/stokes_cavity_reference.cpp): an independent check of both macro and
# the published Bi = 0 value.
"$build/bench/stokes_cavity_reference" 128 | sed 's/^/streamfunction reference: /'
# Bi, published u_min, published y
for factor in 1 1.41421356; do
while read -r bi_pub u_ref y_ref; do
  bi=$(echo "$bi_pub * $factor" | bc -l)
  model=bingham; [ "$bi_pub" = 0 ] && model=newtonian; [ "$bi_pub" = 0 ] && bi=0
  cat > "$work/cavity.prm" <<PRM
set scene = cavity
subsection material
  set model = $model
  set yield stress = $bi
  set consistency = 1
  set flow index = 1
end
subsection cavity
  set side = 1
  set cells = $cells
end
subsection solver
  set preset = $preset
end
subsection sweep
  set values = 1
end
subsection output
  set vtu = none
end
PRM
  "$build/macro/macro" run "$work/cavity.prm" -o "$work/out_$bi" -q --force
  tail -1 "$work/out_$bi/results.csv" | awk -F, -v bi="$bi" -v u="$u_ref" -v y="$y_ref" \
    -v f="$factor" '{printf "cavity tau_y/Bi=%s tau_y=%.4g u_min=%.4f (published %s, rel. diff %+.3f) y=%.3f (published %s) dofs=%d seconds=%.1f\n", f, bi, $2, u, ($2-u)/(-u), $5, y, $8, $10}'
done <<'REF'
0 -0.2007 0.53
2 -0.1955 0.57
5 -0.1714 0.57
20 -0.1131 0.57
REF
done

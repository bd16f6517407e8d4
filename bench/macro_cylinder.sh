#!/usr/bin/env bash
# Bingham flow past a cylinder (macro.md; Tokpavi et al. 2008 correlation
# C_D/Bi = 11.98 + 20.43 Bi^-0.68, C_D = F/(mu U), Bi = tau_y d/(mu U)):
# d = 1, U = 1, mu = 1, the cylinder in a square box of side BOX d whose walls
# move at U. Prints C_D (drag from the power balance, and from the surface
# traction) against the correlation for each Bi.
#   usage: bench/macro_cylinder.sh [BUILD_DIR] [PRESET] [BOX]
set -euo pipefail
here=$(cd "$(dirname "$0")" && pwd)
build=${1:-$here/../build}; preset=${2:-fast}; box=${3:-20}
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
for bi in 10 100; do
  cat > "$work/cylinder.prm" <<PRM
set scene = cylinder
subsection material
  set model = bingham
  set yield stress = $bi
  set consistency = 1
  set flow index = 1
end
subsection cylinder
  set diameter = 1
  set box = $box
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
  "$build/macro/macro" run "$work/cylinder.prm" -o "$work/out_$bi" -q --force
  tail -1 "$work/out_$bi/results.csv" | awk -F, -v bi="$bi" \
    '{ref = bi * (11.98 + 20.43 * bi^(-0.68));
      printf "cylinder Bi=%s C_D=%.1f (+-%.1f discretisation; surface traction %.1f) Tokpavi=%.1f rel. diff %+.3f dofs=%d seconds=%.1f\n",
             bi, $5, $3, $6, ref, ($5 - ref) / ref, $9, $11}'
done

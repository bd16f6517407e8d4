#!/usr/bin/env bash
# The model-fidelity study (docs/fidelity.md): every modelling choice the paper
# leaves open or gets wrong, sheared with one fixed cheap protocol — N = 250,
# phi = 0.75, 0.85, 0.90, gamma~ = 1e-9 ... 1e-4 (one per decade) plus the
# quasi-static case, two packings (the same seeds for every variant), 5 strain
# per run — and fitted by `bridge fit`; then the static check of the contact
# laws (G0 of relaxed packings, N = 1000, against compressed emulsions).
#
# Usage: bench/model_sensitivity.sh [build dir] [output dir]
#   env: VARIANTS (comma-separated; `bench/model_sensitivity.py --list` names
#   them), RANKS (MPI ranks, default 2). Not run by CI: the default variants take
#   hours on two cores (docs/fidelity.md gives each variant's wall time);
#   finished variants are not rerun, so the study can be grown variant by variant.
set -euo pipefail
build=${1:-build}
out=${2:-out/model_sensitivity}
here=$(cd "$(dirname "$0")" && pwd)
variants=${VARIANTS:-literal,hertz,nominal,fr0.05,fr1,fr100,full_fr100,ehd_off,neighbours,neighbours_fr0.05,full,nonaffine,poly20}
bin="$out/bin"
mkdir -p "$bin"
# The study runs on a copy of the tools, so that a rebuild meanwhile cannot
# mix two versions in one table.
cp "$build/micro/micro" "$build/bridge/bridge" "$bin/"
start=$(date +%s)
/usr/bin/python3 "$here/model_sensitivity.py" --bin "$bin" --out "$out" --ranks "${RANKS:-2}" \
  --rates 1e-9,1e-8,1e-7,1e-6,1e-5,1e-4 --variants "$variants"
/usr/bin/python3 "$here/model_sensitivity.py" --bin "$bin" --out "$out" --static \
  --particles 1000 --packings 3 --ranks 1 --variants literal,hertz,nominal
echo "model_sensitivity_wall_seconds $(($(date +%s) - start))"

#!/usr/bin/env bash
# Installs the Debian packages softglass needs, and only those that are missing.
#   scripts/install-deps.sh          build, tests and demo
#   scripts/install-deps.sh bench    also the peers measured in bench/ (LAMMPS)
set -euo pipefail

packages=(
  cmake g++ make ccache pkg-config
  libeigen3-dev libhdf5-dev hdf5-tools libboost-math-dev
  libcli11-dev libfmt-dev libgtest-dev libbenchmark-dev
  libdeal.ii-dev libopenmpi-dev openmpi-bin
  libopenblas0-serial  # optimised BLAS for MUMPS's dense fronts (macro); single-threaded beside MPI
  gnuplot-nox python3-matplotlib python3-h5py python3-numpy python3-pandas
  # the Python module (python/) and its tests: the notebook runs in Debian's kernel,
  # `pip install ./python` in a venv with Debian's pip and setuptools
  python3-dev pybind11-dev python3-pybind11 python3-pytest
  python3-nbclient python3-nbformat python3-ipykernel python3-pip python3-venv python3-setuptools
)
if [ "${1:-}" = bench ]; then
  packages+=(lammps time rheolef librheolef-dev)  # the peers of bench/
fi

missing=()
for p in "${packages[@]}"; do
  dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed" || missing+=("$p")
done
if [ ${#missing[@]} -eq 0 ]; then
  exit 0
fi

echo "softglass: installing missing Debian packages: ${missing[*]}"
sudo_cmd=()
if [ "$(id -u)" -ne 0 ]; then
  command -v sudo >/dev/null || { echo "error: need root (or sudo) to install: ${missing[*]}" >&2; exit 1; }
  sudo_cmd=(sudo)
fi
export DEBIAN_FRONTEND=noninteractive
"${sudo_cmd[@]}" apt-get update -qq
"${sudo_cmd[@]}" apt-get install -y -qq --no-install-recommends "${missing[@]}" >/dev/null

# The LAMMPS peer of the engine benches, sourced by lammps_comparison.sh and
# lammps_scaling.sh: the same work as engine_bench's Hertz runs (the peer input
# in ../shared/peers/lammps), on one core.
lammps_peer="$(cd "$(dirname "${BASH_SOURCE[0]}")" && pwd)/../../shared/peers/lammps/shear_hertz.in"

require_lammps() {
  command -v lmp >/dev/null || { echo "lmp not found: apt-get install lammps" >&2; exit 1; }
  [ -f "$lammps_peer" ] || { echo "peer input $lammps_peer not found" >&2; exit 1; }
}

# lammps_shear N STEPS DIR: makes a packing of N at phi = 0.80 and shears it
# STEPS steps; the log goes to DIR/lammps.txt.
lammps_shear() {
  (cd "$3" && OMP_NUM_THREADS=1 lmp -in "$lammps_peer" -var N "$1" -var phi 0.80 -var nshear "$2" \
      -log none > lammps.txt 2>&1)
}

# lammps_shear_seconds DIR: the wall time of the last run in DIR/lammps.txt, the shear.
lammps_shear_seconds() {
  awk '/^Loop time/{t=$4} END{print t}' "$1/lammps.txt"
}

# The two materials the project predicts from a law, defined once for
# scripts/demo.sh, scripts/regenerate_bundled.sh and bench/compare_measured.sh
# (source this file; BRIDGE is the bridge executable, LAW a law file, OUT the
# material file written, further arguments go to `bridge material`):
#   paper_emulsion BRIDGE LAW OUT   the paper's emulsion: phi 0.80, E* 40 kPa,
#                                   water (1 mPa s)
#   castoroil85 BRIDGE LAW OUT      the 85 % castor-oil emulsion of
#                                   ../shared/data/rheometry: phi 0.85, water at
#                                   25 C (0.89 mPa s), E* from its measured G'
#                                   plateau of 143 Pa (its amplitude sweep)
paper_emulsion() {
  "$1" material "$2" --phi 0.80 --modulus 40e3 --viscosity 1e-3 -o "$3" -f "${@:4}"
}
castoroil85() {
  "$1" material "$2" --phi 0.85 --plateau-modulus 143 --viscosity 0.89e-3 -o "$3" -f "${@:4}"
}

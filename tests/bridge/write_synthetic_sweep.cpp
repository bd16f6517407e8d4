// Writes a synthetic sweep (synthetic_sweep.h) as the two CSV files of
// docs/flow-curve-format.md, for trying `bridge fit` before the particle
// engine's sweeps exist:
//     bridge_synthetic_sweep TABLE.csv RUNS.csv [SEED]
// cases/bridge_synthetic_sweep.csv and cases/bridge_synthetic_sweep_packings.csv
// are its output for seed 1.
#include <cstdio>
#include <fstream>
#include <string>

#include "synthetic_sweep.h"

int main(int argc, char** argv) {
  using namespace softglass::bridge::testing;
  if (argc < 3 || argc > 4) {
    std::fprintf(stderr, "usage: %s TABLE.csv RUNS.csv [SEED]\n", argv[0]);
    return 2;
  }
  const std::uint64_t seed = argc == 4 ? std::stoull(argv[3]) : 1;
  const SyntheticSweep sweep = make_synthetic_sweep(SyntheticTruth(), seed);
  std::ofstream(argv[1]) << table_csv(sweep);
  std::ofstream(argv[2]) << runs_csv(sweep);
  return 0;
}

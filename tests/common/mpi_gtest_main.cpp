// The main() of test suites that call the finite-element solvers: their
// distributed vectors and meshes need MPI even on one rank.
#include <deal.II/base/mpi.h>
#include <gtest/gtest.h>

#include "common/mpi_launch.h"

int main(int argc, char** argv) {
  softglass::prefer_lean_mpi_singleton();  // as the tools start, and with their own session files
  dealii::Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  testing::InitGoogleTest(&argc, argv);
  return RUN_ALL_TESTS();
}

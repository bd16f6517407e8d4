#include "micro/app/workers.h"

#include <mpi.h>

#include <cstdlib>

namespace softglass::micro {

namespace {

// Set by Open MPI's, MPICH's (Hydra) and Slurm's starters respectively.
bool launched_by_mpi() {
  for (const char* variable : {"OMPI_COMM_WORLD_SIZE", "PMI_SIZE", "PMIX_RANK", "SLURM_STEP_NUM_TASKS"})
    if (std::getenv(variable)) return true;
  return false;
}

}  // namespace

Workers::Workers() : mpi_(launched_by_mpi()) {
  if (!mpi_) return;
  MPI_Init(nullptr, nullptr);
  MPI_Comm_rank(MPI_COMM_WORLD, &rank_);
  MPI_Comm_size(MPI_COMM_WORLD, &size_);
}

Workers::~Workers() {
  if (mpi_) MPI_Finalize();
}

bool Workers::all(bool ok) const {
  if (!mpi_) return ok;
  int mine = ok ? 1 : 0, every = 0;
  MPI_Allreduce(&mine, &every, 1, MPI_INT, MPI_LAND, MPI_COMM_WORLD);
  return every != 0;
}

void Workers::abort(int code) const {
  if (mpi_) MPI_Abort(MPI_COMM_WORLD, code);
  std::exit(code);
}

}  // namespace softglass::micro

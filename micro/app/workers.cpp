#include "micro/app/workers.h"

#include <mpi.h>

#include <cstdlib>

#include "common/mpi_launch.h"

namespace softglass::micro {

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

// Writing a solver's fields as one VTU file, whether one rank holds the mesh
// or several share it.
#pragma once

#include <deal.II/base/mpi.h>
#include <deal.II/numerics/data_out.h>
#include <fmt/format.h>

#include <filesystem>
#include <fstream>

#include "common/errors.h"

namespace softglass::macro::io {

/// Every rank of `communicator` calls this with the same file name. A mesh on
/// one rank is written with a plain stream; a shared one through MPI-IO, each
/// rank writing its cells into the one file. (Open MPI's MPI-IO keeps a
/// shared-memory file in its session directory, which a process started
/// without mpirun does not have: it would complain on stderr.)
template <int dim>
void write_vtu(const dealii::DataOut<dim>& data_out, const std::filesystem::path& file,
               MPI_Comm communicator) {
  try {
    if (dealii::Utilities::MPI::n_mpi_processes(communicator) == 1) {
      std::ofstream out(file);
      data_out.write_vtu(out);
      out.close();  // a full disk shows only when the last buffer is written
      if (out) return;
    } else {
      data_out.write_vtu_in_parallel(file.string(), communicator);
      return;
    }
  } catch (const std::exception&) {
  }
  throw NumericalError(fmt::format("cannot write {}", file.string()));
}

}  // namespace softglass::macro::io

// Whether this process was started by an MPI launcher, and the lean start of
// one that was not.
#pragma once

#include <cstdlib>
#include <initializer_list>

namespace softglass {

/// Set by Open MPI's, MPICH's (Hydra) and Slurm's starters respectively.
inline bool launched_by_mpi() {
  for (const char* variable :
       {"OMPI_COMM_WORLD_SIZE", "PMI_SIZE", "PMIX_RANK", "SLURM_STEP_NUM_TASKS"})
    if (std::getenv(variable)) return true;
  return false;
}

/// Open MPI keeps every singleton's session files under one folder per user,
/// /tmp/ompi.<host>.<uid>, and singletons started at the same moment (two
/// `macro run` in a script, a parallel test suite) can remove each other's
/// job-family folder there: the later then fails in orte_init ("mkdir ... No
/// such file or directory"). Gives this process a base of its own,
/// <temp>/softglass-mpi-<pid>, removed at exit (those of processes no longer
/// alive are removed here), unless the user set orte_tmpdir_base.
void own_mpi_session_directory();

/// Call before MPI_Init. A process started without a launcher is an MPI
/// singleton, and Open MPI's defaults then start a server for MPI_Comm_spawn
/// and probe the UCX network layer — neither of any use to one process, and
/// together most of the start-up time of a small `macro run`. Settings the user made win;
/// other MPI implementations ignore these.
inline void prefer_lean_mpi_singleton() {
  if (launched_by_mpi()) return;
  setenv("OMPI_MCA_ess_singleton_isolated", "1", 0);
  setenv("OMPI_MCA_pml", "ob1", 0);
  own_mpi_session_directory();
}

}  // namespace softglass

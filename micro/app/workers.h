// The processes that share a sweep. Launched by mpirun (or srun), the sweep's
// cases are spread over the MPI ranks, on one machine or several sharing the
// output folder; started alone, it is one worker and MPI is never initialised
// (so `micro` runs where no MPI runtime is configured).
#pragma once

namespace softglass::micro {

class Workers {
 public:
  Workers();   // MPI_Init when launched by an MPI starter
  ~Workers();  // MPI_Finalize
  Workers(const Workers&) = delete;
  Workers& operator=(const Workers&) = delete;

  int rank() const { return rank_; }
  int size() const { return size_; }
  bool leader() const { return rank_ == 0; }

  /// Whether every worker reports `ok`; a collective, so also a barrier.
  bool all(bool ok) const;
  /// Ends all workers at once when one of them cannot go on.
  [[noreturn]] void abort(int code) const;

 private:
  bool mpi_ = false;
  int rank_ = 0, size_ = 1;
};

}  // namespace softglass::micro

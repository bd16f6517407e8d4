#include "macro/app/mpi_gather.h"

#include <numeric>

namespace softglass::macro::app {

namespace {

// Gathers variable-length arrays of one MPI type on rank 0.
template <typename T>
std::vector<T> gather_flat(MPI_Comm comm, const std::vector<T>& mine, MPI_Datatype type,
                           std::vector<int>& counts) {
  int rank = 0, ranks = 1;
  MPI_Comm_rank(comm, &rank);
  MPI_Comm_size(comm, &ranks);
  const int count = static_cast<int>(mine.size());
  counts.assign(ranks, 0);
  MPI_Gather(&count, 1, MPI_INT, counts.data(), 1, MPI_INT, 0, comm);
  std::vector<int> offsets(ranks, 0);
  std::exclusive_scan(counts.begin(), counts.end(), offsets.begin(), 0);
  std::vector<T> all(rank == 0 ? std::accumulate(counts.begin(), counts.end(), 0) : 0);
  MPI_Gatherv(mine.data(), count, type, all.data(), counts.data(), offsets.data(), type, 0, comm);
  return all;
}

}  // namespace

std::vector<std::vector<double>> gather_rows(MPI_Comm comm,
                                             const std::vector<std::vector<double>>& rows) {
  // Each row preceded by its length.
  std::vector<double> flat;
  for (const auto& row : rows) {
    flat.push_back(double(row.size()));
    flat.insert(flat.end(), row.begin(), row.end());
  }
  std::vector<int> counts;
  const std::vector<double> all = gather_flat(comm, flat, MPI_DOUBLE, counts);
  std::vector<std::vector<double>> result;
  for (std::size_t k = 0; k < all.size(); k += 1 + std::size_t(all[k]))
    result.emplace_back(all.begin() + k + 1, all.begin() + k + 1 + std::size_t(all[k]));
  return result;
}

std::vector<std::string> gather_text(MPI_Comm comm, const std::string& text) {
  std::vector<int> counts;
  const std::vector<char> all =
      gather_flat(comm, std::vector<char>(text.begin(), text.end()), MPI_CHAR, counts);
  std::vector<std::string> result;
  std::size_t offset = 0;
  for (int count : counts) {
    if (all.empty()) break;
    result.emplace_back(all.begin() + offset, all.begin() + offset + count);
    offset += count;
  }
  return result;
}

std::string broadcast_text(MPI_Comm comm, const std::string& text) {
  unsigned long size = text.size();
  MPI_Bcast(&size, 1, MPI_UNSIGNED_LONG, 0, comm);
  std::string result = text;
  result.resize(size);
  MPI_Bcast(result.data(), int(size), MPI_CHAR, 0, comm);
  return result;
}

bool broadcast_flag(MPI_Comm comm, bool flag) {
  int value = flag ? 1 : 0;
  MPI_Bcast(&value, 1, MPI_INT, 0, comm);
  return value != 0;
}

}  // namespace softglass::macro::app

// Collecting a sweep's results on rank 0 with plain MPI collectives. (deal.II's
// Utilities::MPI::gather serialises through boost::iostreams' gzip filter,
// which GCC 12 flags with a false -Wrestrict warning; rows of doubles and
// short messages need no serialisation.)
#pragma once

#include <mpi.h>

#include <string>
#include <vector>

namespace softglass::macro::app {

/// Every rank's rows (of any lengths), concatenated in rank order on rank 0;
/// empty elsewhere.
std::vector<std::vector<double>> gather_rows(MPI_Comm comm,
                                             const std::vector<std::vector<double>>& rows);

/// Every rank's text, in rank order on rank 0; empty elsewhere.
std::vector<std::string> gather_text(MPI_Comm comm, const std::string& text);

/// Rank 0's text on every rank.
std::string broadcast_text(MPI_Comm comm, const std::string& text);

/// Rank 0's flag on every rank.
bool broadcast_flag(MPI_Comm comm, bool flag);

}  // namespace softglass::macro::app

// SPDX-License-Identifier: LGPL-2.1-or-later
// Concatenating small vectors of plain values over the processes.
#ifndef viscoslide_mpi_gather_h
#define viscoslide_mpi_gather_h

#include <deal.II/base/mpi.h>

#include <type_traits>
#include <vector>

namespace viscoslide
{
  // The elements of every process's `local`, in the order of the processes,
  // on every process (root < 0) or on `root` alone (empty elsewhere).
  // Utilities::MPI::gather and all_gather serialize and compress their
  // objects even on one process, which cost more than a condensed solve
  // where the Newton loop gathers the surface terms; plain values need
  // neither. [mpi_gather.cc]
  template <typename T>
  std::vector<T>
  gather_concatenated(MPI_Comm comm, const std::vector<T> &local, int root);
} // namespace viscoslide

#endif

// SPDX-License-Identifier: LGPL-2.1-or-later
#include <viscoslide/io/postprocessing.h>
#include <viscoslide/numerics/mesh.h>
#include <viscoslide/numerics/mpi_gather.h>

#include <utility>

namespace viscoslide
{
  template <typename T>
  std::vector<T>
  gather_concatenated(const MPI_Comm        comm,
                      const std::vector<T> &local,
                      int                   root)
  {
    // Copied byte by byte (std::pair is not trivially copyable by the
    // letter, but its bytes are its value).
    static_assert(std::is_standard_layout_v<T> &&
                  std::is_trivially_destructible_v<T>);
    const unsigned int n   = dealii::Utilities::MPI::n_mpi_processes(comm);
    const bool         all = root < 0;
    const bool here = all || dealii::Utilities::MPI::this_mpi_process(comm) ==
                               static_cast<unsigned int>(root);
    if (n == 1)
      return here ? local : std::vector<T>();

    const int        bytes = static_cast<int>(local.size() * sizeof(T));
    std::vector<int> counts(n), offsets(n, 0);
    if (all)
      MPI_Allgather(&bytes, 1, MPI_INT, counts.data(), 1, MPI_INT, comm);
    else
      MPI_Gather(&bytes, 1, MPI_INT, counts.data(), 1, MPI_INT, root, comm);
    for (unsigned int p = 1; p < n; ++p)
      offsets[p] = offsets[p - 1] + counts[p - 1];
    std::vector<T> gathered(here ? (offsets[n - 1] + counts[n - 1]) / sizeof(T)
                                 : 0);
    if (all)
      MPI_Allgatherv(local.data(),
                     bytes,
                     MPI_BYTE,
                     gathered.data(),
                     counts.data(),
                     offsets.data(),
                     MPI_BYTE,
                     comm);
    else
      MPI_Gatherv(local.data(),
                  bytes,
                  MPI_BYTE,
                  gathered.data(),
                  counts.data(),
                  offsets.data(),
                  MPI_BYTE,
                  root,
                  comm);
    return gathered;
  }


  template std::vector<int>
  gather_concatenated(MPI_Comm, const std::vector<int> &, int);
  template std::vector<double>
  gather_concatenated(MPI_Comm, const std::vector<double> &, int);
  template std::vector<std::pair<double, double>>
  gather_concatenated(MPI_Comm,
                      const std::vector<std::pair<double, double>> &,
                      int);
  template std::vector<ProfilePoint>
  gather_concatenated(MPI_Comm, const std::vector<ProfilePoint> &, int);
  template SurfaceRegions<2>
  gather_concatenated(MPI_Comm, const SurfaceRegions<2> &, int);
  template SurfaceRegions<3>
  gather_concatenated(MPI_Comm, const SurfaceRegions<3> &, int);
} // namespace viscoslide

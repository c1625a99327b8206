// SPDX-License-Identifier: LGPL-2.1-or-later
// BoundaryElementSolver: the profile of the surface and, in 3D, its map.
#include <deal.II/base/mpi.h>

#include <viscoslide/boundary_element/solver.h>

#include <cmath>
#include <limits>

namespace viscoslide
{
  template <int dim>
  void
  BoundaryElementSolver<dim>::write_profile(const std::string &path) const
  {
    // Every point where the surfaces interact, and every eighth one
    // elsewhere within the Domain width, so that the wake shows without a
    // file of the whole period (a grid that follows the contact has its
    // window about it, which at real scale is wider than the Domain
    // width); in 3D along the track's centre line (y = 0), with the map of
    // the surface beside it.
    const auto               &p = grid->at();
    std::vector<ProfilePoint> points;
    const double              half_width = grid->follows_contact()
                                             ? std::numeric_limits<double>::infinity()
                                             : prm.geometry.domain_width * scales.eps / 2;
    for (unsigned int j = 0; j < grid->size(); ++j)
      if (p.y[j] == 0. && std::abs(p.x[j]) <= half_width &&
          (gaps[j] < 10 * scales.eps || j % 8 == 0))
        points.push_back({p.x[j], gaps[j], -traction[j], displacement[j]});
    const std::string what =
      "steady state (boundary elements), V_hat = " + CsvTable::format(V_hat) +
      ", delta_hat = " + CsvTable::format(approach() / scales.eps);
    // Where two processes take the stations from both ends, each writes
    // its own.
    const MPI_Comm writers =
      stations_from_both_ends(*this, prm, comm) ? MPI_COMM_SELF : comm;
    write_profile_csv(path, points, scales, what, writers);
    if (Utilities::MPI::this_mpi_process(writers) == 0)
      grid->write_map(path.substr(0, path.rfind('.')) + ".vti",
                      what,
                      gaps,
                      traction,
                      displacement,
                      scales.eps,
                      scales.sigma_max,
                      scales.R);
  }


  template void
  BoundaryElementSolver<2>::write_profile(const std::string &) const;
  template void
  BoundaryElementSolver<3>::write_profile(const std::string &) const;
} // namespace viscoslide

// SPDX-License-Identifier: LGPL-2.1-or-later
#include <viscoslide/boundary_element/surface_grid.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>

namespace viscoslide
{
  template <int dim>
  FullMatrix<double>
  SurfaceGrid<dim>::block(const unsigned int, const unsigned int) const
  {
    throw std::logic_error("this surface grid offers no matrix block");
  }


  template <int dim>
  double
  SurfaceGrid<dim>::dissipation_rate(const Vector<double> &q) const
  {
    Vector<double> slope;
    creep_slope(q, slope);
    double sum = 0;
    for (unsigned int j = 0; j < size(); ++j)
      sum += q[j] * slope[j] * points.area[j];
    // The traction q pulls (attraction > 0), the solid's surface moves by
    // u towards the indenter: the work rate on the solid is -V q du/dx.
    return -speed * sum;
  }


  template <int dim>
  std::pair<double, double>
  SurfaceGrid<dim>::reach_within(const Vector<double> &gaps,
                                 const double          gap) const
  {
    std::pair<double, double> reach{0., 0.};
    for (unsigned int j = 0; j < size(); ++j)
      if (gaps[j] < gap)
        {
          reach.first  = std::max(reach.first, std::abs(points.x[j]));
          reach.second = std::max(reach.second, std::abs(points.y[j]));
        }
    return reach;
  }


  template <int dim>
  SurfaceQuantities
  SurfaceGrid<dim>::measure(const Vector<double> &gaps,
                            const Vector<double> &traction,
                            const Vector<double> &u,
                            const double          gc) const
  {
    const auto       &p = points;
    SurfaceQuantities q{};
    q.minimum_gap = gaps.linfty_norm();
    q.x_trail     = std::numeric_limits<double>::infinity();
    q.x_lead      = -q.x_trail;
    for (unsigned int j = 0; j < size(); ++j)
      {
        const double pressure = -traction[j];
        q.normal_force += pressure * p.area[j];
        q.absolute_force += std::abs(pressure) * p.area[j];
        q.tangential_force += pressure * p.slope[j] * p.area[j];
        if (gaps[j] < gc && next(j) != previous(j))
          {
            const double du_dx =
              (u[next(j)] - u[previous(j)]) / distance_across(j);
            q.contact_set_tangential_force += pressure * du_dx * p.area[j];
          }
        q.minimum_gap = std::min(q.minimum_gap, gaps[j]);
        // The contact set's edges between j and its next neighbour, the
        // gap linear in between (the fraction of the way where it crosses
        // gc); in 2D its length.
        const double g0 = gaps[j], g1 = gaps[next(j)];
        if (dim == 2 && g0 < gc && g1 < gc)
          q.contact_length += distance_to_next(j);
        else if ((g0 < gc) != (g1 < gc))
          {
            const double t = (gc - g0) / (g1 - g0);
            if (dim == 2)
              q.contact_length += (g0 < gc ? t : 1. - t) * distance_to_next(j);
            const double edge = p.x[j] + t * distance_to_next(j);
            q.x_trail         = std::min(q.x_trail, edge);
            q.x_lead          = std::max(q.x_lead, edge);
          }
      }
    measure_plane(gaps, gc, q);
    if (q.x_lead < q.x_trail)
      q.x_trail = q.x_lead = 0.;
    return q;
  }


  template class SurfaceGrid<2>;
  template class SurfaceGrid<3>;
} // namespace viscoslide

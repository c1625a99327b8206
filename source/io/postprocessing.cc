// SPDX-License-Identifier: LGPL-2.1-or-later
#include <deal.II/base/quadrature_lib.h>

#include <deal.II/fe/fe_values.h>

#include <viscoslide/io/output.h>
#include <viscoslide/io/postprocessing.h>
#include <viscoslide/numerics/mesh.h>
#include <viscoslide/numerics/mpi_gather.h>

#include <algorithm>
#include <cmath>

namespace viscoslide
{
  namespace
  {
    // Equally spaced points on a face, end points included, so that the
    // contact length can be found by linear interpolation of the gap.
    template <int dim>
    Quadrature<dim - 1>
    sampling_points(const unsigned int n_intervals)
    {
      return QIterated<dim - 1>(QTrapezoid<1>(), n_intervals);
    }

    template <int dim, typename Function>
    void
    for_each_top_face(const DoFHandler<dim>   &dof_handler,
                      const types::boundary_id top,
                      const Function          &f)
    {
      for (const auto &cell : dof_handler.active_cell_iterators())
        if (cell->is_locally_owned())
          for (const unsigned int face : cell->face_indices())
            if (cell->face(face)->at_boundary() &&
                cell->face(face)->boundary_id() == top)
              f(cell, face);
    }
  } // namespace


  template <int dim>
  SurfacePostprocessor<dim>::SurfacePostprocessor(
    const InteractionLaw    &law,
    const Indenter          &indenter,
    const double             eps,
    const double             contact_gap,
    const unsigned int       n_face_points,
    const types::boundary_id top,
    const double             elongation)
    : law(law)
    , indenter(indenter)
    , eps(eps)
    , contact_gap(contact_gap)
    , n_face_points(n_face_points)
    , top(top)
    , elongation(elongation)
  {
  }


  template <int dim>
  double
  SurfacePostprocessor<dim>::slope_at(const Point<dim> &p, const double s) const
  {
    const double xi = apex_distance(p, s, elongation);
    if constexpr (dim == 2)
      return indenter.slope(xi);
    else // h(r): dh/dx = h'(r) (x - s)/r
      return xi > 0. ? indenter.slope(xi) * (p[0] - s) / xi : 0.;
  }


  template <int dim>
  void
  SurfacePostprocessor<dim>::add_contact_samples(
    const FEFaceValues<dim>   &values,
    const std::vector<double> &u,
    const double               delta,
    const double               s,
    ContactSet                &set,
    double                    &g_min) const
  {
    const unsigned int n = values.n_quadrature_points;
    if constexpr (dim == 2)
      {
        // Trapezoid points: the set's ends by linear interpolation of the
        // gap between neighbours.
        std::vector<std::pair<double, double>> samples(n);
        for (unsigned int q = 0; q < n; ++q)
          {
            const double x = values.quadrature_point(q)[0];
            samples[q]     = {x,
                              gap_at(values.quadrature_point(q), u[q], delta, s)};
            g_min          = std::min(g_min, samples[q].second);
          }
        std::sort(samples.begin(), samples.end());
        for (unsigned int i = 0; i + 1 < samples.size(); ++i)
          {
            const auto [x0, g0] = samples[i];
            const auto [x1, g1] = samples[i + 1];
            const bool in0 = g0 < contact_gap, in1 = g1 < contact_gap;
            if (in0 && in1)
              set.measure += x1 - x0;
            else if (in0 != in1)
              {
                // the part of the interval on the contact side of the
                // crossing
                const double t = (contact_gap - g0) / (g1 - g0);
                set.measure += (in0 ? t : 1. - t) * (x1 - x0);
                set.x_trail = std::min(set.x_trail, x0 + t * (x1 - x0));
                set.x_lead  = std::max(set.x_lead, x0 + t * (x1 - x0));
              }
          }
      }
    else
      // Midpoints of sub-squares: the area of those in contact, and the
      // extent of their centres.
      for (unsigned int q = 0; q < n; ++q)
        {
          const auto  &p = values.quadrature_point(q);
          const double g = gap_at(p, u[q], delta, s);
          g_min          = std::min(g_min, g);
          if (g < contact_gap)
            {
              set.measure += values.JxW(q);
              set.x_trail = std::min(set.x_trail, p[0]);
              set.x_lead  = std::max(set.x_lead, p[0]);
              set.y_half  = std::max(set.y_half, std::abs(p[1]));
            }
        }
  }


  template <int dim>
  SurfaceQuantities
  SurfacePostprocessor<dim>::integrate(const DoFHandler<dim> &dofs,
                                       const TrilinosWrappers::MPI::Vector &u,
                                       const double delta,
                                       const double s) const
  {
    const FEValuesExtractors::Scalar uy(vertical<dim>);
    const QGauss<dim - 1>            gauss(n_face_points);
    FEFaceValues<dim>                gauss_values(dofs.get_fe(),
                                   gauss,
                                   update_values | update_gradients |
                                     update_quadrature_points |
                                     update_JxW_values);
    const Quadrature<dim - 1>        sampling =
      dim == 2 ? sampling_points<dim>(4 * n_face_points)
                      : Quadrature<dim - 1>(
                   QIterated<dim - 1>(QMidpoint<1>(), 4 * n_face_points));
    FEFaceValues<dim>           sample_values(dofs.get_fe(),
                                    sampling,
                                    update_values | update_quadrature_points |
                                      (dim == 3 ? update_JxW_values
                                                          : update_default));
    std::vector<double>         u_y(gauss.size()), s_u_y(sampling.size());
    std::vector<Tensor<1, dim>> grad_u_y(gauss.size());

    double Fn = 0, Ft = 0, Fh = 0, F_abs = 0,
           g_min = std::numeric_limits<double>::max();
    ContactSet set;
    set.x_trail = std::numeric_limits<double>::max();
    set.x_lead  = -std::numeric_limits<double>::max();
    for_each_top_face(dofs, top, [&](const auto &cell, const unsigned int f) {
      gauss_values.reinit(cell, f);
      gauss_values[uy].get_function_values(u, u_y);
      gauss_values[uy].get_function_gradients(u, grad_u_y);
      for (unsigned int q = 0; q < gauss.size(); ++q)
        {
          const auto  &x = gauss_values.quadrature_point(q);
          const double g = gap_at(x, u_y[q], delta, s);
          const double p = -law.traction(g);
          const double w = gauss_values.JxW(q);
          Fn += p * w;
          F_abs += std::abs(p) * w;
          if (g < contact_gap)
            Ft += p * grad_u_y[q][0] * w;
          Fh += p * slope_at(x, s) * w;
        }

      sample_values.reinit(cell, f);
      sample_values[uy].get_function_values(u, s_u_y);
      add_contact_samples(sample_values, s_u_y, delta, s, set, g_min);
    });

    const MPI_Comm    comm = dofs.get_communicator();
    SurfaceQuantities q{Utilities::MPI::sum(Fn, comm),
                        Utilities::MPI::sum(Fh, comm),
                        Utilities::MPI::sum(Ft, comm),
                        Utilities::MPI::sum(set.measure, comm),
                        Utilities::MPI::sum(F_abs, comm),
                        Utilities::MPI::min(g_min, comm)};
    // Relative to the apex; without contact both at the apex.
    const double x_trail = Utilities::MPI::min(set.x_trail, comm);
    const double x_lead  = Utilities::MPI::max(set.x_lead, comm);
    q.x_trail            = x_lead >= x_trail ? x_trail - s : 0.;
    q.x_lead             = x_lead >= x_trail ? x_lead - s : 0.;
    q.y_half             = Utilities::MPI::max(set.y_half, comm);
    return q;
  }


  template <int dim>
  template <typename Function>
  void
  SurfacePostprocessor<dim>::for_each_sampled_face(
    const DoFHandler<dim>               &dofs,
    const TrilinosWrappers::MPI::Vector &u,
    const double                         delta,
    const double                         s,
    const Function                      &f) const
  {
    const FEValuesExtractors::Scalar uy(vertical<dim>);
    const Quadrature<dim - 1>        sampling = sampling_points<dim>(4);
    FEFaceValues<dim>                values(dofs.get_fe(),
                             sampling,
                             update_values | update_quadrature_points);
    std::vector<double>              u_y(sampling.size()), g(sampling.size());
    std::vector<Point<dim>>          x(sampling.size());
    for_each_top_face(dofs,
                      top,
                      [&](const auto &cell, const unsigned int face) {
                        values.reinit(cell, face);
                        values[uy].get_function_values(u, u_y);
                        for (unsigned int q = 0; q < sampling.size(); ++q)
                          {
                            x[q] = values.quadrature_point(q);
                            g[q] = gap_at(x[q], u_y[q], delta, s);
                          }
                        f(cell, face, x, g, u_y);
                      });
  }


  template <int dim>
  std::vector<ProfilePoint>
  SurfacePostprocessor<dim>::profile(const DoFHandler<dim>               &dofs,
                                     const TrilinosWrappers::MPI::Vector &u,
                                     const double                         delta,
                                     const double s) const
  {
    std::vector<ProfilePoint> points;
    for_each_sampled_face(
      dofs,
      u,
      delta,
      s,
      [&](const auto &,
          unsigned int,
          const auto &x,
          const auto &g,
          const auto &u_y) {
        for (unsigned int q = 0; q < x.size(); ++q)
          if (dim == 2 || x[q][1] == 0.) // in 3D the centre line
            points.push_back({x[q][0], g[q], -law.traction(g[q]), u_y[q]});
      });

    std::vector<ProfilePoint> all =
      gather_concatenated(dofs.get_communicator(), points, 0);
    std::sort(all.begin(), all.end(), [](const auto &a, const auto &b) {
      return a.x < b.x;
    });
    // Face end points appear twice (in 3D up to four times); keep one.
    all.erase(std::unique(all.begin(),
                          all.end(),
                          [](const auto &a, const auto &b) {
                            return std::abs(a.x - b.x) <=
                                   1e-12 * (1. + std::abs(a.x));
                          }),
              all.end());
    return all;
  }


  template <int dim>
  SurfaceRegions<dim>
  SurfacePostprocessor<dim>::faces_in_gap_band(
    const DoFHandler<dim>               &dofs,
    const TrilinosWrappers::MPI::Vector &u,
    const double                         delta,
    const double                         s,
    const double                         g_lo,
    const double                         g_hi) const
  {
    SurfaceRegions<dim> regions;
    for_each_sampled_face(dofs,
                          u,
                          delta,
                          s,
                          [&](const auto  &cell,
                              unsigned int face,
                              const auto &,
                              const auto &g,
                              const auto &) {
                            const auto [lo, hi] =
                              std::minmax_element(g.begin(), g.end());
                            if (*lo > g_hi || *hi < g_lo)
                              return;
                            const auto box = cell->face(face)->bounding_box();
                            SurfaceRegion<dim> region;
                            for (unsigned int d = 0; d + 1 < dim; ++d)
                              {
                                region.lower[d] = box.lower_bound(d);
                                region.upper[d] = box.upper_bound(d);
                              }
                            regions.push_back(region);
                          });
    return gather_concatenated(dofs.get_communicator(), regions, -1);
  }


  template class SurfacePostprocessor<2>;
  template class SurfacePostprocessor<3>;


  void
  write_profile_csv(const std::string               &path,
                    const std::vector<ProfilePoint> &points,
                    const Scales                    &scales,
                    const std::string               &comment,
                    MPI_Comm                         comm)
  {
    CsvTable table(path,
                   {"x_over_R", "gap_over_eps", "p_hat", "u_y_over_eps"},
                   comment,
                   comm,
                   scales.si_columns);
    for (const auto &p : points)
      table.add_row({{"x_over_R", CsvTable::format(p.x / scales.R)},
                     {"gap_over_eps", CsvTable::format(p.gap / scales.eps)},
                     {"p_hat", CsvTable::format(p.pressure / scales.sigma_max)},
                     {"u_y_over_eps", CsvTable::format(p.u_y / scales.eps)}});
  }
} // namespace viscoslide

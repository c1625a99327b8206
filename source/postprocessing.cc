#include <deal.II/base/quadrature_lib.h>

#include <deal.II/fe/fe_values.h>

#include <viscoslide/mpi_gather.h>
#include <viscoslide/output.h>
#include <viscoslide/postprocessing.h>

#include <algorithm>
#include <cmath>

namespace viscoslide
{
  namespace
  {
    // Equally spaced points on a face, end points included, so that the
    // contact length can be found by linear interpolation of the gap.
    Quadrature<1>
    sampling_points(const unsigned int n_intervals)
    {
      return QIterated<1>(QTrapezoid<1>(), n_intervals);
    }

    template <typename Function>
    void
    for_each_top_face(const DoFHandler<2>     &dof_handler,
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


  SurfacePostprocessor::SurfacePostprocessor(const InteractionLaw &law,
                                             const Indenter       &indenter,
                                             const double          eps,
                                             const double          contact_gap,
                                             const unsigned int n_face_points,
                                             const types::boundary_id top)
    : law(law)
    , indenter(indenter)
    , eps(eps)
    , contact_gap(contact_gap)
    , n_face_points(n_face_points)
    , top(top)
  {
  }


  SurfaceQuantities
  SurfacePostprocessor::integrate(const DoFHandler<2>                 &dofs,
                                  const TrilinosWrappers::MPI::Vector &u,
                                  const double                         delta,
                                  const double                         s) const
  {
    const FEValuesExtractors::Scalar uy(1);
    const QGauss<1>                  gauss(n_face_points);
    FEFaceValues<2>                  gauss_values(dofs.get_fe(),
                                 gauss,
                                 update_values | update_gradients |
                                   update_quadrature_points |
                                   update_JxW_values);
    const Quadrature<1>       sampling = sampling_points(4 * n_face_points);
    FEFaceValues<2>           sample_values(dofs.get_fe(),
                                  sampling,
                                  update_values | update_quadrature_points);
    std::vector<double>       u_y(gauss.size()), s_u_y(sampling.size());
    std::vector<Tensor<1, 2>> grad_u_y(gauss.size());
    std::vector<std::pair<double, double>> samples(sampling.size());

    double Fn = 0, Ft = 0, Fh = 0, L = 0, F_abs = 0,
           g_min = std::numeric_limits<double>::max();
    // The contact set's ends, from the crossings of the threshold.
    double x_trail = std::numeric_limits<double>::max(),
           x_lead  = -std::numeric_limits<double>::max();
    for_each_top_face(dofs, top, [&](const auto &cell, const unsigned int f) {
      gauss_values.reinit(cell, f);
      gauss_values[uy].get_function_values(u, u_y);
      gauss_values[uy].get_function_gradients(u, grad_u_y);
      for (unsigned int q = 0; q < gauss.size(); ++q)
        {
          const double x = gauss_values.quadrature_point(q)[0];
          const double g = gap(indenter, eps, delta, s, x, u_y[q]);
          const double p = -law.traction(g);
          const double w = gauss_values.JxW(q);
          Fn += p * w;
          F_abs += std::abs(p) * w;
          if (g < contact_gap)
            Ft += p * grad_u_y[q][0] * w;
          Fh += p * indenter.slope(x - s) * w;
        }

      sample_values.reinit(cell, f);
      sample_values[uy].get_function_values(u, s_u_y);
      for (unsigned int q = 0; q < sampling.size(); ++q)
        {
          const double x = sample_values.quadrature_point(q)[0];
          samples[q]     = {x, gap(indenter, eps, delta, s, x, s_u_y[q])};
          g_min          = std::min(g_min, samples[q].second);
        }
      std::sort(samples.begin(), samples.end());
      for (unsigned int i = 0; i + 1 < samples.size(); ++i)
        {
          const auto [x0, g0] = samples[i];
          const auto [x1, g1] = samples[i + 1];
          const bool in0 = g0 < contact_gap, in1 = g1 < contact_gap;
          if (in0 && in1)
            L += x1 - x0;
          else if (in0 != in1)
            {
              // the part of the interval on the contact side of the
              // crossing
              const double t = (contact_gap - g0) / (g1 - g0);
              L += (in0 ? t : 1. - t) * (x1 - x0);
              x_trail = std::min(x_trail, x0 + t * (x1 - x0));
              x_lead  = std::max(x_lead, x0 + t * (x1 - x0));
            }
        }
    });

    const MPI_Comm    comm = dofs.get_communicator();
    SurfaceQuantities q{Utilities::MPI::sum(Fn, comm),
                        Utilities::MPI::sum(Fh, comm),
                        Utilities::MPI::sum(Ft, comm),
                        Utilities::MPI::sum(L, comm),
                        Utilities::MPI::sum(F_abs, comm),
                        Utilities::MPI::min(g_min, comm)};
    // Relative to the apex; without contact both at the apex.
    x_trail   = Utilities::MPI::min(x_trail, comm);
    x_lead    = Utilities::MPI::max(x_lead, comm);
    q.x_trail = x_lead >= x_trail ? x_trail - s : 0.;
    q.x_lead  = x_lead >= x_trail ? x_lead - s : 0.;
    return q;
  }


  template <typename Function>
  void
  SurfacePostprocessor::for_each_sampled_face(
    const DoFHandler<2>                 &dofs,
    const TrilinosWrappers::MPI::Vector &u,
    const double                         delta,
    const double                         s,
    const Function                      &f) const
  {
    const FEValuesExtractors::Scalar uy(1);
    const Quadrature<1>              sampling = sampling_points(4);
    FEFaceValues<2>                  values(dofs.get_fe(),
                           sampling,
                           update_values | update_quadrature_points);
    std::vector<double>              u_y(sampling.size()), x(sampling.size()),
      g(sampling.size());
    for_each_top_face(dofs,
                      top,
                      [&](const auto &cell, const unsigned int face) {
                        values.reinit(cell, face);
                        values[uy].get_function_values(u, u_y);
                        for (unsigned int q = 0; q < sampling.size(); ++q)
                          {
                            x[q] = values.quadrature_point(q)[0];
                            g[q] = gap(indenter, eps, delta, s, x[q], u_y[q]);
                          }
                        f(cell, face, x, g, u_y);
                      });
  }


  std::vector<ProfilePoint>
  SurfacePostprocessor::profile(const DoFHandler<2>                 &dofs,
                                const TrilinosWrappers::MPI::Vector &u,
                                const double                         delta,
                                const double                         s) const
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
          points.push_back({x[q], g[q], -law.traction(g[q]), u_y[q]});
      });

    std::vector<ProfilePoint> all =
      gather_concatenated(dofs.get_communicator(), points, 0);
    std::sort(all.begin(), all.end(), [](const auto &a, const auto &b) {
      return a.x < b.x;
    });
    // Face end points appear twice; keep one.
    all.erase(std::unique(all.begin(),
                          all.end(),
                          [](const auto &a, const auto &b) {
                            return std::abs(a.x - b.x) <=
                                   1e-12 * (1. + std::abs(a.x));
                          }),
              all.end());
    return all;
  }


  std::vector<std::pair<double, double>>
  SurfacePostprocessor::faces_in_gap_band(
    const DoFHandler<2>                 &dofs,
    const TrilinosWrappers::MPI::Vector &u,
    const double                         delta,
    const double                         s,
    const double                         g_lo,
    const double                         g_hi) const
  {
    std::vector<std::pair<double, double>> intervals;
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
                            if (*lo <= g_hi && *hi >= g_lo)
                              intervals.push_back(
                                std::minmax(cell->face(face)->vertex(0)[0],
                                            cell->face(face)->vertex(1)[0]));
                          });
    return gather_concatenated(dofs.get_communicator(), intervals, -1);
  }


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

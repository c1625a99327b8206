// SPDX-License-Identifier: LGPL-2.1-or-later
#include <deal.II/base/mpi.h>

#include <viscoslide/boundary_element/uniform_grid.h>

#include <algorithm>
#include <cmath>
#include <fstream>
#include <iomanip>

namespace viscoslide
{
  // The smallest n >= m of the form 2^a 3^b 5^c 7^d, even, for which
  // FFTW is fastest.
  unsigned int
  fft_size(const double m)
  {
    for (unsigned int n = std::max(2u, 2 * (unsigned int)(std::ceil(m / 2)));;
         n += 2)
      {
        unsigned int r = n;
        for (const unsigned int p : {2u, 3u, 5u, 7u})
          while (r % p == 0)
            r /= p;
        if (r == 1)
          return n;
      }
  }

  // The part of a triangle where a linear function of vertex values g
  // is below c.
  double
  fraction_below(std::array<double, 3> g, const double c)
  {
    std::sort(g.begin(), g.end());
    if (c <= g[0])
      return 0.;
    if (c >= g[2])
      return 1.;
    if (c <= g[1])
      return (c - g[0]) * (c - g[0]) / ((g[1] - g[0]) * (g[2] - g[0]));
    return 1. - (g[2] - c) * (g[2] - c) / ((g[2] - g[0]) * (g[2] - g[1]));
  }


  template <int dim>
  UniformGrid<dim>::UniformGrid(const Indenter     &indenter,
                                const double        elongation,
                                const double        dx,
                                const double        length,
                                const double        eps,
                                ConditionalOStream &out)
    : SurfaceGrid<dim>(dx)
    , indenter(indenter)
    , elongation(elongation)
    , length(length)
    , eps(eps)
    , out(out)
  {
  }


  template <int dim>
  void
  UniformGrid<dim>::fit_to_speed(const double V_hat, SurfaceState &state)
  {
    // In 3D, x and y coarsen together in the multigrid: both counts a
    // multiple of 2^levels, so that the coarsest grid is small.
    const unsigned int                multiple = dim == 2 ? 1 : 16;
    const double                      dx       = this->dx;
    std::array<unsigned int, dim - 1> new_shape;
    new_shape[dim - 2] = multiple * fft_size(period_for(V_hat) / dx / multiple);
    if constexpr (dim == 3)
      new_shape[0] = multiple * fft_size(length / dx / multiple);
    const unsigned int n_x = new_shape[dim - 2], old_x = shape[dim - 2];
    if (this->size() == 0 || n_x > old_x || 4 * n_x < old_x)
      remake(new_shape, state);
  }


  template <int dim>
  void
  UniformGrid<dim>::remake(const std::array<unsigned int, dim - 1> &new_shape,
                           SurfaceState                            &state)
  {
    // The displacements carried over at the same places.
    const Vector<double> old_u = state.displacement(this->points.h, eps);
    const std::array<unsigned int, dim - 1> old_shape = shape;
    shape                                             = new_shape;
    make_operators(shape);
    this->set_speed(this->speed);
    const unsigned int n_x = shape[dim - 2], n_y = dim == 2 ? 1 : shape[0];
    const unsigned int n = n_x * n_y;
    auto              &p = this->points;
    p.x.resize(n);
    p.y.resize(n);
    p.h.resize(n);
    p.slope.resize(n);
    Vector<double>     u(n);
    const unsigned int old_x = old_shape[dim - 2],
                       old_y = dim == 2 ? 1 : old_shape[0];
    for (unsigned int j = 0; j < n; ++j)
      {
        const long i_x = j % n_x, i_y = j / n_x;
        p.x[j] = (double(i_x) - n_x / 2) * this->dx;
        p.y[j] = dim == 2 ? 0. : (double(i_y) - n_y / 2) * this->dx;
        // In 3D the body of revolution of the profile, stretched across
        // the track by the elongation.
        const double r = dim == 2
                           ? p.x[j]
                           : std::hypot(p.x[j], p.y[j] / std::sqrt(elongation));
        p.h[j]         = indenter.profile(r);
        p.slope[j]     = dim == 2 ? indenter.slope(p.x[j])
                                  : (r > 0 ? indenter.slope(r) * p.x[j] / r : 0.);
        // The same point on the old grid; beyond it, its nearer end.
        if (old_u.size() > 0)
          {
            const long o_x = std::clamp<long>(i_x - n_x / 2 + old_x / 2,
                                              0,
                                              long(old_x) - 1),
                       o_y = std::clamp<long>(i_y - n_y / 2 + old_y / 2,
                                              0,
                                              long(old_y) - 1);
            u[j]           = old_u[o_y * old_x + o_x];
          }
      }
    state.set_displacement(u, p.h, eps);
    p.area.assign(n, this->dA);
    ++this->n_generation;
    this->preconditioner().reset();
    out << describe() << std::endl;
  }


  // Neighbours along x within a row, periodic.
  template <int dim>
  unsigned int
  UniformGrid<dim>::next(const unsigned int j) const
  {
    const unsigned int n_x = shape[dim - 2];
    return j - j % n_x + (j % n_x + 1) % n_x;
  }


  template <int dim>
  unsigned int
  UniformGrid<dim>::previous(const unsigned int j) const
  {
    const unsigned int n_x = shape[dim - 2];
    return j - j % n_x + (j % n_x + n_x - 1) % n_x;
  }


  template <int dim>
  void
  UniformGrid<dim>::measure_plane(const Vector<double> &gaps,
                                  const double          gc,
                                  SurfaceQuantities    &q) const
  {
    if constexpr (dim == 3)
      {
        const unsigned int n_x = shape[1], n = gaps.size(), n_y = n / n_x;
        const double       dx = this->dx;
        for (unsigned int j = 0; j + n_x < n; ++j)
          if ((gaps[j] < gc) != (gaps[j + n_x] < gc))
            q.y_half = std::max(q.y_half,
                                std::abs(this->points.y[j] +
                                         (gc - gaps[j]) /
                                           (gaps[j + n_x] - gaps[j]) * dx));
        // Each square of four neighbouring points as two triangles, the
        // gap linear on each: second order in the spacing for a smooth
        // edge (a row's length times dx is not, at the rows near the edge
        // across the track).
        double area = 0;
        for (unsigned int b = 0; b + 1 < n_y; ++b)
          for (unsigned int a = 0; a + 1 < n_x; ++a)
            {
              const unsigned int j   = b * n_x + a;
              const double       g00 = gaps[j], g10 = gaps[j + 1],
                           g01 = gaps[j + n_x], g11 = gaps[j + n_x + 1];
              if (std::min({g00, g10, g01, g11}) >= gc)
                continue;
              area += fraction_below({{g00, g10, g11}}, gc) +
                      fraction_below({{g00, g01, g11}}, gc);
            }
        q.contact_length = 0.5 * area * dx * dx;
      }
  }


  template <int dim>
  void
  UniformGrid<dim>::write_map(const std::string    &path,
                              const std::string    &what,
                              const Vector<double> &gaps,
                              const Vector<double> &traction,
                              const Vector<double> &u,
                              const double          eps,
                              const double          sigma_max,
                              const double          R) const
  {
    if constexpr (dim == 3)
      {
        // VTK image data (ParaView): the rectangle about the contact where
        // the surfaces are within 10 eps, with a margin of a quarter of its
        // size, every point; pressure in sigma_max, gap and displacement
        // in eps, lengths in R.
        const unsigned int n_x = shape[1], n_y = shape[0];
        const double       dx           = this->dx;
        const auto [extent_x, extent_y] = this->reach_within(gaps, 10 * eps);
        const auto half_points = [dx](const double extent, const unsigned n) {
          return std::min<unsigned int>(std::ceil((1.25 * extent + 4 * dx) /
                                                  dx),
                                        n / 2 - 1);
        };
        const unsigned int half_x = half_points(extent_x, n_x),
                           half_y = half_points(extent_y, n_y);
        const unsigned int i0 = n_x / 2 - half_x, j0 = n_y / 2 - half_y,
                           m_x = 2 * half_x + 1, m_y = 2 * half_y + 1;
        std::ofstream out(path);
        out << "<?xml version=\"1.0\"?>\n<!-- " << what << " -->\n"
            << "<VTKFile type=\"ImageData\" version=\"0.1\">\n"
            << "<ImageData WholeExtent=\"0 " << m_x - 1 << " 0 " << m_y - 1
            << " 0 0\" Origin=\"" << -double(half_x) * dx / R << " "
            << -double(half_y) * dx / R << " 0\" Spacing=\"" << dx / R << " "
            << dx / R << " 1\">\n"
            << "<Piece Extent=\"0 " << m_x - 1 << " 0 " << m_y - 1
            << " 0 0\">\n"
            << "<PointData Scalars=\"p_hat\">\n";
        const auto field = [&](const char *name, const auto &value) {
          out << "<DataArray type=\"Float64\" Name=\"" << name
              << "\" format=\"ascii\">\n"
              << std::setprecision(8);
          for (unsigned int b = 0; b < m_y; ++b)
            for (unsigned int a = 0; a < m_x; ++a)
              out << value((j0 + b) * n_x + i0 + a)
                  << (a + 1 < m_x ? ' ' : '\n');
          out << "</DataArray>\n";
        };
        field("p_hat",
              [&](unsigned int j) { return -traction[j] / sigma_max; });
        field("gap_over_eps", [&](unsigned int j) { return gaps[j] / eps; });
        field("u_over_eps", [&](unsigned int j) { return u[j] / eps; });
        out << "</PointData>\n</Piece>\n</ImageData>\n</VTKFile>\n";
        if (!out)
          throw std::runtime_error("could not write " + path);
      }
  }


  template class UniformGrid<2>;
  template class UniformGrid<3>;
} // namespace viscoslide

// BoundaryElementSolver: the surface quantities, the dissipation, the
// profile and, in 3D, the map of the surface.
#include <viscoslide/boundary_element/solver.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <fstream>
#include <iomanip>
#include <limits>

namespace viscoslide
{
  template <int dim>
  void
  BoundaryElementSolver<dim>::update_quantities()
  {
    assemble(false);
    const unsigned int n   = u.size();
    const unsigned int n_x = shape[dim - 2];
    // Neighbours along x within a row, periodic; on the graded grid the
    // ends are their own neighbours (no traction reaches them), and the
    // distance to the next point is its own.
    const auto next = [this, n_x](const unsigned int j) {
      if (graded)
        return std::min(j + 1, n_x - 1);
      return j - j % n_x + (j % n_x + 1) % n_x;
    };
    const auto previous = [this, n_x](const unsigned int j) {
      if (graded)
        return j > 0 ? j - 1 : 0u;
      return j - j % n_x + (j % n_x + n_x - 1) % n_x;
    };
    const auto spacing = [&](const unsigned int j) {
      return graded ? x[next(j)] - x[j] : dx;
    };
    const double      gc = prm.adhesion.contact_gap * law_range;
    SurfaceQuantities q{};
    q.minimum_gap = gaps.linfty_norm();
    q.x_trail     = std::numeric_limits<double>::infinity();
    q.x_lead      = -q.x_trail;
    for (unsigned int j = 0; j < n; ++j)
      {
        const double p = -traction[j];
        q.normal_force += p * area[j];
        q.absolute_force += std::abs(p) * area[j];
        q.tangential_force += p * slope[j] * area[j];
        if (gaps[j] < gc && next(j) != previous(j))
          {
            const double du_dx =
              (u[next(j)] - u[previous(j)]) /
              (graded ? x[next(j)] - x[previous(j)] : 2 * dx);
            q.contact_set_tangential_force += p * du_dx * area[j];
          }
        q.minimum_gap = std::min(q.minimum_gap, gaps[j]);
        // The contact set's edges between j and its neighbours, the gap
        // linear in between (the fraction of the way where it crosses gc);
        // in 2D its length.
        const double g0 = gaps[j], g1 = gaps[next(j)];
        const auto   crossing = [g0, gc](const double g) {
          return (gc - g0) / (g - g0);
        };
        if (dim == 2 && g0 < gc && g1 < gc)
          q.contact_length += spacing(j);
        else if ((g0 < gc) != (g1 < gc))
          {
            const double t = crossing(g1);
            if (dim == 2)
              q.contact_length += (g0 < gc ? t : 1. - t) * spacing(j);
            const double edge = x[j] + t * spacing(j);
            q.x_trail         = std::min(q.x_trail, edge);
            q.x_lead          = std::max(q.x_lead, edge);
          }
        if (dim == 3 && j + n_x < n && (g0 < gc) != (gaps[j + n_x] < gc))
          q.y_half =
            std::max(q.y_half, std::abs(y[j] + crossing(gaps[j + n_x]) * dx));
      }
    if (dim == 3)
      q.contact_length = contact_area(gc);
    if (q.x_lead < q.x_trail)
      q.x_trail = q.x_lead = 0.;
    last_quantities = q;
  }


  namespace
  {
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
  } // namespace


  template <int dim>
  double
  BoundaryElementSolver<dim>::contact_area(const double gc) const
  {
    // Each square of four neighbouring points as two triangles, the gap
    // linear on each: second order in the spacing for a smooth edge (a
    // row's length times dx is not, at the rows near the edge across the
    // track).
    const unsigned int n_x = shape[dim - 2], n_y = u.size() / n_x;
    double             area = 0;
    for (unsigned int b = 0; b + 1 < n_y; ++b)
      for (unsigned int a = 0; a + 1 < n_x; ++a)
        {
          const unsigned int j = b * n_x + a;
          const double g00 = gaps[j], g10 = gaps[j + 1], g01 = gaps[j + n_x],
                       g11 = gaps[j + n_x + 1];
          if (std::min({g00, g10, g01, g11}) >= gc)
            continue;
          area += fraction_below({{g00, g10, g11}}, gc) +
                  fraction_below({{g00, g01, g11}}, gc);
        }
    return 0.5 * area * dx * dx;
  }


  template <int dim>
  double
  BoundaryElementSolver<dim>::dissipation_rate() const
  {
    return compliance->dissipation_rate(traction);
  }


  template <int dim>
  void
  BoundaryElementSolver<dim>::write_profile(const std::string &path) const
  {
    // Every point where the surfaces interact, and every eighth one
    // elsewhere within the Domain width, so that the wake shows without a
    // file of the whole period; in 3D along the track's centre line
    // (y = 0), with the map of the surface beside it.
    const unsigned int        n = u.size();
    std::vector<ProfilePoint> points;
    const double half_width = prm.geometry.domain_width * scales.eps / 2;
    for (unsigned int j = 0; j < n; ++j)
      if (y[j] == 0. && std::abs(x[j]) <= half_width &&
          (gaps[j] < 10 * scales.eps || j % 8 == 0))
        points.push_back({x[j], gaps[j], -traction[j], u[j]});
    const std::string what =
      "steady state (boundary elements), V_hat = " + CsvTable::format(V_hat) +
      ", delta_hat = " + CsvTable::format(approach() / scales.eps);
    write_profile_csv(path, points, scales, what, comm);
    if constexpr (dim == 3)
      write_map(path.substr(0, path.rfind('.')) + ".vti", what);
  }


  template <int dim>
  void
  BoundaryElementSolver<dim>::write_map(const std::string &path,
                                        const std::string &what) const
  {
    // VTK image data (ParaView): the rectangle about the contact where
    // the surfaces are within 10 eps, with a margin of a quarter of its
    // size, every point; pressure in sigma_max, gap and displacement in
    // eps, lengths in R.
    if (Utilities::MPI::this_mpi_process(comm) != 0)
      return;
    const unsigned int n_x = shape[dim - 2], n_y = shape[0];
    double             extent_x = 0, extent_y = 0;
    for (unsigned int j = 0; j < u.size(); ++j)
      if (gaps[j] < 10 * scales.eps)
        {
          extent_x = std::max(extent_x, std::abs(x[j]));
          extent_y = std::max(extent_y, std::abs(y[j]));
        }
    const auto half_points = [this](const double extent, const unsigned n) {
      return std::min<unsigned int>(std::ceil((1.25 * extent + 4 * dx) / dx),
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
        << " 0 0\" Origin=\"" << -double(half_x) * dx / scales.R << " "
        << -double(half_y) * dx / scales.R << " 0\" Spacing=\"" << dx / scales.R
        << " " << dx / scales.R << " 1\">\n"
        << "<Piece Extent=\"0 " << m_x - 1 << " 0 " << m_y - 1 << " 0 0\">\n"
        << "<PointData Scalars=\"p_hat\">\n";
    const auto field = [&](const char *name, const auto &value) {
      out << "<DataArray type=\"Float64\" Name=\"" << name
          << "\" format=\"ascii\">\n"
          << std::setprecision(8);
      for (unsigned int b = 0; b < m_y; ++b)
        for (unsigned int a = 0; a < m_x; ++a)
          out << value((j0 + b) * n_x + i0 + a) << (a + 1 < m_x ? ' ' : '\n');
      out << "</DataArray>\n";
    };
    field("p_hat",
          [&](unsigned int j) { return -traction[j] / scales.sigma_max; });
    field("gap_over_eps", [&](unsigned int j) { return gaps[j] / scales.eps; });
    field("u_over_eps", [&](unsigned int j) { return u[j] / scales.eps; });
    out << "</PointData>\n</Piece>\n</ImageData>\n</VTKFile>\n";
    if (!out)
      throw std::runtime_error("could not write " + path);
  }


  // The class itself is instantiated in solver.cc; here the members this
  // file defines.
#define VISCOSLIDE_INSTANTIATE(dim)                                              \
  template void   BoundaryElementSolver<dim>::update_quantities();               \
  template double BoundaryElementSolver<dim>::dissipation_rate() const;          \
  template double BoundaryElementSolver<dim>::contact_area(double) const;        \
  template void   BoundaryElementSolver<dim>::write_profile(const std::string &) \
    const;                                                                       \
  template void BoundaryElementSolver<dim>::write_map(const std::string &,       \
                                                      const std::string &)       \
    const;
  VISCOSLIDE_INSTANTIATE(2)
  VISCOSLIDE_INSTANTIATE(3)
#undef VISCOSLIDE_INSTANTIATE
} // namespace viscoslide

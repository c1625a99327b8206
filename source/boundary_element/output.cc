// BoundaryElementSolver: the surface quantities, the dissipation, the
// profile and, in 3D, the map of the surface.
#include <viscoslide/boundary_element/solver.h>

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
    // Neighbours along x within a row, periodic.
    const auto next = [n_x](const unsigned int j) {
      return j - j % n_x + (j % n_x + 1) % n_x;
    };
    const auto previous = [n_x](const unsigned int j) {
      return j - j % n_x + (j % n_x + n_x - 1) % n_x;
    };
    const double      gc = prm.adhesion.contact_gap * scales.eps;
    SurfaceQuantities q{};
    q.minimum_gap = gaps.linfty_norm();
    q.x_trail     = std::numeric_limits<double>::infinity();
    q.x_lead      = -q.x_trail;
    for (unsigned int j = 0; j < n; ++j)
      {
        const double p = -traction[j];
        q.normal_force += p * dA;
        q.absolute_force += std::abs(p) * dA;
        q.tangential_force += p * slope[j] * dA;
        if (gaps[j] < gc)
          {
            const double du_dx = (u[next(j)] - u[previous(j)]) / (2 * dx);
            q.contact_set_tangential_force += p * du_dx * dA;
            q.y_half = std::max(q.y_half, std::abs(y[j]) + 0.5 * dx);
          }
        q.minimum_gap = std::min(q.minimum_gap, gaps[j]);
        // The contact set between j and its neighbour along x, the gap
        // linear in between; in 3D each row stands for a strip dx wide.
        const double g0 = gaps[j], g1 = gaps[next(j)];
        const double strip = dA / dx;
        if (g0 < gc && g1 < gc)
          q.contact_length += dx * strip;
        else if ((g0 < gc) != (g1 < gc))
          {
            const double t = (gc - g0) / (g1 - g0);
            q.contact_length += (g0 < gc ? t : 1. - t) * dx * strip;
            const double edge = x[j] + t * dx;
            q.x_trail         = std::min(q.x_trail, edge);
            q.x_lead          = std::max(q.x_lead, edge);
          }
      }
    if (q.x_lead < q.x_trail)
      q.x_trail = q.x_lead = 0.;
    last_quantities = q;
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
    // VTK image data (ParaView): the square about the contact where the
    // surfaces are within 10 eps, with a margin of a quarter of its size,
    // every point; pressure in sigma_max, gap and displacement in eps,
    // lengths in R.
    if (Utilities::MPI::this_mpi_process(comm) != 0)
      return;
    const unsigned int n_x = shape[dim - 2], n_y = shape[0];
    double             extent = 0;
    for (unsigned int j = 0; j < u.size(); ++j)
      if (gaps[j] < 10 * scales.eps)
        extent = std::max({extent, std::abs(x[j]), std::abs(y[j])});
    extent = 1.25 * extent + 4 * dx;
    const unsigned int half =
      std::min<unsigned int>(std::ceil(extent / dx),
                             std::min(n_x, n_y) / 2 - 1);
    const unsigned int i0 = n_x / 2 - half, j0 = n_y / 2 - half,
                       m = 2 * half + 1;
    std::ofstream out(path);
    out << "<?xml version=\"1.0\"?>\n<!-- " << what << " -->\n"
        << "<VTKFile type=\"ImageData\" version=\"0.1\">\n"
        << "<ImageData WholeExtent=\"0 " << m - 1 << " 0 " << m - 1
        << " 0 0\" Origin=\"" << -double(half) * dx / scales.R << " "
        << -double(half) * dx / scales.R << " 0\" Spacing=\"" << dx / scales.R
        << " " << dx / scales.R << " 1\">\n"
        << "<Piece Extent=\"0 " << m - 1 << " 0 " << m - 1 << " 0 0\">\n"
        << "<PointData Scalars=\"p_hat\">\n";
    const auto field = [&](const char *name, const auto &value) {
      out << "<DataArray type=\"Float64\" Name=\"" << name
          << "\" format=\"ascii\">\n"
          << std::setprecision(8);
      for (unsigned int b = 0; b < m; ++b)
        for (unsigned int a = 0; a < m; ++a)
          out << value((j0 + b) * n_x + i0 + a) << (a + 1 < m ? ' ' : '\n');
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
  template void   BoundaryElementSolver<dim>::write_profile(const std::string &) \
    const;                                                                       \
  template void BoundaryElementSolver<dim>::write_map(const std::string &,       \
                                                      const std::string &)       \
    const;
  VISCOSLIDE_INSTANTIATE(2)
  VISCOSLIDE_INSTANTIATE(3)
#undef VISCOSLIDE_INSTANTIATE
} // namespace viscoslide

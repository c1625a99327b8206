// BoundaryElementSolver: the surface quantities, the dissipation and the
// profile.
#include <viscoslide/boundary_element/solver.h>

#include <cmath>

namespace viscoslide
{
  void
  BoundaryElementSolver::update_quantities()
  {
    assemble(false);
    const unsigned int n  = u.size();
    const double       gc = prm.adhesion.contact_gap * scales.eps;
    SurfaceQuantities  q{};
    q.minimum_gap = gaps.linfty_norm();
    for (unsigned int j = 0; j < n; ++j)
      {
        const double p = -traction[j];
        q.normal_force += p * dx;
        q.absolute_force += std::abs(p) * dx;
        q.tangential_force += p * indenter.slope(x[j]) * dx;
        if (gaps[j] < gc)
          {
            const double slope =
              (u[(j + 1) % n] - u[(j + n - 1) % n]) / (2 * dx);
            q.contact_set_tangential_force += p * slope * dx;
          }
        q.minimum_gap = std::min(q.minimum_gap, gaps[j]);
        // The contact set between j and j + 1, the gap linear in between.
        const double g0 = gaps[j], g1 = gaps[(j + 1) % n];
        if (g0 < gc && g1 < gc)
          q.contact_length += dx;
        else if ((g0 < gc) != (g1 < gc))
          {
            const double t = (gc - g0) / (g1 - g0);
            q.contact_length += (g0 < gc ? t : 1. - t) * dx;
          }
      }
    last_quantities = q;
  }


  double
  BoundaryElementSolver::dissipation_rate() const
  {
    return compliance->dissipation_rate(traction);
  }


  void
  BoundaryElementSolver::write_profile(const std::string &path) const
  {
    // Every point where the surfaces interact, and every eighth one
    // elsewhere within the Domain width, so that the wake shows without a
    // file of the whole period.
    const unsigned int        n = u.size();
    std::vector<ProfilePoint> points;
    const double half_width = prm.geometry.domain_width * scales.eps / 2;
    for (unsigned int j = 0; j < n; ++j)
      if (std::abs(x[j]) <= half_width &&
          (gaps[j] < 10 * scales.eps || j % 8 == 0))
        points.push_back({x[j], gaps[j], -traction[j], u[j]});
    write_profile_csv(path,
                      points,
                      scales,
                      "steady state (boundary elements), V_hat = " +
                        CsvTable::format(V_hat) +
                        ", delta_hat = " + CsvTable::format(delta / scales.eps),
                      comm);
  }
} // namespace viscoslide

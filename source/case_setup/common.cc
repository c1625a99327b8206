// SPDX-License-Identifier: LGPL-2.1-or-later
#include <viscoslide/case_setup/common.h>
#include <viscoslide/physics/scales.h>

#include <algorithm>
#include <cmath>
#include <iomanip>
#include <sstream>

namespace viscoslide
{
  namespace CaseSetup
  {
    namespace internal
    {
      double
      hertz_half_width(const double         F_hat,
                       const double         E_star,
                       const AllParameters &p)
      {
        // Plane strain: F = pi E* a^2/(4R); the sphere: F = 4 E* a^3/(3R).
        const Scales s(p);
        const double F = std::max(F_hat, 0.) * s.force;
        return p.geometry.dimension == 3
                 ? std::cbrt(3. * F * s.R / (4. * E_star))
                 : std::sqrt(4. * F * s.R / (M_PI * E_star));
      }


      double
      adhesive_zone(const AllParameters &p)
      {
        const Scales s(p);
        const double softest = std::min(1., 1. / p.material.E0_over_Einf);
        return M_PI / 8 * softest * s.dgamma / std::pow(s.sigma_max, 2);
      }


      double
      surface_grid_spacing(const AllParameters &p)
      {
        return p.boundary_element.grid_spacing > 0
                 ? p.boundary_element.grid_spacing
                 : p.mesh.finest_cell / 2;
      }


      bool
      runs_only(const AllParameters                       &p,
                const std::initializer_list<SlidingSolver> solvers)
      {
        const auto listed = [&](const SlidingSolver s) {
          return std::find(solvers.begin(), solvers.end(), s) != solvers.end();
        };
        return listed(p.sliding.solver) && std::all_of(p.sweep.solvers.begin(),
                                                       p.sweep.solvers.end(),
                                                       listed);
      }


      bool
      boundary_elements_only(const AllParameters &p)
      {
        return runs_only(p, {SlidingSolver::boundary_element});
      }


      bool
      graded_grid_only(const AllParameters &p)
      {
        return p.boundary_element.grid == GridKind::graded &&
               boundary_elements_only(p);
      }


      double
      fastest_wake(const AllParameters &p)
      {
        const auto &V = p.sliding.speeds;
        return V.empty() ? 0.
                         : *std::max_element(V.begin(), V.end()) *
                             longest_creep_time(p);
      }


      std::string
      speeds_relaxing_within(const AllParameters &p,
                             const double         tau,
                             const double         length)
      {
        std::ostringstream speeds;
        for (const double V_hat : p.sliding.speeds)
          if (V_hat > 0 && V_hat * tau < length)
            speeds << (speeds.tellp() > 0 ? ", " : "") << V_hat;
        return speeds.str();
      }


      std::string
      wake_advice(const AllParameters &p)
      {
        if (p.sliding.speeds.empty() ||
            std::abs(p.geometry.domain_width -
                     p.geometry.wake_lengths * fastest_wake(p)) >
              1e-12 * p.geometry.domain_width)
          return "";
        std::ostringstream advice;
        advice << std::setprecision(3) << "; the block is "
               << p.geometry.domain_width
               << " eps long to hold the wake of the fastest speed: lower "
                  "the fastest 'Sliding/Sliding speed' or 'Geometry/Wake "
                  "lengths'";
        return advice.str();
      }
    } // namespace internal
  }   // namespace CaseSetup
} // namespace viscoslide

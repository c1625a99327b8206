// SPDX-License-Identifier: LGPL-2.1-or-later
#include <viscoslide/physics/interaction_laws/lennard_jones.h>

#include <algorithm>
#include <cmath>

namespace viscoslide
{
  LennardJones::LennardJones(const double dgamma,
                             const double eps,
                             const bool   repulsive_only)
    : dgamma(dgamma)
    , eps(eps)
    , repulsive_only(repulsive_only)
  {
  }

  double
  LennardJones::raw_traction(const double g) const
  {
    const double r = eps / g, r3 = r * r * r; // not pow: 4 % of a 3D curve
    return 8. * dgamma / (3. * eps) * (r3 - r3 * r3 * r3);
  }

  double
  LennardJones::raw_derivative(const double g) const
  {
    const double r = eps / g, r3 = r * r * r;
    return 8. * dgamma / (3. * eps) * (-3. * r3 + 9. * r3 * r3 * r3) / g;
  }

  // The repulsive branch alone has a kink at g = eps (slope 16 dgamma/eps^2
  // below, 0 above), and Newton stalls on a kink: surface nodes flip sides
  // and a predicted sliding step need not be a descent direction there.
  // Over [g1, eps], g1 = (1 - rounding) eps, the branch is replaced by the
  // cubic Hermite interpolant matching its value and slope at g1 and
  // meeting zero with zero slope at eps. Fritsch-Carlson: it is monotone
  // (it never attracts) since slope(g1) < 3 |p(g1)| / (eps - g1).
  double
  LennardJones::traction(const double g) const
  {
    const double g0 = 0.5 * eps;
    if (g < g0)
      return raw_traction(g0) + raw_derivative(g0) * (g - g0);
    if (!repulsive_only)
      return raw_traction(g);
    const double g1 = (1. - rounding) * eps;
    if (g >= eps)
      return 0.;
    if (g <= g1)
      return raw_traction(g);
    const double w = eps - g1, t = (g - g1) / w;
    return raw_traction(g1) * (2. * t * t * t - 3. * t * t + 1.) +
           w * raw_derivative(g1) * (t * t * t - 2. * t * t + t);
  }

  double
  LennardJones::derivative(const double g) const
  {
    if (!repulsive_only || g <= (1. - rounding) * eps)
      return raw_derivative(std::max(g, 0.5 * eps));
    if (g >= eps)
      return 0.;
    const double g1 = (1. - rounding) * eps;
    const double w = eps - g1, t = (g - g1) / w;
    return raw_traction(g1) * (6. * t * t - 6. * t) / w +
           raw_derivative(g1) * (3. * t * t - 4. * t + 1.);
  }


  VISCOSLIDE_REGISTER(InteractionLawType,
                      {"lennard-jones",
                       "the 3-9 law of doc/model.md.",
                       [](const double dgamma, const double eps) {
                         return std::make_unique<LennardJones>(dgamma, eps);
                       },
                       true})

  VISCOSLIDE_REGISTER(
    InteractionLawType,
    {"repulsive",
     "only its repulsive branch (g < eps), rounded to zero slope over "
     "[0.98 eps, eps] so that Newton converges, i.e. frictionless contact "
     "without adhesion.",
     [](const double dgamma, const double eps) {
       return std::make_unique<LennardJones>(dgamma, eps, true);
     },
     false})
} // namespace viscoslide

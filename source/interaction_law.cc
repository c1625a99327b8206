#include <viscoslide/interaction_law.h>

#include <cmath>
#include <stdexcept>

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
    const double r3 = std::pow(eps / g, 3);
    return 8. * dgamma / (3. * eps) * (r3 - r3 * r3 * r3);
  }

  double
  LennardJones::raw_derivative(const double g) const
  {
    const double r3 = std::pow(eps / g, 3);
    return 8. * dgamma / (3. * eps) * (-3. * r3 + 9. * r3 * r3 * r3) / g;
  }

  double
  LennardJones::traction(const double g) const
  {
    if (repulsive_only && g >= eps)
      return 0.;
    const double g0 = 0.5 * eps;
    if (g < g0)
      return raw_traction(g0) + raw_derivative(g0) * (g - g0);
    return raw_traction(g);
  }

  double
  LennardJones::derivative(const double g) const
  {
    if (repulsive_only && g >= eps)
      return 0.;
    return raw_derivative(std::max(g, 0.5 * eps));
  }

  std::unique_ptr<InteractionLaw>
  create_interaction_law(const std::string &name,
                         const double       dgamma,
                         const double       eps)
  {
    if (name == "lennard-jones")
      return std::make_unique<LennardJones>(dgamma, eps);
    if (name == "repulsive")
      return std::make_unique<LennardJones>(dgamma, eps, true);
    throw std::invalid_argument("Unknown interaction law '" + name + "'");
  }
} // namespace viscoslide

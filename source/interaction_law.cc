#include <viscoslide/interaction_law.h>

#include <algorithm>
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

  Exponential::Exponential(const double dgamma, const double eps)
    : dgamma(dgamma)
    , eps(eps)
    , delta(9. * std::sqrt(3.) / (16. * std::exp(1.)) * eps)
  {
  }

  double
  Exponential::traction(const double g) const
  {
    const double d0 = -0.5 * eps, d = g - eps;
    if (d < d0) // linear continuation, as for the Lennard-Jones law
      return dgamma * d0 / (delta * delta) * std::exp(-d0 / delta) +
             derivative(g) * (d - d0);
    return dgamma * d / (delta * delta) * std::exp(-d / delta);
  }

  double
  Exponential::derivative(const double g) const
  {
    const double d = std::max(g - eps, -0.5 * eps);
    return dgamma / (delta * delta) * (1. - d / delta) * std::exp(-d / delta);
  }


  namespace
  {
    // Smooth step from 0 at t <= 0 to 1 at t >= 1 and its derivative.
    double
    step(const double t)
    {
      const double x = std::clamp(t, 0., 1.);
      return x * x * (3. - 2. * x);
    }
    double
    step_derivative(const double t)
    {
      return t <= 0. || t >= 1. ? 0. : 6. * t * (1. - t);
    }
  } // namespace

  // With the steps centred on eps and eps + h the attraction integrates to
  // sigma0 h exactly, since each step is antisymmetric about its middle.
  Dugdale::Dugdale(const double dgamma, const double eps)
    : wall(dgamma, eps, true)
    , eps(eps)
    , sigma0(16. * dgamma / (9. * std::sqrt(3.) * eps))
    , h(dgamma / sigma0)
    , w_rise(0.05 * h)
    , w_fall(0.25 * h)
  {
  }

  double
  Dugdale::traction(const double g) const
  {
    const double rise = step((g - eps) / w_rise + 0.5),
                 fall = 1. - step((g - eps - h) / w_fall + 0.5);
    return wall.traction(g) + sigma0 * rise * fall;
  }

  double
  Dugdale::derivative(const double g) const
  {
    const double a = (g - eps) / w_rise + 0.5, b = (g - eps - h) / w_fall + 0.5;
    return wall.derivative(g) +
           sigma0 * (step_derivative(a) / w_rise * (1. - step(b)) -
                     step(a) * step_derivative(b) / w_fall);
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
    if (name == "exponential")
      return std::make_unique<Exponential>(dgamma, eps);
    if (name == "dugdale")
      return std::make_unique<Dugdale>(dgamma, eps);
    throw std::invalid_argument("Unknown interaction law '" + name + "'");
  }
} // namespace viscoslide

// SPDX-License-Identifier: LGPL-2.1-or-later
// Xu-Needleman's normal law about the equilibrium gap eps: with d = g -
// eps, p = dgamma d/delta^2 exp(-d/delta), whose work of separation from
// d = 0 is exactly dgamma. delta = 9 sqrt(3)/(16 e) eps gives the peak
// traction dgamma/(e delta) of the Lennard-Jones law, so that muT keeps
// its meaning. Repulsion (d < 0) grows exponentially; continued linearly
// below d = -eps/2 like the Lennard-Jones law.
#include <viscoslide/physics/interaction_law.h>

#include <algorithm>
#include <cmath>

namespace viscoslide
{
  namespace
  {
    class Exponential : public InteractionLaw
    {
    public:
      Exponential(double dgamma, double eps);

      double
      traction(double gap) const override;

      double
      derivative(double gap) const override;

    private:
      double dgamma, eps, delta;
    };
  } // namespace


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


  VISCOSLIDE_REGISTER(
    InteractionLawType,
    {"exponential",
     "Xu-Needleman's normal law about the gap eps, with the Lennard-Jones "
     "peak traction.",
     [](const double dgamma, const double eps) {
       return std::make_unique<Exponential>(dgamma, eps);
     },
     true})
} // namespace viscoslide

// SPDX-License-Identifier: LGPL-2.1-or-later
// The Lennard-Jones law, p(g) = 8 dgamma/(3 eps) [(eps/g)^3 - (eps/g)^9],
// and its repulsive branch alone. Declared here because the Dugdale law
// uses its repulsive branch as the wall.
#ifndef viscoslide_interaction_laws_lennard_jones_h
#define viscoslide_interaction_laws_lennard_jones_h

#include <viscoslide/physics/interaction_law.h>

namespace viscoslide
{
  // Below g = eps/2 the law is continued linearly so that a wild Newton
  // iterate cannot produce Inf/NaN; converged states stay far from it.
  class LennardJones : public InteractionLaw
  {
  public:
    LennardJones(double dgamma, double eps, bool repulsive_only = false);

    double
    traction(double gap) const override;

    double
    derivative(double gap) const override;

  private:
    double
    raw_traction(double gap) const;
    double
    raw_derivative(double gap) const;

    double dgamma, eps;
    bool   repulsive_only;
    // Width of the C1 rounding of the repulsive-only branch below g = eps,
    // in units of eps (see traction()). Narrow: a band of 0.1 eps softened
    // the wall enough to widen the Hertz contact by 1 % (hertz test).
    static constexpr double rounding = 0.02;
  };
} // namespace viscoslide

#endif

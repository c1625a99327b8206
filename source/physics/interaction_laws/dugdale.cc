// SPDX-License-Identifier: LGPL-2.1-or-later
// Maugis-Dugdale: a constant attraction sigma0 (the Lennard-Jones peak
// traction) from the contact up to the range h = dgamma/sigma0, on top of
// the rounded repulsive branch of the Lennard-Jones law below eps. Newton
// needs a continuous law: the attraction rises by a cubic step of width
// 0.05 h centred on eps and falls by one of width 0.25 h centred on
// eps + h, which keeps the work of separation from the contact at
// dgamma. The fall is the wider: each surface point crosses it during an
// approach or a retraction, and Newton's linearisation holds only over a
// fraction of the step's width (with 0.05 h a step of 0.1 eps near the
// jump-in had to be cut to 1/64).
#include <viscoslide/physics/interaction_laws/lennard_jones.h>

#include <algorithm>
#include <cmath>

namespace viscoslide
{
  namespace
  {
    class Dugdale : public InteractionLaw
    {
    public:
      Dugdale(double dgamma, double eps);

      double
      traction(double gap) const override;

      double
      derivative(double gap) const override;

    private:
      LennardJones wall;
      double       eps, sigma0, h, w_rise, w_fall;
    };
  } // namespace


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


  VISCOSLIDE_REGISTER(
    InteractionLawType,
    {"dugdale",
     "Maugis-Dugdale, the Lennard-Jones peak traction constant over the "
     "range dgamma/sigma_max beyond the repulsive wall, its ends smoothed "
     "over 5 % of the range.",
     [](const double dgamma, const double eps) {
       return std::make_unique<Dugdale>(dgamma, eps);
     },
     true})
} // namespace viscoslide

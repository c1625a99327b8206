// SPDX-License-Identifier: LGPL-2.1-or-later
#include <viscoslide/io/parameters.h>
#include <viscoslide/physics/scales.h>

#include <cmath>

namespace viscoslide
{
  Scales::Scales(const Parameters::AllParameters &p)
    : eps(1.)
    , R(p.adhesion.R_over_eps)
    , E0_star(1.)
    , Einf_star(1. / p.material.E0_over_Einf)
    , dgamma(std::sqrt(std::pow(p.adhesion.tabor_parameter, 3) /
                       p.adhesion.R_over_eps))
    , sigma_max(16. * dgamma / (9. * std::sqrt(3.) * eps))
    , force(p.geometry.dimension == 3
              ? 1.5 * M_PI * dgamma * R
              : std::cbrt(M_PI * dgamma * dgamma * E0_star * R))
    , contact(p.geometry.dimension == 3 ? M_PI * R * eps : R)
    , dimension(p.geometry.dimension)
    , tau_arm(p.material.time_constant == Parameters::TimeConstant::relaxation
                ? 1.
                : p.material.E0_over_Einf)
    , tau_ref(1.)
    , si_columns(p.units.si_columns(p.geometry.dimension))
  {
  }


  ViscoelasticSolid
  make_solid(const Parameters::AllParameters &p, const Scales &scales)
  {
    const double one_minus_nu2 = 1. - std::pow(p.material.poisson_ratio, 2);
    return ViscoelasticSolid(one_minus_nu2,
                             one_minus_nu2 / p.material.E0_over_Einf,
                             p.material.poisson_ratio,
                             scales.tau_arm,
                             p.material.prony_series);
  }


  double
  longest_creep_time(const Parameters::AllParameters &p)
  {
    return make_solid(p, Scales(p)).longest_relaxation_time() /
           p.material.E0_over_Einf;
  }
} // namespace viscoslide

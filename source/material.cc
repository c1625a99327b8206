#include <viscoslide/material.h>

#include <algorithm>
#include <cmath>
#include <limits>

namespace viscoslide
{
  namespace
  {
    // In-plane part of the isotropic stiffness in plane strain.
    SymmetricTensor<4, 2>
    plane_strain_stiffness(const double lambda, const double mu)
    {
      return lambda * outer_product(unit_symmetric_tensor<2>(),
                                    unit_symmetric_tensor<2>()) +
             2. * mu * identity_tensor<2>();
    }

    double
    lame_lambda(const double E, const double nu)
    {
      return E * nu / ((1. + nu) * (1. - 2. * nu));
    }
  } // namespace


  ViscoelasticSolid::ViscoelasticSolid(const double                  E0,
                                       const double                  Einf,
                                       const double                  nu,
                                       const double                  tau,
                                       const std::vector<PronyTerm> &series)
    : nu(nu)
    , lambda0(lame_lambda(E0, nu))
    , C0(plane_strain_stiffness(lambda0, E0 / (2. * (1. + nu))))
  {
    const std::vector<PronyTerm> terms =
      series.empty() ? std::vector<PronyTerm>{{1., 1.}} : series;
    double total = 0.;
    for (const auto &t : terms)
      total += t.weight;
    // One arm: E_1 = 1 * (Einf - E0) exactly, the standard linear solid
    // bit for bit.
    for (const auto &t : terms)
      {
        const double E = (t.weight / total) * (Einf - E0);
        arms.push_back(
          {E,
           t.time_ratio * tau,
           lame_lambda(E, nu),
           plane_strain_stiffness(lame_lambda(E, nu), E / (2. * (1. + nu)))});
      }
  }


  std::vector<ViscoelasticSolid::StepFactors>
  ViscoelasticSolid::step_factors(const double dt) const
  {
    std::vector<StepFactors> factors;
    for (const auto &arm : arms)
      {
        const double x = dt / arm.tau;
        if (!std::isfinite(dt))
          factors.push_back({0., 0.});
        else if (x < 1e-8) // avoid 0/0; gamma = 1 - x/2 + O(x^2)
          factors.push_back({std::exp(-x), 1. - 0.5 * x});
        else
          factors.push_back({std::exp(-x), -std::expm1(-x) / x});
      }
    return factors;
  }


  ArmStress
  ViscoelasticSolid::updated_arm_stress(
    const unsigned int           k,
    const ArmStress             &old_h,
    const SymmetricTensor<2, 2> &strain_increment,
    const StepFactors           &f) const
  {
    ArmStress h;
    h.in_plane =
      f.a * old_h.in_plane + f.gamma * (arms[k].C * strain_increment);
    h.zz = f.a * old_h.zz + f.gamma * arms[k].lambda * trace(strain_increment);
    return h;
  }


  SymmetricTensor<2, 2>
  ViscoelasticSolid::stress(const SymmetricTensor<2, 2> &strain,
                            const ArmStress             &h) const
  {
    return C0 * strain + h.in_plane;
  }


  double
  ViscoelasticSolid::stress_zz(const SymmetricTensor<2, 2> &strain,
                               const ArmStress             &h) const
  {
    return lambda0 * trace(strain) + h.zz;
  }


  SymmetricTensor<4, 2>
  ViscoelasticSolid::tangent(const std::vector<StepFactors> &f) const
  {
    SymmetricTensor<4, 2> C = C0;
    for (unsigned int k = 0; k < arms.size(); ++k)
      C += f[k].gamma * arms[k].C;
    return C;
  }


  double
  ViscoelasticSolid::arm_energy(const unsigned int k, const ArmStress &h) const
  {
    if (arms[k].E <= 0.)
      return 0.;
    // h : C^{-1} : h with C^{-1} = ((1 + nu) I - nu 1 x 1)/E in 3D.
    const double hh = h.in_plane * h.in_plane + h.zz * h.zz;
    const double tr = trace(h.in_plane) + h.zz;
    return 0.5 * ((1. + nu) * hh - nu * tr * tr) / arms[k].E;
  }


  ArmStress
  ViscoelasticSolid::arm_stress(const unsigned int           k,
                                const SymmetricTensor<2, 2> &arm_strain) const
  {
    return {arms[k].C * arm_strain, arms[k].lambda * trace(arm_strain)};
  }


  double
  ViscoelasticSolid::dissipation_rate(const unsigned int k,
                                      const ArmStress   &h) const
  {
    return 2. * arm_energy(k, h) / arms[k].tau;
  }


  double
  ViscoelasticSolid::dissipated_energy(const unsigned int k,
                                       const ArmStress   &old_h,
                                       const ArmStress   &new_h,
                                       const double       dt) const
  {
    if (!std::isfinite(dt))
      return arm_energy(k, old_h);
    return 0.5 * dt * (dissipation_rate(k, old_h) + dissipation_rate(k, new_h));
  }


  double
  ViscoelasticSolid::longest_relaxation_time() const
  {
    double longest = 0.;
    for (const auto &arm : arms)
      longest = std::max(longest, arm.tau);
    return longest;
  }
} // namespace viscoslide

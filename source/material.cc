#include <viscoslide/material.h>

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


  StandardLinearSolid::StandardLinearSolid(const double E0,
                                           const double Einf,
                                           const double nu,
                                           const double tau)
    : E1(Einf - E0)
    , nu(nu)
    , tau(tau)
    , lambda0(lame_lambda(E0, nu))
    , lambda1(lame_lambda(E1, nu))
    , C0(plane_strain_stiffness(lambda0, E0 / (2. * (1. + nu))))
    , C1(plane_strain_stiffness(lambda1, E1 / (2. * (1. + nu))))
  {
  }


  StandardLinearSolid::StepFactors
  StandardLinearSolid::step_factors(const double dt) const
  {
    if (!std::isfinite(dt))
      return {0., 0.};
    const double x = dt / tau;
    if (x < 1e-8) // avoid 0/0; gamma = 1 - x/2 + O(x^2)
      return {std::exp(-x), 1. - 0.5 * x};
    return {std::exp(-x), -std::expm1(-x) / x};
  }


  ArmStress
  StandardLinearSolid::updated_arm_stress(
    const ArmStress             &old_h,
    const SymmetricTensor<2, 2> &strain_increment,
    const StepFactors           &f) const
  {
    ArmStress h;
    h.in_plane = f.a * old_h.in_plane + f.gamma * (C1 * strain_increment);
    h.zz       = f.a * old_h.zz + f.gamma * lambda1 * trace(strain_increment);
    return h;
  }


  SymmetricTensor<2, 2>
  StandardLinearSolid::stress(const SymmetricTensor<2, 2> &strain,
                              const ArmStress             &h) const
  {
    return C0 * strain + h.in_plane;
  }


  double
  StandardLinearSolid::stress_zz(const SymmetricTensor<2, 2> &strain,
                                 const ArmStress             &h) const
  {
    return lambda0 * trace(strain) + h.zz;
  }


  SymmetricTensor<4, 2>
  StandardLinearSolid::tangent(const StepFactors &f) const
  {
    return C0 + f.gamma * C1;
  }


  double
  StandardLinearSolid::arm_energy(const ArmStress &h) const
  {
    if (E1 <= 0.)
      return 0.;
    // h : C1^{-1} : h with C1^{-1} = ((1 + nu) I - nu 1 x 1)/E1 in 3D.
    const double hh = h.in_plane * h.in_plane + h.zz * h.zz;
    const double tr = trace(h.in_plane) + h.zz;
    return 0.5 * ((1. + nu) * hh - nu * tr * tr) / E1;
  }


  ArmStress
  StandardLinearSolid::arm_stress(const SymmetricTensor<2, 2> &arm_strain) const
  {
    return {C1 * arm_strain, lambda1 * trace(arm_strain)};
  }


  double
  StandardLinearSolid::dissipation_rate(const ArmStress &h) const
  {
    return 2. * arm_energy(h) / tau;
  }


  double
  StandardLinearSolid::dissipated_energy(const ArmStress &old_h,
                                         const ArmStress &new_h,
                                         const double     dt) const
  {
    if (!std::isfinite(dt))
      return arm_energy(old_h);
    return 0.5 * dt * (dissipation_rate(old_h) + dissipation_rate(new_h));
  }
} // namespace viscoslide

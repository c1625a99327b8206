// Standard linear solid in plane strain: a spring C0 (modulus E0) in
// parallel with a Maxwell arm (spring C1, modulus Einf - E0, in series with
// a dashpot of relaxation time tau). The arm stress h is the history
// variable; its out-of-plane component h_zz is kept because the dissipation
// depends on it (physics.md).
#ifndef viscoslide_material_h
#define viscoslide_material_h

#include <deal.II/base/symmetric_tensor.h>

namespace viscoslide
{
  using namespace dealii;

  // The arm stress at one quadrature point.
  struct ArmStress
  {
    SymmetricTensor<2, 2> in_plane;
    double                zz = 0.;
  };

  class StandardLinearSolid
  {
  public:
    // Young's moduli E0 <= Einf, Poisson ratio nu, arm relaxation time tau.
    StandardLinearSolid(double E0, double Einf, double nu, double tau);

    // Exact exponential integration of dh/dt + h/tau = C1 : deps/dt over a
    // step of length dt with the strain varying linearly: the factors a and
    // gamma of physics.md. dt = infinity is the fully relaxed limit (a =
    // gamma = 0); dt = 0 the instantaneous one (a = gamma = 1).
    struct StepFactors
    {
      double a;
      double gamma;
    };
    StepFactors
    step_factors(double dt) const;

    ArmStress
    updated_arm_stress(const ArmStress             &old_h,
                       const SymmetricTensor<2, 2> &strain_increment,
                       const StepFactors           &factors) const;

    SymmetricTensor<2, 2>
    stress(const SymmetricTensor<2, 2> &strain, const ArmStress &h) const;

    double
    stress_zz(const SymmetricTensor<2, 2> &strain, const ArmStress &h) const;

    // Consistent tangent C0 + gamma C1.
    SymmetricTensor<4, 2>
    tangent(const StepFactors &factors) const;

    // D = h : C1^{-1} : h / tau (3D contraction, >= 0).
    double
    dissipation_rate(const ArmStress &h) const;

    // Energy a step dissipates per unit volume: trapezoidal rule on D for a
    // finite step; for a relaxed step (dt = infinity) all the energy the arm
    // held, since it relaxes completely.
    double
    dissipated_energy(const ArmStress &old_h,
                      const ArmStress &new_h,
                      double           dt) const;

    double
    arm_energy(const ArmStress &h) const;

    // The arm stress C1 : (eps - eps_v) of the steady-state formulation,
    // where the viscous strain eps_v is the unknown. Its out-of-plane
    // component is zero (eps_zz = 0 and eps_v relaxes towards eps), so
    // h_zz = lambda1 tr(eps - eps_v).
    ArmStress
    arm_stress(const SymmetricTensor<2, 2> &arm_strain) const;

    // C1 (in plane) and its Young's modulus Einf - E0.
    const SymmetricTensor<4, 2> &
    arm_stiffness() const
    {
      return C1;
    }
    double
    arm_modulus() const
    {
      return E1;
    }
    double
    relaxation_time() const
    {
      return tau;
    }


  private:
    double                E1, nu, tau;
    double                lambda0, lambda1;
    SymmetricTensor<4, 2> C0, C1;
  };
} // namespace viscoslide

#endif

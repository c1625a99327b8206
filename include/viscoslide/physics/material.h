// SPDX-License-Identifier: LGPL-2.1-or-later
// Generalised Maxwell solid (Prony series) in plane strain: a spring C0
// (modulus E0) in parallel with N Maxwell arms, arm k a spring C_k
// (modulus E_k) in series with a dashpot of relaxation time tau_k, so that
//     E(t) = E0 + sum_k E_k exp(-t/tau_k),   sum_k E_k = Einf - E0.
// One arm is the paper's standard linear solid. The arm stresses h_k are
// the history variables; their out-of-plane components are kept because
// the dissipation depends on them (doc/model.md, Standard linear solid).
#ifndef viscoslide_material_h
#define viscoslide_material_h

#include <deal.II/base/symmetric_tensor.h>

#include <viscoslide/io/input.h>

#include <vector>

namespace viscoslide
{
  using namespace dealii;

  // The stress of one arm (or the sum of several) at one quadrature point.
  struct ArmStress
  {
    SymmetricTensor<2, 2> in_plane;
    double                zz = 0.;

    // Arms in parallel: their stresses add.
    ArmStress &
    operator+=(const ArmStress &other)
    {
      in_plane += other.in_plane;
      zz += other.zz;
      return *this;
    }
  };

  // One term of the Prony series as the user gives it: its share of
  // Einf - E0 (weights are normalised to sum 1) and its relaxation time in
  // units of the reference time tau.
  struct PronyTerm
  {
    double weight;
    double time_ratio;
  };

  class ViscoelasticSolid
  {
  public:
    // Young's moduli E0 <= Einf, Poisson ratio nu (the same for every
    // branch), reference time tau; arm k gets E_k = w_k (Einf - E0) and
    // tau_k = time_ratio_k tau. An empty series is one arm {1, 1}.
    ViscoelasticSolid(double                        E0,
                      double                        Einf,
                      double                        nu,
                      double                        tau,
                      const std::vector<PronyTerm> &series = {});

    unsigned int
    n_arms() const
    {
      return arms.size();
    }

    // Exact exponential integration of dh_k/dt + h_k/tau_k = C_k : deps/dt
    // over a step of length dt with the strain varying linearly: the
    // factors a and gamma of doc/model.md, one pair per arm. dt = infinity
    // is the fully relaxed limit (a = gamma = 0); dt = 0 the instantaneous
    // one (a = gamma = 1).
    struct StepFactors
    {
      double a;
      double gamma;
    };
    std::vector<StepFactors>
    step_factors(double dt) const;

    ArmStress
    updated_arm_stress(unsigned int                 arm,
                       const ArmStress             &old_h,
                       const SymmetricTensor<2, 2> &strain_increment,
                       const StepFactors           &factors) const;

    // Stress from the strain and the sum of the arm stresses.
    SymmetricTensor<2, 2>
    stress(const SymmetricTensor<2, 2> &strain, const ArmStress &h_sum) const;

    double
    stress_zz(const SymmetricTensor<2, 2> &strain,
              const ArmStress             &h_sum) const;

    // Consistent tangent C0 + sum_k gamma_k C_k.
    SymmetricTensor<4, 2>
    tangent(const std::vector<StepFactors> &factors) const;


    // D_k = h_k : C_k^{-1} : h_k / tau_k (3D contraction, >= 0).
    double
    dissipation_rate(unsigned int arm, const ArmStress &h) const;
    // The same for an arm stress of a 3D body.
    double
    dissipation_rate(unsigned int arm, const SymmetricTensor<2, 3> &h) const;

    // C0 and C_k alone (the steady-state solver carries the arms as
    // unknowns): in 2D the in-plane stiffnesses of plane strain, in 3D the
    // whole isotropic ones.
    template <int dim>
    SymmetricTensor<4, dim>
    relaxed_stiffness_of() const;
    template <int dim>
    SymmetricTensor<4, dim>
    arm_stiffness_of(unsigned int arm) const;

    // Energy a step dissipates in one arm per unit volume: trapezoidal
    // rule on D_k for a finite step; for a relaxed step (dt = infinity)
    // all the energy the arm held, since it relaxes completely.
    double
    dissipated_energy(unsigned int     arm,
                      const ArmStress &old_h,
                      const ArmStress &new_h,
                      double           dt) const;

    double
    arm_energy(unsigned int arm, const ArmStress &h) const;

    // The arm stress C_k : (eps - eps_v,k) of the steady-state formulation,
    // where the viscous strain eps_v,k is the unknown. Its out-of-plane
    // component is zero (eps_zz = 0 and eps_v relaxes towards eps), so
    // h_zz = lambda_k tr(eps - eps_v,k).
    ArmStress
    arm_stress(unsigned int arm, const SymmetricTensor<2, 2> &arm_strain) const;

    // Arm k's Young's modulus E_k and relaxation time tau_k.
    double
    arm_modulus(const unsigned int arm) const
    {
      return arms[arm].E;
    }
    double
    relaxation_time(const unsigned int arm) const
    {
      return arms[arm].tau;
    }
    double
    longest_relaxation_time() const;

  private:
    struct Arm
    {
      double                E, tau, lambda;
      SymmetricTensor<4, 2> C;
    };
    double                nu, E0, lambda0;
    SymmetricTensor<4, 2> C0;
    std::vector<Arm>      arms;
  };


  template <>
  SymmetricTensor<4, 2>
  ViscoelasticSolid::relaxed_stiffness_of<2>() const;
  template <>
  SymmetricTensor<4, 3>
  ViscoelasticSolid::relaxed_stiffness_of<3>() const;
  template <>
  SymmetricTensor<4, 2>
  ViscoelasticSolid::arm_stiffness_of<2>(unsigned int arm) const;
  template <>
  SymmetricTensor<4, 3>
  ViscoelasticSolid::arm_stiffness_of<3>(unsigned int arm) const;


  namespace Parameters
  {
    enum class TimeConstant
    {
      relaxation,
      retardation
    };
    VISCOSLIDE_CHOICES(TimeConstant, "relaxation", "retardation")

    // The 'Material' section: the standard linear solid or its Prony
    // series (make_solid() of scales.h builds the solid in internal units).
    struct Material
    {
      // The declared default (units.cc refuses a changed one in SI).
      static constexpr const char *default_E0_over_Einf = "0.1";

      double       E0_over_Einf;
      double       poisson_ratio;
      TimeConstant time_constant;
      // Arms of the generalised Maxwell solid; empty: one arm, the
      // standard linear solid.
      std::vector<PronyTerm> prony_series;

      static void
      declare(ParameterHandler &prm);
      void
      parse(ParameterHandler &prm);
    };
  } // namespace Parameters
} // namespace viscoslide

#endif

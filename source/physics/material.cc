// SPDX-License-Identifier: LGPL-2.1-or-later
#include <viscoslide/physics/material.h>

#include <algorithm>
#include <cmath>
#include <limits>

namespace viscoslide
{
  namespace
  {
    // The isotropic stiffness; in 2D its in-plane part, that of plane
    // strain.
    template <int dim>
    SymmetricTensor<4, dim>
    isotropic_stiffness(const double lambda, const double mu)
    {
      return lambda * outer_product(unit_symmetric_tensor<dim>(),
                                    unit_symmetric_tensor<dim>()) +
             2. * mu * identity_tensor<dim>();
    }

    SymmetricTensor<4, 2>
    plane_strain_stiffness(const double lambda, const double mu)
    {
      return isotropic_stiffness<2>(lambda, mu);
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
    , E0(E0)
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
  ViscoelasticSolid::dissipation_rate(const unsigned int           k,
                                      const SymmetricTensor<2, 3> &h) const
  {
    if (arms[k].E <= 0.)
      return 0.;
    // 2 (h : C^{-1} : h)/2 / tau with C^{-1} as in arm_energy().
    const double tr = trace(h);
    return ((1. + nu) * (h * h) - nu * tr * tr) / arms[k].E / arms[k].tau;
  }


  template <>
  SymmetricTensor<4, 2>
  ViscoelasticSolid::relaxed_stiffness_of<2>() const
  {
    return C0;
  }


  template <>
  SymmetricTensor<4, 3>
  ViscoelasticSolid::relaxed_stiffness_of<3>() const
  {
    return isotropic_stiffness<3>(lambda0, E0 / (2. * (1. + nu)));
  }


  template <>
  SymmetricTensor<4, 2>
  ViscoelasticSolid::arm_stiffness_of<2>(const unsigned int k) const
  {
    return arms[k].C;
  }


  template <>
  SymmetricTensor<4, 3>
  ViscoelasticSolid::arm_stiffness_of<3>(const unsigned int k) const
  {
    return isotropic_stiffness<3>(arms[k].lambda, arms[k].E / (2. * (1. + nu)));
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


  namespace Parameters
  {
    namespace
    {
      // A Prony term's weight and time must be positive and finite; where
      // names the list or the file row.
      PronyTerm
      prony_term(const double       weight,
                 const double       time_ratio,
                 const std::string &where)
      {
        require(std::isfinite(weight) && weight > 0,
                where + ": the weight must be a positive number");
        require(std::isfinite(time_ratio) && time_ratio > 0,
                where + ": the relaxation time must be a positive number");
        return {weight, time_ratio};
      }

      std::vector<PronyTerm>
      prony_series_from_lists(const std::string &weights,
                              const std::string &times)
      {
        const auto w = Utilities::split_string_list(weights);
        const auto t = Utilities::split_string_list(times);
        require(w.size() == t.size(),
                "'Material/Prony weights' has " + std::to_string(w.size()) +
                  " entries and 'Material/Prony relaxation times' " +
                  std::to_string(t.size()) + ": one of each per arm");
        std::vector<PronyTerm> series;
        for (unsigned int k = 0; k < w.size(); ++k)
          series.push_back(
            prony_term(to_number(w[k]),
                       to_number(t[k]),
                       "'Material/Prony weights' = " + weights +
                         ", 'Prony relaxation times' = " + times + ", arm " +
                         std::to_string(k + 1)));
        return series;
      }

      std::vector<PronyTerm>
      prony_series_from_file(const std::string &filename)
      {
        const auto columns =
          read_csv_columns(filename,
                           {"weight", "tau_over_tau"},
                           "'Material/Prony file' = " + filename);
        std::vector<PronyTerm> series;
        for (unsigned int k = 0; k < columns[0].size(); ++k)
          series.push_back(prony_term(columns[0][k],
                                      columns[1][k],
                                      "'Material/Prony file' = " + filename +
                                        ", arm " + std::to_string(k + 1)));
        require(!series.empty(),
                "'Material/Prony file' = " + filename + ": no arm in the file");
        return series;
      }
    } // namespace


    void
    Material::declare(ParameterHandler &prm)
    {
      prm.enter_subsection("Material");
      prm.declare_entry("E0 over Einf",
                        default_E0_over_Einf,
                        Patterns::Double(),
                        "Ratio of the relaxed (low-frequency) to the "
                        "instantaneous (high-frequency) Young's modulus of "
                        "the standard linear solid, in (0, 1]. 1 makes the "
                        "material elastic. Einf < E0 is unphysical and "
                        "refused.");
      prm.declare_entry("Poisson ratio",
                        "0.49",
                        Patterns::Double(),
                        "Poisson ratio, the same for both branches, in "
                        "[0, 0.5).");
      prm.declare_entry(
        "Time constant",
        "relaxation",
        Patterns::Selection(choice_pattern<TimeConstant>()),
        "Which time constant tau makes V_hat = V tau/eps and time_over_tau "
        "dimensionless. 'relaxation': tau is the relaxation time of the "
        "Maxwell arm, E(t) = E0 + (Einf - E0) exp(-t/tau) (the paper's "
        "wording). 'retardation': tau is the creep (retardation) time "
        "tau_c = tau_relaxation Einf/E0 of J(t) = 1/E0 - (1/E0 - 1/Einf) "
        "exp(-t/tau_c). The choice is written into every output file.");
      prm.declare_entry(
        "Prony weights",
        "",
        Patterns::Anything(),
        "Generalised Maxwell solid (Prony series): a comma-separated list of "
        "positive weights w_k, one per Maxwell arm. Arm k carries the "
        "modulus E_k = w_k (Einf - E0) / sum(w), so 'E0 over Einf' still "
        "fixes the slow and fast limits and the weights only share out "
        "Einf - E0; measured moduli E_k (in any unit) may be given as they "
        "are. Empty (default): one arm, the standard linear solid of the "
        "paper. Needs 'Prony relaxation times' of the same length; not "
        "together with 'Prony file'.");
      prm.declare_entry(
        "Prony relaxation times",
        "",
        Patterns::Anything(),
        "The relaxation times tau_k/tau of the arms of 'Prony weights', "
        "positive, in units of the reference time tau of V_hat and "
        "time_over_tau. E(t) = E0 + sum_k E_k exp(-t/tau_k).");
      prm.declare_entry(
        "Prony file",
        "",
        Patterns::Anything(),
        "The Prony series as a CSV file (path relative to the working "
        "directory; lines starting with # are comments) with a header "
        "naming the columns weight and tau_over_tau, one arm per row: a "
        "measured relaxation spectrum (weights as 'Prony weights', times "
        "as 'Prony relaxation times'). Empty: the lists above.");
      prm.leave_subsection();
    }

    void
    Material::parse(ParameterHandler &prm)
    {
      prm.enter_subsection("Material");
      E0_over_Einf  = prm.get_double("E0 over Einf");
      poisson_ratio = prm.get_double("Poisson ratio");
      time_constant = parse_choice<TimeConstant>(prm.get("Time constant"),
                                                 "Material/Time constant");
      const std::string weights = prm.get("Prony weights"),
                        times   = prm.get("Prony relaxation times"),
                        file    = prm.get("Prony file");
      prm.leave_subsection();
      require(file.empty() || (weights.empty() && times.empty()),
              "'Material/Prony file' and 'Material/Prony weights' or "
              "'Material/Prony relaxation times' are both set: give the "
              "series one way");
      prony_series = file.empty() ? prony_series_from_lists(weights, times)
                                  : prony_series_from_file(file);
      require(prony_series.size() <= 1 ||
                time_constant == TimeConstant::relaxation,
              "'Material/Time constant' = retardation is defined for one "
              "Maxwell arm only; a Prony series needs relaxation");
      require(E0_over_Einf > 0 && E0_over_Einf <= 1,
              entry("Material", "E0 over Einf", E0_over_Einf) +
                " is outside (0, 1]: Einf must not be smaller than E0");
      require(poisson_ratio >= 0 && poisson_ratio < 0.5,
              entry("Material", "Poisson ratio", poisson_ratio) +
                " is outside [0, 0.5)");
    }
  } // namespace Parameters
} // namespace viscoslide

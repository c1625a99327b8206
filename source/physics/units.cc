// SPDX-License-Identifier: LGPL-2.1-or-later
#include <viscoslide/io/parameters.h>
#include <viscoslide/physics/units.h>

#include <algorithm>
#include <cmath>
#include <sstream>

namespace viscoslide
{
  namespace Parameters
  {
    namespace
    {
      constexpr double gas_constant = 8.314462618; // J/(mol K)
      constexpr double zero_celsius = 273.15;      // K

      // The speeds of a list as text, for the notes.
      std::string
      list(const std::vector<double> &values)
      {
        std::ostringstream s;
        for (std::size_t i = 0; i < values.size(); ++i)
          s << (i ? ", " : "") << values[i];
        return s.str();
      }

      // An entry SI replaces must keep its default, else the file gives
      // one number two ways.
      void
      require_default(const bool         is_default,
                      const std::string &entry,
                      const std::string &instead)
      {
        require(is_default,
                "'" + entry +
                  "' is set in a file with 'Units/System' = SI: give " +
                  instead + " in the Units section instead");
      }
    } // namespace


    void
    Units::declare(ParameterHandler &prm)
    {
      prm.enter_subsection("Units");
      prm.declare_entry(
        "System",
        "dimensionless",
        Patterns::Selection(choice_pattern<UnitSystem>()),
        "'dimensionless': every entry in the reduced units of "
        "doc/conventions.md. 'SI': the material and the contact are given "
        "below in SI units; Sliding/Sliding speed and the speeds of "
        "Sliding/Program are then in m/s, the Program's rests in s, "
        "Loading/Target load, Sweep/Loads and the loads of Sliding/Load "
        "path in N/m (2D, per unit length of the cylinder) or N (3D). "
        "Lengths of the block and the mesh, approaches and distances stay "
        "in eps. The program prints the dimensionless numbers it derives "
        "and writes SI columns beside the dimensionless ones in every "
        "table. Material/E0 over Einf, Adhesion/Tabor parameter and R "
        "over eps are then derived and must not be set.");
      prm.declare_entry("Relaxed modulus",
                        "0",
                        Patterns::Double(),
                        "SI: E0, the relaxed (rubbery) Young's modulus, Pa.");
      prm.declare_entry(
        "Instantaneous modulus",
        "0",
        Patterns::Double(),
        "SI: Einf, the instantaneous (glassy) Young's modulus of the "
        "standard linear solid, Pa. With a Material/Prony file, leave it "
        "0: the file's weights are then the arms' moduli E_k in Pa (as "
        "scripts/dma writes them) and Einf = E0 + sum E_k.");
      prm.declare_entry(
        "Time constant",
        "1",
        Patterns::Double(),
        "SI: in seconds, the time unit tau of V_hat = V tau/eps: the "
        "standard linear solid's time constant (relaxation or retardation, "
        "as Material/Time constant says), or with a Prony file the unit of "
        "its tau_over_tau column (1: its times are in seconds).");
      prm.declare_entry("Radius",
                        "0",
                        Patterns::Double(),
                        "SI: R, the indenter's radius (of curvature at the "
                        "apex), m.");
      prm.declare_entry("Work of adhesion",
                        "0",
                        Patterns::Double(),
                        "SI: dgamma, J/m^2.");
      prm.declare_entry("Interaction range",
                        "0",
                        Patterns::Double(),
                        "SI: eps, the range of the traction law (the "
                        "equilibrium gap of Lennard-Jones), m.");
      prm.declare_entry(
        "Temperature",
        "20",
        Patterns::Double(),
        "Degrees Celsius, both systems: the material's relaxation times "
        "are those at the Reference temperature times the shift factor "
        "a_T of the Shift law (time-temperature superposition; the moduli "
        "are not shifted). Sweep/Temperatures sweeps it.");
      prm.declare_entry("Reference temperature",
                        "20",
                        Patterns::Double(),
                        "Degrees Celsius: where the material's times were "
                        "given (the master curve's reference).");
      prm.declare_entry(
        "Shift law",
        "none",
        Patterns::Selection(choice_pattern<ShiftLaw>()),
        "'WLF': log10 a_T = -C1 (T - T_ref)/(C2 + T - T_ref). "
        "'Arrhenius': log10 a_T = Ea/(R ln 10) (1/T - 1/T_ref), T in K. "
        "'none': a_T = 1 (the temperature is not used). scripts/dma fits "
        "both to a DMA measurement.");
      prm.declare_entry("WLF C1", "8.86", Patterns::Double(), "WLF C1.");
      prm.declare_entry("WLF C2", "101.6", Patterns::Double(), "WLF C2, K.");
      prm.declare_entry("Activation energy",
                        "0",
                        Patterns::Double(),
                        "Arrhenius Ea, J/mol.");
      prm.leave_subsection();
    }


    void
    Units::parse(ParameterHandler &prm)
    {
      prm.enter_subsection("Units");
      system = parse_choice<UnitSystem>(prm.get("System"), "Units/System");
      relaxed_modulus       = prm.get_double("Relaxed modulus");
      instantaneous_modulus = prm.get_double("Instantaneous modulus");
      time_constant         = prm.get_double("Time constant");
      radius                = prm.get_double("Radius");
      work_of_adhesion      = prm.get_double("Work of adhesion");
      range                 = prm.get_double("Interaction range");
      temperature           = prm.get_double("Temperature");
      reference_temperature = prm.get_double("Reference temperature");
      shift_law =
        parse_choice<ShiftLaw>(prm.get("Shift law"), "Units/Shift law");
      wlf_c1            = prm.get_double("WLF C1");
      wlf_c2            = prm.get_double("WLF C2");
      activation_energy = prm.get_double("Activation energy");
      prm.leave_subsection();
      for (const auto &[name, value] :
           {std::pair{"Temperature", temperature},
            std::pair{"Reference temperature", reference_temperature}})
        require(value > -zero_celsius && std::isfinite(value),
                entry("Units", name, value) +
                  " must be a finite temperature above absolute zero "
                  "(degrees Celsius)");
      require(shift_law != ShiftLaw::arrhenius || activation_energy > 0,
              entry("Units", "Activation energy", activation_energy) +
                " must be positive for the Arrhenius shift law");
      require(shift_law != ShiftLaw::wlf || (wlf_c1 > 0 && wlf_c2 > 0),
              "'Units/WLF C1' = " + num(wlf_c1) +
                " and 'WLF C2' = " + num(wlf_c2) + " must be positive");
      if (system == UnitSystem::si)
        for (const auto &[name, value] :
             {std::pair{"Relaxed modulus", relaxed_modulus},
              std::pair{"Time constant", time_constant},
              std::pair{"Radius", radius},
              std::pair{"Work of adhesion", work_of_adhesion},
              std::pair{"Interaction range", range}})
          require(value > 0 && std::isfinite(value),
                  entry("Units", name, value) +
                    " must be positive with 'Units/System' = SI");
      // The shift law's own range, checked at once.
      log_shift_factor(temperature);
    }


    double
    Units::log_shift_factor(const double T) const
    {
      const double dT = T - reference_temperature;
      switch (shift_law)
        {
          case ShiftLaw::wlf:
            require(wlf_c2 + dT > 0,
                    entry("Units", "Temperature", T) +
                      " lies at or below the WLF asymptote T_ref - C2 = " +
                      num(reference_temperature - wlf_c2) +
                      " C, where the law has no meaning");
            return -wlf_c1 * dT / (wlf_c2 + dT);
          case ShiftLaw::arrhenius:
            return activation_energy / (gas_constant * std::log(10.)) *
                   (1. / (T + zero_celsius) -
                    1. / (reference_temperature + zero_celsius));
          default:
            return 0.;
        }
    }


    std::vector<CsvTable::Derived>
    Units::si_columns(const int dimension) const
    {
      if (system != UnitSystem::si)
        return {};
      const std::string per  = dimension == 3 ? "" : "_per_m";
      const double      rate = force * length / time;
      return {{"V_hat", "V_m_per_s", length / time},
              {"time_over_tau", "time_s", time},
              {"s_over_eps", "s_m", length},
              {"delta_hat", "delta_m", length},
              {"t_hat", "t_m", length},
              {"F_n_hat", "F_n_N" + per, force},
              {"F_t_hat", "F_t_N" + per, force},
              {"F_t_contact_set_hat", "F_t_contact_set_N" + per, force},
              {"L_hat", "L_m", contact},
              {"A_hat", "A_m2", contact},
              {"dissipation_rate_hat", "dissipation_rate_W" + per, rate},
              {"x_over_R", "x_m", radius},
              {"x_trail_over_R", "x_trail_m", radius},
              {"x_lead_over_R", "x_lead_m", radius},
              {"y_half_over_R", "y_half_m", radius},
              {"gap_over_eps", "gap_m", length},
              {"min_gap_over_eps", "min_gap_m", length},
              {"u_y_over_eps", "u_y_m", length},
              {"p_hat", "p_Pa", pressure}};
    }


    namespace
    {
      // A measured spectrum spans more decades than a case can see. In a
      // steady state at speeds V_min..V_max (V_hat) through a block or
      // window W eps wide, an arm with V_max tau_k < 1e-4 eps relaxes
      // within 1e-4 of the time the material takes to cross an eps: its
      // stress is negligible and the arm is dropped. An arm with
      // V_min tau_k > 1e4 W relaxes by less than 1e-4 while the material
      // crosses the block: it is a spring, added to the relaxed modulus
      // (the steady state does not depend on the relaxed start it is
      // continued from). Returns that modulus, E0 plus the springs (the
      // weights in Pa); the case's notes say what was done. The transient
      // solver, which starts from the relaxed approach, keeps every arm.
      double
      trim_spectrum(AllParameters &p)
      {
        auto        &series = p.material.prony_series;
        const auto  &speeds = p.sliding.speeds;
        const double E0     = p.units.relaxed_modulus;
        if (p.sliding.solver == SlidingSolver::transient || series.size() < 2 ||
            *std::min_element(speeds.begin(), speeds.end()) <= 0)
          return E0;
        const double V_min = *std::min_element(speeds.begin(), speeds.end());
        const double V_max = *std::max_element(speeds.begin(), speeds.end());
        const double fast  = 1e-4 / V_max,
                     slow  = 1e4 * p.geometry.domain_width / V_min;
        double                 springs = 0.;
        std::vector<PronyTerm> kept;
        unsigned int           dropped = 0, stiffened = 0;
        for (const auto &term : series)
          if (term.time_ratio < fast)
            ++dropped;
          else if (term.time_ratio > slow)
            {
              springs += term.weight;
              ++stiffened;
            }
          else
            kept.push_back(term);
        if (dropped + stiffened == 0)
          return E0;
        require(!kept.empty(),
                "the Prony series has no arm between the times the speeds "
                "see (" +
                  num(fast * p.units.time_constant) + " to " +
                  num(slow * p.units.time_constant) +
                  " s): at these speeds the solid is elastic");
        series = kept;
        std::ostringstream note;
        note << "Prony series: of its " << kept.size() + dropped + stiffened
             << " arms, " << dropped << " faster than "
             << fast * p.units.time_constant
             << " s are relaxed at every speed and left out, " << stiffened
             << " slower than " << slow * p.units.time_constant
             << " s never relax in the block and act as springs: the "
                "relaxed modulus the case sees is "
             << E0 + springs << " Pa (E0 " << E0 << " Pa); " << kept.size()
             << " arms kept";
        p.notes.push_back(note.str());
        return E0 + springs;
      }


      // The reduced entries that SI units derive must be left at their
      // defaults.
      void
      require_reduced_defaults(const AllParameters &p)
      {
        using Parameters::Adhesion;
        using Parameters::Material;
        require_default(p.material.E0_over_Einf ==
                          std::stod(Material::default_E0_over_Einf),
                        "Material/E0 over Einf",
                        "Relaxed modulus and Instantaneous modulus");
        require_default(p.adhesion.tabor_parameter ==
                            std::stod(Adhesion::default_tabor_parameter) &&
                          p.sweep.tabor_parameters.empty(),
                        "Adhesion/Tabor parameter",
                        "Radius, Work of adhesion and Interaction range");
        require_default(p.adhesion.R_over_eps ==
                          std::stod(Adhesion::default_R_over_eps),
                        "Adhesion/R over eps",
                        "Radius and Interaction range");
      }


      // The relaxed and instantaneous moduli (Pa) of the SI material:
      // E0/Einf set, E0 returned.
      double
      convert_moduli(AllParameters &p, const bool spectrum)
      {
        const Units &u = p.units;
        // A Prony series' weights are the arms' moduli in Pa.
        auto  &series = p.material.prony_series;
        double E0     = u.relaxed_modulus;
        require(spectrum != (u.instantaneous_modulus > 0),
                spectrum
                  ? "'Units/Instantaneous modulus' is set together with a "
                    "Prony series: its moduli (Pa) fix Einf, leave it 0"
                  : entry("Units",
                          "Instantaneous modulus",
                          u.instantaneous_modulus) +
                      " must be positive for a standard linear solid");
        double Einf = u.instantaneous_modulus;
        if (spectrum)
          {
            // The weights share out Einf - E0 (Material): Einf is that of
            // the arms the case keeps.
            E0   = trim_spectrum(p);
            Einf = E0;
            for (const auto &term : series)
              Einf += term.weight;
          }
        require(Einf >= E0,
                entry("Units", "Instantaneous modulus", Einf) +
                  " Pa lies below the Relaxed modulus " + num(E0) + " Pa");
        p.material.E0_over_Einf = E0 / Einf;
        return E0;
      }


      // The SI material and contact of `u` in reduced units, and the SI
      // values of the reduced units in `u`; notes what it derived.
      void
      convert_from_si(AllParameters &p, const bool spectrum)
      {
        Units       &u = p.units;
        const double R = u.radius, eps = u.range, dgamma = u.work_of_adhesion;
        const std::vector<double> si_speeds = p.sliding.speeds;
        for (double &V : p.sliding.speeds)
          V *= u.time_constant / eps;
        p.sliding.speed = p.sliding.speeds.back();
        for (auto &segment : p.sliding.program)
          if (segment.rest())
            segment.length /= u.time_constant; // s to tau
          else
            segment.speed *= u.time_constant / eps;
        require_reduced_defaults(p);
        const double E0 = convert_moduli(p, spectrum);

        const double nu            = p.material.poisson_ratio;
        const double E0_star       = E0 / (1. - nu * nu);
        p.adhesion.R_over_eps      = R / eps;
        p.adhesion.tabor_parameter = std::cbrt(
          R * dgamma * dgamma / (E0_star * E0_star * eps * eps * eps));
        require(p.adhesion.R_over_eps >= 10,
                "'Units/Radius' over 'Units/Interaction range' is " +
                  num(p.adhesion.R_over_eps) +
                  ": R/eps must be at least 10 (Derjaguin approximation)");

        // The reduced units in SI (Scales::force and Scales::contact).
        const bool three_d = p.geometry.dimension == 3;
        u.length           = eps;
        u.time             = u.time_constant;
        u.force            = three_d ? 1.5 * M_PI * dgamma * R
                                     : std::cbrt(M_PI * dgamma * dgamma * E0_star * R);
        u.contact          = three_d ? M_PI * R * eps : R;
        u.pressure         = 16. * dgamma / (9. * std::sqrt(3.) * eps);
        const std::string force_unit = three_d ? " N" : " N/m";

        if (p.sliding.control != Control::displacement)
          for (double &F : p.sliding.load_path)
            F /= u.force;
        const double si_load = p.loading.target_load;
        if (p.loading.has_target_load())
          p.loading.target_load /= u.force;

        std::ostringstream note;
        note << "SI units: E0* = E0/(1 - nu^2) = " << E0_star
             << " Pa, E0/Einf = " << p.material.E0_over_Einf
             << ", R_hat = R/eps = " << p.adhesion.R_over_eps
             << ", muT = " << p.adhesion.tabor_parameter << "; V_hat = V/("
             << u.length / u.time << " m/s) = " << list(p.sliding.speeds)
             << " from " << list(si_speeds) << " m/s";
        if (p.loading.has_target_load())
          note << "; F_hat = F/(" << u.force << force_unit
               << ") = " << p.loading.target_load << " from " << si_load
               << force_unit;
        p.notes.push_back(note.str());
      }
    } // namespace


    void
    apply_units(AllParameters &p)
    {
      Units     &u        = p.units;
      const bool spectrum = !p.material.prony_series.empty();
      // a_T moves every arm's time (one arm {1, 1}: the standard linear
      // solid).
      u.shift_factor = std::pow(10., u.log_shift_factor(u.temperature));
      if (u.shift_factor != 1.)
        {
          if (!spectrum)
            p.material.prony_series = {{1., 1.}};
          for (auto &term : p.material.prony_series)
            term.time_ratio *= u.shift_factor;
          std::ostringstream note;
          note << "Temperature " << u.temperature
               << " C: the relaxation times are those at "
               << u.reference_temperature << " C times a_T = " << u.shift_factor
               << " (" << to_string(u.shift_law) << ")";
          p.notes.push_back(note.str());
        }
      if (u.system == UnitSystem::si)
        convert_from_si(p, spectrum);
    }
  } // namespace Parameters
} // namespace viscoslide

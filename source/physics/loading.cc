// SPDX-License-Identifier: LGPL-2.1-or-later
#include <deal.II/base/utilities.h>

#include <viscoslide/physics/loading.h>

#include <algorithm>
#include <cmath>
#include <limits>

namespace viscoslide
{
  namespace Parameters
  {
    void
    Loading::declare(ParameterHandler &prm)
    {
      prm.enter_subsection("Loading");
      prm.declare_entry("Initial approach",
                        "-2",
                        Patterns::Double(),
                        "delta_hat at the start: the apex is at a gap of "
                        "1 - delta_hat eps from the undeformed surface.");
      prm.declare_entry("Final approach",
                        "3",
                        Patterns::Double(),
                        "delta_hat reached at the end of the approach "
                        "(displacement control).");
      prm.declare_entry("Approach increment",
                        "0.1",
                        Patterns::Double(),
                        "Increment of delta_hat per step. Steps are halved "
                        "automatically when Newton fails.");
      prm.declare_entry("Minimum increment",
                        "1e-3",
                        Patterns::Double(),
                        "Smallest increment step cutting may reach; below it "
                        "a surface instability (jump-in, jump-out) is "
                        "assumed and the new branch is found by damped "
                        "relaxation.");
      prm.declare_entry("Approach speed",
                        "0",
                        Patterns::Double(),
                        "Normal speed V_n tau/eps. 0 means quasi-static: "
                        "every step is fully relaxed (modulus E0).");
      prm.declare_entry("Hold time",
                        "0",
                        Patterns::Double(),
                        "After the approach, hold delta for this time "
                        "(in tau) while the material relaxes.");
      prm.declare_entry("Hold steps",
                        "20",
                        Patterns::Integer(1),
                        "Time steps of the hold, spaced geometrically from "
                        "1e-3 tau so that the relaxation is resolved.");
      prm.declare_entry(
        "Target load",
        "",
        Patterns::Anything(),
        "F_hat to reach instead of Final approach: the approach goes on "
        "in steps of Approach increment until F_n passes this value (after "
        "contact is made), and that step is then solved with F_n held at "
        "exactly this load. Negative values are tensile loads; they must "
        "lie above the pull-off force. Final approach then only bounds the "
        "search. Empty: no target, the approach ends at Final approach.");
      prm.declare_entry("Retract",
                        "false",
                        Patterns::Bool(),
                        "After approach (and hold) retract to Retract to, "
                        "completing a loading-unloading cycle; the minimum "
                        "force on the way is the pull-off force. Without "
                        "sliding (Sliding speed = 0) with every solver; "
                        "the boundary elements retract quasi-statically.");
      prm.declare_entry("Retract to",
                        "-3",
                        Patterns::Double(),
                        "delta_hat at the end of the retraction.");
      prm.leave_subsection();
    }

    void
    Loading::parse(ParameterHandler &prm)
    {
      prm.enter_subsection("Loading");
      initial_approach       = prm.get_double("Initial approach");
      final_approach         = prm.get_double("Final approach");
      increment              = prm.get_double("Approach increment");
      minimum_increment      = prm.get_double("Minimum increment");
      approach_speed         = prm.get_double("Approach speed");
      hold_time              = prm.get_double("Hold time");
      hold_steps             = prm.get_integer("Hold steps");
      retract                = prm.get_bool("Retract");
      retract_to             = prm.get_double("Retract to");
      const std::string load = prm.get("Target load");
      prm.leave_subsection();
      target_load = std::numeric_limits<double>::quiet_NaN();
      if (!dealii::Utilities::trim(load).empty())
        {
          target_load = to_number(load);
          require(std::isfinite(target_load),
                  "'Loading/Target load' = " + load +
                    " is not a finite number");
        }
      require(increment > 0,
              entry("Loading", "Approach increment", increment) +
                " must be positive");
      require(minimum_increment > 0 && minimum_increment <= increment,
              entry("Loading", "Minimum increment", minimum_increment) +
                " must be positive and not above the Approach increment");
      require(approach_speed >= 0,
              entry("Loading", "Approach speed", approach_speed) +
                " must not be negative");
      require(hold_time >= 0,
              entry("Loading", "Hold time", hold_time) +
                " must not be negative");
      require(final_approach >= initial_approach,
              entry("Loading", "Final approach", final_approach) +
                " is below the Initial approach");
      require(!retract || retract_to < final_approach,
              entry("Loading", "Retract to", retract_to) +
                " must be below the Final approach");
    }


    namespace
    {
      // The speeds, the control of the load and the solver.
      void
      declare_motion(ParameterHandler &prm)
      {
        prm.declare_entry(
          "Sliding speed",
          "0",
          Patterns::List(Patterns::Double(), 1),
          "V_hat = V tau/eps of the sliding phase that follows the approach "
          "(and hold); the indenter profile moves towards +x over the fixed "
          "surface. 0: no sliding. A comma-separated list of positive "
          "speeds is a sweep: the steady-state solver visits them in the "
          "order given by one continuation (each speed starts from the "
          "solution of the one before), the transient solver runs each as a "
          "case of its own; either way one row per speed in "
          "steady_state.csv.");
        prm.declare_entry(
          "Control",
          "displacement",
          Patterns::Selection(choice_pattern<Control>()),
          "'displacement': delta stays at its value after the approach and Fn "
          "is an output. 'force': Fn stays at the value reached at the end of "
          "the approach and delta is an unknown solved with the displacements. "
          "'spring': the indenter hangs on a vertical spring of stiffness "
          "Spring stiffness whose far end stays where it was at the end of "
          "the approach, so Fn = F0 + k (delta0 - delta) with F0, delta0 "
          "those of the approach; between force control (k -> 0) and "
          "displacement control (k -> infinity), like a real tribometer.");
        prm.declare_entry(
          "Spring stiffness",
          "1",
          Patterns::Double(),
          "Control = spring: k_hat = dF_hat/d delta_hat, the spring's force "
          "(per unit length, in (pi dgamma^2 E0* R)^(1/3)) per eps of "
          "approach. For scale: the contact's own stiffness dF_hat/d "
          "delta_hat is about 0.35 at muT = 1, R_hat = 1e4, F_hat = 1.");
        prm.declare_entry(
          "Solver",
          "transient",
          Patterns::Selection(choice_pattern<SlidingSolver>()),
          "'transient': the moving-profile time stepping of the paper until "
          "steady state. 'steady-state': the steady sliding state solved "
          "directly in the frame of the indenter (doc/steady_state.md), with "
          "continuation in V_hat from the relaxed state of the approach; "
          "no history.csv, no retraction afterwards. 'boundary-element': the "
          "same steady states of a periodic half-plane or bonded layer from "
          "the surface compliance alone, applied by FFT on a uniform grid "
          "(doc/boundary_element.md, section Boundary element): no mesh, "
          "no fields, an independent check of the finite elements.");
      }


      // The transient solver's sliding: its steps, its steady state, its
      // programs.
      void
      declare_transient(ParameterHandler &prm)
      {
        prm.declare_entry(
          "Sliding increment",
          "1",
          Patterns::Double(),
          "Sliding distance per time step, in finest surface "
          "cells (Mesh/Finest surface cell); dt = increment/V.");
        prm.declare_entry(
          "Maximum sliding distance",
          "0",
          Patterns::Double(),
          "Stop sliding after this distance (in eps) even "
          "without steady state (then steady = 0). 0: "
          "automatic, 4 L + 30 min(V tau_c, 4 L) with L the "
          "contact length after the approach and tau_c the "
          "retardation time; refused if the indenter would come closer "
          "than 2 L to the lateral boundary.");
        prm.declare_entry(
          "Steady-state tolerance",
          "1e-3",
          Patterns::Double(),
          "Steady state: the means of Fn (or delta under force control), Ft "
          "and L_hat over the two halves of the last Steady-state window of "
          "sliding differ by less than this, relative to their magnitude (Ft: "
          "to max(|Ft|, 1e-3 |Fn|)). The steady values in steady_state.csv "
          "are the means over that window: with adhesion the contact edges "
          "jump from node to node and Ft flickers about its mean.");
        prm.declare_entry(
          "Energy balance tolerance",
          "5e-3",
          Patterns::Double(),
          "The transient declares a steady state only when, besides the "
          "window test of Steady-state tolerance, the work of the x force on "
          "the indenter balances the dissipation over the window to this "
          "fraction: |F_t V / D - 1| <= tolerance (not judged where "
          "mu_energy < 1e-3, the elastic limits). A coarse mesh leaves the "
          "balance off by about 1 % even once the window has settled.");
        prm.declare_entry("Steady-state window",
                          "0",
                          Patterns::Double(),
                          "Sliding distance (eps) over which steady state is "
                          "judged and its values averaged. 0: automatic, "
                          "max(L, 2 min(V tau_c, 4 L)); the cap at 4 L can "
                          "accept a state a few % from steady when V tau_c "
                          "is much longer than L (doc/steady_state.md): set "
                          "V tau_c or more for 1 %.");
        prm.declare_entry(
          "Program",
          "",
          Patterns::Anything(),
          "Transient solver: a sliding program instead of sliding to the "
          "steady state, as segments separated by ';', each 'slide V for D' "
          "(V_hat, negative to slide back towards -x, over D eps) or 'rest "
          "for T' (the indenter held for T tau, under the control of "
          "Sliding/Control): e.g. 'slide 1 for 400; rest for 100; slide 1 "
          "for 400' (a start, a stop and a restart after a dwell) or 'slide "
          "1 for 200; slide -1 for 200' with Program repeats = 5 (five "
          "reciprocating strokes). history.csv gets a row per step; no row "
          "in steady_state.csv. Empty: slide at the Sliding speed to the "
          "steady state.");
        prm.declare_entry("Program repeats",
                          "1",
                          Patterns::Integer(),
                          "How many times the Program runs in a row.");
      }


      // The steady-state solvers' continuation in speed and load.
      void
      declare_steady_state(ParameterHandler &prm)
      {
        prm.declare_entry("Continuation factor",
                          "4",
                          Patterns::Double(),
                          "Steady-state solver: largest ratio between two "
                          "successive speeds of the continuation from the "
                          "relaxed state to Sliding speed (halved in log "
                          "scale when Newton fails). It starts at the speed "
                          "whose relaxation length V tau, of the slowest arm, "
                          "is a tenth of the finest surface cell.");
        prm.declare_entry("Viscous strain degree",
                          "1",
                          Patterns::Integer(),
                          "Steady-state solver: polynomial degree of the "
                          "discontinuous viscous strain field (FE_DGQ). The "
                          "arm sees the L2 projection of eps(u) onto this "
                          "space (doc/steady_state.md); 1 agrees with 2 to "
                          "0.03 % in mu in the Hunter test at a fifth of the "
                          "cost.");
        prm.declare_entry(
          "Load path",
          "",
          Patterns::List(Patterns::Anything(), 0),
          "Steady-state solver: after the last listed speed, follow the "
          "steady state at that speed through these loads, in the order "
          "given, by continuation (each from the solution of the one before, "
          "in steps halved where Newton fails): F_hat values under force "
          "control (spring control: the spring's force at the approach's "
          "delta), delta_hat values under displacement control. One row per "
          "load in steady_state.csv, after the speeds' rows. Follows a "
          "branch, e.g. a sliding contact unloaded towards pull-off. Empty: "
          "none.");
      }
    } // namespace


    void
    Sliding::declare(ParameterHandler &prm)
    {
      prm.enter_subsection("Sliding");
      declare_motion(prm);
      declare_transient(prm);
      declare_steady_state(prm);
      prm.leave_subsection();
    }

    namespace
    {
      // 'Sliding/Program' as segments, each checked; the message names
      // the segment.
      std::vector<ProgramSegment>
      parse_program(const std::string &text, const int repeats)
      {
        std::vector<ProgramSegment> program;
        if (text.empty())
          return program;
        require(repeats >= 1,
                entry("Sliding", "Program repeats", repeats) +
                  " must be at least 1");
        const auto segments = Utilities::split_string_list(text, ';');
        for (unsigned int k = 0; k < segments.size(); ++k)
          {
            ProgramSegment    segment{0., 0., segments[k]};
            const std::string where = segment.name(k);
            const auto words = Utilities::split_string_list(segments[k], ' ');
            const bool slide =
              words.size() == 4 && words[0] == "slide" && words[2] == "for";
            const bool rest =
              words.size() == 3 && words[0] == "rest" && words[1] == "for";
            require(slide || rest,
                    where + ": a segment is 'slide V for D' or 'rest for T'");
            segment.speed  = slide ? to_number(words[1]) : 0.;
            segment.length = to_number(words.back());
            require(std::isfinite(segment.speed) &&
                      (rest || segment.speed != 0),
                    where + ": the speed must be a finite number other than "
                            "0 (a stop is 'rest for T')");
            require(std::isfinite(segment.length) && segment.length > 0,
                    where + ": the " + (slide ? "distance" : "time") +
                      " must be positive");
            program.push_back(segment);
          }
        const auto once = program;
        for (int r = 1; r < repeats; ++r)
          program.insert(program.end(), once.begin(), once.end());
        return program;
      }
    } // namespace

    void
    Sliding::parse(ParameterHandler &prm)
    {
      prm.enter_subsection("Sliding");
      const std::string speed_list = prm.get("Sliding speed");
      speeds.clear();
      for (const auto &v : dealii::Utilities::split_string_list(speed_list))
        {
          const double V = dealii::Utilities::string_to_double(v);
          require(V >= 0 && std::isfinite(V),
                  entry("Sliding", "Sliding speed", V) +
                    " must not be negative");
          speeds.push_back(V);
        }
      speed   = speeds.back();
      control = parse_choice<Control>(prm.get("Control"), "Sliding/Control");
      spring_stiffness  = prm.get_double("Spring stiffness");
      increment         = prm.get_double("Sliding increment");
      max_distance      = prm.get_double("Maximum sliding distance");
      steady_tolerance  = prm.get_double("Steady-state tolerance");
      steady_window     = prm.get_double("Steady-state window");
      balance_tolerance = prm.get_double("Energy balance tolerance");
      solver = parse_choice<SlidingSolver>(prm.get("Solver"), "Sliding/Solver");
      continuation_factor   = prm.get_double("Continuation factor");
      viscous_strain_degree = prm.get_integer("Viscous strain degree");
      load_path.clear();
      for (const auto &w : Utilities::split_string_list(prm.get("Load path")))
        {
          const double value = to_number(w);
          require(std::isfinite(value),
                  "'Sliding/Load path' = " + prm.get("Load path") + ": '" + w +
                    "' is not a finite number");
          load_path.push_back(value);
        }
      program =
        parse_program(prm.get("Program"), prm.get_integer("Program repeats"));
      prm.leave_subsection();
      require(program.empty() || (solver == SlidingSolver::transient &&
                                  speeds.size() == 1 && speed == 0),
              "'Sliding/Program' needs 'Sliding/Solver' = transient and "
              "leaves 'Sliding/Sliding speed' at 0: the program gives the "
              "speeds");
      require(load_path.empty() || solver == SlidingSolver::steady_state,
              "'Sliding/Load path' needs 'Sliding/Solver' = steady-state "
              "(the transient solver holds the load of the approach)");
      require(load_path.empty() || speed > 0,
              "'Sliding/Load path' needs a positive 'Sliding/Sliding "
              "speed' to follow the loads at");
      require(continuation_factor > 1 && std::isfinite(continuation_factor),
              entry("Sliding", "Continuation factor", continuation_factor) +
                " must be larger than 1");
      require(viscous_strain_degree >= 0 && viscous_strain_degree <= 4,
              entry("Sliding", "Viscous strain degree", viscous_strain_degree) +
                " must be between 0 and 4");
      require(speeds.size() == 1 ||
                *std::min_element(speeds.begin(), speeds.end()) > 0,
              "'Sliding/Sliding speed' = " + speed_list +
                ": a list of speeds must hold positive speeds only");
      require(spring_stiffness > 0 && std::isfinite(spring_stiffness),
              entry("Sliding", "Spring stiffness", spring_stiffness) +
                " must be positive");
      require(increment > 0,
              entry("Sliding", "Sliding increment", increment) +
                " must be positive");
      require(max_distance >= 0,
              entry("Sliding", "Maximum sliding distance", max_distance) +
                " must not be negative");
      require(steady_tolerance > 0,
              entry("Sliding", "Steady-state tolerance", steady_tolerance) +
                " must be positive");
      require(balance_tolerance > 0,
              entry("Sliding", "Energy balance tolerance", balance_tolerance) +
                " must be positive");
      require(steady_window >= 0,
              entry("Sliding", "Steady-state window", steady_window) +
                " must not be negative");
    }
  } // namespace Parameters
} // namespace viscoslide

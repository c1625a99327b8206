// SPDX-License-Identifier: LGPL-2.1-or-later
#include <deal.II/base/utilities.h>

#include <viscoslide/driver/sweep.h>
#include <viscoslide/physics/indenter.h>
#include <viscoslide/physics/loading.h>

#include <cmath>
#include <type_traits>

namespace viscoslide
{
  namespace Parameters
  {
    void
    Sweep::declare(ParameterHandler &prm)
    {
      prm.enter_subsection("Sweep");
      const auto list = Patterns::List(Patterns::Anything(), 0);
      prm.declare_entry(
        "Tabor parameters",
        "",
        list,
        "Comma-separated muT values; each replaces Adhesion/Tabor "
        "parameter in its own cases. The driver runs the product of all "
        "non-empty lists of this section (and of the speeds of a transient "
        "run), each case in its own folder of the Output directory, and "
        "collects one row per case and speed in the sweep's "
        "steady_state.csv (doc/sweeps.md). Empty: no sweep over muT.");
      prm.declare_entry("Layer thicknesses",
                        "",
                        list,
                        "Comma-separated t_hat values and/or 'half-plane'; "
                        "each replaces Geometry/Substrate and Layer "
                        "thickness in its own cases.");
      prm.declare_entry("Approaches",
                        "",
                        list,
                        "Comma-separated delta_hat values; each replaces "
                        "Loading/Final approach. Not together with Loads.");
      prm.declare_entry("Loads",
                        "",
                        list,
                        "Comma-separated F_hat values; each becomes "
                        "Loading/Target load. Not together with Approaches.");
      prm.declare_entry(
        "Controls",
        "",
        Patterns::List(Patterns::Selection(choice_pattern<Control>()), 0),
        "Comma-separated 'displacement', 'force' and/or 'spring'; "
        "each replaces Sliding/Control.");
      prm.declare_entry(
        "Solvers",
        "",
        Patterns::List(Patterns::Selection(choice_pattern<SlidingSolver>()), 0),
        "Comma-separated sliding solvers ('transient', 'steady-state', "
        "'boundary-element'); each replaces Sliding/Solver, so that one "
        "file compares the methods on the same cases.");
      prm.declare_entry("Spring stiffnesses",
                        "",
                        list,
                        "Comma-separated k_hat values; each replaces "
                        "Sliding/Spring stiffness (used where Control is "
                        "spring).");
      prm.declare_entry(
        "Indenter shapes",
        "",
        Patterns::List(Patterns::Selection(Registry<IndenterShape>::pattern()),
                       0),
        "Comma-separated shapes; each replaces Indenter/Shape (the other "
        "Indenter entries apply to the shape that uses them). Case folders "
        "are named by the shape with '-' for spaces.");
      prm.declare_entry("Temperatures",
                        "",
                        list,
                        "Comma-separated temperatures in degrees Celsius; "
                        "each replaces Units/Temperature, whose Shift law "
                        "moves the material's times (friction against "
                        "speed at several temperatures, or against "
                        "temperature at one speed).");
      prm.leave_subsection();
    }

    void
    Sweep::parse(ParameterHandler &prm)
    {
      prm.enter_subsection("Sweep");
      // Numbers of a list, each checked, named in the message.
      auto numbers = [&](const std::string        &name,
                         const bool                positive,
                         std::vector<std::string> *words = nullptr) {
        std::vector<double> values;
        for (const auto &w : Utilities::split_string_list(prm.get(name)))
          {
            if (words != nullptr)
              words->push_back(w);
            if (words != nullptr && w == "half-plane")
              continue;
            const double v = to_number(w);
            require(std::isfinite(v) && (!positive || v > 0),
                    "'Sweep/" + name + "' holds '" + w + "': " +
                      (positive ? "each entry must be a positive number"
                                : "each entry must be a finite number") +
                      (words != nullptr ? " or half-plane" : ""));
            values.push_back(v);
          }
        return values;
      };
      tabor_parameters = numbers("Tabor parameters", true);
      thicknesses.clear();
      numbers("Layer thicknesses", true, &thicknesses);
      approaches = numbers("Approaches", false);
      loads      = numbers("Loads", false);
      // Choices of a list, each checked, named in the message.
      auto choices = [&](const std::string &name, auto &list) {
        using Choice = typename std::decay_t<decltype(list)>::value_type;
        list.clear();
        for (const auto &w : Utilities::split_string_list(prm.get(name)))
          list.push_back(parse_choice<Choice>(w, "Sweep/" + name));
      };
      choices("Controls", controls);
      choices("Solvers", solvers);
      spring_stiffnesses = numbers("Spring stiffnesses", true);
      shapes       = Utilities::split_string_list(prm.get("Indenter shapes"));
      temperatures = numbers("Temperatures", false);
      prm.leave_subsection();
      require(approaches.empty() || loads.empty(),
              "'Sweep/Approaches' and 'Sweep/Loads' are both given: a "
              "case ends its approach either at a delta_hat or at an F_hat");
    }
  } // namespace Parameters
} // namespace viscoslide

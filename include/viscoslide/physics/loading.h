// SPDX-License-Identifier: LGPL-2.1-or-later
// What the indenter is made to do, for every solver: the approach (to a
// depth or a load), hold and retraction of the 'Loading' section, and the
// sliding of the 'Sliding' section (its speeds, the control of the normal
// direction, and the choice of solver).
#ifndef viscoslide_loading_h
#define viscoslide_loading_h

#include <viscoslide/io/input.h>

#include <cmath>
#include <string>
#include <vector>

namespace viscoslide
{
  namespace Parameters
  {
    enum class Control
    {
      displacement,
      force,
      spring
    };
    VISCOSLIDE_CHOICES(Control, "displacement", "force", "spring")

    enum class SlidingSolver
    {
      transient,
      steady_state,
      boundary_element
    };
    VISCOSLIDE_CHOICES(SlidingSolver,
                       "transient",
                       "steady-state",
                       "boundary-element")

    struct Loading
    {
      double       initial_approach;
      double       final_approach;
      double       increment;
      double       minimum_increment;
      double       approach_speed;
      double       hold_time;
      unsigned int hold_steps;
      bool         retract;
      double       retract_to;
      // F_hat to reach at the end of the approach; NaN: none, the approach
      // ends at final_approach.
      double target_load;

      bool
      has_target_load() const
      {
        return !std::isnan(target_load);
      }

      static void
      declare(ParameterHandler &prm);
      void
      parse(ParameterHandler &prm);
    };

    // One segment of a sliding program: the indenter slides at a signed
    // speed (V_hat; negative: back towards -x) over a distance (eps), or
    // rests (speed 0) for a time (tau).
    struct ProgramSegment
    {
      double speed;
      double length;
      // As the parameter file says it, for messages and the log.
      std::string text;

      bool
      rest() const
      {
        return speed == 0.;
      }
      // How far it moves the indenter along x (eps; 0 at rest).
      double
      displacement() const
      {
        return rest() ? 0. : speed > 0 ? length : -length;
      }
      // The segment as messages name it; k counts from 0.
      std::string
      name(const unsigned int k) const
      {
        return "'Sliding/Program' segment " + std::to_string(k + 1) + " ('" +
               text + "')";
      }
    };

    struct Sliding
    {
      std::vector<double> speeds; // V_hat, in the order of continuation
      double              speed;  // the last of them; 0: no sliding phase
      Control             control;
      double              spring_stiffness; // k_hat, Control = spring
      double              increment;        // in finest cells
      double              max_distance;
      double              steady_tolerance;
      double              balance_tolerance; // of the transient's steady state
      double              steady_window;
      SlidingSolver       solver;
      double              continuation_factor;
      int                 viscous_strain_degree;
      // F_hat (force control) or delta_hat (displacement control) values
      // followed at the last speed by the steady-state solver.
      std::vector<double> load_path;
      // The transient solver's sliding program, its repeats unrolled;
      // empty: slide at `speed` to the steady state.
      std::vector<ProgramSegment> program;

      static void
      declare(ParameterHandler &prm);
      void
      parse(ParameterHandler &prm);
    };
  } // namespace Parameters
} // namespace viscoslide

#endif

#include <viscoslide/boundary_element/grid.h>

#include <cmath>

namespace viscoslide
{
  namespace Parameters
  {
    void
    BoundaryElement::declare(ParameterHandler &prm)
    {
      prm.enter_subsection("Boundary element");
      prm.declare_entry("Grid spacing",
                        "0",
                        Patterns::Double(),
                        "Spacing (in eps) of the uniform surface grid of "
                        "Sliding/Solver = boundary-element. 0: half the "
                        "Mesh/Finest surface cell, the node spacing of the "
                        "finite elements' quadratic surface cells there.");
      prm.declare_entry(
        "Period",
        "0",
        Patterns::Double(),
        "Length (in eps) of the periodic cell of the boundary-element "
        "solver: one indenter per period. 0: automatic, the larger of "
        "Geometry/Domain width and Wake periods x V tau_c at each speed "
        "(tau_c the longest retardation time), so that the wake has "
        "relaxed before it reaches the next indenter.");
      prm.declare_entry("Wake periods",
                        "20",
                        Patterns::Double(),
                        "See Period.");
      prm.leave_subsection();
    }

    void
    BoundaryElement::parse(ParameterHandler &prm)
    {
      prm.enter_subsection("Boundary element");
      grid_spacing = prm.get_double("Grid spacing");
      period       = prm.get_double("Period");
      wake_periods = prm.get_double("Wake periods");
      prm.leave_subsection();
      require(grid_spacing >= 0 && std::isfinite(grid_spacing),
              entry("Boundary element", "Grid spacing", grid_spacing) +
                " must not be negative");
      require(period >= 0 && std::isfinite(period),
              entry("Boundary element", "Period", period) +
                " must not be negative");
      require(wake_periods > 0 && std::isfinite(wake_periods),
              entry("Boundary element", "Wake periods", wake_periods) +
                " must be positive");
    }
  } // namespace Parameters
} // namespace viscoslide

// The 'Boundary element' section: the uniform surface grid of the
// boundary-element solver and its period (boundary_element/solver.h).
#ifndef viscoslide_boundary_element_grid_h
#define viscoslide_boundary_element_grid_h

#include <viscoslide/input.h>

namespace viscoslide
{
  namespace Parameters
  {
    struct BoundaryElement
    {
      double grid_spacing; // eps; 0: half the Finest surface cell
      double period;       // eps; 0: automatic
      double wake_periods; // the automatic period, in V tau_c

      static void
      declare(ParameterHandler &prm);
      void
      parse(ParameterHandler &prm);
    };
  } // namespace Parameters
} // namespace viscoslide

#endif

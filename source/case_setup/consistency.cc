// SPDX-License-Identifier: LGPL-2.1-or-later
// Entries of different sections that contradict each other.
#include <viscoslide/case_setup.h>
#include <viscoslide/case_setup/common.h>
#include <viscoslide/io/input.h>
#include <viscoslide/physics/indenter.h>

#include <algorithm>
#include <cmath>
#include <string>

namespace viscoslide
{
  namespace CaseSetup
  {
    using namespace Parameters;
    using namespace internal;

    namespace
    {
      // A program's segments: each at least one sliding step long, and the
      // indenter kept within the block.
      void
      check_sliding_program(const AllParameters &p)
      {
        double s = 0.;
        for (unsigned int k = 0; k < p.sliding.program.size(); ++k)
          {
            const auto       &segment = p.sliding.program[k];
            const std::string where   = segment.name(k);
            const double      step = p.sliding.increment * p.mesh.finest_cell;
            require(segment.rest() || segment.length >= step,
                    where + " slides " + num(segment.length) +
                      " eps, less than one sliding step ('Sliding/Sliding "
                      "increment' x 'Mesh/Finest surface cell' = " +
                      num(step) + " eps)");
            s += segment.displacement();
            require(std::abs(s) < p.geometry.domain_width / 2,
                    where + " takes the indenter " + num(s) +
                      " eps from the block's centre, beyond its lateral "
                      "boundary ('Geometry/Domain width' = " +
                      num(p.geometry.domain_width) +
                      "): widen the block or shorten the program");
          }
      }


      // The boundary elements' controls, approach and grid.
      void
      check_boundary_elements(const AllParameters &p)
      {
        require(p.sliding.control != Control::spring,
                "'Sliding/Control' = spring is not available with "
                "'Sliding/Solver' = boundary-element: use force or "
                "displacement");
        require(p.sliding.control == Control::force ||
                  p.geometry.substrate == Substrate::layer ||
                  p.sliding.speed == 0 || p.geometry.dimension == 3,
                "'Sliding/Solver' = boundary-element on a half-plane "
                "needs 'Sliding/Control' = force: the periodic "
                "half-plane has no depth to measure delta from");
        require(p.loading.approach_speed == 0,
                "'Sliding/Solver' = boundary-element approaches "
                "quasi-statically: set 'Loading/Approach speed' = 0");
        const double h = surface_grid_spacing(p);
        if (p.boundary_element.grid == GridKind::graded)
          {
            check_graded_grid(p, h);
            return;
          }
        require(p.boundary_element.grid != GridKind::nested ||
                  (p.geometry.dimension == 3 &&
                   p.geometry.substrate == Substrate::half_plane),
                "'Boundary element/Grid' = nested is the isolated contact "
                "on the 3D half-space: set 'Geometry/Dimension' = 3 and "
                "'Geometry/Substrate' = half-plane");
        const double L = p.boundary_element.period > 0
                           ? p.boundary_element.period
                           : p.geometry.domain_width;
        require(L / h >= 64 && L / h <= 1e8,
                entry("Boundary element", "Grid spacing", h) +
                  " and the period " + std::to_string(L) + " eps give " +
                  std::to_string(L / h) +
                  " grid points; between 64 and 1e8 are allowed");
        if (p.geometry.dimension == 3)
          check_plane_grid_fits(p, h, L);
      }
    } // namespace


    void
    check_consistency(const AllParameters &p)
    {
      // Builds the profile once, so that an unreadable table or a bad
      // expression is reported with the other input errors, before a run.
      create_indenter(p.indenter,
                      p.adhesion.R_over_eps,
                      p.geometry.domain_width);
      require(p.mesh.finest_cell < p.geometry.height() / 4,
              entry("Mesh", "Finest surface cell", p.mesh.finest_cell) +
                " must be well below the substrate height " +
                std::to_string(p.geometry.height()));
      require(p.geometry.domain_width >= 2 * p.geometry.height() ||
                p.geometry.substrate == Substrate::half_plane,
              entry("Geometry", "Domain width", p.geometry.domain_width) +
                " must be at least twice the Layer thickness");
      require(!p.loading.has_target_load() || p.loading.approach_speed == 0,
              "'Loading/Target load' needs a quasi-static approach "
              "('Loading/Approach speed' = 0): the load is found on the "
              "relaxed loading curve");
      require(p.sliding.solver == SlidingSolver::transient ||
                !p.loading.retract || p.sliding.speed == 0,
              "'Loading/Retract' = true needs 'Sliding/Solver' = transient: "
              "the steady-state solver has no time to retract in");
      check_sliding_program(p);
      require(p.sliding.speeds.size() == 1 ||
                std::find(p.sweep.solvers.begin(),
                          p.sweep.solvers.end(),
                          SlidingSolver::transient) == p.sweep.solvers.end(),
              "'Sweep/Solvers' with 'transient' needs a single 'Sliding/"
              "Sliding speed' (the transient solver runs each listed speed "
              "as a case of its own; the steady solvers follow the list)");
      require(p.geometry.dimension == 2 ||
                runs_only(p,
                          {SlidingSolver::boundary_element,
                           SlidingSolver::steady_state}),
              "'Geometry/Dimension' = 3 needs 'Sliding/Solver' = "
              "boundary-element or steady-state (and no other in "
              "'Sweep/Solvers'): the transient solver is plane strain");
      require(p.geometry.dimension == 2 ||
                p.geometry.substrate == Substrate::layer ||
                !boundary_elements_only(p) ||
                p.geometry.domain_height == Geometry::default_domain_height,
              "'Geometry/Domain height' is the depth of the 3D finite "
              "elements' block; the boundary elements' half-space is "
              "infinite: remove it");
      if (p.sliding.solver == SlidingSolver::boundary_element)
        check_boundary_elements(p);
    }
  } // namespace CaseSetup
} // namespace viscoslide

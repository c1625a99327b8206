// SPDX-License-Identifier: LGPL-2.1-or-later
// What is legal but known to be inaccurate, said when the case starts.
// Each warning computes what it says from the case (the cells across a
// length it must resolve) and points to the table in doc/ that measured
// the error, rather than quoting a number that would go stale.
#include <viscoslide/case_setup.h>
#include <viscoslide/case_setup/common.h>
#include <viscoslide/io/input.h>
#include <viscoslide/physics/scales.h>

#include <algorithm>
#include <cmath>
#include <iomanip>
#include <sstream>

namespace viscoslide
{
  namespace CaseSetup
  {
    using namespace Parameters;
    using namespace internal;

    namespace
    {
      // The largest Tabor parameter at which the graded grid's curve was
      // measured to converge (doc/boundary_element.md, Reach at the Tabor
      // parameters of real bodies: scripts/bench_graded 10000 0.0002, and
      // 0.0001 for its convergence).
      constexpr double graded_grid_measured_reach = 10000;

      // The finest surface cell or grid spacing of the case's solver, in
      // eps, and the entry that sets it.
      std::pair<double, std::string>
      finest_cell(const AllParameters &p)
      {
        if (p.sliding.solver != SlidingSolver::boundary_element)
          return {p.mesh.finest_cell, "'Mesh/Finest surface cell'"};
        const double spacing = surface_grid_spacing(p);
        // The nested grid's band, along the contact's edge, is the finest.
        if (p.boundary_element.grid == GridKind::nested)
          return {spacing / p.boundary_element.refinement,
                  "'Boundary element/Grid spacing' over 'Boundary "
                  "element/Refinement'"};
        return {spacing, "'Boundary element/Grid spacing'"};
      }

      // The 3D finite elements: their size before the mesh is built, and
      // how far they are verified.
      void
      note_finite_elements_3d(AllParameters &p)
      {
        if (p.geometry.dimension != 3 || boundary_elements_only(p))
          return;
        const FiniteElements3dSize size = finite_elements_3d_size(p);
        std::ostringstream         note;
        note << std::setprecision(3)
             << "Note: the 3D finite elements about the relaxed contact "
             << "will have about " << size.unknowns << " unknowns and need "
             << "about " << size.gigabytes << " GB with "
             << linear_solver_name(size) << ", of " << size.available
             << " GB (an estimate before the mesh is built: "
             << "doc/steady_state.md, Memory)";
        p.notes.push_back(note.str());
        std::ostringstream warning;
        warning << std::setprecision(3)
                << "Warning: the 3D finite elements are verified on coarse "
                << "meshes only: their friction error falls at first order "
                << "in the cell at the contact's edge (doc/steady_state.md, "
                << "Mesh convergence, against the boundary elements); this "
                << "case's cells there are " << p.mesh.finest_cell << " eps";
        if (p.adhesion.adhesive() && p.adhesion.tabor_parameter > 0)
          warning << ", the adhesive zone about " << adhesive_zone(p)
                  << " eps wide";
        warning << ". Use 'Sliding/Solver' = boundary-element for the "
                << "friction, and halve 'Mesh/Finest surface cell' to see "
                << "how far a case is from converged";
        p.notes.push_back(warning.str());
      }

      // The adhesive zone at the contact edges against the finest cell.
      void
      warn_unresolved_zone(AllParameters &p)
      {
        if (!p.adhesion.adhesive() || !(p.adhesion.tabor_parameter > 0))
          return;
        const double zone          = adhesive_zone(p);
        const auto [cell, setting] = finest_cell(p);
        if (cell <= zone / 2)
          return;
        std::ostringstream note;
        note << std::setprecision(3) << "Warning: " << setting << " = " << cell
             << " eps ";
        if (cell > zone)
          note << "is " << cell / zone << " times the adhesive zone at the "
               << "contact edges (about " << zone << " eps): the zone is not "
               << "resolved, and the contact edges, the pull-off and the "
               << "slow-speed friction made there are not converged; set it "
               << "to " << zone / 2 << " eps or less";
        else
          note << "puts " << zone / cell << " cells across the adhesive "
               << "zone at the contact edges (about " << zone << " eps); the "
               << "slow-speed friction made there converges at first order "
               << "in the cell (doc/sphere.md and doc/boundary_element.md, "
               << "the convergence tables): halve it to see how far this "
               << "case is from converged";
        if (p.geometry.dimension == 2 &&
            p.boundary_element.grid != GridKind::graded)
          note << " (plane strain on a half-plane: 'Sliding/Solver' = "
                  "boundary-element with 'Boundary element/Grid' = graded "
                  "resolves the zone at any R over eps, doc/"
                  "boundary_element.md)";
        if (p.geometry.dimension == 3 &&
            p.geometry.substrate == Substrate::half_plane &&
            p.sliding.solver == SlidingSolver::boundary_element &&
            p.boundary_element.grid == GridKind::uniform)
          note << " ('Boundary element/Grid' = nested divides the cells "
                  "of a band along the contact's edge by 'Boundary "
                  "element/Refinement', doc/boundary_element.md, Nested "
                  "grid)";
        p.notes.push_back(note.str());
      }

      void
      warn_beyond_graded_reach(AllParameters &p)
      {
        if (p.sliding.solver != SlidingSolver::boundary_element ||
            p.boundary_element.grid != GridKind::graded ||
            p.adhesion.tabor_parameter <= graded_grid_measured_reach)
          return;
        p.notes.push_back(
          "Warning: 'Adhesion/Tabor parameter' = " +
          num(p.adhesion.tabor_parameter) +
          " is beyond the largest at which the graded grid's curve has been "
          "measured to converge, " +
          num(graded_grid_measured_reach) +
          " (doc/boundary_element.md, Reach at the Tabor parameters of real "
          "bodies): it may take minutes, or stop with a message that names "
          "the step where Newton's method did not converge. The edge model "
          "of scripts/edge_cracks (--predict) gives the curve from the "
          "contact edges' energy release rates measured at Tabor parameter "
          "1000 (doc/boundary_element.md, The edges as cracks)");
      }

      // The transient's step: an adhesive edge that snaps within one step
      // dissipates at the step's rate, not the material's (doc/
      // steady_state.md, Cross-validation table, measures mu against the
      // steps in relaxation lengths). tau is the slowest arm's, in units
      // of tau_ref.
      void
      warn_coarse_sliding_step(AllParameters &p, const double tau)
      {
        if (p.sliding.solver != SlidingSolver::transient ||
            !p.adhesion.adhesive())
          return;
        const double      step   = p.sliding.increment * p.mesh.finest_cell;
        const std::string coarse = speeds_relaxing_within(p, tau, step / 2.);
        if (coarse.empty())
          return;
        const double slowest =
          *std::min_element(p.sliding.speeds.begin(), p.sliding.speeds.end());
        std::ostringstream note;
        note << std::setprecision(3) << "Warning: at V_hat = " << coarse
             << " the sliding step ('Sliding/Sliding increment' x 'Mesh/"
             << "Finest surface cell' = " << step << " eps) is longer than "
             << "two relaxation lengths V tau of the slowest arm ("
             << step / (slowest * tau) << " of them at V_hat " << slowest
             << "): an adhesive edge that snaps within one step dissipates "
             << "at the step's rate, and the friction is off by what the "
             << "table of doc/steady_state.md (Cross-validation) shows for "
             << "that many; a Sliding increment of about V tau / Finest "
             << "surface cell resolves it";
        p.notes.push_back(note.str());
      }

      // The finite elements resolve the arms' relaxation over a cell at
      // best: where even the slowest arm relaxes within the finest cell,
      // the dissipation at the contact edges lies below the mesh.
      void
      warn_relaxation_below_cell(AllParameters &p)
      {
        if (p.sliding.solver == SlidingSolver::boundary_element ||
            p.geometry.dimension != 2)
          return;
        const Scales s(p);
        const double tau =
          make_solid(p, s).longest_relaxation_time() / s.tau_ref;
        warn_coarse_sliding_step(p, tau);
        const std::string slow =
          speeds_relaxing_within(p, tau, p.mesh.finest_cell);
        if (!slow.empty())
          p.notes.push_back(
            "Warning: at V_hat = " + slow +
            " the relaxation length V tau of the slowest arm is shorter "
            "than 'Mesh/Finest surface cell' = " +
            num(p.mesh.finest_cell) +
            " eps: the arms relax inside one cell and the dissipation at the "
            "contact edges is not resolved, so that the friction there is "
            "not converged (the energy balance printed with each row says "
            "how far it is off); refine the finest cell to about V tau");
      }

      // The fields' dissipation map converges more slowly in the grading
      // than the table's values (doc/steady_state.md, Fields).
      void
      warn_dissipation_field(AllParameters &p)
      {
        if (!p.output.write_fields ||
            p.sliding.solver != SlidingSolver::steady_state ||
            p.mesh.grading <= 0.125 || p.geometry.dimension != 2)
          return;
        std::ostringstream note;
        note << "Warning: 'Mesh/Mesh grading' = " << p.mesh.grading
             << " with 'Output/Write fields': the written dissipation field "
             << "away from the contact edges converges more slowly in the "
             << "grading than the table's values (doc/steady_state.md, "
             << "Fields, measures its shares against the grading); 0.125 "
             << "resolves it at two to three times the cost";
        p.notes.push_back(note.str());
      }

      void
      warn_block_narrow_for_contact(AllParameters &p)
      {
        if (!p.loading.has_target_load() || p.mesh.uniform_surface)
          return;
        const double softest = std::min(1., 1. / p.material.E0_over_Einf);
        const double width =
          2 * hertz_half_width(p.loading.target_load, softest, p);
        if (width <= p.geometry.domain_width / 4)
          return;
        std::ostringstream note;
        note << "Warning: the contact at 'Loading/Target load' = "
             << p.loading.target_load << " is about " << width
             << " eps wide (Hertz, relaxed modulus), more than a quarter of "
             << "'Geometry/Domain width' = " << p.geometry.domain_width
             << "; the block's edges will shift the results";
        p.notes.push_back(note.str());
      }
    } // namespace


    void
    warn_about_accuracy(AllParameters &p)
    {
      note_finite_elements_3d(p);
      warn_unresolved_zone(p);
      warn_beyond_graded_reach(p);
      warn_relaxation_below_cell(p);
      warn_dissipation_field(p);
      if (p.sliding.solver == SlidingSolver::transient && p.sliding.speed > 0)
        p.notes.push_back(
          "Note: 'Sliding/Solver' = transient slides the indenter until the "
          "contact is steady, thousands of eps in steps of the finest cell: "
          "minutes to hours per speed (doc/benchmark.md times it). For the "
          "steady friction alone, 'Sliding/Solver' = steady-state solves it "
          "directly");
      warn_block_narrow_for_contact(p);
    }
  } // namespace CaseSetup
} // namespace viscoslide

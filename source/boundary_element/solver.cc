// SPDX-License-Identifier: LGPL-2.1-or-later
// BoundaryElementSolver: the grid a case asks for, the run, the residual,
// GMRES on the grid's preconditioner and Newton's method.
#include <deal.II/base/utilities.h>
#include <deal.II/lac/solver_control.h>
#include <deal.II/lac/solver_gmres.h>

#include <viscoslide/boundary_element/graded_grid.h>
#include <viscoslide/boundary_element/isolated_grid.h>
#include <viscoslide/boundary_element/nested_grid.h>
#include <viscoslide/boundary_element/periodic_grid.h>
#include <viscoslide/boundary_element/solver.h>
#include <viscoslide/case_setup/common.h>

#include <algorithm>
#include <cmath>
#include <limits>

namespace viscoslide
{
  template <int dim>
  std::unique_ptr<SurfaceGrid<dim>>
  make_surface_grid(const CaseParts &parts, ConditionalOStream &out)
  {
    const auto  &prm = parts.prm;
    const double dx =
      CaseSetup::internal::surface_grid_spacing(prm) * parts.scales.eps;
    const auto &s = parts.scales;
    const auto &m = parts.material;
    const auto &i = *parts.indenter;
    if constexpr (dim == 2)
      {
        if (prm.boundary_element.grid == Parameters::GridKind::graded)
          return std::make_unique<GradedGrid>(prm, s, m, i, dx, out);
      }
    else if (prm.geometry.substrate == Parameters::Substrate::half_plane)
      {
        if (prm.boundary_element.grid == Parameters::GridKind::nested)
          return std::make_unique<NestedGrid>(prm, s, m, i, dx, out);
        return std::make_unique<IsolatedGrid>(prm, s, m, i, dx, out);
      }
    return std::make_unique<PeriodicGrid<dim>>(prm, s, m, i, dx, out);
  }


  template <int dim>
  BoundaryElementSolver<dim>::BoundaryElementSolver(CaseParts &parts)
    : prm(parts.prm)
    , comm(parts.comm)
    , pcout(std::cout,
            Utilities::MPI::this_mpi_process(comm) == 0 &&
              prm.output.verbosity != Parameters::Verbosity::quiet)
    // Every process holds the whole problem and may take other stations
    // than the rest (from_both_ends): its timers are its own, not
    // synchronized (the statistics are gathered at the end).
    , timer(MPI_COMM_SELF, pcout, TimerOutput::never, TimerOutput::wall_times)
    , scales(parts.scales)
    , material(parts.material)
    , law(*parts.law)
    , law_range(parts.scales.eps)
    , writer(parts.writer)
    , steady_state_table(parts.steady_state_table)
    , progress(parts.progress)
    , grid(make_surface_grid<dim>(parts, pcout))
  {
  }


  template <int dim>
  BoundaryElementSolver<dim>::~BoundaryElementSolver() = default;


  template <int dim>
  void
  BoundaryElementSolver<dim>::run()
  {
    start();
    if (prm.sliding.control == Parameters::Control::force)
      control.hold_force(last_quantities.normal_force);
    else
      control.hold_approach();
    // From the solid of the approach to the sliding one (the 2D
    // half-plane's approach is on a block), at the load of the approach.
    if (grid->to_sliding_solid(state) && solve() < 0)
      throw std::runtime_error(
        "the boundary-element solver could not carry the state of the "
        "approach over to the half-plane");
    grid->preconditioner().reset();
    if (prm.sliding.speed > 0)
      {
        pcout << "Steady sliding under "
              << Parameters::to_string(prm.sliding.control)
              << " control, boundary elements on " << state.gap.size()
              << " points" << std::endl;
        run_stations(*this,
                     Parameters::SlidingSolver::boundary_element,
                     prm,
                     scales,
                     writer,
                     steady_state_table,
                     progress,
                     pcout,
                     comm);
      }
    else
      write_profile(writer.path("surface_profile_final.csv"));
    pcout << "GMRES: " << gmres_iterations << " iterations in " << gmres_solves
          << " solves ("
          << (gmres_solves > 0 ? double(gmres_iterations) / gmres_solves : 0.)
          << " per Newton step)" << std::endl;
    timer.print_wall_time_statistics(comm);
  }


  template <int dim>
  void
  BoundaryElementSolver<dim>::assemble(const bool with_matrix)
  {
    TimerOutput::Scope t(timer, "boundary element: residual");
    const unsigned int n = state.gap.size();
    const auto        &p = grid->at();
    gaps                 = state.gap;
    displacement         = state.displacement(p.h, scales.eps);
    const auto &u        = displacement;
    traction.reinit(n);
    tangent.reinit(n);
    Vector<double> w(n), Cw;
    double         Fn = 0;
    for (unsigned int j = 0; j < n; ++j)
      {
        traction[j] = traction_law().traction(gaps[j]);
        tangent[j]  = traction_law().derivative(gaps[j]);
        w[j] = traction[j] - (dashpot > 0 ? dashpot * (u[j] - anchor[j]) : 0.);
        Fn -= traction[j] * p.area[j];
      }
    grid->apply(w, Cw);
    residual.reinit(n + 1);
    for (unsigned int j = 0; j < n; ++j)
      residual[j] = u[j] - Cw[j];
    residual[n] = control.force_controlled
                    ? control.mismatch(Fn, state.delta) / scales.sigma_max
                    : 0.;
    if (with_matrix)
      assemble_matrix();
  }


  template <int dim>
  void
  BoundaryElementSolver<dim>::assemble_matrix()
  {
    const unsigned int n = state.gap.size();
    const auto        &p = grid->at();
    const auto        &u = displacement;
    if (round_off_due && grid->positive_compliance())
      {
        // The residual's rounding error, once per solve (it costs a
        // product with C, an eighth of a Newton step on the 3D grids, and
        // changes little between steps): the gaps' last digits times the
        // repulsive wall's stiffness, a traction that the coarse cells'
        // compliance magnifies, and u's own (at R_hat 1e6 and more u is
        // 1e4 eps). Where the compliance is positive, C|v| sums the
        // magnitudes of the terms of C v; their rounding errors, of either
        // sign, add up as a random walk (1/sqrt(n) of that sum).
        Vector<double> magnitude(n), C_magnitude;
        for (unsigned int j = 0; j < n; ++j)
          magnitude[j] =
            std::abs(traction[j]) +
            std::abs(tangent[j]) * (std::abs(gaps[j]) + scales.eps);
        grid->apply(magnitude, C_magnitude);
        double sum = 0;
        for (unsigned int j = 0; j < n; ++j)
          sum += std::pow(std::numeric_limits<double>::epsilon() *
                            (std::abs(u[j]) + std::abs(p.h[j]) +
                             std::abs(state.delta) + C_magnitude[j]),
                          2);
        round_off     = std::sqrt(sum / n) / scales.eps;
        round_off_due = false;
      }
    TimerOutput::Scope t(timer, "boundary element: preconditioner");
    grid->preconditioner().update(tangent, dashpot, control.force_controlled);
  }


  template <int dim>
  double
  BoundaryElementSolver<dim>::residual_norm() const
  {
    // The l2 norm of the displacement misfit: a smooth merit function for
    // the line search (the largest misfit alone stalled it at the contact
    // edges). With it the load equation relative to the total absolute
    // traction, as the finite-element solvers measure their residual.
    const unsigned int n        = state.gap.size();
    const auto        &area     = grid->at().area;
    double             misfit   = 0;
    double             absolute = 0;
    for (unsigned int j = 0; j < n; ++j)
      {
        misfit += residual[j] * residual[j];
        absolute += std::abs(traction[j]) * area[j];
      }
    const double load = residual[n] * scales.sigma_max /
                        (absolute + scales.sigma_max * grid->cell_area());
    misfit /= grid->rows();
    return std::sqrt(misfit / (scales.eps * scales.eps) + load * load);
  }


  template <int dim>
  void
  BoundaryElementSolver<dim>::compute_update()
  {
    Vector<double> rhs(residual);
    rhs *= -1.;
    solve_linearized(rhs, update);
  }


  template <int dim>
  void
  BoundaryElementSolver<dim>::jacobian_vmult(Vector<double>       &dst,
                                             const Vector<double> &src) const
  {
    // The Jacobian: du + C[(q' + c) du + q' d delta], and the load row.
    const unsigned int n     = state.gap.size();
    const auto        &area  = grid->at().area;
    const bool         force = control.force_controlled;
    Vector<double>     w(n), Cw;
    double             load = 0;
    for (unsigned int j = 0; j < n; ++j)
      {
        const double du = src[j];
        const double dd = force ? src[n] : 0.;
        w[j]            = tangent[j] * (du + dd) + dashpot * du;
        load += tangent[j] * (du + dd) * area[j];
      }
    grid->apply(w, Cw);
    dst.reinit(n + 1);
    for (unsigned int j = 0; j < n; ++j)
      dst[j] = src[j] + Cw[j];
    dst[n] = force ? load / scales.sigma_max : src[n];
  }


  template <int dim>
  void
  BoundaryElementSolver<dim>::solve_linearized(const Vector<double> &rhs,
                                               Vector<double>       &solution)
  {
    const NewtonPreconditioner &P = grid->preconditioner();
    run_gmres([this](Vector<double>       &dst,
                     const Vector<double> &src) { jacobian_vmult(dst, src); },
              [&P](Vector<double> &dst, const Vector<double> &src) {
                P.vmult(dst, src);
              },
              rhs,
              solution);
  }


  template <int dim>
  void
  BoundaryElementSolver<dim>::run_gmres(const LinearMap      &op,
                                        const LinearMap      &preconditioner,
                                        const Vector<double> &rhs,
                                        Vector<double>       &solution)
  {
    TimerOutput::Scope t(timer, "boundary element: GMRES");
    struct Map
    {
      const LinearMap &map;
      void
      vmult(Vector<double> &dst, const Vector<double> &src) const
      {
        map(dst, src);
      }
    };
    solution.reinit(rhs.size());
    // GMRES is preconditioned from the left: it measures the preconditioned
    // residual, and the forcing term of an inexact Newton step is a
    // reduction of that.
    ReductionControl solver_control(
      1000, 1e-8 * rhs.l2_norm(), forcing, false, false);
    SolverGMRES<Vector<double>> gmres(
      solver_control, SolverGMRES<Vector<double>>::AdditionalData(100));
    bool converged = true;
    try
      {
        gmres.solve(Map{op}, solution, rhs, Map{preconditioner});
      }
    catch (SolverControl::NoConvergence &)
      {
        // Newton's method judges the update by the residual it gives; the
        // preconditioner hears of it.
        converged = false;
      }
    if (prm.solver.verbose)
      pcout << "        GMRES: " << solver_control.last_step()
            << " iterations, " << (converged ? "converged" : "not converged")
            << std::endl;
    gmres_iterations += solver_control.last_step();
    ++gmres_solves;
    grid->preconditioner().solved(solver_control.last_step(), converged);
  }


  template <int dim>
  void
  BoundaryElementSolver<dim>::step_state(const double alpha)
  {
    // The update is one of u and delta; a gap changes by -(du + d delta).
    const unsigned int n  = state.gap.size();
    const double       dd = control.force_controlled ? alpha * update[n] : 0.;
    for (unsigned int j = 0; j < n; ++j)
      state.gap[j] -= alpha * update[j] + dd;
    state.delta += dd;
  }


  template <int dim>
  NewtonProblem
  BoundaryElementSolver<dim>::newton_problem()
  {
    NewtonProblem p;
    p.assemble = [this](const bool with_matrix) { assemble(with_matrix); };
    p.assemble_matrix = [this] { assemble_matrix(); };
    p.residual_norm   = [this] { return residual_norm(); };
    p.tolerance       = [this] {
      return std::max(100. * prm.solver.newton_tolerance, round_off);
    };
    p.compute_update  = [this] { compute_update(); };
    p.update_norm     = [this] { return update.l2_norm(); };
    p.update_max_norm = [this] { return update.linfty_norm(); };
    // On a grid that follows the edges: along the nearly singular
    // translation of a wide contact a residual within the tolerance can
    // still ask for eps.
    if (grid->n_motions() > 0)
      p.update_negligible = [this] {
        return update.linfty_norm() <= negligible_update * grid->spacing();
      };
    if (!grid->preconditioner().nearly_exact())
      p.set_forcing = [this](const double eta) { forcing = eta; };
    p.remember_iterate = [this] { start_of_step = state; };
    p.step             = [this](const double alpha) {
      state = start_of_step;
      step_state(alpha);
    };
    p.set_dashpot = [this](const double c) {
      dashpot = c;
      if (c > 0)
        anchor = state.displacement(grid->at().h, scales.eps);
    };
    return p;
  }


  template <int dim>
  int
  BoundaryElementSolver<dim>::solve(const bool relax)
  {
    int its = solve_on_grid(relax);
    if (its < 0)
      return its;
    // A grid that follows the contact (its edges, or its band of refined
    // cells): solved again on a grid about the contact found, until it is
    // where the grid is finest. If that fails, the state before, on its
    // own grid. A fixed grid follows nothing.
    const auto         old_placement = grid->placement();
    const SurfaceState old_state     = state;
    for (unsigned int k = 0;
         k < 8 && grid->follow(last_quantities, traction, false, state);
         ++k)
      {
        const int more = solve_on_grid(relax);
        if (more < 0)
          {
            if (old_placement)
              grid->regrid(*old_placement, state);
            state = old_state;
            update_quantities();
            return -1;
          }
        its += more;
      }
    last_newton_iterations = its;
    return its;
  }


  template <int dim>
  int
  BoundaryElementSolver<dim>::solve_on_grid(const bool relax)
  {
    const SurfaceState  start_state = state;
    const NewtonProblem problem     = newton_problem();
    round_off_due                   = true;
    const auto restart              = [&] {
      state = start_state;
      grid->preconditioner().reset();
    };
    // Without contact the surface jumps in. Newton's method from the flat
    // surface lands on whichever equilibrium its steps reach; the
    // pseudo-transient relaxation follows the jump as an overdamped motion
    // would, to the first equilibrium on its way, as the finite-element
    // approach does.
    assemble(false);
    const bool in_contact = *std::min_element(gaps.begin(), gaps.end()) <
                            prm.adhesion.contact_gap * law_range;
    int its = in_contact ? newton(problem,
                                  prm.solver.max_newton_iterations,
                                  prm.solver.line_search,
                                  prm.solver.verbose,
                                  pcout)
                         : -1;
    // On a grid with motions an edge's zone that must move by more than
    // its width moves as one unknown (solve_moving_grid).
    if (its < 0 && in_contact && grid->n_motions() > 0)
      {
        restart();
        its = solve_moving_grid();
        if (its >= 0)
          return its;
      }
    // Past a jump of a contact edge the equilibrium is not near: relax
    // towards it (newton.h).
    if (its < 0 && relax)
      {
        restart();
        its     = relax_surface(problem, scales, prm.solver, pcout);
        dashpot = 0;
      }
    if (its < 0)
      {
        restart();
        return -1;
      }
    last_newton_iterations = its;
    update_quantities();
    return its;
  }


  template <int dim>
  void
  BoundaryElementSolver<dim>::update_quantities()
  {
    assemble(false);
    last_quantities = grid->measure(gaps,
                                    traction,
                                    displacement,
                                    prm.adhesion.contact_gap * law_range);
  }


  template std::unique_ptr<SurfaceGrid<2>>
  make_surface_grid(const CaseParts &, ConditionalOStream &);
  template std::unique_ptr<SurfaceGrid<3>>
  make_surface_grid(const CaseParts &, ConditionalOStream &);
  template class BoundaryElementSolver<2>;
  template class BoundaryElementSolver<3>;
} // namespace viscoslide

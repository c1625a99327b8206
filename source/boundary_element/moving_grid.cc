// SPDX-License-Identifier: LGPL-2.1-or-later
// Newton's method with the grid's motions among the unknowns
// (doc/boundary_element.md, Graded grid, The edges as unknowns).
#include <deal.II/lac/full_matrix.h>

#include <viscoslide/boundary_element/solver.h>

#include <cmath>

namespace viscoslide
{
  template <int dim>
  void
  BoundaryElementSolver<dim>::assemble_moving_grid(const bool with_matrix)
  {
    const unsigned int n_motions = grid->n_motions();
    if (with_matrix)
      {
        // Each motion's column by a difference: the grid moved by a
        // thousandth of its finest cell with the gaps kept, which changes
        // the indenter's height at the points and the compliance. The
        // present grid is kept whole for after.
        assemble(false);
        const Vector<double> r0 = residual, g = gaps, u_kept = state.u;
        const auto           from = grid->placement();
        auto                 kept = std::move(grid);
        const double         step = 1e-3 * kept->spacing();
        motion_columns.resize(n_motions);
        for (unsigned int k = 0; k < n_motions; ++k)
          {
            std::vector<double> d(n_motions, 0.);
            d[k] = step;
            grid = kept->moved(*from, d, g, state);
            assemble(false);
            motion_columns[k] = residual;
            motion_columns[k] -= r0;
            motion_columns[k] /= step;
          }
        grid    = std::move(kept);
        state.u = u_kept;
      }
    assemble(with_matrix);
    const double gc = prm.adhesion.contact_gap * law_range;
    pin_misfit.resize(n_motions);
    for (unsigned int k = 0; k < n_motions; ++k)
      {
        double g = 0;
        for (const auto &[i, w] : grid->pin(k))
          g += w * gaps[i];
        pin_misfit[k] = g - gc;
      }
  }


  template <int dim>
  void
  BoundaryElementSolver<dim>::compute_moving_grid_update()
  {
    // The Jacobian bordered by the motions' columns and the pins, by
    // elimination: update = z + Z a, with J z = -r, J Z_k = -dr/dm_k, and
    // a from the pins. J is nearly singular along an edge's translation;
    // its solves carry that mode, the combination cancels it.
    const unsigned int n         = state.u.size();
    const unsigned int n_motions = grid->n_motions();
    compute_update();
    std::vector<Vector<double>> Z(n_motions);
    for (unsigned int k = 0; k < n_motions; ++k)
      {
        Vector<double> rhs(motion_columns[k]);
        rhs *= -1.;
        solve_linearized(rhs, Z[k]);
      }
    // The change of pin e by an update v (the gaps move with the grid).
    const auto pin_change = [&](const Vector<double> &v, const unsigned int e) {
      const double d_delta = control.force_controlled ? v[n] : 0.;
      double       change  = 0;
      for (const auto &[i, w] : grid->pin(e))
        change += w * v[i];
      return -change - d_delta;
    };
    FullMatrix<double> M(n_motions, n_motions), M_inverse(n_motions, n_motions);
    Vector<double>     b(n_motions), a(n_motions);
    for (unsigned int e = 0; e < n_motions; ++e)
      {
        for (unsigned int k = 0; k < n_motions; ++k)
          M(e, k) = pin_change(Z[k], e);
        b[e] = -pin_misfit[e] - pin_change(update, e);
      }
    M_inverse.invert(M);
    M_inverse.vmult(a, b);
    motion_update.resize(n_motions);
    for (unsigned int k = 0; k < n_motions; ++k)
      {
        update.add(a[k], Z[k]);
        motion_update[k] = a[k];
      }
  }


  template <int dim>
  NewtonProblem
  BoundaryElementSolver<dim>::moving_grid_problem()
  {
    NewtonProblem p = newton_problem();
    p.assemble      = [this](const bool with_matrix) {
      assemble_moving_grid(with_matrix);
    };
    p.residual_norm = [this] {
      const double r      = residual_norm();
      double       misfit = 0;
      for (const double m : pin_misfit)
        misfit += m * m;
      return std::sqrt(r * r + misfit / (scales.eps * scales.eps));
    };
    p.compute_update = [this] { compute_moving_grid_update(); };
    p.update_norm    = [this] {
      double norm = update.l2_norm();
      for (const double m : motion_update)
        norm += std::abs(m);
      return norm;
    };
    p.remember_iterate = [this] {
      start_of_step = state;
      gaps0         = gaps;
      placement0    = grid->placement();
    };
    p.step = [this](const double alpha) {
      std::vector<double> d(motion_update.size());
      for (unsigned int k = 0; k < d.size(); ++k)
        d[k] = alpha * motion_update[k];
      state.delta = start_of_step.delta;
      grid->move(*placement0, d, gaps0, state);
      const unsigned int n = state.u.size();
      for (unsigned int j = 0; j < n; ++j)
        state.u[j] += alpha * update[j];
      if (control.force_controlled)
        state.delta += alpha * update[n];
    };
    return p;
  }


  template <int dim>
  int
  BoundaryElementSolver<dim>::solve_moving_grid()
  {
    assemble(false);
    const auto              start            = grid->placement();
    const SurfaceState      state_start      = state;
    const Vector<double>    gaps_start       = gaps;
    const SurfaceQuantities quantities_start = last_quantities;
    const auto              restore          = [&] {
      state.delta = state_start.delta;
      grid->place(*start, gaps_start, state);
      state.u         = state_start.u;
      last_quantities = quantities_start;
      return -1;
    };
    update_quantities();
    if (!grid->prepare_motions(last_quantities, state))
      return restore();
    assemble(false);
    for (unsigned int k = 0; k < grid->n_motions(); ++k)
      if (grid->pin(k).empty())
        return restore();
    const int its = newton(moving_grid_problem(),
                           prm.solver.max_newton_iterations,
                           prm.solver.line_search,
                           prm.solver.verbose,
                           pcout);
    if (its < 0)
      return restore();
    grid->count_generation();
    last_newton_iterations = its;
    update_quantities();
    return its;
  }


  // The class is instantiated in solver.cc; here the members this file
  // defines.
#define VISCOSLIDE_INSTANTIATE(dim)                                         \
  template void BoundaryElementSolver<dim>::assemble_moving_grid(bool);     \
  template void BoundaryElementSolver<dim>::compute_moving_grid_update();   \
  template NewtonProblem BoundaryElementSolver<dim>::moving_grid_problem(); \
  template int           BoundaryElementSolver<dim>::solve_moving_grid();
  VISCOSLIDE_INSTANTIATE(2)
  VISCOSLIDE_INSTANTIATE(3)
#undef VISCOSLIDE_INSTANTIATE
} // namespace viscoslide

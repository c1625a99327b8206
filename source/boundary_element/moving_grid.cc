// SPDX-License-Identifier: LGPL-2.1-or-later
// Newton's method with the grid's motions among the unknowns
// (doc/boundary_element.md, Graded grid, The edges as unknowns).
#include <deal.II/lac/full_matrix.h>

#include <viscoslide/boundary_element/solver.h>

#include <algorithm>
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
        // Each motion's column by a difference: the grid moved by its
        // finest cell with the gaps kept, which changes the indenter's
        // height at the points and the compliance. The cells carry their
        // gaps, so the residual is smooth in the motion (the heights change
        // by h' d + d^2/(2R)); the step is set by the residual's rounding,
        // which the difference divides by it. At Tabor parameter 2000 and
        // R_hat 1e7 (a rounding of 1e-7 eps) a tenth of the finest cell
        // left the columns wrong by 1 % and Newton's direction no descent
        // direction (the residual grew in proportion to the step along
        // it); at a thousandth it failed at Tabor parameter 1000. The
        // present grid is kept whole for after.
        assemble(false);
        const Vector<double> r0 = residual, g = gaps;
        const auto           from = grid->placement();
        auto                 kept = std::move(grid);
        const double         step = kept->spacing();
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
        grid      = std::move(kept);
        state.gap = g;
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
  double
  BoundaryElementSolver<dim>::pin_change(const Vector<double> &v,
                                         const unsigned int    e) const
  {
    const unsigned int n       = state.gap.size();
    const double       d_delta = control.force_controlled ? v[n] : 0.;
    double             change  = 0;
    for (const auto &[i, w] : grid->pin(e))
      change += w * v[i];
    return -change - d_delta;
  }


  template <int dim>
  void
  BoundaryElementSolver<dim>::compute_moving_grid_update()
  {
    // The Jacobian bordered by the motions' columns c_k and the pins' rows,
    //   [J C; P 0] (v, m) = (-r, -pin misfits),
    // solved as one system by GMRES. J alone is nearly singular along the
    // contact's translation and width (a wide contact's neutral modes), so
    // eliminating the motions through solves with J (v = z + Z m) leaves
    // errors along those modes in z and Z, at GMRES's tolerance times J's
    // condition, that the combination does not cancel: at Tabor parameter
    // 1000 and R_hat 1e7 they moved the edges by thousands of eps. The
    // bordered system holds the edges and is well conditioned; the same
    // elimination with the grid's preconditioner in place of J^-1 is its
    // preconditioner.
    const unsigned int          n_motions = grid->n_motions();
    const unsigned int          N         = state.gap.size() + 1;
    NewtonPreconditioner       &P         = grid->preconditioner();
    std::vector<Vector<double>> Z(n_motions);
    FullMatrix<double> M(n_motions, n_motions), M_inverse(n_motions, n_motions);
    for (unsigned int k = 0; k < n_motions; ++k)
      {
        Vector<double> c(motion_columns[k]);
        c *= -1.;
        Z[k].reinit(N);
        P.vmult(Z[k], c);
      }
    for (unsigned int e = 0; e < n_motions; ++e)
      for (unsigned int k = 0; k < n_motions; ++k)
        M(e, k) = pin_change(Z[k], e);
    M_inverse.invert(M);

    // The bordered matrix applied to (v, m).
    const auto bordered = [this, N](Vector<double>       &dst,
                                    const Vector<double> &src) {
      Vector<double> v(N), Jv;
      std::copy(src.begin(), src.begin() + N, v.begin());
      jacobian_vmult(Jv, v);
      for (unsigned int k = 0; k < motion_columns.size(); ++k)
        Jv.add(src[N + k], motion_columns[k]);
      dst.reinit(src.size());
      std::copy(Jv.begin(), Jv.end(), dst.begin());
      for (unsigned int e = 0; e < motion_columns.size(); ++e)
        dst[N + e] = pin_change(v, e);
    };
    // Its inverse by elimination, J^-1 replaced by the preconditioner.
    const auto elimination = [&, this](Vector<double>       &dst,
                                       const Vector<double> &src) {
      Vector<double> f(N), z(N), b(n_motions), m(n_motions);
      std::copy(src.begin(), src.begin() + N, f.begin());
      P.vmult(z, f);
      for (unsigned int e = 0; e < n_motions; ++e)
        b[e] = src[N + e] - pin_change(z, e);
      M_inverse.vmult(m, b);
      for (unsigned int k = 0; k < n_motions; ++k)
        z.add(m[k], Z[k]);
      dst.reinit(src.size());
      std::copy(z.begin(), z.end(), dst.begin());
      for (unsigned int k = 0; k < n_motions; ++k)
        dst[N + k] = m[k];
    };
    Vector<double> rhs(N + n_motions), solution;
    for (unsigned int j = 0; j < N; ++j)
      rhs[j] = -residual[j];
    for (unsigned int e = 0; e < n_motions; ++e)
      rhs[N + e] = -pin_misfit[e];
    run_gmres(bordered, elimination, rhs, solution);
    update.reinit(N);
    std::copy(solution.begin(), solution.begin() + N, update.begin());
    motion_update.assign(solution.begin() + N, solution.end());
    if (prm.solver.verbose)
      {
        pcout << "        the motions:";
        for (const double m : motion_update)
          pcout << " " << m / scales.eps;
        pcout << " eps, the displacements by up to "
              << update.linfty_norm() / scales.eps << " eps" << std::endl;
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
    p.compute_update    = [this] { compute_moving_grid_update(); };
    p.update_negligible = [this] {
      double largest = update.linfty_norm();
      for (const double m : motion_update)
        largest = std::max(largest, std::abs(m));
      return largest <= negligible_update * grid->spacing();
    };
    p.update_norm = [this] {
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
      step_state(alpha);
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
    if (prm.solver.verbose)
      {
        // Newton's method assembles again; the misfits are only shown.
        assemble_moving_grid(false);
        for (unsigned int k = 0; k < grid->n_motions(); ++k)
          pcout << "      edge " << k << ": the gap at its pin misfits by "
                << pin_misfit[k] / scales.eps << " eps" << std::endl;
      }
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
  template void   BoundaryElementSolver<dim>::assemble_moving_grid(bool);   \
  template void   BoundaryElementSolver<dim>::compute_moving_grid_update(); \
  template double BoundaryElementSolver<dim>::pin_change(                   \
    const Vector<double> &, unsigned int) const;                            \
  template NewtonProblem BoundaryElementSolver<dim>::moving_grid_problem(); \
  template int           BoundaryElementSolver<dim>::solve_moving_grid();
  VISCOSLIDE_INSTANTIATE(2)
  VISCOSLIDE_INSTANTIATE(3)
#undef VISCOSLIDE_INSTANTIATE
} // namespace viscoslide

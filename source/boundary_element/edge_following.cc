// Newton's method on the graded grid with the contact edges among the
// unknowns (doc/boundary_element.md, Graded grid, The edges as unknowns).
#include <deal.II/lac/full_matrix.h>

#include <viscoslide/boundary_element/grid.h>
#include <viscoslide/boundary_element/solver.h>
#include <viscoslide/boundary_element/window_preconditioner.h>

#include <algorithm>
#include <cmath>

namespace viscoslide
{
  template <int dim>
  std::vector<double>
  BoundaryElementSolver<dim>::moved_boundaries(
    const std::vector<double>       &from,
    const std::pair<double, double> &from_edges,
    const double                     d_trail,
    const double                     d_lead)
  {
    const auto          shift = edge_shift(from_edges, d_trail, d_lead);
    std::vector<double> moved(from);
    for (double &b : moved)
      b += shift(b);
    return moved;
  }


  template <int dim>
  void
  BoundaryElementSolver<dim>::assemble_following_edges(const bool with_matrix)
  {
    if (with_matrix)
      {
        // Each edge's column by a difference: the grid moved by a
        // thousandth of its finest cell with the gaps kept, which changes
        // the indenter's height at the cells and, through the cells
        // between the edges, the compliance.
        assemble(false);
        const Vector<double> r0 = residual, g = gaps, u_kept = u;
        const auto           b                   = boundaries;
        const auto           e                   = grid_edges;
        auto                 kept_compliance     = std::move(compliance);
        auto                 kept_preconditioner = std::move(preconditioner);
        const double         step                = 1e-3 * dx;
        for (unsigned int k = 0; k < 2; ++k)
          {
            const double d_trail = k == 0 ? step : 0.,
                         d_lead  = k == 1 ? step : 0.;
            set_graded_cells(moved_boundaries(b, e, d_trail, d_lead),
                             {e.first + d_trail, e.second + d_lead},
                             g);
            assemble(false);
            edge_columns[k] = residual;
            edge_columns[k] -= r0;
            edge_columns[k] /= step;
          }
        set_graded_cells(b, e, g, std::move(kept_compliance));
        preconditioner = std::move(kept_preconditioner);
        u              = u_kept;
      }
    assemble(with_matrix);
    const double gc = prm.adhesion.contact_gap * law_range;
    for (unsigned int e = 0; e < 2; ++e)
      pin_misfit[e] = 0.5 * (gaps[focus[e] - 1] + gaps[focus[e]]) - gc;
  }


  template <int dim>
  void
  BoundaryElementSolver<dim>::compute_edge_following_update()
  {
    // The Jacobian bordered by the edges' columns and the gap equations,
    // by elimination: update = z + Z a, with J z = -r, J Z_k = -dr/de_k,
    // and a from the two gap equations. J is nearly singular along an
    // edge's translation; its solves carry that mode, the combination
    // cancels it.
    const unsigned int n = u.size();
    compute_update();
    std::array<Vector<double>, 2> Z;
    for (unsigned int k = 0; k < 2; ++k)
      {
        Vector<double> rhs(edge_columns[k]);
        rhs *= -1.;
        solve_linearized(rhs, Z[k]);
      }
    // The change of the gap equation of edge e by an update v (the gaps
    // move with the edges).
    const auto gap_change = [&](const Vector<double> &v, const unsigned int e) {
      const double d_delta = control.force_controlled ? v[n] : 0.;
      return -0.5 * (v[focus[e] - 1] + v[focus[e]]) - d_delta;
    };
    FullMatrix<double> M(2, 2), M_inverse(2, 2);
    Vector<double>     b(2), a(2);
    for (unsigned int e = 0; e < 2; ++e)
      {
        for (unsigned int k = 0; k < 2; ++k)
          M(e, k) = gap_change(Z[k], e);
        b[e] = -pin_misfit[e] - gap_change(update, e);
      }
    M_inverse.invert(M);
    M_inverse.vmult(a, b);
    for (unsigned int k = 0; k < 2; ++k)
      {
        update.add(a[k], Z[k]);
        edge_update[k] = a[k];
      }
  }


  template <int dim>
  NewtonProblem
  BoundaryElementSolver<dim>::edge_following_problem()
  {
    NewtonProblem p = newton_problem();
    p.assemble      = [this](const bool with_matrix) {
      assemble_following_edges(with_matrix);
    };
    p.residual_norm = [this] {
      const double r = residual_norm();
      return std::sqrt(r * r + (pin_misfit[0] * pin_misfit[0] +
                                pin_misfit[1] * pin_misfit[1]) /
                                 (scales.eps * scales.eps));
    };
    p.compute_update = [this] { compute_edge_following_update(); };
    p.update_norm    = [this] {
      return update.l2_norm() + std::abs(edge_update[0]) +
             std::abs(edge_update[1]);
    };
    p.remember_iterate = [this] {
      u0          = u;
      delta0      = delta;
      gaps0       = gaps;
      boundaries0 = boundaries;
      grid_edges0 = grid_edges;
    };
    p.step = [this](const double alpha) {
      const double d_trail = alpha * edge_update[0],
                   d_lead  = alpha * edge_update[1];
      delta                = delta0;
      set_graded_cells(
        moved_boundaries(boundaries0, grid_edges0, d_trail, d_lead),
        {grid_edges0.first + d_trail, grid_edges0.second + d_lead},
        gaps0);
      const unsigned int n = u.size();
      for (unsigned int j = 0; j < n; ++j)
        u[j] += alpha * update[j];
      if (control.force_controlled)
        delta += alpha * update[n];
    };
    return p;
  }


  template <int dim>
  int
  BoundaryElementSolver<dim>::solve_following_edges()
  {
    assemble(false);
    const std::vector<double>       b_start = boundaries;
    const std::pair<double, double> e_start = grid_edges;
    const Vector<double>            u_start = u, g_start = gaps;
    const double                    delta_start      = delta;
    const SurfaceQuantities         quantities_start = last_quantities;
    const auto                      restore          = [&] {
      delta = delta_start;
      set_graded_cells(b_start, e_start, g_start);
      u               = u_start;
      last_quantities = quantities_start;
      return -1;
    };
    // The grid about the edges of the start, so that the gap equations
    // hold there: solve() refits the grid only when an edge strays from
    // its focus by more than 0.5 dx/(ratio - 1), where the gap equations
    // would ask the zone to move by tens of cells against the grid.
    update_quantities();
    const double trail = last_quantities.x_trail, lead = last_quantities.x_lead;
    if (!(lead > trail))
      return restore(); // no contact
    if (std::abs(trail - grid_edges.first) > 0.25 * dx ||
        std::abs(lead - grid_edges.second) > 0.25 * dx)
      {
        make_graded_grid_about(trail, lead);
        assemble(false);
      }
    const unsigned int n = u.size();
    if (focus[0] < 1 || focus[1] >= n || focus[1] <= focus[0])
      return restore();
    const int its = newton(edge_following_problem(),
                           prm.solver.max_newton_iterations,
                           prm.solver.line_search,
                           prm.solver.verbose,
                           pcout);
    if (its < 0)
      return restore();
    ++grid_generation;
    last_newton_iterations = its;
    update_quantities();
    return its;
  }


  template std::vector<double>
  BoundaryElementSolver<2>::moved_boundaries(const std::vector<double> &,
                                             const std::pair<double, double> &,
                                             double,
                                             double);
  template void
  BoundaryElementSolver<2>::assemble_following_edges(bool);
  template void
  BoundaryElementSolver<2>::compute_edge_following_update();
  template NewtonProblem
  BoundaryElementSolver<2>::edge_following_problem();
  template int
  BoundaryElementSolver<2>::solve_following_edges();
} // namespace viscoslide

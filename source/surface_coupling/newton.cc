// SPDX-License-Identifier: LGPL-2.1-or-later
// Newton's method and the relaxation on the system bordered by the load
// control.
#include <viscoslide/numerics/mesh.h>
#include <viscoslide/numerics/mpi_gather.h>
#include <viscoslide/surface_coupling.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <map>

namespace viscoslide
{


  template <int dim>
  double
  SurfaceCoupling<dim>::residual_norm(const VectorType &rhs) const
  {
    const double r = rhs.l2_norm();
    return control.force_controlled ? std::hypot(r, force_mismatch) : r;
  }


  template <int dim>
  void
  SurfaceCoupling<dim>::solve_bordered(const LinearSolve &solve,
                                       const VectorType  &rhs,
                                       VectorType        &update)
  {
    VectorType x1;
    x1.reinit(rhs);
    solve(rhs, x1);
    delta_update = 0.;
    if (control.force_controlled)
      {
        VectorType x2;
        x2.reinit(rhs);
        solve(delta_coupling, x2);
        delta_update = (-force_mismatch - (delta_coupling * x1)) /
                       (delta_stiffness - (delta_coupling * x2));
        x1.add(-delta_update, x2);
      }
    update = x1;
  }


  template <int dim>
  void
  SurfaceCoupling<dim>::solve_bordered(
    ReusedFactorization                  &solver,
    const TrilinosWrappers::SparseMatrix &matrix,
    const VectorType                     &rhs,
    VectorType                           &update)
  {
    delta_update = 0.;
    if (control.force_controlled)
      delta_update = solver.solve_bordered(
        matrix, delta_coupling, delta_stiffness, rhs, -force_mismatch, update);
    else
      solver.solve(matrix, rhs, update);
  }


  template <int dim>
  NewtonProblem
  SurfaceCoupling<dim>::newton_problem(const System &system)
  {
    // The line search's start lives here, in the layout of the update.
    u0.reinit(system.update);
    delta0 = system.delta;
    NewtonProblem problem;
    problem.assemble      = system.assemble;
    problem.residual_norm = [this, &system] {
      return residual_norm(system.rhs);
    };
    problem.tolerance      = [this] { return tolerance(); };
    problem.compute_update = system.compute_update;
    return with_iterate(problem,
                        {system.solution,
                         system.delta,
                         system.update,
                         delta_update,
                         surface_damping,
                         relaxation_anchor},
                        u0,
                        delta0);
  }


  template <int dim>
  int
  SurfaceCoupling<dim>::newton(const System &system, ConditionalOStream &out)
  {
    return viscoslide::newton(newton_problem(system),
                              prm.solver.max_newton_iterations,
                              prm.solver.line_search,
                              prm.solver.verbose,
                              out);
  }


  template <int dim>
  int
  SurfaceCoupling<dim>::relax(const System &system, ConditionalOStream &out)
  {
    relaxation_anchor.reinit(system.solution);
    relaxing = true;
    const int steps =
      relax_surface(newton_problem(system), scales, prm.solver, out);
    surface_damping = 0.;
    relaxing        = false;
    return steps;
  }


  template class SurfaceCoupling<2>;
  template class SurfaceCoupling<3>;
} // namespace viscoslide

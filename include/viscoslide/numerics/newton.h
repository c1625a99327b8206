// SPDX-License-Identifier: LGPL-2.1-or-later
// Newton's method with backtracking on the residual norm, shared by the
// transient and the steady-state solvers.
#ifndef viscoslide_newton_h
#define viscoslide_newton_h

#include <deal.II/base/conditional_ostream.h>

#include <deal.II/lac/trilinos_solver.h>
#include <deal.II/lac/trilinos_sparse_matrix.h>

#include <viscoslide/io/input.h>
#include <viscoslide/physics/scales.h>

#include <functional>
#include <memory>

namespace viscoslide
{
  using namespace dealii;

  namespace Parameters
  {
    enum class LinearSolver
    {
      automatic,
      direct,
      iterative
    };
    VISCOSLIDE_CHOICES(LinearSolver, "automatic", "direct", "iterative")

    // How the iterative steady solver applies the inverse of its
    // displacement block A~: one multigrid V-cycle, a sparse factorization
    // (exact, its memory a factorization's), or the V-cycle where it
    // converges and the factorization beyond (Solver::factorizes()).
    enum class DisplacementBlock
    {
      automatic,
      multigrid,
      direct
    };
    VISCOSLIDE_CHOICES(DisplacementBlock, "automatic", "multigrid", "direct")

    // The 'Solver' section: Newton's method and its linear solves.
    struct Solver
    {
      LinearSolver      linear_solver;
      unsigned int      direct_solver_limit;
      DisplacementBlock displacement_block;
      double            newton_tolerance;
      unsigned int      max_newton_iterations;
      bool              line_search;
      unsigned int      max_relaxation_steps;
      bool              verbose;

      // Whether a Newton system of n unknowns goes to the direct solver:
      // 'direct', or 'automatic' up to direct_solver_limit.
      bool
      direct_for(const std::size_t n) const
      {
        return linear_solver == LinearSolver::direct ||
               (linear_solver == LinearSolver::automatic &&
                n <= direct_solver_limit);
      }

      // Whether the iterative steady solver factorizes A~ for a bulk
      // operator whose slowest arm's relaxation length V tau_k is `memory`
      // finest cells. In 3D one V-cycle on A~ converged at a quarter of a
      // cell (311 to 447 GMRES iterations per solve) and not at 0.375 or
      // 1.25 (V_hat 3 and 10 on 8-eps cells; at 10 A~ is indefinite in the
      // inflow layer), where the factorization took 40 to 78 and 72 to
      // 136 (doc/steady_state.md, The iterative linear solver).
      static constexpr double factorized_memory = 0.3;
      bool
      factorizes(const double memory) const
      {
        return displacement_block == DisplacementBlock::direct ||
               (displacement_block == DisplacementBlock::automatic &&
                memory >= factorized_memory);
      }

      static void
      declare(ParameterHandler &prm);
      void
      parse(ParameterHandler &prm);
    };
  } // namespace Parameters


  // What Newton's method needs of a problem. The iterate includes delta
  // under force control.
  struct NewtonProblem
  {
    // System residual, and the Jacobian if asked.
    std::function<void(bool with_matrix)> assemble;
    // Optional: the Jacobian alone, at the iterate whose residual the last
    // assemble(false) computed (the accepted trial of the line search),
    // where the residual costs as much as the Jacobian's setup (the
    // boundary elements' product with the compliance).
    std::function<void()>   assemble_matrix;
    std::function<double()> residual_norm;
    std::function<double()> tolerance;
    // The Newton update from the assembled system.
    std::function<void()> compute_update;
    // The update's norm, to catch a linear solve that gave Inf/NaN.
    std::function<double()> update_norm;
    // Remember the iterate a line search starts from ...
    std::function<void()> remember_iterate;
    // ... and set the iterate to it plus alpha times the update.
    std::function<void(double alpha)> step;
    // For relax(): a surface dashpot of stiffness c (per unit area)
    // anchored at the present iterate enters assemble() from now on; 0
    // removes it.
    std::function<void(double c)> set_dashpot;
    // Largest displacement in the update, for relax().
    std::function<double()> update_max_norm;
    // Whether the last update is as small as the round-off of the
    // residual can explain (optional: taken as true if not set). Where
    // no step reduces a residual within a few tolerances, Newton's method
    // takes the iterate only if so: a nearly singular Jacobian turns a
    // residual at the round-off into a large change of the solution.
    std::function<bool()> update_negligible;
    // The relative tolerance of the linear solve of the next update
    // (optional, for an iterative linear solver): newton() sets the
    // forcing term of the inexact Newton method before each update, 0
    // when it returns (the solver's own tolerance again).
    std::function<void(double eta)> set_forcing;
  };

  // Where a solver keeps its iterate (the displacements and, under force
  // control, delta), its Newton direction and its surface dashpot. Both
  // solvers hold the same members; with_iterate() builds the callbacks that
  // only move these around.
  struct NewtonIterate
  {
    TrilinosWrappers::MPI::Vector       &solution;
    double                              &delta;
    const TrilinosWrappers::MPI::Vector &update;
    const double                        &delta_update;
    double                              &surface_damping;
    TrilinosWrappers::MPI::Vector       &relaxation_anchor;
  };

  // Sets remember_iterate, step, set_dashpot, update_norm and
  // update_max_norm of `problem`; u0 and delta0 keep the iterate a line
  // search starts from and must outlive the problem.
  NewtonProblem
  with_iterate(NewtonProblem                  problem,
               const NewtonIterate           &iterate,
               TrilinosWrappers::MPI::Vector &u0,
               double                        &delta0);

  // Returns the iterations used, or -1: residual or update not finite, no
  // reduction along the update (with line search: within 8 halvings), the
  // line search cutting the step to 1/16 or less three times in a row, or
  // no convergence within max_iterations.
  int
  newton(const NewtonProblem &problem,
         unsigned int         max_iterations,
         bool                 line_search,
         bool                 verbose,
         ConditionalOStream  &out);

  // Pseudo-transient continuation (Kelley and Keyes 1998) for a state whose
  // equilibrium is not near, after a jump of the contact edge: each
  // pseudo-step is one Newton step on the system with a surface dashpot c
  // anchored at the present iterate. c starts at c0 and is steered by the
  // motion: steps that move the surface by more than `move` stiffen it,
  // shorter ones soften it, so that the iteration becomes plain Newton as
  // the equilibrium is reached, where newton() with its line search
  // finishes. Only an undamped equilibrium is accepted.
  // Returns the pseudo-steps used, or -1.
  int
  relax(const NewtonProblem &problem,
        double               c0,
        double               move,
        unsigned int         max_steps,
        bool                 verbose,
        ConditionalOStream  &out);

  // relax() of a surface held by the traction laws of these scales, as
  // every solver uses it: the dashpot starts as stiff as the Lennard-Jones
  // wall, 16 dgamma/eps^2, and a pseudo-step should move the surface by
  // about eps/2; the steps and the verbosity of the Solver section.
  int
  relax_surface(const NewtonProblem      &problem,
                const Scales             &scales,
                const Parameters::Solver &solver,
                ConditionalOStream       &out);
} // namespace viscoslide

#endif

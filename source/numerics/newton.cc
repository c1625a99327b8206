// SPDX-License-Identifier: LGPL-2.1-or-later
#include <deal.II/lac/solver_control.h>

#include <viscoslide/numerics/heartbeat.h>
#include <viscoslide/numerics/newton.h>

#include <algorithm>
#include <cmath>

namespace viscoslide
{
  namespace
  {
    // The forcing term of Eisenstat and Walker (1996, their choice 2): the
    // linear solve of a step need reduce its residual only as far as the
    // last Newton step reduced the nonlinear one (squared), so that the
    // early steps, far from the solution, take few iterations while the
    // convergence stays superlinear; safeguarded against a sudden drop
    // (not below 0.9 eta_before^2 while that is above 0.1), at most 0.1,
    // and never asking for less than a tenth of the Newton tolerance.
    double
    forcing_term(const double residual,
                 const double residual_before,
                 const double eta_before,
                 const double tolerance)
    {
      constexpr double eta_max = 0.1, gamma = 0.9;
      double           eta = eta_max;
      if (residual_before > 0)
        {
          const double ratio = residual / residual_before;
          eta                = gamma * ratio * ratio;
          const double guard = gamma * eta_before * eta_before;
          if (guard > 0.1)
            eta = std::max(eta, guard);
        }
      return std::min(eta_max, std::max(eta, 0.1 * tolerance / residual));
    }

    // Backtracking along the update from alpha = 1 (a single step without
    // line search) to the first step that reduces the residual enough:
    // that step, the residual there, and whether it was found.
    struct LineSearch
    {
      double alpha, residual;
      bool   reduced;
    };
    LineSearch
    search_line(const NewtonProblem &p,
                const double         residual,
                const bool           line_search,
                const bool           verbose,
                ConditionalOStream  &out)
    {
      double alpha = 1.;
      for (unsigned int k = 0; k < (line_search ? 8 : 1); ++k)
        {
          p.step(alpha);
          p.assemble(false);
          const double r = p.residual_norm();
          if (verbose && line_search)
            out << "        trial alpha = " << alpha << ": residual " << r
                << std::endl;
          if (std::isfinite(r) &&
              (r < (1. - 1e-4 * alpha) * residual || !line_search))
            {
              if (verbose)
                out << "        line search: alpha = " << alpha << std::endl;
              return {alpha, r, true};
            }
          alpha *= 0.5;
        }
      if (verbose)
        out << "        line search: alpha = " << alpha << std::endl;
      return {alpha, residual, false};
    }

    // The line search's accepted trial is the iterate, its residual
    // assembled: the Jacobian alone where the problem can set it up so.
    void
    assemble_at_trial(const NewtonProblem &p)
    {
      if (p.assemble_matrix)
        p.assemble_matrix();
      else
        p.assemble(true);
    }

    // Resets the forcing term of a problem when newton() returns.
    struct ForcingReset
    {
      const NewtonProblem &p;
      ~ForcingReset()
      {
        if (p.set_forcing)
          p.set_forcing(0.);
      }
    };
  } // namespace


  int
  newton(const NewtonProblem &p,
         const unsigned int   max_iterations,
         const bool           line_search,
         const bool           verbose,
         ConditionalOStream  &out)
  {
    p.assemble(true);
    double       residual = p.residual_norm();
    unsigned int crawling = 0; // consecutive steps cut to alpha <= 1/16
    Heartbeat    heartbeat;
    double       residual_before = 0, eta = 0;
    ForcingReset reset{p};
    for (unsigned int it = 0; it <= max_iterations; ++it)
      {
        if (!std::isfinite(residual))
          {
            out << "      Newton: residual is " << residual << " at iteration "
                << it << "\n";
            return -1;
          }
        const double tolerance = p.tolerance();
        if (verbose || heartbeat.due())
          out << "      Newton " << it << ": residual " << residual
              << " (tolerance " << tolerance << "), " << heartbeat.seconds()
              << " s in this solve" << std::endl;
        if (residual <= tolerance)
          return it;
        if (it == max_iterations)
          break;

        if (p.set_forcing)
          {
            eta = forcing_term(residual, residual_before, eta, tolerance);
            p.set_forcing(eta);
          }
        residual_before = residual;
        p.compute_update();
        if (!std::isfinite(p.update_norm()))
          {
            out << "      Newton: linear solve gave a non-finite update at "
                   "iteration "
                << it << "\n";
            return -1;
          }

        // Accept the first step that reduces the residual, else give up
        // (the caller cuts the step). Within a few tolerances the line
        // search sees only round-off (a graded grid's displacements are 1e4
        // eps and more): that is the equilibrium if the update is as small
        // as that round-off explains.
        p.remember_iterate();
        const auto [alpha, trial, reduced] =
          search_line(p, residual, line_search, verbose, out);
        const double round_off  = 10 * tolerance;
        const bool   negligible = !p.update_negligible || p.update_negligible();
        if (!reduced)
          {
            if (residual > round_off || !negligible)
              return -1;
            p.step(0.);
            p.assemble(true);
            return it;
          }
        // Steps cut this short three times in a row mean that no
        // equilibrium is near (a contact edge must jump): the caller's
        // relaxation gets there, and the iterations left would be spent
        // for nothing.
        crawling = alpha <= 1. / 16 ? crawling + 1 : 0;
        if (crawling == 3)
          {
            if (trial <= round_off && negligible)
              {
                assemble_at_trial(p);
                return it + 1;
              }
            if (verbose)
              out << "        Newton: steps cut to alpha <= 1/16 three times "
                     "in a row, given up"
                  << std::endl;
            return -1;
          }
        assemble_at_trial(p);
        residual = p.residual_norm();
      }
    return -1;
  }


  NewtonProblem
  with_iterate(NewtonProblem                  problem,
               const NewtonIterate           &it,
               TrilinosWrappers::MPI::Vector &u0,
               double                        &delta0)
  {
    problem.update_norm      = [it] { return it.update.l2_norm(); };
    problem.update_max_norm  = [it] { return it.update.linfty_norm(); };
    problem.remember_iterate = [it, &u0, &delta0] {
      u0     = it.solution;
      delta0 = it.delta;
    };
    problem.step = [it, &u0, &delta0](const double alpha) {
      TrilinosWrappers::MPI::Vector trial(u0);
      trial.add(alpha, it.update);
      it.solution = trial;
      it.delta    = delta0 + alpha * it.delta_update;
    };
    problem.set_dashpot = [it](const double c) {
      it.surface_damping = c;
      if (c > 0)
        it.relaxation_anchor = it.solution;
    };
    return problem;
  }


  int
  relax(const NewtonProblem &p,
        const double         c0,
        const double         move,
        const unsigned int   max_steps,
        const bool           verbose,
        ConditionalOStream  &out)
  {
    double c = c0;
    p.set_dashpot(0.);
    p.assemble(false);
    double    residual = p.residual_norm();
    Heartbeat heartbeat;
    for (unsigned int k = 0; k < max_steps; ++k)
      {
        if (residual <= p.tolerance())
          return k;
        // Once the dashpot has softened this far the pseudo-steps are
        // Newton's steps, and without a line search they can cycle about
        // the equilibrium (seen between two states of an edge node):
        // Newton's method with its line search finishes, or, failing, hands
        // back to a dashpot that acts again.
        if (c < 1e-4 * c0)
          {
            const int its =
              newton(p, std::min(20u, max_steps - k), true, verbose, out);
            if (its >= 0)
              return k + its;
            c = 1e-2 * c0;
            p.assemble(false);
            residual = p.residual_norm();
            if (!std::isfinite(residual))
              return -1;
          }
        p.set_dashpot(c); // anchored here: the dashpot force vanishes at u
        p.assemble(true);
        p.compute_update();
        p.remember_iterate();
        p.step(1.);
        const double moved = p.update_max_norm() / move;
        p.set_dashpot(0.);
        p.assemble(false);
        const double r = p.residual_norm();
        if (verbose || heartbeat.due())
          out << "      relaxation " << k << " (of at most " << max_steps
              << "): residual " << r << ", dashpot " << c << ", "
              << heartbeat.seconds() << " s in this solve" << std::endl;
        if (!std::isfinite(r) || !std::isfinite(moved))
          {
            p.step(0.);
            c *= 4.;
            if (c > 1e10 * c0)
              return -1;
            continue;
          }
        c = std::clamp(c * std::clamp(moved, 0.25, 4.), 1e-14 * c0, 1e10 * c0);
        residual = r;
      }
    return -1;
  }


  int
  relax_surface(const NewtonProblem      &problem,
                const Scales             &scales,
                const Parameters::Solver &solver,
                ConditionalOStream       &out)
  {
    return relax(problem,
                 16. * scales.dgamma / (scales.eps * scales.eps),
                 0.5 * scales.eps,
                 solver.max_relaxation_steps,
                 solver.verbose,
                 out);
  }


  namespace Parameters
  {
    void
    Solver::declare(ParameterHandler &prm)
    {
      prm.enter_subsection("Solver");
      prm.declare_entry("Linear solver",
                        "automatic",
                        Patterns::Selection(choice_pattern<LinearSolver>()),
                        "'direct': MUMPS, one factorization per bulk operator, "
                        "through which every Newton system is solved exactly "
                        "(doc/model.md, Linear solver). "
                        "'iterative': GMRES with algebraic multigrid (ML); "
                        "in the steady-state solver with the viscous strain "
                        "swept in the flow direction (doc/steady_state.md, "
                        "The iterative linear solver). 'automatic': direct "
                        "up to Direct solver limit unknowns (in 3D also "
                        "only while its factors fit in four fifths of the "
                        "memory), iterative above; the 2D steady state "
                        "always direct.");
      prm.declare_entry("Direct solver limit",
                        "500000",
                        Patterns::Integer(1),
                        "See Linear solver.");
      prm.declare_entry(
        "Displacement block",
        "automatic",
        Patterns::Selection(choice_pattern<DisplacementBlock>()),
        "The iterative steady-state solver's inverse of its displacement "
        "block A~: 'multigrid', one V-cycle of algebraic multigrid (ML); "
        "'direct', a sparse factorization of A~ (MUMPS, on all "
        "processes): exact, GMRES then needs few iterations at every "
        "speed, but its memory grows as a factorization's; 'automatic', "
        "the V-cycle while the slowest arm's relaxation length V tau "
        "stays below 0.3 finest cells, and the factorization at "
        "faster speeds and wherever a V-cycle did not converge "
        "(doc/steady_state.md, The iterative linear solver).");
      prm.declare_entry("Newton tolerance",
                        "1e-9",
                        Patterns::Double(),
                        "Newton converges when the residual norm falls "
                        "below this times the total absolute surface "
                        "traction (plus one finest cell loaded with "
                        "sigma_max).");
      prm.declare_entry("Maximum Newton iterations",
                        "25",
                        Patterns::Integer(1),
                        "Newton iterations before the step is cut.");
      prm.declare_entry("Line search",
                        "true",
                        Patterns::Bool(),
                        "Backtracking line search on the residual norm.");
      prm.declare_entry("Maximum relaxation steps",
                        "400",
                        Patterns::Integer(1),
                        "Pseudo-time steps allowed to land on a new branch "
                        "after a surface instability.");
      prm.leave_subsection();
    }

    void
    Solver::parse(ParameterHandler &prm)
    {
      prm.enter_subsection("Solver");
      linear_solver       = parse_choice<LinearSolver>(prm.get("Linear solver"),
                                                 "Solver/Linear solver");
      direct_solver_limit = prm.get_integer("Direct solver limit");
      displacement_block =
        parse_choice<DisplacementBlock>(prm.get("Displacement block"),
                                        "Solver/Displacement block");
      newton_tolerance      = prm.get_double("Newton tolerance");
      max_newton_iterations = prm.get_integer("Maximum Newton iterations");
      line_search           = prm.get_bool("Line search");
      max_relaxation_steps  = prm.get_integer("Maximum relaxation steps");
      prm.leave_subsection();
      require(newton_tolerance > 0 && newton_tolerance < 1,
              entry("Solver", "Newton tolerance", newton_tolerance) +
                " must be in (0, 1)");
    }
  } // namespace Parameters
} // namespace viscoslide

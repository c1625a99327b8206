#include <deal.II/base/mpi.h>
#include <deal.II/base/timer.h>

#include <deal.II/lac/solver_control.h>
#include <deal.II/lac/solver_gmres.h>

#include <viscoslide/linear_solver.h>

#include <algorithm>

namespace viscoslide
{
  std::unique_ptr<TrilinosWrappers::SolverDirect>
  factorize(const TrilinosWrappers::SparseMatrix &matrix)
  {
    static SolverControl control(1, 0);
    auto solver = std::make_unique<TrilinosWrappers::SolverDirect>(
      control,
      TrilinosWrappers::SolverDirect::AdditionalData(false, "Amesos_Mumps"));
    solver->initialize(matrix);
    return solver;
  }


  ReusedFactorization::ReusedFactorization(TimerOutput &timer, MPI_Comm comm)
    : timer(timer)
    , comm(comm)
  {
  }


  void
  ReusedFactorization::matrix_changed(const double bulk)
  {
    current        = false;
    assembled_bulk = bulk;
  }


  void
  ReusedFactorization::clear()
  {
    direct.reset();
    current = false;
  }


  template <typename F>
  double
  ReusedFactorization::timed(const F &f) const
  {
    Timer clock;
    f();
    return Utilities::MPI::max(clock.wall_time(), comm);
  }


  bool
  ReusedFactorization::worth_reusing() const
  {
    return direct && !current && factorized_bulk == assembled_bulk &&
           last_iterations * iteration_cost < factorization_cost;
  }


  void
  ReusedFactorization::solve(const TrilinosWrappers::SparseMatrix &matrix,
                             const TrilinosWrappers::MPI::Vector  &rhs,
                             TrilinosWrappers::MPI::Vector        &x)
  {
    if (worth_reusing() && solve_with_earlier(matrix, rhs, x))
      return;
    const bool first_solve = !current;
    if (!current)
      {
        TimerOutput::Scope t(timer, "linear: factorize");
        factorization_cost = timed([&] { direct = factorize(matrix); });
        current            = true;
        factorized_bulk    = assembled_bulk;
        last_iterations    = 0;
        ++factorizations;
      }
    TimerOutput::Scope t(timer, "linear: back-substitution");
    const double       cost = timed([&] { direct->solve(x, rhs); });
    if (first_solve)
      iteration_cost = cost;
  }


  bool
  ReusedFactorization::solve_with_earlier(
    const TrilinosWrappers::SparseMatrix &matrix,
    const TrilinosWrappers::MPI::Vector  &rhs,
    TrilinosWrappers::MPI::Vector        &x)
  {
    TimerOutput::Scope t(timer, "linear: GMRES on an earlier factorization");
    struct Preconditioner
    {
      TrilinosWrappers::SolverDirect &factorization;
      void
      vmult(TrilinosWrappers::MPI::Vector       &dst,
            const TrilinosWrappers::MPI::Vector &src) const
      {
        factorization.solve(dst, src);
      }
    } preconditioner{*direct};
    // Give up once GMRES has cost as much as a new factorization. A
    // relative 1e-4 is enough for Newton's method, which judges the
    // residual itself.
    const unsigned int max_iterations = static_cast<unsigned int>(
      std::clamp(factorization_cost / iteration_cost, 2., 50.));
    SolverControl control(max_iterations, 1e-4 * rhs.l2_norm());
    SolverGMRES<TrilinosWrappers::MPI::Vector> gmres(
      control,
      SolverGMRES<TrilinosWrappers::MPI::Vector>::AdditionalData(
        max_iterations + 2));
    x                      = 0.;
    bool         converged = true;
    const double spent     = timed([&] {
      try
        {
          gmres.solve(matrix, x, rhs, preconditioner);
        }
      catch (const SolverControl::NoConvergence &)
        {
          converged = false;
        }
    });
    last_iterations        = std::max(1u, control.last_step());
    iteration_cost         = spent / last_iterations;
    krylov_iterations += control.last_step();
    if (!converged)
      last_iterations = max_iterations;
    return converged;
  }
} // namespace viscoslide

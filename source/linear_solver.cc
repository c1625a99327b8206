#include <deal.II/lac/solver_control.h>
#include <deal.II/lac/solver_gmres.h>

#include <viscoslide/linear_solver.h>

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


  ReusedFactorization::ReusedFactorization(TimerOutput &timer)
    : timer(timer)
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


  void
  ReusedFactorization::solve(const TrilinosWrappers::SparseMatrix &matrix,
                             const TrilinosWrappers::MPI::Vector  &rhs,
                             TrilinosWrappers::MPI::Vector        &x)
  {
    if (direct && !current && factorized_bulk == assembled_bulk &&
        solve_with_earlier(matrix, rhs, x))
      return;
    if (!current)
      {
        TimerOutput::Scope t(timer, "linear: factorize");
        direct          = factorize(matrix);
        current         = true;
        factorized_bulk = assembled_bulk;
        ++factorizations;
      }
    TimerOutput::Scope t(timer, "linear: back-substitution");
    direct->solve(x, rhs);
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
    SolverControl control(max_reuse_iterations, 1e-4 * rhs.l2_norm());
    SolverGMRES<TrilinosWrappers::MPI::Vector> gmres(
      control,
      SolverGMRES<TrilinosWrappers::MPI::Vector>::AdditionalData(
        max_reuse_iterations + 2));
    x = 0.;
    try
      {
        gmres.solve(matrix, x, rhs, preconditioner);
        krylov_iterations += control.last_step();
        return true;
      }
    catch (const SolverControl::NoConvergence &)
      {
        return false;
      }
  }
} // namespace viscoslide

// The direct solver of both solvers' Newton systems, with the
// factorization of one Jacobian reused for the next ones.
#ifndef viscoslide_linear_solver_h
#define viscoslide_linear_solver_h

#include <deal.II/base/timer.h>

#include <deal.II/lac/trilinos_solver.h>
#include <deal.II/lac/trilinos_sparse_matrix.h>
#include <deal.II/lac/trilinos_vector.h>

#include <memory>

namespace viscoslide
{
  using namespace dealii;

  // MUMPS factorization of a Newton matrix, for solves with several
  // right-hand sides [linear_solver.cc].
  std::unique_ptr<TrilinosWrappers::SolverDirect>
  factorize(const TrilinosWrappers::SparseMatrix &matrix);

  // At a given mesh the bulk operator is linear and fixed by one number,
  // the speed (steady state) or the time step (transient): between Newton
  // iterations only the surface terms of the Jacobian change, on the few
  // hundred dofs near the contact. So the factorization of one Jacobian
  // preconditions GMRES for the later Jacobians of the same bulk operator,
  // which then costs a few back-substitutions instead of a new
  // factorization. A new one is made when the bulk changed, or when GMRES
  // does not converge within max_reuse_iterations [linear_solver.cc].
  class ReusedFactorization
  {
  public:
    explicit ReusedFactorization(TimerOutput &timer);

    // The matrix was assembled anew, for the bulk operator named by
    // `bulk` (the speed or the time step).
    void
    matrix_changed(double bulk);

    // The mesh changed: the factorization refers to the old matrix.
    void
    clear();

    void
    solve(const TrilinosWrappers::SparseMatrix &matrix,
          const TrilinosWrappers::MPI::Vector  &rhs,
          TrilinosWrappers::MPI::Vector        &x);

    // Counters for the log and the benchmarks.
    unsigned int factorizations = 0, krylov_iterations = 0;

  private:
    static constexpr unsigned int max_reuse_iterations = 30;

    bool
    solve_with_earlier(const TrilinosWrappers::SparseMatrix &matrix,
                       const TrilinosWrappers::MPI::Vector  &rhs,
                       TrilinosWrappers::MPI::Vector        &x);

    TimerOutput                                    &timer;
    std::unique_ptr<TrilinosWrappers::SolverDirect> direct;
    // Whether `direct` is the factorization of the matrix as assembled
    // last, and the bulk operator it was made for.
    bool   current         = false;
    double factorized_bulk = 0.;
    double assembled_bulk  = 0.;
  };
} // namespace viscoslide

#endif

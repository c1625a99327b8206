// The direct solver of both solvers' Newton systems, with the
// factorization of one Jacobian reused for the next ones.
#ifndef viscoslide_linear_solver_h
#define viscoslide_linear_solver_h

#include <deal.II/base/mpi.h>
#include <deal.II/base/timer.h>

#include <deal.II/lac/trilinos_sparse_matrix.h>
#include <deal.II/lac/trilinos_vector.h>

#include <memory>

class Amesos_BaseSolver;
class Epetra_LinearProblem;

namespace viscoslide
{
  using namespace dealii;

  // Wall time of f, the same on every process of comm (their maximum), so
  // that a choice steered by measured costs takes the same branch on all
  // of them (their timer sections synchronize).
  template <typename F>
  double
  timed(const F &f, const MPI_Comm comm)
  {
    Timer clock;
    f();
    return Utilities::MPI::max(clock.wall_time(), comm);
  }

  // MUMPS, through Trilinos Amesos. Its analysis (the fill-reducing
  // ordering and the symbolic factorization) depends on the sparsity
  // pattern only, and on these meshes it costs about as much as the
  // numerical factorization itself; so it is kept for every later matrix of
  // the same pattern, until clear(). Since that choice depends on the
  // pattern alone, not on timings, the results stay the same on every
  // machine.
  class SparseDirect
  {
  public:
    SparseDirect();
    ~SparseDirect();

    void
    factorize(const TrilinosWrappers::SparseMatrix &matrix);

    void
    solve(TrilinosWrappers::MPI::Vector       &x,
          const TrilinosWrappers::MPI::Vector &b) const;

    // The next matrix may have another sparsity pattern.
    void
    clear();

    bool
    factorized() const;

  private:
    std::unique_ptr<Epetra_LinearProblem> problem;
    std::unique_ptr<Amesos_BaseSolver>    mumps;
    // The pattern the analysis was made for, by its size: a cheap guard,
    // since clear() is the contract.
    long long int analysed_rows = -1, analysed_nonzeros = -1;
    bool          has_factorization = false;
  };

  // At a given mesh the bulk operator is linear and fixed by one number,
  // the speed (steady state) or the time step (transient): between Newton
  // iterations only the surface terms of the Jacobian change, on the few
  // hundred dofs near the contact. So the factorization of one Jacobian
  // preconditions GMRES for the later Jacobians of the same bulk operator.
  // Whether that is cheaper than a new factorization depends on the mesh
  // and on how far the contact moved since, so the choice is steered by
  // the measured costs: GMRES is tried while its expected cost (the
  // iterations it needed last, at the measured cost of one) is below that
  // of the last factorization, and is given up for a new factorization as
  // soon as it has spent as much [linear_solver.cc].
  class ReusedFactorization
  {
  public:
    // With reuse = false every new matrix is factorized: the transient
    // solver's states are path-dependent (a contact edge that jumps from
    // node to node can land on either of two neighbouring equilibria), and
    // there the exact solves keep its results independent of the costs
    // measured on a given machine.
    ReusedFactorization(TimerOutput &timer, MPI_Comm comm, bool reuse = true);

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

    // The bordered system of force control,
    //   [K   b] [x]   [r]
    //   [b^T d] [t] = [m],
    // for K = matrix; returns t. With a reusable factorization, one GMRES
    // on the whole system, preconditioned by the bordered system of the
    // factorized matrix; else two back-substitutions of a factorization
    // of K.
    double
    solve_bordered(const TrilinosWrappers::SparseMatrix &matrix,
                   const TrilinosWrappers::MPI::Vector  &b,
                   double                                d,
                   const TrilinosWrappers::MPI::Vector  &r,
                   double                                m,
                   TrilinosWrappers::MPI::Vector        &x);

    // Counters for the log and the benchmarks.
    unsigned int factorizations = 0, krylov_iterations = 0;

  private:
    // The border of the factorized matrix and K0^-1 b0, for the
    // preconditioner of the bordered system.
    struct Border
    {
      TrilinosWrappers::MPI::Vector b, w;
      double                        d     = 0.;
      bool                          valid = false;
    };

    bool
    worth_reusing() const;
    void
    factorize_if_needed(const TrilinosWrappers::SparseMatrix &matrix);
    template <typename VectorType, typename Matrix, typename Preconditioner>
    bool
    gmres(const Matrix         &matrix,
          const Preconditioner &preconditioner,
          const VectorType     &rhs,
          VectorType           &x);

    TimerOutput &timer;
    MPI_Comm     comm;
    const bool   reuse;
    SparseDirect direct;
    // Whether `direct` is the factorization of the matrix as assembled
    // last, and the bulk operator it was made for.
    bool   current         = false;
    double factorized_bulk = 0.;
    double assembled_bulk  = 0.;
    // Measured: the last factorization, one GMRES iteration (at first one
    // back-substitution), and the iterations GMRES needed last.
    double       factorization_cost = 0., iteration_cost = 0.;
    unsigned int last_iterations = 0;
    Border       border;
  };
} // namespace viscoslide

#endif

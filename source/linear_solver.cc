#include <deal.II/base/mpi.h>
#include <deal.II/base/timer.h>

#include <deal.II/lac/solver_control.h>
#include <deal.II/lac/solver_gmres.h>
#include <deal.II/lac/trilinos_parallel_block_vector.h>

#include <viscoslide/linear_solver.h>

#include <Amesos.h>
#include <Amesos_BaseSolver.h>
#include <Epetra_LinearProblem.h>

#include <algorithm>

namespace viscoslide
{
  namespace
  {
    using Vector      = TrilinosWrappers::MPI::Vector;
    using BlockVector = TrilinosWrappers::MPI::BlockVector;

    // The bordered system's unknowns: x in block 0, the scalar t in block
    // 1 (one entry, owned by the first process).
    double
    scalar(const BlockVector &v)
    {
      return v.block(1).mean_value();
    }

    BlockVector
    bordered_vector(const Vector &x, const double t, const MPI_Comm comm)
    {
      IndexSet one(1);
      if (Utilities::MPI::this_mpi_process(comm) == 0)
        one.add_index(0);
      BlockVector v(std::vector<IndexSet>{x.locally_owned_elements(), one},
                    comm);
      v.block(0) = x;
      v.block(1) = t;
      return v;
    }

    // [K b; b^T d]
    struct BorderedMatrix
    {
      const TrilinosWrappers::SparseMatrix &K;
      const Vector                         &b;
      const double                          d;

      void
      vmult(BlockVector &y, const BlockVector &x) const
      {
        const double t = scalar(x);
        K.vmult(y.block(0), x.block(0));
        y.block(0).add(t, b);
        y.block(1) = (b * x.block(0)) + d * t;
      }
    };

    // The inverse of [K0 b0; b0^T d0] from the factorization of K0 and
    // w0 = K0^-1 b0, by block elimination: one back-substitution.
    struct BorderedFactorization
    {
      const SparseDirect &K0;
      const Vector       &b0, &w0;
      const double        schur; // d0 - b0 . w0

      void
      vmult(BlockVector &y, const BlockVector &x) const
      {
        K0.solve(y.block(0), x.block(0));
        const double t = (scalar(x) - b0 * y.block(0)) / schur;
        y.block(0).add(-t, w0);
        y.block(1) = t;
      }
    };

    struct Factorization
    {
      const SparseDirect &K0;

      void
      vmult(Vector &y, const Vector &x) const
      {
        K0.solve(y, x);
      }
    };
  } // namespace


  SparseDirect::SparseDirect()
    : problem(std::make_unique<Epetra_LinearProblem>())
  {
  }


  SparseDirect::~SparseDirect() = default;


  void
  SparseDirect::clear()
  {
    mumps.reset();
    has_factorization = false;
  }


  bool
  SparseDirect::factorized() const
  {
    return has_factorization;
  }


  void
  SparseDirect::factorize(const TrilinosWrappers::SparseMatrix &matrix)
  {
    const Epetra_CrsMatrix &A = matrix.trilinos_matrix();
    if (mumps && (A.NumGlobalRows64() != analysed_rows ||
                  A.NumGlobalNonzeros64() != analysed_nonzeros))
      clear();
    has_factorization = false;
    problem->SetOperator(const_cast<Epetra_CrsMatrix *>(&A));
    if (!mumps)
      {
        mumps.reset(Amesos().Create("Amesos_Mumps", *problem));
        AssertThrow(mumps, ExcMessage("Trilinos has no Amesos_Mumps"));
        AssertThrow(mumps->SymbolicFactorization() == 0,
                    ExcMessage("MUMPS analysis failed"));
        analysed_rows     = A.NumGlobalRows64();
        analysed_nonzeros = A.NumGlobalNonzeros64();
      }
    AssertThrow(mumps->NumericFactorization() == 0,
                ExcMessage("MUMPS factorization failed"));
    has_factorization = true;
  }


  void
  SparseDirect::solve(Vector &x, const Vector &b) const
  {
    problem->SetLHS(&x.trilinos_vector());
    problem->SetRHS(const_cast<Epetra_MultiVector *>(&b.trilinos_vector()));
    AssertThrow(mumps->Solve() == 0, ExcMessage("MUMPS solve failed"));
  }


  ReusedFactorization::ReusedFactorization(TimerOutput &timer,
                                           MPI_Comm     comm,
                                           const bool   reuse)
    : timer(timer)
    , comm(comm)
    , reuse(reuse)
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
    direct.clear();
    current      = false;
    border.valid = false;
  }


  bool
  ReusedFactorization::worth_reusing() const
  {
    return reuse && direct.factorized() && !current &&
           factorized_bulk == assembled_bulk &&
           last_iterations * iteration_cost < factorization_cost;
  }


  void
  ReusedFactorization::factorize_if_needed(
    const TrilinosWrappers::SparseMatrix &matrix)
  {
    if (current)
      return;
    TimerOutput::Scope t(timer, "linear: factorize");
    factorization_cost = timed([&] { direct.factorize(matrix); }, comm);
    current            = true;
    factorized_bulk    = assembled_bulk;
    last_iterations    = 0;
    border.valid       = false;
    iteration_cost     = 0.;
    ++factorizations;
  }


  void
  ReusedFactorization::solve(const TrilinosWrappers::SparseMatrix &matrix,
                             const Vector                         &rhs,
                             Vector                               &x)
  {
    if (worth_reusing() && gmres(matrix, Factorization{direct}, rhs, x))
      return;
    factorize_if_needed(matrix);
    TimerOutput::Scope t(timer, "linear: back-substitution");
    const double       cost = timed([&] { direct.solve(x, rhs); }, comm);
    if (iteration_cost == 0.)
      iteration_cost = cost;
  }


  double
  ReusedFactorization::solve_bordered(
    const TrilinosWrappers::SparseMatrix &matrix,
    const Vector                         &b,
    const double                          d,
    const Vector                         &r,
    const double                          m,
    Vector                               &x)
  {
    if (worth_reusing() && border.valid)
      {
        BlockVector       y   = bordered_vector(x, 0., comm);
        const BlockVector rhs = bordered_vector(r, m, comm);
        if (gmres(BorderedMatrix{matrix, b, d},
                  BorderedFactorization{
                    direct, border.b, border.w, border.d - border.b * border.w},
                  rhs,
                  y))
          {
            x = y.block(0);
            return scalar(y);
          }
      }
    // Exact: x = K^-1 r - t K^-1 b. K^-1 b and the border are kept for the
    // preconditioner of the next matrices.
    Vector w;
    w.reinit(r);
    solve(matrix, r, x);
    solve(matrix, b, w);
    const double t = (m - b * x) / (d - b * w);
    x.add(-t, w);
    if (reuse)
      {
        border.b.reinit(b);
        border.b     = b;
        border.w     = w;
        border.d     = d;
        border.valid = true;
      }
    return t;
  }


  // GMRES to a relative 1e-4, enough for Newton's method, which judges the
  // residual itself; given up once it has cost as much as a new
  // factorization.
  template <typename VectorType, typename Matrix, typename Preconditioner>
  bool
  ReusedFactorization::gmres(const Matrix         &matrix,
                             const Preconditioner &preconditioner,
                             const VectorType     &rhs,
                             VectorType           &x)
  {
    TimerOutput::Scope t(timer, "linear: GMRES on an earlier factorization");
    const unsigned int max_iterations = static_cast<unsigned int>(
      std::clamp(factorization_cost / iteration_cost, 2., 50.));
    SolverControl           control(max_iterations, 1e-4 * rhs.l2_norm());
    SolverGMRES<VectorType> solver(
      control,
      typename SolverGMRES<VectorType>::AdditionalData(max_iterations + 2));
    x                      = 0.;
    bool         converged = true;
    const double spent     = timed(
      [&] {
        try
          {
            solver.solve(matrix, x, rhs, preconditioner);
          }
        catch (const SolverControl::NoConvergence &)
          {
            converged = false;
          }
      },
      comm);
    last_iterations = std::max(1u, control.last_step());
    iteration_cost  = spent / last_iterations;
    krylov_iterations += control.last_step();
    if (!converged)
      last_iterations = max_iterations;
    return converged;
  }
} // namespace viscoslide

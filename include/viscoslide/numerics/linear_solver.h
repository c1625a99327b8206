// SPDX-License-Identifier: LGPL-2.1-or-later
// The direct solver of both solvers' Newton systems: one sparse
// factorization per bulk operator, condensed onto the surface.
#ifndef viscoslide_linear_solver_h
#define viscoslide_linear_solver_h

#include <deal.II/base/index_set.h>
#include <deal.II/base/mpi.h>
#include <deal.II/base/timer.h>

#include <deal.II/lac/full_matrix.h>
#include <deal.II/lac/lapack_full_matrix.h>
#include <deal.II/lac/trilinos_sparse_matrix.h>
#include <deal.II/lac/trilinos_vector.h>
#include <deal.II/lac/vector.h>

#include <functional>
#include <memory>
#include <vector>

class Epetra_CrsMatrix;

namespace viscoslide
{
  using namespace dealii;

  // MUMPS through its own C interface (Amesos does not reach its Schur
  // complement): the factorization of a matrix A whose unknowns split into
  // the interior I and a few unknowns T, with the Schur complement
  //   S = A_TT - A_TI A_II^-1 A_IT
  // returned dense on the first process (the host). Its analysis (the
  // fill-reducing ordering and the symbolic factorization) depends on the
  // sparsity pattern and T only, so it is kept until clear().
  class SparseDirect
  {
  public:
    explicit SparseDirect(MPI_Comm comm);
    ~SparseDirect();

    // The ordering and symbolic factorization for the pattern of `matrix`
    // with the Schur unknowns T (global indices, ascending, the same on
    // every process); kept until clear().
    void
    analyse(const TrilinosWrappers::SparseMatrix &matrix,
            const std::vector<int>               &T);
    bool
    analysed() const
    {
      return mumps != nullptr;
    }
    // The numerical factorization of a matrix of the analysed pattern.
    void
    factorize(const TrilinosWrappers::SparseMatrix &matrix);

    // Drops the analysis: the next matrix may have another pattern or T.
    void
    clear();

    // On the host: S, row by row, and T (global indices, ascending).
    const std::vector<double> &
    schur_complement() const
    {
      return schur;
    }

    // The forward elimination of b, on the host: b_T - A_TI A_II^-1 b_I.
    std::vector<double>
    reduce(const TrilinosWrappers::MPI::Vector &b);
    // After reduce(b), the solution x with x_T given (on the host):
    // x_I = A_II^-1 (b_I - A_IT x_T).
    void
    expand(const std::vector<double> &x_T, TrilinosWrappers::MPI::Vector &x);

  private:
    void
    call(int job, const char *what);

    MPI_Comm comm;
    struct Mumps;
    std::unique_ptr<Mumps> mumps;
    // The local entries in MUMPS's coordinate format (1-based).
    std::vector<int>    rows, columns;
    std::vector<double> values;
    std::vector<int>    schur_list; // 1-based
    std::vector<double> schur;
    // The right-hand side gathered on the host, kept from reduce() to
    // expand(); the locally owned ranges of all processes.
    std::vector<double> gathered;
    std::vector<int>    counts, offsets;
    std::vector<double> reduced;
    // Operations per second of the last factorization (its own count over
    // its wall time), for the time left of the next; 0 before the first.
    double flop_rate = 0;
  };

  // The surface terms on the window T as functions of the unknowns of T
  // alone, the rest of the system held by the linear bulk: the model on
  // which ReusedFactorization iterates Newton's method between two sparse
  // substitutions.
  struct WindowTerms
  {
    dealii::Vector<double> rhs; // their part of -R on the rows of T
    // -d rhs / d x_T by its entries, which may repeat: a face couples only
    // its own unknowns, so a dense k x k matrix would be nearly empty.
    struct Entry
    {
      unsigned int row, column;
      double       value;
    };
    std::vector<Entry>     tangent;
    dealii::Vector<double> border; // b_T = -d rhs / d delta
    // Their part of G = F_n - target (up to a constant), and dG / d delta.
    double force = 0., stiffness = 0.;
  };

  struct WindowModel
  {
    // On the host: the terms with the unknowns of T moved by x_T (in the
    // order of T) and delta by t. Empty where no model serves (the
    // relaxation's dashpot): one linear solve then.
    std::function<WindowTerms(const dealii::Vector<double> &x_T, double t)>
      terms;
    // The residual norm that Newton's method accepts.
    double tolerance = 0.;
  };

  // Collective: the model of the present iterate for the window T (global
  // indices, ascending).
  using WindowModelBuilder =
    std::function<WindowModel(const std::vector<int> &T)>;

  // At a given mesh the bulk operator is linear and fixed by one number,
  // the speed (steady state) or the time step (transient): between Newton
  // iterations only the surface terms of the Jacobian change, and they act
  // on the u_y unknowns of the top surface alone
  // (SurfaceCoupling::surface_unknowns()), appreciably only in the window
  // T of them where the traction law is stiff
  // (SurfaceCoupling::surface_window(), a few hundred). So the first
  // Jacobian A of a bulk operator is factorized with its Schur complement S
  // on T, and every later Jacobian J = A + D of that operator is solved
  // with it: MUMPS's forward elimination reduces the right-hand side to T,
  // a dense LU of S + D_TT solves on T, and MUMPS's back-substitution
  // expands the solution. The solve is exact but for the changes of the
  // surface terms outside T, which are below 1e-3 of the matrix's diagonal
  // (else a new window is factorized): Newton's method, which judges the
  // residual itself, is unaffected, and the results do not depend on a
  // choice between solvers.
  //
  // Given a WindowModel, the dense stage does more than one linear solve:
  // with the bulk linear, the reduced system on T is
  //   y - S_b x_T + F_T(x_T, t) - F_T(0, 0) = 0,
  //   S_b = S - (surface tangent of A on T x T),
  // exact but for the surface terms outside T, and Newton's method with
  // a line search solves it (and G = 0 under force control) on the host,
  // each iteration a dense LU. The sparse substitutions are done once per
  // call. So the slow iterations where a contact edge moves node by node,
  // and the nonlinear ones of the traction law's wall, cost dense work on
  // a few hundred unknowns instead of sparse work on the whole block.
  class ReusedFactorization
  {
  public:
    ReusedFactorization(TimerOutput &timer, MPI_Comm comm);

    // After every setup: the locally owned surface unknowns, on whose rows
    // alone two Jacobians of one bulk operator may differ and on which the
    // border of solve_bordered() lives, and the function that picks the
    // window T among them at the present iterate. Drops the factorization.
    void
    reinit(const IndexSet           &surface_unknowns,
           std::function<IndexSet()> window,
           WindowModelBuilder        model = {});

    // The matrix was assembled anew, for the bulk operator named by
    // `bulk` (the speed or the time step).
    void
    matrix_changed(double bulk);

    // Makes `system` the matrix `bulk` (whose pattern it shares) of the
    // bulk operator named by `bulk_id` again, before a Newton iteration
    // adds its surface terms, and calls matrix_changed(bulk_id). Only the
    // surface unknowns' rows are copied if `system` holds that operator
    // already (since reinit()): its other rows are the bulk's, and copying
    // the whole matrix costs more.
    void
    load_bulk(const TrilinosWrappers::SparseMatrix &bulk,
              TrilinosWrappers::SparseMatrix       &system,
              double                                bulk_id);

    void
    solve(const TrilinosWrappers::SparseMatrix &matrix,
          const TrilinosWrappers::MPI::Vector  &rhs,
          TrilinosWrappers::MPI::Vector        &x);

    // The bordered system of force control,
    //   [K   b] [x]   [r]
    //   [b^T d] [t] = [m],
    // for K = matrix and b zero outside the surface unknowns; returns t.
    // Where b reaches outside T (an attractive law's tail beyond a capped
    // 3D window) by two solves of the linear window system instead of
    // one: t from K z = r and K w = b, x = z - t w.
    double
    solve_bordered(const TrilinosWrappers::SparseMatrix &matrix,
                   const TrilinosWrappers::MPI::Vector  &b,
                   double                                d,
                   const TrilinosWrappers::MPI::Vector  &r,
                   double                                m,
                   TrilinosWrappers::MPI::Vector        &x);

    // Counters for the log and the benchmarks.
    unsigned int factorizations = 0, surface_solves = 0, window_iterations = 0;

  private:
    // An owned entry of a surface row, in the order surface_block() visits
    // them: its row and column positions in T (-1: outside), and its row's
    // index among the owned surface rows.
    struct Entry
    {
      int          row, column;
      unsigned int surface_row;
    };

    // On the host, per process: (row, column, value) of D = J_TT - A_TT,
    // and (row, value) of the border b_T; on every process, whether a
    // change outside T asks for a new window.
    struct SurfaceTerms
    {
      std::vector<double> change, border;
      bool                outside_window = false;
    };

    void
    restore_surface_rows(const TrilinosWrappers::SparseMatrix &bulk,
                         TrilinosWrappers::SparseMatrix       &system) const;
    void
    factorize_if_needed(const TrilinosWrappers::SparseMatrix &matrix);
    void
    factorize(const TrilinosWrappers::SparseMatrix &matrix);
    // The position of global index i in T, or -1.
    int
    position(long long int i) const;
    std::vector<double>
    surface_block(const TrilinosWrappers::SparseMatrix &matrix, bool record);
    // The dense window system of solve_condensed(), on the first process.
    LAPACKFullMatrix<double>
    window_matrix(const SurfaceTerms &terms, bool bordered, double d) const;
    SurfaceTerms
    gather_surface_terms(const TrilinosWrappers::SparseMatrix &matrix,
                         const TrilinosWrappers::MPI::Vector  *b);
    bool
    border_outside_window(const TrilinosWrappers::MPI::Vector &b) const;
    double
    solve_by_superposition(const SurfaceTerms                  &terms,
                           const TrilinosWrappers::MPI::Vector &b,
                           double                               d,
                           const TrilinosWrappers::MPI::Vector &r,
                           double                               m,
                           TrilinosWrappers::MPI::Vector       &x);
    double
    solve_condensed(const TrilinosWrappers::SparseMatrix &matrix,
                    const TrilinosWrappers::MPI::Vector  *b,
                    double                                d,
                    const TrilinosWrappers::MPI::Vector  &r,
                    double                                m,
                    TrilinosWrappers::MPI::Vector        &x);

    TimerOutput &timer;
    MPI_Comm     comm;
    SparseDirect direct;
    // The owned surface unknowns; the window T (all processes', ascending)
    // and the function that picks it.
    IndexSet                  surface;
    std::size_t               surface_size = 0; // on all processes
    std::vector<int>          window_list;
    std::function<IndexSet()> choose_window;
    WindowModelBuilder        build_model;
    // Whether `direct` holds a factorization of the present bulk operator.
    bool   factorized      = false;
    double factorized_bulk = 0.;
    double assembled_bulk  = 0.;
    // The bulk operator whose matrix the system matrix holds off the
    // surface rows (-1: none since reinit()).
    double system_bulk = -1.;
    // The owned surface rows of the factorized matrix, where their entries
    // go, and the magnitude of each row's diagonal.
    std::vector<Entry>  entries;
    std::vector<double> factorized_block, diagonal;
  };
} // namespace viscoslide

#endif

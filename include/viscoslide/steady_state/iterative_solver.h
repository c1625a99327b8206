// SPDX-License-Identifier: LGPL-2.1-or-later
// The steady state's Newton systems solved by a Krylov method, for meshes
// beyond the sparse direct solver (a 3D block): GMRES on the whole system
//   J = [A B]   displacement rows
//       [C D]   viscous-strain rows
// right-preconditioned by the block triangular
//   P = [A~ B]
//       [0  D],
// in which
// * D, the strain's upwind advection and reaction, is inverted exactly by
//   a sweep over the cells in the flow direction (step-63): a cell's rows
//   couple only to the cells upstream of it, so in that order D is block
//   lower triangular; across processes the sweep is block Jacobi (the
//   inflow from another process's cells is left out);
// * A~ = A - sum_K B_K D_K^-1 C_K, D_K the block of D in cell K, is the
//   displacement block with each cell's strain eliminated without its
//   inflow (exact in the relaxed and the instantaneous limits), surface
//   terms included, approximated by one V-cycle of smoothed-aggregation
//   AMG (Trilinos ML) with the translations and the linear displacement
//   fields (rotations and shears) as near null space, smoothed by
//   Chebyshev where A~ is nearly symmetric and by damped Gauss-Seidel
//   where the strain's memory makes it far from symmetric; or factorized
//   (Parameters::Solver::factorizes()).
// The spectrum of J P^-1 is 1 and that of S A~^-1, S = A - B D^-1 C the
// solid's true displacement operator. What A~ leaves out, the strain's
// memory over V tau downstream, costs little; the iterations grow with
// speed because the V-cycle approximates A~ worse where V tau nears a
// cell, and at nu near 1/2 it is slow already at rest
// (doc/steady_state.md, "The iterative linear solver").
// doc/steady_state.md ("The linear solver") has the design and its
// measured iteration counts.
#ifndef viscoslide_steady_state_iterative_solver_h
#define viscoslide_steady_state_iterative_solver_h

#include <deal.II/base/index_set.h>
#include <deal.II/base/mpi.h>
#include <deal.II/base/timer.h>

#include <deal.II/dofs/dof_handler.h>

#include <deal.II/lac/full_matrix.h>
#include <deal.II/lac/solver_control.h>
#include <deal.II/lac/solver_gmres.h>
#include <deal.II/lac/trilinos_sparse_matrix.h>
#include <deal.II/lac/trilinos_vector.h>

#include <viscoslide/numerics/newton.h>

#include <memory>
#include <vector>

class Epetra_CrsMatrix;
class Epetra_Map;
namespace ML_Epetra
{
  class MultiLevelPreconditioner;
}

namespace viscoslide
{
  using namespace dealii;

  template <int dim>
  class SteadyIterativeSolver
  {
  public:
    SteadyIterativeSolver(TimerOutput              &timer,
                          MPI_Comm                  comm,
                          const Parameters::Solver &parameters);
    ~SteadyIterativeSolver();

    // After every setup: which unknowns are displacements (components 0 to
    // dim - 1 of the element) and which strain cells they belong to, and
    // the near null space at the displacements' support points.
    void
    reinit(const DoFHandler<dim> &dof_handler);

    // The system matrix was assembled anew; `bulk` names its bulk operator
    // (the speed), on which A~'s strain part depends alone, and `memory`
    // is that operator's longest relaxation length V tau_k over the finest
    // cell, which chooses the V-cycle's smoother or the factorization.
    void
    matrix_changed(double bulk, double memory);

    // x = J^-1 b to a relative 1e-10 of |b|, x's start ignored. A solve
    // that does not converge leaves GMRES's last iterate: Newton's method
    // judges it by the residual. Within one bulk operator the last A~ is
    // tried first and rebuilt only when GMRES needs more than twice the
    // iterations of the last solve with a fresh one (and 20), or at once
    // when that solve took half GMRES's limit of 1000. Under 'automatic'
    // a V-cycle that does not converge is replaced by the factorization,
    // for this bulk operator and every one with a longer memory.
    void
    solve(const TrilinosWrappers::SparseMatrix &matrix,
          const TrilinosWrappers::MPI::Vector  &b,
          TrilinosWrappers::MPI::Vector        &x);

    // Counters for the log and the benchmarks.
    unsigned int solves = 0, iterations = 0, setups = 0;

    // The preconditioner: x = P^-1 r (GMRES's interface).
    void
    vmult(TrilinosWrappers::MPI::Vector       &x,
          const TrilinosWrappers::MPI::Vector &r) const;

  private:
    // D's rows of one strain component in one cell: their positions among
    // the owned unknowns, the inverse of their diagonal block, and their
    // couplings to the owned cells upstream.
    struct StrainBlock
    {
      std::vector<unsigned int> rows;
      FullMatrix<double>        inverse;
      std::vector<unsigned int> upstream_row, upstream_column;
      std::vector<double>       upstream_value;
    };

    void
    setup(const TrilinosWrappers::SparseMatrix &matrix);
    void
    setup_strain_blocks(const TrilinosWrappers::SparseMatrix &matrix);
    void
    setup_displacement_block(const TrilinosWrappers::SparseMatrix &matrix);
    // B D^-1 C, the strain eliminated cell by cell (made once: B, C and D
    // do not change with the Newton iterate).
    void
    eliminate_strains(const TrilinosWrappers::SparseMatrix &matrix);
    // A - B D^-1 C on the owned displacement rows.
    void
    assemble_displacement_block(const TrilinosWrappers::SparseMatrix &matrix);
    std::vector<bool>
    displacement_columns(const Epetra_CrsMatrix &m) const;
    // A line every 10 s of a long solve: its residual and the time left.
    void
    report_progress(SolverGMRES<TrilinosWrappers::MPI::Vector> &solver,
                    const SolverControl                        &control) const;
    // GMRES to 1e-10 of |b| in at most max_steps: its steps, and whether
    // it converged.
    std::pair<unsigned int, bool>
    gmres(const TrilinosWrappers::SparseMatrix &matrix,
          const TrilinosWrappers::MPI::Vector  &b,
          TrilinosWrappers::MPI::Vector        &x,
          unsigned int                          max_steps);
    // z_e = D^-1 r_e on the owned strain rows (positions among the owned
    // unknowns), by the sweep.
    void
    sweep(const TrilinosWrappers::MPI::Vector &r,
          TrilinosWrappers::MPI::Vector       &z) const;

    TimerOutput              &timer;
    MPI_Comm                  comm;
    const Parameters::Solver &parameters;

    IndexSet owned;
    // The owned displacement unknowns, node by node (the dim components of
    // a support point together, as ML's PDE equations ask), and their
    // positions among the owned unknowns.
    std::vector<types::global_dof_index> displacement;
    std::vector<unsigned int>            displacement_position;
    // The strain blocks in sweep order (upstream first).
    std::vector<StrainBlock> blocks;
    // The near null space, mode by mode over `displacement`.
    std::vector<double> near_null_space;
    unsigned int        n_modes = 0;

    // sum_K B_K D_K^-1 C_K for the bulk `strain_bulk` (-1: none).
    std::unique_ptr<Epetra_CrsMatrix> relaxation;
    double                            strain_bulk    = -1.;
    double                            assembled_bulk = 0., memory = 0.;
    // Whether A~ is factorized, and the shortest memory at which a V-cycle
    // did not converge.
    bool   factorized    = false;
    double failed_memory = 1e300;
    bool   set_up        = false;
    // A~ is that of an earlier Newton matrix of the same bulk operator;
    // the last solve with a fresh one took fresh_iterations.
    bool                                                 stale = false;
    unsigned int                                         fresh_iterations = 0;
    std::unique_ptr<Epetra_Map>                          map;
    std::unique_ptr<Epetra_CrsMatrix>                    block;
    std::unique_ptr<ML_Epetra::MultiLevelPreconditioner> amg;
    // The matrix of the present solve, and vmult()'s work vectors.
    const TrilinosWrappers::SparseMatrix *system = nullptr;
    mutable TrilinosWrappers::MPI::Vector strain_part, coupled;
  };
} // namespace viscoslide

#endif

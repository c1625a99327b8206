// SPDX-License-Identifier: LGPL-2.1-or-later
// SteadyIterativeSolver: GMRES with the block triangular preconditioner of
// the header, the strain block by a sweep, the displacement block by ML.
#include <deal.II/base/conditional_ostream.h>
#include <deal.II/base/quadrature.h>

#include <deal.II/fe/fe_values.h>
#include <deal.II/fe/mapping_q1.h>

#include <deal.II/lac/full_matrix.h>
#include <deal.II/lac/solver_control.h>
#include <deal.II/lac/solver_gmres.h>
#include <deal.II/lac/trilinos_index_access.h>

#include <viscoslide/io/output.h>
#include <viscoslide/numerics/heartbeat.h>
#include <viscoslide/steady_state/iterative_solver.h>

#include <EpetraExt_MatrixMatrix.h>
#include <Epetra_CrsMatrix.h>
#include <Epetra_Map.h>
#include <Epetra_MpiComm.h>
#include <Epetra_Vector.h>
#include <ml_MultiLevelPreconditioner.h>

#include <algorithm>
#include <cmath>
#include <numeric>

namespace viscoslide
{
  template <int dim>
  SteadyIterativeSolver<dim>::SteadyIterativeSolver(
    TimerOutput              &timer,
    MPI_Comm                  comm,
    const Parameters::Solver &parameters)
    : timer(timer)
    , comm(comm)
    , parameters(parameters)
  {
  }


  template <int dim>
  SteadyIterativeSolver<dim>::~SteadyIterativeSolver() = default;


  namespace
  {
    // The near null space of the displacement at point p, component c:
    // the dim translations and the dim^2 linear fields x_j e_c, which hold
    // the rotations and also the shears. A nearly incompressible solid's
    // softest smooth errors are shears (divergence-free), which
    // aggregates of rigid-body modes alone represent poorly.
    template <int dim>
    std::vector<double>
    near_null_space_values(const Point<dim> &p, const unsigned int c)
    {
      std::vector<double> v(dim + dim * dim, 0.);
      v[c] = 1.;
      for (unsigned int j = 0; j < dim; ++j)
        v[dim + c * dim + j] = p[j];
      return v;
    }
  } // namespace


  template <int dim>
  void
  SteadyIterativeSolver<dim>::reinit(const DoFHandler<dim> &dof_handler)
  {
    const FiniteElement<dim> &fe   = dof_handler.get_fe();
    const FiniteElement<dim> &u_fe = fe.base_element(0);
    owned                          = dof_handler.locally_owned_dofs();
    displacement.clear();
    displacement_position.clear();
    blocks.clear();
    near_null_space.clear();
    n_modes = dim + dim * dim;

    // The displacement's support points on a cell: the quadrature points
    // of a formula whose points are the base element's support points.
    const Quadrature<dim> support(u_fe.get_unit_support_points());
    const MappingQ1<dim>  mapping;
    FEValues<dim> points(mapping, fe, support, update_quadrature_points);
    std::vector<types::global_dof_index> dofs(fe.n_dofs_per_cell());
    std::vector<bool>                    seen(owned.n_elements(), false);
    std::vector<std::vector<double>>     modes(n_modes);
    // The owned cells' strain rows by component, and the x of the cells'
    // centres for the sweep order.
    const unsigned int n_strain_components = fe.n_components() - dim;
    std::vector<std::pair<double, StrainBlock>> cells;
    for (const auto &cell : dof_handler.active_cell_iterators())
      {
        if (!cell->is_locally_owned())
          continue;
        cell->get_dof_indices(dofs);
        points.reinit(cell);
        for (unsigned int k = 0; k < u_fe.n_dofs_per_cell(); ++k)
          {
            const types::global_dof_index first =
              dofs[fe.component_to_system_index(0, k)];
            if (!owned.is_element(first) || seen[owned.index_within_set(first)])
              continue;
            for (unsigned int c = 0; c < dim; ++c)
              {
                const types::global_dof_index g =
                  dofs[fe.component_to_system_index(c, k)];
                seen[owned.index_within_set(g)] = true;
                displacement.push_back(g);
                displacement_position.push_back(owned.index_within_set(g));
                const std::vector<double> v =
                  near_null_space_values(points.quadrature_point(k), c);
                for (unsigned int m = 0; m < n_modes; ++m)
                  modes[m].push_back(v[m]);
              }
          }
        std::vector<StrainBlock> of_cell(n_strain_components);
        for (unsigned int i = 0; i < dofs.size(); ++i)
          if (const unsigned int c = fe.system_to_component_index(i).first;
              c >= dim)
            of_cell[c - dim].rows.push_back(owned.index_within_set(dofs[i]));
        for (auto &b : of_cell)
          cells.emplace_back(cell->center()[0], std::move(b));
      }
    // Material flows towards -x: the cells of larger x are upstream.
    std::stable_sort(cells.begin(),
                     cells.end(),
                     [](const auto &a, const auto &b) {
                       return a.first > b.first;
                     });
    for (auto &c : cells)
      blocks.push_back(std::move(c.second));
    for (const auto &m : modes)
      near_null_space.insert(near_null_space.end(), m.begin(), m.end());

    std::vector<int> gids(displacement.begin(), displacement.end());
    map = std::make_unique<Epetra_Map>(
      -1, static_cast<int>(gids.size()), gids.data(), 0, Epetra_MpiComm(comm));
    strain_part.reinit(owned, comm);
    coupled.reinit(owned, comm);
    set_up      = false;
    strain_bulk = -1.;
    amg.reset();
    block.reset();
    relaxation.reset();
  }


  // A new bulk operator changes the whole preconditioner. Within one, a
  // new Newton matrix differs from the last only in its surface terms,
  // and the old A~ is tried first (solve()).
  template <int dim>
  void
  SteadyIterativeSolver<dim>::matrix_changed(const double bulk,
                                             const double bulk_memory)
  {
    if (bulk != strain_bulk)
      set_up = false;
    stale          = set_up;
    assembled_bulk = bulk;
    memory         = bulk_memory;
  }


  // D's blocks from the strain rows of the matrix: the diagonal block
  // inverted, the couplings to other owned strain blocks kept.
  template <int dim>
  void
  SteadyIterativeSolver<dim>::setup_strain_blocks(
    const TrilinosWrappers::SparseMatrix &matrix)
  {
    const Epetra_CrsMatrix &m = matrix.trilinos_matrix();
    // the block of each owned strain row, and its place in the block
    std::vector<int>          block_of(owned.n_elements(), -1);
    std::vector<unsigned int> slot_of(owned.n_elements(), 0);
    for (unsigned int b = 0; b < blocks.size(); ++b)
      for (unsigned int i = 0; i < blocks[b].rows.size(); ++i)
        {
          block_of[blocks[b].rows[i]] = b;
          slot_of[blocks[b].rows[i]]  = i;
        }
    for (unsigned int b = 0; b < blocks.size(); ++b)
      {
        StrainBlock       &block = blocks[b];
        const unsigned int n     = block.rows.size();
        FullMatrix<double> diagonal(n, n);
        block.upstream_row.clear();
        block.upstream_column.clear();
        block.upstream_value.clear();
        for (unsigned int i = 0; i < n; ++i)
          {
            const int row = m.RowMap().LID(
              static_cast<int>(owned.nth_index_in_set(block.rows[i])));
            int     n_entries;
            double *values;
            int    *columns;
            m.ExtractMyRowView(row, n_entries, values, columns);
            for (int k = 0; k < n_entries; ++k)
              {
                const types::global_dof_index g =
                  TrilinosWrappers::global_index(m.ColMap(), columns[k]);
                if (!owned.is_element(g))
                  continue; // upstream on another process: block Jacobi
                const unsigned int p = owned.index_within_set(g);
                if (block_of[p] == static_cast<int>(b))
                  diagonal(i, slot_of[p]) += values[k];
                else if (block_of[p] >= 0)
                  {
                    block.upstream_row.push_back(i);
                    block.upstream_column.push_back(p);
                    block.upstream_value.push_back(values[k]);
                  }
              }
          }
        diagonal.gauss_jordan();
        block.inverse = std::move(diagonal);
      }
  }


  template <int dim>
  void
  SteadyIterativeSolver<dim>::sweep(const TrilinosWrappers::MPI::Vector &r,
                                    TrilinosWrappers::MPI::Vector &z) const
  {
    const double  *rv = r.trilinos_vector()[0];
    double        *zv = z.trilinos_vector()[0];
    Vector<double> rhs, x;
    for (const StrainBlock &b : blocks)
      {
        const unsigned int n = b.rows.size();
        rhs.reinit(n, true);
        x.reinit(n, true);
        for (unsigned int i = 0; i < n; ++i)
          rhs(i) = rv[b.rows[i]];
        for (unsigned int e = 0; e < b.upstream_row.size(); ++e)
          rhs(b.upstream_row[e]) -=
            b.upstream_value[e] * zv[b.upstream_column[e]];
        b.inverse.vmult(x, rhs);
        for (unsigned int i = 0; i < n; ++i)
          zv[b.rows[i]] = x(i);
      }
  }


  // Whether each column of m is a displacement unknown, asked of the
  // displacement map's directory: a row's columns reach beyond the ghost
  // cells (through hanging nodes and through D_K^-1), so what this process
  // knows of its neighbours does not decide it.
  template <int dim>
  std::vector<bool>
  SteadyIterativeSolver<dim>::displacement_columns(
    const Epetra_CrsMatrix &m) const
  {
    const Epetra_Map &columns = m.ColMap();
    const int         n       = columns.NumMyElements();
    std::vector<int>  owner(n), local(n);
    map->RemoteIDList(n,
                      columns.MyGlobalElements(),
                      owner.data(),
                      local.data());
    std::vector<bool> is_displacement(n);
    for (int k = 0; k < n; ++k)
      is_displacement[k] = owner[k] >= 0;
    return is_displacement;
  }


  template <int dim>
  void
  SteadyIterativeSolver<dim>::eliminate_strains(
    const TrilinosWrappers::SparseMatrix &matrix)
  {
    // B D_K^-1 C as J (D_K^-1 J), D_K^-1 the inverses of D's diagonal
    // blocks on the strain rows (zero on the displacement's).
    const Epetra_CrsMatrix &j = matrix.trilinos_matrix();
    Epetra_CrsMatrix        inverse(Copy, j.RowMap(), 0);
    std::vector<int>        columns;
    for (const StrainBlock &b : blocks)
      {
        columns.clear();
        for (const unsigned int p : b.rows)
          columns.push_back(owned.nth_index_in_set(p));
        for (unsigned int i = 0; i < b.rows.size(); ++i)
          inverse.InsertGlobalValues(columns[i],
                                     columns.size(),
                                     &b.inverse(i, 0),
                                     columns.data());
      }
    inverse.FillComplete(j.DomainMap(), j.RangeMap());
    Epetra_CrsMatrix eliminated(Copy, j.RowMap(), 0);
    EpetraExt::MatrixMatrix::Multiply(inverse, false, j, false, eliminated);
    relaxation = std::make_unique<Epetra_CrsMatrix>(Copy, j.RowMap(), 0);
    EpetraExt::MatrixMatrix::Multiply(j, false, eliminated, false, *relaxation);
  }


  template <int dim>
  void
  SteadyIterativeSolver<dim>::assemble_displacement_block(
    const TrilinosWrappers::SparseMatrix &matrix)
  {
    const Epetra_CrsMatrix &a       = matrix.trilinos_matrix();
    const Epetra_CrsMatrix &r       = *relaxation;
    const std::vector<bool> kept_a  = displacement_columns(a);
    const std::vector<bool> kept_r  = displacement_columns(r);
    unsigned int            longest = 0;
    for (int row = 0; row < a.NumMyRows(); ++row)
      longest = std::max<unsigned int>(longest, a.NumMyEntries(row));
    block = std::make_unique<Epetra_CrsMatrix>(Copy, *map, longest);
    std::vector<std::pair<int, double>> entries;
    std::vector<int>                    columns;
    std::vector<double>                 values;
    const auto                          add_row = [&](const Epetra_CrsMatrix  &m,
                             const std::vector<bool> &kept,
                             const int                g,
                             const double             factor) {
      const int row = m.RowMap().LID(g);
      int       n;
      double   *v;
      int      *c;
      m.ExtractMyRowView(row, n, v, c);
      for (int k = 0; k < n; ++k)
        if (kept[c[k]])
          entries.emplace_back(TrilinosWrappers::global_index(m.ColMap(), c[k]),
                               factor * v[k]);
    };
    for (const types::global_dof_index g : displacement)
      {
        entries.clear();
        add_row(a, kept_a, g, 1.);
        add_row(r, kept_r, g, -1.);
        std::sort(entries.begin(), entries.end());
        columns.clear();
        values.clear();
        for (const auto &[col, value] : entries)
          if (!columns.empty() && columns.back() == col)
            values.back() += value;
          else
            {
              columns.push_back(col);
              values.push_back(value);
            }
        block->InsertGlobalValues(static_cast<int>(g),
                                  columns.size(),
                                  values.data(),
                                  columns.data());
      }
    block->FillComplete(*map, *map);
  }


  // A~ = A - sum_K B_K D_K^-1 C_K on the owned displacement rows, node by
  // node, and ML's hierarchy on it.
  template <int dim>
  void
  SteadyIterativeSolver<dim>::setup_displacement_block(
    const TrilinosWrappers::SparseMatrix &matrix)
  {
    if (!relaxation)
      eliminate_strains(matrix);
    amg.reset(); // before the matrix it was built on
    assemble_displacement_block(matrix);

    Teuchos::ParameterList list;
    ML_Epetra::SetDefaults("SA", list);
    list.set("ML output", 0);
    // The smoother. Where the strain's memory reaches a hundredth of a
    // cell, the strain eliminated cell by cell makes A~ far from
    // symmetric (at V tau_k an eighth of a cell its symmetric part,
    // inverted exactly, takes GMRES 278 iterations on A~), and Chebyshev,
    // whose polynomial assumes a real spectrum, smooths it poorly: there
    // Gauss-Seidel, damped by 0.6 (undamped, ML's Gauss-Seidel, Jacobi
    // between processes, stalls on two). Below, A~ is nearly symmetric
    // and Chebyshev, which does not weaken between processes, costs less
    // (doc/benchmark.md, Damped Gauss-Seidel where A~ is far from
    // symmetric).
    if (memory >= 0.01)
      {
        list.set("smoother: type", "Gauss-Seidel");
        list.set("smoother: damping factor", 0.6);
      }
    else
      list.set("smoother: type", "Chebyshev");
    // Four sweeps: at nu = 0.49 fewer iterations than two, at about the
    // same cost.
    list.set("smoother: sweeps", 4);
    list.set("aggregation: threshold", 0.02);
    list.set("coarse: type", "Amesos-KLU");
    list.set("coarse: max size", 2000);
    list.set("PDE equations", dim);
    list.set("null space: type", "pre-computed");
    list.set("null space: dimension", static_cast<int>(n_modes));
    list.set("null space: vectors", near_null_space.data());
    // One level: ML applies its coarse solver to A~ itself, MUMPS
    // factorizing it on all processes.
    factorized = parameters.factorizes(memory) || memory >= failed_memory;
    if (factorized)
      {
        list.set("max levels", 1);
        list.set("coarse: type", "Amesos-MUMPS");
      }
    amg =
      std::make_unique<ML_Epetra::MultiLevelPreconditioner>(*block, list, true);
  }


  template <int dim>
  void
  SteadyIterativeSolver<dim>::setup(
    const TrilinosWrappers::SparseMatrix &matrix)
  {
    TimerOutput::Scope t(timer, "linear: preconditioner setup");
    if (strain_bulk != assembled_bulk)
      {
        setup_strain_blocks(matrix);
        relaxation.reset();
        strain_bulk = assembled_bulk;
      }
    setup_displacement_block(matrix);
    set_up = true;
    stale  = false;
    ++setups;
  }


  template <int dim>
  void
  SteadyIterativeSolver<dim>::vmult(
    TrilinosWrappers::MPI::Vector       &x,
    const TrilinosWrappers::MPI::Vector &r) const
  {
    // x_e = D^-1 r_e, then x_u = A~^-1 (r_u - B x_e).
    strain_part = 0.;
    sweep(r, strain_part);
    system->vmult(coupled, strain_part);
    const unsigned int n  = displacement.size();
    const double      *rv = r.trilinos_vector()[0];
    const double      *cv = coupled.trilinos_vector()[0];
    Epetra_Vector      in(*map), out(*map);
    for (unsigned int i = 0; i < n; ++i)
      in[i] = rv[displacement_position[i]] - cv[displacement_position[i]];
    amg->ApplyInverse(in, out);
    x          = strain_part;
    double *xv = x.trilinos_vector()[0];
    for (unsigned int i = 0; i < n; ++i)
      xv[displacement_position[i]] = out[i];
  }


  template <int dim>
  void
  SteadyIterativeSolver<dim>::solve(
    const TrilinosWrappers::SparseMatrix &matrix,
    const TrilinosWrappers::MPI::Vector  &b,
    TrilinosWrappers::MPI::Vector        &x)
  {
    if (!set_up)
      setup(matrix);
    system = &matrix;
    // A stale A~ may cost at most twice the iterations of the last fresh
    // one (and 20); beyond, A~ is rebuilt and the solve begins again. Where
    // that would reach GMRES's limit, A~ is rebuilt at once.
    const unsigned int limit       = 1000,
                       stale_limit = std::max(20U, 2 * fresh_iterations);
    if (stale && stale_limit < limit && gmres(matrix, b, x, stale_limit).second)
      return;
    if (stale)
      setup(matrix);
    const auto [steps, converged] = gmres(matrix, b, x, limit);
    fresh_iterations              = steps;
    if (converged || factorized ||
        parameters.displacement_block !=
          Parameters::DisplacementBlock::automatic)
      return;
    failed_memory = memory;
    ConditionalOStream(std::cout, Utilities::MPI::this_mpi_process(comm) == 0)
      << "        GMRES with one V-cycle on A~ did not converge in " << limit
      << " iterations: A~ factorized from here on\n";
    setup(matrix);
    fresh_iterations = gmres(matrix, b, x, limit).first;
  }


  template <int dim>
  void
  SteadyIterativeSolver<dim>::report_progress(
    SolverGMRES<TrilinosWrappers::MPI::Vector> &solver,
    const SolverControl                        &control) const
  {
    // Every 10 s: the residual against the target, and the time left at
    // the mean rate of decrease so far.
    solver.connect([this, &control, heartbeat = Heartbeat(), first = -1.](
                     const unsigned int step,
                     const double       residual,
                     const TrilinosWrappers::MPI::Vector &) mutable {
      if (first < 0)
        first = residual;
      if (step > 0 && heartbeat.due())
        {
          const double per_step = heartbeat.seconds() / step,
                       rate     = std::log(residual / first) / step,
                       at_limit = (control.max_steps() - step) * per_step,
                       left =
                         rate < 0
                           ? std::min(std::log(control.tolerance() / residual) /
                                        rate * per_step,
                                      at_limit)
                           : at_limit;
          ConditionalOStream(std::cout,
                             Utilities::MPI::this_mpi_process(comm) == 0)
            << "        GMRES " << step << ": residual " << residual
            << " (target " << control.tolerance() << "), "
            << format_duration(heartbeat.seconds()) << " in this solve, ~"
            << format_duration(left) << " left" << std::endl;
        }
      return SolverControl::success; // leaves the decision to `control`
    });
  }


  template <int dim>
  std::pair<unsigned int, bool>
  SteadyIterativeSolver<dim>::gmres(
    const TrilinosWrappers::SparseMatrix &matrix,
    const TrilinosWrappers::MPI::Vector  &b,
    TrilinosWrappers::MPI::Vector        &x,
    const unsigned int                    max_steps)
  {
    TimerOutput::Scope t(timer, "linear: block-preconditioned GMRES");
    SolverControl      control(max_steps, 1e-10 * b.l2_norm());
    using Solver = SolverGMRES<TrilinosWrappers::MPI::Vector>;
    Solver::AdditionalData data(100, true);
    Solver                 solver(control, data);
    report_progress(solver, control);
    x              = 0.;
    bool converged = true;
    try
      {
        solver.solve(matrix, x, b, *this);
      }
    catch (const SolverControl::NoConvergence &)
      {
        converged = false;
      }
    ++solves;
    iterations += control.last_step();
    return {control.last_step(), converged};
  }


  template class SteadyIterativeSolver<2>;
  template class SteadyIterativeSolver<3>;
} // namespace viscoslide

// SPDX-License-Identifier: LGPL-2.1-or-later
#include <deal.II/dofs/dof_tools.h>

#include <deal.II/fe/fe_values.h>

#include <deal.II/lac/vector.h>

#include <viscoslide/io/field_recovery.h>

namespace viscoslide
{
  template <int dim>
  FieldRecovery<dim>::FieldRecovery(const DoFHandler<dim> &solver_dofs)
    : solver_dofs(solver_dofs)
    , fe(1)
    , dofs(solver_dofs.get_triangulation())
  {
    dofs.distribute_dofs(fe);
    owned = dofs.locally_owned_dofs();
    DoFTools::extract_locally_relevant_dofs(dofs, relevant);
    constraints.reinit(relevant);
    DoFTools::make_hanging_node_constraints(dofs, constraints);
    constraints.close();
  }


  template <int dim>
  std::vector<TrilinosWrappers::MPI::Vector>
  FieldRecovery<dim>::recover(const Quadrature<dim> &quadrature,
                              const unsigned int     n_fields,
                              const CellValues      &values) const
  {
    const MPI_Comm comm = dofs.get_triangulation().get_communicator();
    FEValues<dim>  fe_values(fe, quadrature, update_values | update_JxW_values);
    const unsigned int                   n = fe.n_dofs_per_cell();
    std::vector<types::global_dof_index> indices(n);
    std::vector<std::vector<double>>     v(n_fields,
                                       std::vector<double>(quadrature.size()));
    // Row k < n_fields: int psi_j f_k; row n_fields: int psi_j.
    std::vector<TrilinosWrappers::MPI::Vector> moment(n_fields + 1);
    for (auto &m : moment)
      m.reinit(owned, relevant, comm, true);
    std::vector<Vector<double>> local(n_fields + 1, Vector<double>(n));
    for (const auto &cell : dofs.active_cell_iterators())
      if (cell->is_locally_owned())
        {
          fe_values.reinit(cell);
          values(Cell(&dofs.get_triangulation(),
                      cell->level(),
                      cell->index(),
                      &solver_dofs),
                 v);
          for (auto &l : local)
            l = 0.;
          for (unsigned int q = 0; q < quadrature.size(); ++q)
            for (unsigned int i = 0; i < n; ++i)
              {
                const double w = fe_values.shape_value(i, q) * fe_values.JxW(q);
                for (unsigned int k = 0; k < n_fields; ++k)
                  local[k](i) += w * v[k][q];
                local[n_fields](i) += w;
              }
          cell->get_dof_indices(indices);
          for (unsigned int k = 0; k <= n_fields; ++k)
            constraints.distribute_local_to_global(local[k],
                                                   indices,
                                                   moment[k]);
        }
    std::vector<TrilinosWrappers::MPI::Vector> fields(n_fields);
    for (unsigned int k = 0; k <= n_fields; ++k)
      moment[k].compress(VectorOperation::add);
    for (unsigned int k = 0; k < n_fields; ++k)
      {
        TrilinosWrappers::MPI::Vector f(owned, comm);
        for (const auto j : owned)
          if (!constraints.is_constrained(j))
            f[j] = moment[k][j] / moment[n_fields][j];
        f.compress(VectorOperation::insert);
        constraints.distribute(f);
        fields[k].reinit(owned, relevant, comm);
        fields[k] = f;
      }
    return fields;
  }


  template class FieldRecovery<2>;
  template class FieldRecovery<3>;
} // namespace viscoslide

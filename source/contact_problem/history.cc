// SPDX-License-Identifier: LGPL-2.1-or-later
// ContactProblem: the quadrature-point history of the arm stresses and the
// dissipated energy (step-18's idea, kept in a discontinuous field so that
// refinement and checkpoints carry it).
#include <deal.II/dofs/dof_tools.h>

#include <deal.II/fe/fe_values.h>

#include <viscoslide/contact_problem.h>

namespace viscoslide
{
  ArmStress
  ContactProblem::arm_stress_at(const std::vector<double> &values,
                                const unsigned int         arm,
                                const unsigned int         q) const
  {
    const unsigned int n     = quadrature.size();
    const unsigned int first = n_arm_stress_components * arm;
    ArmStress          h;
    h.in_plane[0][0] = values[(first + h_xx) * n + q];
    h.in_plane[1][1] = values[(first + h_yy) * n + q];
    h.in_plane[0][1] = values[(first + h_xy) * n + q];
    h.zz             = values[(first + h_zz) * n + q];
    return h;
  }


  // The history values of a cell of dof_handler, component-major:
  // values[c * n_q + q].
  void
  ContactProblem::read_cell_history(
    const DoFHandler<dim>::active_cell_iterator &cell,
    std::vector<double>                         &values,
    std::vector<types::global_dof_index>        &dofs) const
  {
    const DoFHandler<dim>::active_cell_iterator history_cell(
      &triangulation, cell->level(), cell->index(), &history_dof_handler);
    history_cell->get_dof_indices(dofs);
    const unsigned int n = quadrature_to_history_dof.size();
    values.resize(history.size() * n);
    for (unsigned int c = 0; c < history.size(); ++c)
      for (unsigned int q = 0; q < n; ++q)
        values[c * n + q] = history[c](dofs[quadrature_to_history_dof[q]]);
  }


  void
  ContactProblem::commit_history()
  {
    TimerOutput::Scope t(timer, "history update");
    FEValues<dim>      fe_values(fe, quadrature, update_gradients);
    const FEValuesExtractors::Vector     displacement(0);
    const unsigned int                   n_q = quadrature.size();
    std::vector<types::global_dof_index> history_dofs(
      history_fe.n_dofs_per_cell());
    std::vector<double>                  values;
    std::vector<SymmetricTensor<2, dim>> strain(n_q), old_strain(n_q);
    const auto factors = material.step_factors(current.dt);

    for (const auto &cell : dof_handler.active_cell_iterators())
      if (cell->is_locally_owned())
        {
          fe_values.reinit(cell);
          fe_values[displacement].get_function_symmetric_gradients(solution,
                                                                   strain);
          fe_values[displacement].get_function_symmetric_gradients(old_solution,
                                                                   old_strain);
          read_cell_history(cell, values, history_dofs);
          for (unsigned int q = 0; q < n_q; ++q)
            {
              const auto i = history_dofs[quadrature_to_history_dof[q]];
              double     dissipated = 0.;
              for (unsigned int k = 0; k < material.n_arms(); ++k)
                {
                  const ArmStress old_h = arm_stress_at(values, k, q);
                  const ArmStress h     = material.updated_arm_stress(
                    k, old_h, strain[q] - old_strain[q], factors[k]);
                  const unsigned int first = n_arm_stress_components * k;
                  history[first + h_xx](i) = h.in_plane[0][0];
                  history[first + h_yy](i) = h.in_plane[1][1];
                  history[first + h_xy](i) = h.in_plane[0][1];
                  history[first + h_zz](i) = h.zz;
                  dissipated +=
                    material.dissipated_energy(k, old_h, h, current.dt);
                }
              history[dissipated_energy()](i) += dissipated;
            }
        }
    for (auto &h : history)
      h.compress(VectorOperation::insert);
    TrilinosWrappers::MPI::Vector increment(locally_owned_dofs,
                                            mpi_communicator),
      old(locally_owned_dofs, mpi_communicator);
    increment = solution;
    old       = old_solution;
    increment -= old;
    last_increment       = increment;
    last_increment_delta = current.delta - committed.delta;
    last_increment_s     = current.s - committed.s;
    old_solution         = solution;
    committed            = current;
  }


  std::vector<TrilinosWrappers::MPI::Vector>
  ContactProblem::ghosted_history() const
  {
    IndexSet relevant;
    DoFTools::extract_locally_relevant_dofs(history_dof_handler, relevant);
    std::vector<TrilinosWrappers::MPI::Vector> ghosted(history.size());
    for (unsigned int c = 0; c < history.size(); ++c)
      {
        ghosted[c].reinit(history_dof_handler.locally_owned_dofs(),
                          relevant,
                          mpi_communicator);
        ghosted[c] = history[c];
      }
    return ghosted;
  }


  double
  ContactProblem::total_dissipation_rate() const
  {
    FEValues<dim> fe_values(fe, quadrature, update_JxW_values);
    std::vector<types::global_dof_index> history_dofs(
      history_fe.n_dofs_per_cell());
    std::vector<double> values;
    double              rate = 0.;
    for (const auto &cell : dof_handler.active_cell_iterators())
      if (cell->is_locally_owned())
        {
          fe_values.reinit(cell);
          read_cell_history(cell, values, history_dofs);
          for (unsigned int q = 0; q < quadrature.size(); ++q)
            for (unsigned int k = 0; k < material.n_arms(); ++k)
              rate +=
                material.dissipation_rate(k, arm_stress_at(values, k, q)) *
                fe_values.JxW(q);
        }
    return Utilities::MPI::sum(rate, mpi_communicator);
  }
} // namespace viscoslide

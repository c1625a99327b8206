// SPDX-License-Identifier: LGPL-2.1-or-later
// Continuous fields from values at quadrature points, for pictures that
// show a field rather than the mesh: the lumped L2 projection onto Q1 on
// the solver's own (adapted, distributed) mesh. With psi_j the Q1 basis
// with its hanging nodes constrained (nonnegative, summing to one),
//     f_j = int psi_j f / int psi_j,
// a weighted average of f about node j. The recovered field integrates
// to the integral of f exactly (sum_j f_j int psi_j = int f), and a
// positive f (a dissipation density) stays positive, where the consistent
// projection undershoots at the steep fronts of the contact edges.
#ifndef viscoslide_field_recovery_h
#define viscoslide_field_recovery_h

#include <deal.II/base/quadrature.h>

#include <deal.II/dofs/dof_handler.h>

#include <deal.II/fe/fe_q.h>

#include <deal.II/lac/affine_constraints.h>
#include <deal.II/lac/trilinos_vector.h>

#include <functional>
#include <vector>

namespace viscoslide
{
  using namespace dealii;

  template <int dim>
  class FieldRecovery
  {
  public:
    using Cell = typename DoFHandler<dim>::active_cell_iterator;
    // values(cell, v) sets v[k][q], field k at quadrature point q of a
    // locally owned cell of the solver's DoFHandler.
    using CellValues =
      std::function<void(const Cell &, std::vector<std::vector<double>> &)>;

    // On the triangulation of `solver_dofs`, whose cells values() gets.
    explicit FieldRecovery(const DoFHandler<dim> &solver_dofs);

    // The n_fields fields, ghosted, on dof_handler().
    std::vector<TrilinosWrappers::MPI::Vector>
    recover(const Quadrature<dim> &quadrature,
            unsigned int           n_fields,
            const CellValues      &values) const;

    const DoFHandler<dim> &
    dof_handler() const
    {
      return dofs;
    }

  private:
    const DoFHandler<dim>    &solver_dofs;
    const FE_Q<dim>           fe;
    DoFHandler<dim>           dofs;
    IndexSet                  owned, relevant;
    AffineConstraints<double> constraints;
  };
} // namespace viscoslide

#endif

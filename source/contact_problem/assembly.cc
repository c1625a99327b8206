// SPDX-License-Identifier: LGPL-2.1-or-later
// ContactProblem: the discrete system, its assembly and linear solves, and
// Newton's method on it.
#include <deal.II/dofs/dof_tools.h>

#include <deal.II/fe/fe_values.h>

#include <deal.II/lac/solver_control.h>
#include <deal.II/lac/solver_gmres.h>
#include <deal.II/lac/trilinos_sparsity_pattern.h>

#include <deal.II/numerics/vector_tools.h>

#include <viscoslide/contact_problem.h>
#include <viscoslide/numerics/mesh.h>

namespace viscoslide
{
  void
  ContactProblem::setup_system()
  {
    TimerOutput::Scope t(timer, "setup");
    dof_handler.distribute_dofs(fe);
    history_dof_handler.distribute_dofs(history_fe);
    locally_owned_dofs = dof_handler.locally_owned_dofs();
    DoFTools::extract_locally_relevant_dofs(dof_handler, locally_relevant_dofs);

    // Hanging nodes, and the base bonded to the rigid foundation.
    constraints.clear();
    constraints.reinit(locally_relevant_dofs);
    DoFTools::make_hanging_node_constraints(dof_handler, constraints);
    VectorTools::interpolate_boundary_values(dof_handler,
                                             bottom_boundary<dim>,
                                             Functions::ZeroFunction<dim>(dim),
                                             constraints);
    constraints.close();

    TrilinosWrappers::SparsityPattern sp(locally_owned_dofs,
                                         locally_owned_dofs,
                                         locally_relevant_dofs,
                                         mpi_communicator);
    DoFTools::make_sparsity_pattern(dof_handler,
                                    sp,
                                    constraints,
                                    false,
                                    Utilities::MPI::this_mpi_process(
                                      mpi_communicator));
    sp.compress();
    // The solver objects refer to the old matrix: release them first.
    coupling.attach(linear_solver,
                    dof_handler,
                    constraints,
                    solution,
                    current.delta,
                    current.s);
    amg.reset();
    system_matrix.reinit(sp);
    bulk_matrix.reinit(sp);
    bulk_dt = -1.;

    solution.reinit(locally_owned_dofs,
                    locally_relevant_dofs,
                    mpi_communicator);
    old_solution.reinit(solution);
    last_increment.reinit(solution);
    system_rhs.reinit(locally_owned_dofs, mpi_communicator);
    newton_update.reinit(system_rhs);
    coupling.reinit(locally_owned_dofs);
    for (auto &h : history)
      h.reinit(history_dof_handler.locally_owned_dofs(), mpi_communicator);
  }


  // Residual -R(u) and, if asked, the consistent tangent dR/du of
  //   R(u)(v) = (sigma(u), eps(v)) + (surface terms of SurfaceCoupling),
  // sigma from the arm stresses of the history advanced over the step
  // (ViscoelasticSolid::updated_arm_stress, step-18's scheme). The bulk
  // tangent depends on the time step alone (assemble_bulk()); a Newton
  // iteration adds the surface terms to a copy of it.
  void
  ContactProblem::assemble(const bool with_matrix)
  {
    if (with_matrix && bulk_dt != current.dt)
      assemble_bulk();
    TimerOutput::Scope t(timer, with_matrix ? "assemble" : "assemble residual");
    if (with_matrix)
      linear_solver.load_bulk(bulk_matrix, system_matrix, current.dt);
    system_rhs = 0;
    coupling.start_assembly();

    FEValues<dim>                    fe_values(fe,
                            quadrature,
                            update_gradients | update_JxW_values);
    FEFaceValues<dim>                face_values(fe,
                                  coupling.face_quadrature(),
                                  SurfaceCoupling<dim>::face_update_flags());
    const FEValuesExtractors::Vector displacement(0);

    const unsigned int               dofs_per_cell = fe.n_dofs_per_cell();
    const unsigned int               n_q           = quadrature.size();
    FullMatrix<double>               cell_matrix(dofs_per_cell, dofs_per_cell);
    Vector<double>                   cell_rhs(dofs_per_cell);
    SurfaceCoupling<dim>::LocalTerms surface_terms;
    std::vector<types::global_dof_index> local_dofs(dofs_per_cell);
    std::vector<types::global_dof_index> history_dofs(
      history_fe.n_dofs_per_cell());
    std::vector<double>                  history_values;
    std::vector<SymmetricTensor<2, dim>> strain(n_q), old_strain(n_q);

    const auto factors = material.step_factors(current.dt);

    for (const auto &cell : dof_handler.active_cell_iterators())
      if (cell->is_locally_owned())
        {
          cell_matrix = 0;
          cell_rhs    = 0;
          surface_terms.reinit(dofs_per_cell);
          fe_values.reinit(cell);
          fe_values[displacement].get_function_symmetric_gradients(solution,
                                                                   strain);
          fe_values[displacement].get_function_symmetric_gradients(old_solution,
                                                                   old_strain);
          read_cell_history(cell, history_values, history_dofs);

          add_stress_terms(
            fe_values, strain, old_strain, history_values, factors, cell_rhs);

          bool at_top = false;
          for (const unsigned int f : cell->face_indices())
            if (is_top_face(cell, f))
              {
                at_top = true;
                face_values.reinit(cell, f);
                coupling.add_face_terms(face_values,
                                        solution,
                                        current.delta,
                                        current.s,
                                        with_matrix,
                                        cell_matrix,
                                        cell_rhs,
                                        surface_terms);
              }

          cell->get_dof_indices(local_dofs);
          coupling.copy_local_to_global(surface_terms,
                                        cell_matrix,
                                        cell_rhs,
                                        local_dofs,
                                        constraints,
                                        with_matrix && at_top,
                                        system_matrix,
                                        system_rhs);
        }
    coupling.finish_assembly(current.delta,
                             with_matrix,
                             system_matrix,
                             system_rhs);
  }


  void
  ContactProblem::add_stress_terms(
    const FEValues<dim>                               &fe_values,
    const std::vector<SymmetricTensor<2, dim>>        &strain,
    const std::vector<SymmetricTensor<2, dim>>        &old_strain,
    const std::vector<double>                         &history_values,
    const std::vector<ViscoelasticSolid::StepFactors> &factors,
    Vector<double>                                    &cell_rhs) const
  {
    const FEValuesExtractors::Vector displacement(0);
    for (unsigned int q = 0; q < quadrature.size(); ++q)
      {
        ArmStress h;
        for (unsigned int k = 0; k < material.n_arms(); ++k)
          h += material.updated_arm_stress(k,
                                           arm_stress_at(history_values, k, q),
                                           strain[q] - old_strain[q],
                                           factors[k]);
        const SymmetricTensor<2, dim> sigma = material.stress(strain[q], h);
        const double                  JxW   = fe_values.JxW(q);
        for (unsigned int i = 0; i < fe.n_dofs_per_cell(); ++i)
          cell_rhs(i) -=
            sigma * fe_values[displacement].symmetric_gradient(i, q) * JxW;
      }
  }


  // The tangent of the bulk, (C eps(du), eps(v)), with C the algorithmic
  // tangent of the time step.
  void
  ContactProblem::assemble_bulk()
  {
    TimerOutput::Scope t(timer, "assemble bulk");
    bulk_matrix = 0;
    FEValues<dim>                        fe_values(fe,
                            quadrature,
                            update_gradients | update_JxW_values);
    const FEValuesExtractors::Vector     displacement(0);
    const unsigned int                   n = fe.n_dofs_per_cell();
    FullMatrix<double>                   cell_matrix(n, n);
    std::vector<types::global_dof_index> local_dofs(n);
    std::vector<SymmetricTensor<2, dim>> sym_grad_phi(n);
    const SymmetricTensor<4, 2>          C =
      material.tangent(material.step_factors(current.dt));
    for (const auto &cell : dof_handler.active_cell_iterators())
      if (cell->is_locally_owned())
        {
          cell_matrix = 0;
          fe_values.reinit(cell);
          for (unsigned int q = 0; q < quadrature.size(); ++q)
            {
              for (unsigned int i = 0; i < n; ++i)
                sym_grad_phi[i] =
                  fe_values[displacement].symmetric_gradient(i, q);
              for (unsigned int i = 0; i < n; ++i)
                {
                  const SymmetricTensor<2, dim> C_phi_i = C * sym_grad_phi[i];
                  for (unsigned int j = 0; j < n; ++j)
                    cell_matrix(i, j) +=
                      C_phi_i * sym_grad_phi[j] * fe_values.JxW(q);
                }
            }
          cell->get_dof_indices(local_dofs);
          constraints.distribute_local_to_global(cell_matrix,
                                                 local_dofs,
                                                 bulk_matrix);
        }
    bulk_matrix.compress(VectorOperation::add);
    bulk_dt = current.dt;
  }


  bool
  ContactProblem::use_direct_solver() const
  {
    return prm.solver.direct_for(dof_handler.n_dofs());
  }


  // AMG for meshes beyond the direct solver's limit: set up anew for each
  // Newton matrix.
  void
  ContactProblem::solve_iteratively(const TrilinosWrappers::MPI::Vector &rhs,
                                    TrilinosWrappers::MPI::Vector       &x)
  {
    TimerOutput::Scope t(timer, "linear: AMG-preconditioned GMRES");
    if (!amg)
      {
        TrilinosWrappers::PreconditionAMG::AdditionalData data;
        std::vector<std::vector<bool>>                    modes;
        DoFTools::extract_constant_modes(dof_handler,
                                         ComponentMask(dim, true),
                                         modes);
        data.constant_modes        = modes;
        data.elliptic              = true;
        data.higher_order_elements = true;
        data.smoother_sweeps       = 2;
        data.aggregation_threshold = 0.02;
        amg = std::make_unique<TrilinosWrappers::PreconditionAMG>();
        amg->initialize(system_matrix, data);
      }
    // The tangent is indefinite where p' < 0, so GMRES, not CG.
    SolverControl control(2000, 1e-10 * rhs.l2_norm());
    SolverGMRES<TrilinosWrappers::MPI::Vector> solver(
      control, SolverGMRES<TrilinosWrappers::MPI::Vector>::AdditionalData(200));
    // A solve that does not converge leaves GMRES's last iterate: Newton's
    // line search judges it by the residual, and where it fails the step
    // is cut or relaxed like any other failed Newton step.
    try
      {
        solver.solve(system_matrix, x, rhs, *amg);
      }
    catch (const SolverControl::NoConvergence &)
      {
        pcout << "      GMRES did not converge in " << control.last_step()
              << " iterations (residual " << control.last_value() << " against "
              << control.tolerance()
              << "); Newton's method judges its last iterate" << std::endl;
      }
  }


  void
  ContactProblem::solve_newton_system()
  {
    amg.reset(); // made for the previous matrix
    if (use_direct_solver())
      coupling.solve_bordered(linear_solver,
                              system_matrix,
                              system_rhs,
                              newton_update);
    else
      coupling.solve_bordered([this](const auto &b,
                                     auto &x) { solve_iteratively(b, x); },
                              system_rhs,
                              newton_update);
    constraints.distribute(newton_update);
  }


  SurfaceCoupling<ContactProblem::dim>::System
  ContactProblem::newton_system()
  {
    return {solution,
            current.delta,
            newton_update,
            system_rhs,
            [this](const bool with_matrix) { assemble(with_matrix); },
            [this] { solve_newton_system(); }};
  }


  int
  ContactProblem::solve_newton(const LoadState &target)
  {
    current = target;
    return coupling.newton(newton_system(), pcout);
  }


  int
  ContactProblem::relax_to_equilibrium(const LoadState &target)
  {
    TimerOutput::Scope t(timer, "relaxation");
    current = target;
    return coupling.relax(newton_system(), pcout);
  }
} // namespace viscoslide

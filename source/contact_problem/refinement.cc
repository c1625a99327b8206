// SPDX-License-Identifier: LGPL-2.1-or-later
// ContactProblem: hanging-node refinement at the moving contact edges,
// carrying solution, predictor and history to the new mesh.
#include <deal.II/distributed/solution_transfer.h>

#include <viscoslide/contact_problem.h>

namespace viscoslide
{
  // Refines at the contact edges and transfers solution, last committed
  // solution, predictor and history. Returns whether the mesh changed.
  bool
  ContactProblem::adapt_mesh()
  {
    TimerOutput::Scope t(timer, "adapt mesh");
    if (!coupling.flag_contact_edges(
          triangulation, dof_handler, solution, current.delta, current.s))
      return false;

    parallel::distributed::SolutionTransfer<dim, TrilinosWrappers::MPI::Vector>
      solution_transfer(dof_handler), history_transfer(history_dof_handler);
    solution_transfer.prepare_for_coarsening_and_refinement(
      std::vector<const TrilinosWrappers::MPI::Vector *>{&solution,
                                                         &old_solution,
                                                         &last_increment});
    const auto ghosted = ghosted_history();
    std::vector<const TrilinosWrappers::MPI::Vector *> in;
    for (const auto &h : ghosted)
      in.push_back(&h);
    history_transfer.prepare_for_coarsening_and_refinement(in);

    triangulation.execute_coarsening_and_refinement();
    setup_system();

    TrilinosWrappers::MPI::Vector u(locally_owned_dofs, mpi_communicator),
      u_old(locally_owned_dofs, mpi_communicator),
      du(locally_owned_dofs, mpi_communicator);
    std::vector<TrilinosWrappers::MPI::Vector *> out{&u, &u_old, &du};
    solution_transfer.interpolate(out);
    constraints.distribute(u);
    constraints.distribute(u_old);
    constraints.distribute(du);
    solution       = u;
    old_solution   = u_old;
    last_increment = du;

    std::vector<TrilinosWrappers::MPI::Vector *> history_out;
    for (auto &h : history)
      history_out.push_back(&h);
    history_transfer.interpolate(history_out);
    return true;
  }


  void
  ContactProblem::refine_initial_mesh()
  {
    for (unsigned int i = 0; i < 64 && adapt_mesh(); ++i)
      ;
  }
} // namespace viscoslide

// SPDX-License-Identifier: LGPL-2.1-or-later
// ContactProblem: checkpoint and restart of the transient sliding phase
// (doc/restart.md).
#include <deal.II/distributed/solution_transfer.h>

#include <boost/archive/binary_iarchive.hpp>
#include <boost/archive/binary_oarchive.hpp>
#include <boost/serialization/vector.hpp>

#include <viscoslide/contact_problem.h>
#include <viscoslide/io/checkpoint.h>
#include <viscoslide/numerics/mesh.h>

#include <sstream>

namespace viscoslide
{
  namespace
  {
    // The version raised whenever the serialized scalars change.
    const Checkpoint::Format format{"transient", 4};
  } // namespace


  // A checkpoint of the transient sliding phase, taken between two steps:
  // the mesh with the committed solution, the predictor and the history
  // attached (the same SolutionTransfer that carries them through
  // refinement serializes them with p4est), and every scalar of
  // serialize() in a binary archive, so that a resumed run continues bit
  // for bit.
  void
  ContactProblem::write_checkpoint()
  {
    TimerOutput::Scope t(timer, "checkpoint");
    const std::string  tmp =
      Checkpoint::begin(writer.path(""), mpi_communicator);
    parallel::distributed::SolutionTransfer<dim, TrilinosWrappers::MPI::Vector>
      solution_transfer(dof_handler), history_transfer(history_dof_handler);
    solution_transfer.prepare_for_serialization(
      std::vector<const TrilinosWrappers::MPI::Vector *>{&old_solution,
                                                         &last_increment});
    const auto ghosted = ghosted_history();
    std::vector<const TrilinosWrappers::MPI::Vector *> in;
    for (const auto &h : ghosted)
      in.push_back(&h);
    history_transfer.prepare_for_serialization(in);
    triangulation.save(tmp + "/mesh");

    Checkpoint::commit(
      writer.path(""),
      Checkpoint::pack(format, [this](auto &archive) { archive << *this; }),
      mpi_communicator);
    pcout << "Checkpoint after " << history_rows << " rows of history.csv"
          << std::endl;
  }


  bool
  ContactProblem::has_checkpoint(const std::string &directory)
  {
    return Checkpoint::exists(directory);
  }


  // The inverse of write_checkpoint(), in place of setup, approach and the
  // start of the sliding phase.
  void
  ContactProblem::read_checkpoint()
  {
    std::string       state;
    const std::string dir =
      Checkpoint::open(writer.path(""), state, mpi_communicator);
    Checkpoint::unpack(state, dir, format, [this](auto &archive) {
      archive >> *this;
    });
    current = committed;

    make_block(triangulation, prm);
    triangulation.load(dir + "/mesh");
    setup_system();
    parallel::distributed::SolutionTransfer<dim, TrilinosWrappers::MPI::Vector>
      solution_transfer(dof_handler), history_transfer(history_dof_handler);
    TrilinosWrappers::MPI::Vector u_old(locally_owned_dofs, mpi_communicator),
      du(locally_owned_dofs, mpi_communicator);
    std::vector<TrilinosWrappers::MPI::Vector *> out{&u_old, &du};
    solution_transfer.deserialize(out);
    old_solution   = u_old;
    solution       = u_old;
    last_increment = du;
    std::vector<TrilinosWrappers::MPI::Vector *> history_out;
    for (auto &h : history)
      history_out.push_back(&h);
    history_transfer.deserialize(history_out);

    writer.resume_collection("solution", step_number);
    writer.resume_collection("surface", step_number);
    pcout << "Resumed from the checkpoint of step " << step_number - 1 << ": "
          << triangulation.n_global_active_cells() << " cells, "
          << dof_handler.n_dofs() << " dofs" << std::endl;
  }
} // namespace viscoslide

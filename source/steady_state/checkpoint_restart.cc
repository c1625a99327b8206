// SPDX-License-Identifier: LGPL-2.1-or-later
// SteadyStateSolver: checkpoint and restart of the continuation
// (doc/restart.md).
#include <deal.II/distributed/solution_transfer.h>

#include <boost/archive/binary_iarchive.hpp>
#include <boost/archive/binary_oarchive.hpp>
#include <boost/serialization/vector.hpp>

#include <viscoslide/io/checkpoint.h>
#include <viscoslide/numerics/mesh.h>
#include <viscoslide/steady_state/solver.h>

#include <sstream>

namespace viscoslide
{
  namespace
  {
    // The version raised whenever the scalars change.
    const Checkpoint::Format format{"steady-state", 103};
  } // namespace


  template <int dim>
  void
  SteadyStateSolver<dim>::write_checkpoint(
    const std::string       &directory,
    const StationCheckpoint &station) const
  {
    TimerOutput::Scope t(timer, "steady: checkpoint");
    const std::string  tmp = Checkpoint::begin(directory, mpi_communicator);
    parallel::distributed::SolutionTransfer<dim, TrilinosWrappers::MPI::Vector>
      transfer(dof_handler);
    transfer.prepare_for_serialization(solution);
    triangulation.save(tmp + "/mesh");

    const double force  = coupling.held_force(),
                 spring = coupling.spring_reference();
    Checkpoint::commit(directory,
                       Checkpoint::pack(format,
                                        [&](auto &archive) {
                                          archive << station.next_station
                                                  << station.continuation_rows
                                                  << station.table_rows << V_hat
                                                  << delta << s << force
                                                  << spring << edge_spans;
                                        }),
                       mpi_communicator);
  }


  template <int dim>
  StationCheckpoint
  SteadyStateSolver<dim>::read_checkpoint(const std::string &directory)
  {
    std::string       state;
    const std::string dir =
      Checkpoint::open(directory, state, mpi_communicator);
    StationCheckpoint station;
    double            force = 0., spring = 0.;
    Checkpoint::unpack(state, dir, format, [&](auto &archive) {
      archive >> station.next_station >> station.continuation_rows >>
        station.table_rows >> V_hat >> delta >> s >> force >> spring >>
        edge_spans;
    });
    if (prm.sliding.control != Parameters::Control::displacement)
      coupling.hold_force(
        force, SurfaceCoupling<dim>::spring_stiffness_of(prm, scales), spring);

    triangulation.clear();
    make_block(triangulation, prm);
    triangulation.load(dir + "/mesh");
    setup_system();
    parallel::distributed::SolutionTransfer<dim, TrilinosWrappers::MPI::Vector>
                                  transfer(dof_handler);
    TrilinosWrappers::MPI::Vector x(locally_owned_dofs, mpi_communicator);
    transfer.deserialize(x);
    constraints.distribute(x);
    solution = x;
    update_quantities();
    pcout << "Resumed from the checkpoint after station "
          << station.next_station << " (V_hat = " << V_hat
          << "): " << triangulation.n_global_active_cells() << " cells, "
          << dof_handler.n_dofs() << " dofs" << std::endl;
    return station;
  }


  template class SteadyStateSolver<2>;
  template class SteadyStateSolver<3>;
} // namespace viscoslide

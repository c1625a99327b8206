// SteadyStateSolver: checkpoint and restart of the continuation
// (doc/restart.md).
#include <deal.II/distributed/solution_transfer.h>

#include <boost/archive/binary_iarchive.hpp>
#include <boost/archive/binary_oarchive.hpp>
#include <boost/serialization/vector.hpp>

#include <viscoslide/checkpoint.h>
#include <viscoslide/mesh.h>
#include <viscoslide/steady_state/solver.h>

#include <sstream>

namespace viscoslide
{
  namespace
  {
    // Distinct from the transient's, so that neither solver reads the
    // other's checkpoint; raised whenever the scalars change.
    constexpr unsigned int steady_checkpoint_version = 102;
  } // namespace


  void
  SteadyStateSolver::write_checkpoint(const std::string       &directory,
                                      const StationCheckpoint &station) const
  {
    TimerOutput::Scope t(timer, "steady: checkpoint");
    const std::string  tmp = Checkpoint::begin(directory, mpi_communicator);
    parallel::distributed::SolutionTransfer<dim, TrilinosWrappers::MPI::Vector>
      transfer(dof_handler);
    transfer.prepare_for_serialization(solution);
    triangulation.save(tmp + "/mesh");

    std::ostringstream out;
    {
      boost::archive::binary_oarchive archive(out);
      const double                    force = coupling.held_force(),
                   spring                   = coupling.spring_reference();
      archive << steady_checkpoint_version << station.next_station
              << station.continuation_rows << station.table_rows << V_hat
              << delta << s << force << spring << edge_spans;
    }
    Checkpoint::commit(directory, out.str(), mpi_communicator);
  }


  StationCheckpoint
  SteadyStateSolver::read_checkpoint(const std::string &directory)
  {
    std::string       state;
    const std::string dir =
      Checkpoint::open(directory, state, mpi_communicator);
    StationCheckpoint station;
    double            force = 0., spring = 0.;
    try
      {
        std::istringstream              in(state);
        boost::archive::binary_iarchive archive(in);
        unsigned int                    version = 0;
        archive >> version;
        if (version != steady_checkpoint_version)
          throw Parameters::ExcInvalidInput(
            "checkpoint '" + dir +
            "' was not written by this version's steady-state solver");
        archive >> station.next_station >> station.continuation_rows >>
          station.table_rows >> V_hat >> delta >> s >> force >> spring >>
          edge_spans;
      }
    catch (const boost::archive::archive_exception &)
      {
        throw Parameters::ExcInvalidInput("checkpoint '" + dir +
                                          "/state.bin' is damaged");
      }
    if (prm.sliding.control != Parameters::Control::displacement)
      coupling.hold_force(force,
                          SurfaceCoupling::spring_stiffness_of(prm, scales),
                          spring);

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
} // namespace viscoslide

// SteadyStateSolver: checkpoint and restart of the continuation
// (doc/restart.md).
#include <deal.II/distributed/solution_transfer.h>

#include <boost/archive/binary_iarchive.hpp>
#include <boost/archive/binary_oarchive.hpp>

#include <viscoslide/mesh.h>
#include <viscoslide/steady_state/solver.h>

#include <filesystem>
#include <fstream>
#include <sstream>

namespace viscoslide
{
  namespace
  {
    // Distinct from the transient's, so that neither solver reads the
    // other's checkpoint; raised whenever the scalars change.
    constexpr unsigned int steady_checkpoint_version = 101;
  } // namespace


  // As the transient's: written into checkpoint.tmp/, which then replaces
  // checkpoint/, so that a kill at any moment leaves one complete
  // checkpoint.
  void
  SteadyStateSolver::write_checkpoint(const std::string       &directory,
                                      const StationCheckpoint &station) const
  {
    TimerOutput::Scope t(timer, "steady: checkpoint");
    namespace fs       = std::filesystem;
    const fs::path top = directory;
    const fs::path dir = top / "checkpoint", tmp = top / "checkpoint.tmp",
                   old = top / "checkpoint.old";
    const bool root = Utilities::MPI::this_mpi_process(mpi_communicator) == 0;
    if (root)
      {
        fs::remove_all(tmp);
        fs::create_directories(tmp);
      }
    MPI_Barrier(mpi_communicator);

    parallel::distributed::SolutionTransfer<dim, TrilinosWrappers::MPI::Vector>
      transfer(dof_handler);
    transfer.prepare_for_serialization(solution);
    triangulation.save((tmp / "mesh").string());
    if (root)
      {
        std::ostringstream out;
        {
          boost::archive::binary_oarchive archive(out);
          const double                    force = coupling.held_force(),
                       spring                   = coupling.spring_reference();
          archive << steady_checkpoint_version << station.next_station
                  << station.continuation_rows << station.table_rows << V_hat
                  << delta << s << force << spring;
        }
        write_atomically((tmp / "state.bin").string(), out.str());
        if (fs::exists(dir))
          fs::rename(dir, old);
        fs::rename(tmp, dir);
        fs::remove_all(old);
      }
    MPI_Barrier(mpi_communicator);
  }


  StationCheckpoint
  SteadyStateSolver::read_checkpoint(const std::string &directory)
  {
    namespace fs       = std::filesystem;
    const fs::path dir = fs::path(directory) / "checkpoint",
                   old = fs::path(directory) / "checkpoint.old";
    if (Utilities::MPI::this_mpi_process(mpi_communicator) == 0 &&
        !fs::exists(dir) && fs::exists(old))
      fs::rename(old, dir);
    MPI_Barrier(mpi_communicator);
    std::ifstream in(dir / "state.bin", std::ios::binary);
    if (!in)
      throw Parameters::ExcInvalidInput("no checkpoint to resume from in '" +
                                        dir.string() + "'");
    StationCheckpoint station;
    double            force = 0., spring = 0.;
    try
      {
        boost::archive::binary_iarchive archive(in);
        unsigned int                    version = 0;
        archive >> version;
        if (version != steady_checkpoint_version)
          throw Parameters::ExcInvalidInput(
            "checkpoint '" + dir.string() +
            "' was not written by this version's steady-state solver");
        archive >> station.next_station >> station.continuation_rows >>
          station.table_rows >> V_hat >> delta >> s >> force >> spring;
      }
    catch (const boost::archive::archive_exception &)
      {
        throw Parameters::ExcInvalidInput("checkpoint '" + dir.string() +
                                          "/state.bin' is damaged");
      }
    if (prm.sliding.control != Parameters::Control::displacement)
      coupling.hold_force(force,
                          SurfaceCoupling::spring_stiffness_of(prm, scales),
                          spring);

    triangulation.clear();
    make_block(triangulation, prm);
    triangulation.load((dir / "mesh").string());
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

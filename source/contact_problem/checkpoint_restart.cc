// ContactProblem: checkpoint and restart of the transient sliding phase
// (doc/restart.md).
#include <deal.II/distributed/solution_transfer.h>

#include <boost/archive/binary_iarchive.hpp>
#include <boost/archive/binary_oarchive.hpp>
#include <boost/serialization/vector.hpp>

#include <viscoslide/contact_problem.h>
#include <viscoslide/mesh.h>

#include <filesystem>
#include <fstream>
#include <sstream>

namespace viscoslide
{
  namespace
  {
    // Raised whenever the serialized scalars change, so that an old
    // checkpoint is refused instead of misread.
    constexpr unsigned int checkpoint_version = 2;
  } // namespace


  // A checkpoint of the transient sliding phase, taken between two steps:
  // the mesh with the committed solution, the predictor and the history
  // attached (the same SolutionTransfer that carries them through
  // refinement serializes them with p4est), and every scalar of
  // serialize() in a binary archive, so that a resumed run continues bit
  // for bit. It is written into checkpoint.tmp/, which then replaces
  // checkpoint/, so that a kill at any moment leaves one complete
  // checkpoint.
  void
  ContactProblem::write_checkpoint()
  {
    TimerOutput::Scope t(timer, "checkpoint");
    namespace fs       = std::filesystem;
    const fs::path dir = writer.path("checkpoint"),
                   tmp = writer.path("checkpoint.tmp"),
                   old = writer.path("checkpoint.old");
    const bool root = Utilities::MPI::this_mpi_process(mpi_communicator) == 0;
    if (root)
      {
        fs::remove_all(tmp);
        fs::create_directories(tmp);
      }
    MPI_Barrier(mpi_communicator);

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
    triangulation.save((tmp / "mesh").string());

    if (root)
      {
        std::ostringstream out;
        {
          boost::archive::binary_oarchive archive(out);
          archive << checkpoint_version << *this;
        }
        write_atomically((tmp / "state.bin").string(), out.str());
        if (fs::exists(dir))
          fs::rename(dir, old);
        fs::rename(tmp, dir);
        fs::remove_all(old);
      }
    MPI_Barrier(mpi_communicator);
    pcout << "Checkpoint after " << history_rows << " rows of history.csv"
          << std::endl;
  }


  bool
  ContactProblem::has_checkpoint(const std::string &directory)
  {
    namespace fs = std::filesystem;
    return fs::exists(fs::path(directory) / "checkpoint" / "state.bin");
  }


  // The inverse of write_checkpoint(), in place of setup, approach and the
  // start of the sliding phase. A checkpoint left as checkpoint.old by a
  // kill between the two renames is taken back first.
  void
  ContactProblem::read_checkpoint()
  {
    namespace fs       = std::filesystem;
    const fs::path dir = writer.path("checkpoint");
    const fs::path old = writer.path("checkpoint.old");
    if (Utilities::MPI::this_mpi_process(mpi_communicator) == 0 &&
        !fs::exists(dir) && fs::exists(old))
      fs::rename(old, dir);
    MPI_Barrier(mpi_communicator);
    std::ifstream in(dir / "state.bin", std::ios::binary);
    if (!in)
      throw Parameters::ExcInvalidInput("no checkpoint to resume from in '" +
                                        dir.string() + "'");
    try
      {
        boost::archive::binary_iarchive archive(in);
        unsigned int                    version = 0;
        archive >> version;
        if (version != checkpoint_version)
          throw Parameters::ExcInvalidInput(
            "checkpoint '" + dir.string() +
            "' was written by another version of viscoslide");
        archive >> *this;
      }
    catch (const boost::archive::archive_exception &)
      {
        throw Parameters::ExcInvalidInput("checkpoint '" + dir.string() +
                                          "/state.bin' is damaged");
      }
    current = committed;

    make_block(triangulation, prm);
    triangulation.load((dir / "mesh").string());
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

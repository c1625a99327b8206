// SPDX-License-Identifier: LGPL-2.1-or-later
#include <viscoslide/io/checkpoint.h>
#include <viscoslide/io/output.h>
#include <viscoslide/io/parameters.h>

#include <filesystem>
#include <fstream>
#include <sstream>

#include <boost/serialization/string.hpp>

namespace viscoslide
{
  namespace Checkpoint
  {
    namespace fs = std::filesystem;

    bool
    exists(const std::string &directory)
    {
      const fs::path top = directory;
      return fs::exists(top / "checkpoint" / "state.bin") ||
             fs::exists(top / "checkpoint.old" / "state.bin");
    }


    std::string
    begin(const std::string &directory, MPI_Comm comm)
    {
      const fs::path tmp = fs::path(directory) / "checkpoint.tmp";
      if (Utilities::MPI::this_mpi_process(comm) == 0)
        {
          fs::remove_all(tmp);
          fs::create_directories(tmp);
        }
      MPI_Barrier(comm);
      return tmp.string();
    }


    void
    commit(const std::string &directory,
           const std::string &state,
           MPI_Comm           comm)
    {
      const fs::path top = directory;
      const fs::path dir = top / "checkpoint", tmp = top / "checkpoint.tmp",
                     old = top / "checkpoint.old";
      if (Utilities::MPI::this_mpi_process(comm) == 0)
        {
          write_atomically((tmp / "state.bin").string(), state);
          if (fs::exists(dir))
            {
              // A kill after the previous commit's second rename left an
              // old folder, which would block this rename.
              fs::remove_all(old);
              fs::rename(dir, old);
            }
          fs::rename(tmp, dir);
          fs::remove_all(old);
        }
      MPI_Barrier(comm);
    }


    std::string
    open(const std::string &directory, std::string &state, MPI_Comm comm)
    {
      const fs::path dir = fs::path(directory) / "checkpoint",
                     old = fs::path(directory) / "checkpoint.old";
      if (Utilities::MPI::this_mpi_process(comm) == 0 && !fs::exists(dir) &&
          fs::exists(old))
        fs::rename(old, dir);
      MPI_Barrier(comm);
      std::ifstream in(dir / "state.bin", std::ios::binary);
      if (!in)
        throw Parameters::ExcInvalidInput("no checkpoint to resume from in '" +
                                          dir.string() + "'");
      std::ostringstream contents;
      contents << in.rdbuf();
      state = contents.str();
      return dir.string();
    }


    void
    remove(const std::string &directory, MPI_Comm comm)
    {
      // state.bin goes first, so that a kill during the removal never
      // leaves a folder that exists() takes for a complete checkpoint.
      if (Utilities::MPI::this_mpi_process(comm) == 0)
        for (const char *name :
             {"checkpoint.old", "checkpoint", "checkpoint.tmp"})
          {
            fs::remove(fs::path(directory) / name / "state.bin");
            fs::remove_all(fs::path(directory) / name);
          }
    }


    std::string
    pack(const Format                                                 &format,
         const std::function<void(boost::archive::binary_oarchive &)> &save)
    {
      std::ostringstream out;
      {
        boost::archive::binary_oarchive archive(out);
        archive << format.solver << format.version;
        save(archive);
      }
      return out.str();
    }


    void
    unpack(const std::string                                            &state,
           const std::string                                            &folder,
           const Format                                                 &format,
           const std::function<void(boost::archive::binary_iarchive &)> &load)
    {
      try
        {
          std::istringstream              in(state);
          boost::archive::binary_iarchive archive(in);
          std::string                     solver;
          unsigned int                    version = 0;
          archive >> solver >> version;
          if (solver != format.solver || version != format.version)
            throw Parameters::ExcInvalidInput(
              "checkpoint '" + folder + "' holds the state of the " + solver +
              " solver, version " + std::to_string(version) +
              "; this run needs the " + format.solver + " solver's, version " +
              std::to_string(format.version) +
              " (written by another solver or another version of viscoslide)");
          load(archive);
        }
      catch (const boost::archive::archive_exception &)
        {
          throw Parameters::ExcInvalidInput("checkpoint '" + folder +
                                            "/state.bin' is damaged");
        }
    }
  } // namespace Checkpoint
} // namespace viscoslide

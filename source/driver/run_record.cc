// SPDX-License-Identifier: LGPL-2.1-or-later
#include <deal.II/base/mpi.h>
#include <deal.II/base/utilities.h>

#include <viscoslide/driver/run_record.h>
#include <viscoslide/io/output.h>

#include <array>
#include <cstdio>
#include <ctime>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <unistd.h>

namespace viscoslide
{
  namespace
  {
    std::string
    json_string(const std::string &text)
    {
      std::string out = "\"";
      for (const char c : text)
        if (c == '"' || c == '\\')
          out += std::string("\\") + c;
        else if (static_cast<unsigned char>(c) < 0x20)
          {
            char code[8];
            std::snprintf(code, sizeof(code), "\\u%04x", c);
            out += code;
          }
        else
          out += c;
      return out + "\"";
    }

    std::string
    utc_now()
    {
      const std::time_t now = std::time(nullptr);
      char              text[32];
      std::strftime(text,
                    sizeof(text),
                    "%Y-%m-%dT%H:%M:%SZ",
                    std::gmtime(&now));
      return text;
    }

    // The first line a shell command prints, "" if it fails.
    std::string
    first_line_of(const std::string &command)
    {
      std::string line;
      if (FILE *pipe = ::popen((command + " 2>/dev/null").c_str(), "r"))
        {
          std::array<char, 256> buffer;
          if (std::fgets(buffer.data(), buffer.size(), pipe) != nullptr)
            line = buffer.data();
          ::pclose(pipe);
        }
      while (!line.empty() && (line.back() == '\n' || line.back() == '\r'))
        line.pop_back();
      return line;
    }

    // The source tree's revision and whether it differs from it, read now
    // (the build's revision is fixed when it is configured); null where
    // the tree or git is gone.
    std::string
    source_state()
    {
      const std::string git =
        std::string("git -C '") + VISCOSLIDE_SOURCE_DIR + "' ";
      const std::string revision = first_line_of(git + "rev-parse HEAD");
      if (revision.empty())
        return "\"revision_now\": null, \"tree_modified\": null";
      const bool modified =
        !first_line_of(git + "status --porcelain --untracked-files=no").empty();
      return "\"revision_now\": " + json_string(revision) +
             ",\n  \"tree_modified\": " + (modified ? "true" : "false");
    }

    // The last value of `column` in a table of the run, "null" if none.
    std::string
    last_value(const std::filesystem::path &csv, const std::string &column)
    {
      const auto rows = CsvTable::read(csv.string());
      if (rows.empty() || rows.back().count(column) == 0)
        return "null";
      return rows.back().at(column);
    }
  } // namespace


  PeakMemory
  peak_memory(MPI_Comm comm)
  {
    Utilities::System::MemoryStats stats;
    Utilities::System::get_memory_stats(stats); // in kB; 0 where unknown
    const double gb = 1024. * stats.VmHWM / 1e9;
    return {Utilities::MPI::sum(gb, comm), Utilities::MPI::max(gb, comm)};
  }


  RunRecord::RunRecord(const std::string &directory,
                       const std::string &command_line,
                       MPI_Comm           comm)
    : comm(comm)
    , directory(directory)
    , command_line(command_line)
    , start(utc_now())
    , n_processes(Utilities::MPI::n_mpi_processes(comm))
    , root(Utilities::MPI::this_mpi_process(comm) == 0)
    , clock_start(std::chrono::steady_clock::now())
  {
    write("running", "null", "null", "null", "null");
  }


  void
  RunRecord::finish(const std::string &status) const
  {
    const PeakMemory memory = peak_memory(comm);
    if (!root)
      return;
    const double wall = std::chrono::duration<double>(
                          std::chrono::steady_clock::now() - clock_start)
                          .count();
    const std::filesystem::path dir(directory);
    std::string dofs = last_value(dir / "continuation.csv", "n_dofs");
    if (dofs == "null")
      dofs = last_value(dir / "approach.csv", "n_dofs");
    write(status,
          json_string(utc_now()),
          CsvTable::format(wall),
          "{\"n_dofs_last\": " + dofs + ", \"n_cells_after_approach\": " +
            last_value(dir / "approach.csv", "n_cells") + "}",
          "{\"total\": " + CsvTable::format(memory.total) +
            ", \"largest_process\": " + CsvTable::format(memory.largest) + "}");
  }


  void
  RunRecord::write(const std::string &status,
                   const std::string &end,
                   const std::string &wall,
                   const std::string &mesh,
                   const std::string &memory) const
  {
    if (!root)
      return;
    static const std::string source    = source_state();
    char                     host[256] = "unknown";
    ::gethostname(host, sizeof(host) - 1);
    std::ostringstream json;
    json << "{\n  \"command_line\": " << json_string(command_line)
         << ",\n  \"status\": " << json_string(status)
         << ",\n  \"start\": " << json_string(start) << ",\n  \"end\": " << end
         << ",\n  \"wall_time_seconds\": " << wall
         << ",\n  \"host\": " << json_string(host)
         << ",\n  \"mpi_processes\": " << n_processes
         << ",\n  \"version\": " << json_string(version_string()) << ",\n  "
         << source << ",\n  \"working_directory\": "
         << json_string(std::filesystem::current_path().string())
         << ",\n  \"mesh\": " << mesh << ",\n  \"peak_memory_gb\": " << memory
         << "\n}\n";
    try
      {
        write_atomically(
          (std::filesystem::path(directory) / "run.json").string(), json.str());
      }
    catch (std::exception &)
      {
        // The run's own files report a full disk; the record is not worth
        // failing the run for.
      }
  }
} // namespace viscoslide

// SPDX-License-Identifier: LGPL-2.1-or-later
#include <deal.II/base/utilities.h>

#include <viscoslide/driver/case_folder.h>
#include <viscoslide/io/output.h>
#include <viscoslide/io/steady_state_table.h>

#include <fstream>
#include <sstream>

namespace viscoslide
{
  namespace Study
  {
    // A one-line reason for a CSV cell.
    std::string
    one_line(const std::string &text)
    {
      std::string s;
      for (const char c : text)
        s += c == ',' ? ';' : (c == '\n' || c == '\r' || c == '\t') ? ' ' : c;
      const auto b = s.find_first_not_of(' '), e = s.find_last_not_of(' ');
      s = b == std::string::npos ? "" : s.substr(b, e - b + 1);
      return s.size() > 300 ? s.substr(0, 297) + "..." : s;
    }

    // The verdict of a run in its folder: "done", or "failed" and the
    // reason on the next line.
    void
    write_status(const fs::path &dir, const std::string &failure)
    {
      write_atomically(dir / "status",
                       failure.empty() ? std::string("done\n\n")
                                       : "failed\n" + one_line(failure) + "\n");
    }

    std::string
    read_file(const fs::path &path)
    {
      std::ifstream     in(path);
      std::stringstream s;
      s << in.rdbuf();
      return s.str();
    }

    // What identifies a case's run: its parameters without comment lines
    // (documentation, version) and without the Sweep section, whose lists
    // span the study but do not change a case (its own values are set in
    // their sections). So a list may grow without invalidating the cases
    // already finished.
    std::string
    case_identity(const std::string &text)
    {
      std::istringstream in(text);
      std::string        line, out;
      bool               in_sweep = false;
      while (std::getline(in, line))
        {
          const auto first = line.find_first_not_of(" \t");
          if (first == std::string::npos || line[first] == '#')
            continue;
          const std::string trimmed = Utilities::trim(line);
          if (trimmed == "subsection Sweep")
            in_sweep = true;
          else if (in_sweep && trimmed == "end")
            in_sweep = false;
          else if (!in_sweep)
            out += line + "\n";
        }
      return out;
    }

    // Whether the run in `dir` had the case's parameters (its
    // parameters.prm, compared as case_identity() does).
    bool
    ran_with(const fs::path &dir, const Case &c)
    {
      return case_identity(read_file(dir / "parameters.prm")) ==
             case_identity(c.parameter_text);
    }

    Status
    read_status(const fs::path &folder)
    {
      Status        s;
      std::ifstream in(folder / "status");
      std::getline(in, s.state);
      std::getline(in, s.reason);
      return s;
    }

    // A case's verdict and when it was written: a change between choosing
    // the cases to run and starting one means that another invocation ran
    // it meanwhile.
    std::string
    status_signature(const fs::path &folder)
    {
      std::error_code ec;
      const auto      time = fs::last_write_time(folder / "status", ec);
      return ec ? std::string()
                : read_file(folder / "status") +
                    std::to_string(time.time_since_epoch().count());
    }

    // Beside the case's folder, which a fresh run deletes.
    std::string
    lock_file(const fs::path &top, const std::string &name)
    {
      return (top / ("." + name + ".lock")).string();
    }

    bool
    running_elsewhere(const fs::path &top, const std::string &name)
    {
      try
        {
          return !CaseLock(lock_file(top, name)).held();
        }
      catch (std::exception &)
        {
          return false;
        }
    }

    LockState
    take_lock(std::unique_ptr<CaseLock> &lock,
              const std::string         &file,
              MPI_Comm                   comm,
              std::string               &error,
              const double               patience)
    {
      LockState state = LockState::held;
      if (Utilities::MPI::this_mpi_process(comm) == 0)
        try
          {
            lock = std::make_unique<CaseLock>(file, patience);
            if (!lock->held())
              state = LockState::busy;
          }
        catch (std::exception &e)
          {
            state = LockState::error;
            error = e.what();
          }
      error = Utilities::MPI::broadcast(comm, error, 0);
      return Utilities::MPI::broadcast(comm, state, 0);
    }

    // The sweep's steady_state.csv, rebuilt from the case folders after
    // each case: a row per case and speed, or one row naming the reason
    // for a case that failed before writing any.
    void
    write_sweep_table(const fs::path &directory, const std::vector<Case> &cases)
    {
      const int dimension =
        cases.empty() ? 2 : cases.front().parameters.geometry.dimension;
      // With the SI columns the cases' tables add (units.h).
      const auto columns = CsvTable::header(
        SteadyStateTable::columns(dimension),
        cases.empty() ? std::vector<CsvTable::Derived>{}
                      : cases.front().parameters.units.si_columns(dimension));
      std::ostringstream out;
      out << "# " << version_string() << "; sweep of " << cases.size()
          << " cases, one folder each\ncase,status,reason";
      for (const auto &c : columns)
        out << "," << c;
      out << "\n";
      for (const auto &c : cases)
        {
          const Status status = read_status(directory / c.name);
          if (status.state.empty())
            continue;
          auto rows = CsvTable::read(directory / c.name / "steady_state.csv");
          if (rows.empty())
            {
              // What is known of the case without a result.
              const auto &p = c.parameters;
              rows.push_back(
                {{"control", Parameters::to_string(p.sliding.control)},
                 {"mu_T", CsvTable::format(p.adhesion.tabor_parameter)},
                 {"R_hat", CsvTable::format(p.adhesion.R_over_eps)},
                 {"substrate", Parameters::to_string(p.geometry.substrate)},
                 {"t_hat", CsvTable::format(SteadyStateTable::t_hat(p))},
                 {"steady", "0"},
                 {"time_constant",
                  Parameters::to_string(p.material.time_constant)},
                 {"solver", Parameters::to_string(p.sliding.solver)}});
            }
          for (auto &row : rows)
            {
              out << c.name << "," << status.state << "," << status.reason;
              for (const auto &col : columns)
                out << "," << row[col];
              out << "\n";
            }
        }
      if (read_file(directory / "steady_state.csv") != out.str())
        write_atomically(directory / "steady_state.csv", out.str());
    }

    // parameters.prm (with the version), parameters.json and version.txt
    // in the case's folder.
    void
    write_provenance(const Case &c, MPI_Comm comm)
    {
      std::string error;
      if (Utilities::MPI::this_mpi_process(comm) == 0)
        try
          {
            const fs::path dir(c.parameters.output.directory);
            write_atomically(dir / "parameters.prm",
                             "# " + version_string() + "\n" + c.parameter_text);
            write_atomically(dir / "parameters.json", c.parameter_json);
            write_atomically(dir / "version.txt", version_string() + "\n");
            // What the program changed in the case (the block fitted to
            // the wake), next to the parameters that do not show it.
            std::string notes;
            for (const auto &note : c.parameters.notes)
              notes += note + "\n";
            if (!notes.empty())
              write_atomically(dir / "notes.txt", notes);
          }
        catch (std::exception &e)
          {
            error = e.what();
          }
      // every process leaves together
      error = Utilities::MPI::broadcast(comm, error, 0);
      if (!error.empty())
        throw std::runtime_error(error);
    }
  } // namespace Study
} // namespace viscoslide

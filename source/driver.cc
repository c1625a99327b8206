#include <deal.II/base/parameter_handler.h>

#include <viscoslide/boundary_element/solver.h>
#include <viscoslide/case_lock.h>
#include <viscoslide/contact_problem.h>
#include <viscoslide/driver.h>
#include <viscoslide/output.h>
#include <viscoslide/parameters.h>
#include <viscoslide/run_record.h>
#include <viscoslide/steady_state_table.h>

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <functional>
#include <iostream>
#include <map>
#include <sstream>
#include <type_traits>

namespace viscoslide
{
  namespace
  {
    namespace fs = std::filesystem;

    struct Setting
    {
      std::string section, entry, value;
    };

    // One run of a sweep: the entries it changes in the parameter file, and
    // the folder (relative to the Output directory; empty for a run that
    // is not a sweep).
    struct Case
    {
      std::string               name;
      std::vector<Setting>      settings;
      Parameters::AllParameters parameters;
      std::string               parameter_text; // PRM, for provenance
      std::string               parameter_json;
    };

    // Reads `input`, applies the case's settings, checks every entry.
    void
    read_case(const std::string &input, Case &c)
    {
      ParameterHandler prm;
      Parameters::AllParameters::declare(prm);
      prm.parse_input(input);
      for (const auto &s : c.settings)
        {
          prm.enter_subsection(s.section);
          prm.set(s.entry, s.value);
          prm.leave_subsection();
        }
      c.parameters.parse(prm);
      std::ostringstream text, json;
      prm.print_parameters(text, ParameterHandler::PRM);
      prm.print_parameters(json, ParameterHandler::JSON);
      c.parameter_text = text.str();
      c.parameter_json = json.str();
    }

    // The product of the sweep lists. A list of one entry is applied but
    // does not appear in the folder names.
    std::vector<Case>
    make_cases(const Parameters::AllParameters &p)
    {
      struct Choice
      {
        std::string          label;
        std::vector<Setting> settings;
      };
      std::vector<std::vector<Choice>> dimensions;
      // The entries of a list as the words of a parameter file.
      auto words = [](const auto &v) {
        std::vector<std::string> w;
        for (const auto x : v)
          if constexpr (std::is_same_v<decltype(x), const double>)
            w.push_back(CsvTable::format(x));
          else
            w.push_back(Parameters::to_string(x));
        return w;
      };
      auto add = [&](const std::vector<std::string> &values,
                     const std::string              &prefix,
                     auto                          &&settings_of) {
        if (values.empty())
          return;
        std::vector<Choice> d;
        for (const auto &v : values)
          {
            // a folder name without spaces ("flat punch" -> flat-punch)
            std::string label = v == "half-plane" ? v : prefix + v;
            std::replace(label.begin(), label.end(), ' ', '-');
            d.push_back({label, settings_of(v)});
          }
        dimensions.push_back(d);
      };
      const auto &sw = p.sweep;
      add(words(sw.tabor_parameters), "muT", [](const std::string &v) {
        return std::vector<Setting>{{"Adhesion", "Tabor parameter", v}};
      });
      add(sw.thicknesses, "t", [](const std::string &v) {
        if (v == "half-plane")
          return std::vector<Setting>{{"Geometry", "Substrate", v}};
        return std::vector<Setting>{{"Geometry", "Substrate", "layer"},
                                    {"Geometry", "Layer thickness", v}};
      });
      add(words(sw.approaches), "delta", [](const std::string &v) {
        return std::vector<Setting>{{"Loading", "Final approach", v},
                                    {"Loading", "Target load", ""}};
      });
      add(words(sw.loads), "F", [](const std::string &v) {
        return std::vector<Setting>{{"Loading", "Target load", v}};
      });
      add(words(sw.solvers), "", [](const std::string &v) {
        return std::vector<Setting>{{"Sliding", "Solver", v}};
      });
      add(words(sw.controls), "", [](const std::string &v) {
        return std::vector<Setting>{{"Sliding", "Control", v}};
      });
      add(words(sw.spring_stiffnesses), "k", [](const std::string &v) {
        return std::vector<Setting>{{"Sliding", "Spring stiffness", v}};
      });
      add(sw.shapes, "", [](const std::string &v) {
        return std::vector<Setting>{{"Indenter", "Shape", v}};
      });
      if (p.sliding.solver == Parameters::SlidingSolver::transient &&
          p.sliding.speeds.size() > 1)
        add(words(p.sliding.speeds), "V", [](const std::string &v) {
          return std::vector<Setting>{{"Sliding", "Sliding speed", v}};
        });

      std::vector<Case> cases(1);
      for (const auto &d : dimensions)
        {
          std::vector<Case> product;
          for (const auto &c : cases)
            for (const auto &choice : d)
              {
                Case n = c;
                if (d.size() > 1)
                  n.name += (n.name.empty() ? "" : "_") + choice.label;
                n.settings.insert(n.settings.end(),
                                  choice.settings.begin(),
                                  choice.settings.end());
                product.push_back(n);
              }
          cases = product;
        }
      return cases;
    }

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

    struct Status
    {
      std::string state; // "" (not run or interrupted), "done", "failed"
      std::string reason;
    };

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

    // Takes the lock on the first process of `comm`; every process learns
    // the outcome (and in `error` why the lock could not be tried).
    enum class LockState
    {
      held,
      busy,
      error
    };

    LockState
    take_lock(std::unique_ptr<CaseLock> &lock,
              const std::string         &file,
              MPI_Comm                   comm,
              std::string               &error,
              const double               patience = 0)
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
      const auto         columns = SteadyStateTable::columns();
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

    // The solver of one case, its screen output copied into log.txt;
    // returns "" or the reason it failed. Failures of the solver are
    // collective, so every process returns the same.
    std::string
    run_solver(const Case &c,
               Progress   &progress,
               MPI_Comm    comm,
               const bool  resume,
               const bool  to_screen)
    {
      std::unique_ptr<ScreenLog> log;
      if (Utilities::MPI::this_mpi_process(comm) == 0)
        {
          log = std::make_unique<ScreenLog>(
            (fs::path(c.parameters.output.directory) / "log.txt").string(),
            to_screen,
            resume);
          for (const auto &note : c.parameters.notes)
            std::cout << note << std::endl;
        }
      try
        {
          if (c.parameters.sliding.solver ==
              Parameters::SlidingSolver::boundary_element)
            BoundaryElementSolver(c.parameters, comm, &progress).run();
          else
            ContactProblem(c.parameters, comm, &progress).run(resume);
          return "";
        }
      catch (ExceptionBase &e)
        {
          // A check inside deal.II, p4est or a solver library: its
          // message without the source location and stack trace.
          std::ostringstream info;
          e.print_info(info);
          return "internal error (" + std::string(e.get_exc_name()) +
                 "): " + one_line(info.str()) +
                 " Please report it with the case's parameters.prm.";
        }
      catch (std::exception &e)
        {
          const std::string what = e.what();
          return what.empty() ? "unknown error" : what;
        }
    }

    // Runs one case with its record (run.json).
    std::string
    run_case(const Case       &c,
             Progress         &progress,
             MPI_Comm          comm,
             const bool        resume,
             const RunOptions &options)
    {
      RunRecord         record(c.parameters.output.directory,
                       options.command_line,
                       comm);
      const std::string failure =
        run_solver(c, progress, comm, resume, options.jobs == 1);
      record.finish(failure.empty() ? "done" : "failed");
      return failure;
    }
  } // namespace


  namespace
  {
    // Reads the file and every case of its sweep. Every case is checked
    // before any runs: a bad value in a list must not surface hours into a
    // sweep. Returns false (after saying why) on bad input.
    bool
    read_cases(const std::string &input,
               std::vector<Case> &cases,
               fs::path          &top,
               MPI_Comm           comm)
    {
      const bool  root = Utilities::MPI::this_mpi_process(comm) == 0;
      std::string in_case;
      auto        report = [&](const auto &print) {
        if (!root)
          return;
        std::cerr << "viscoslide: error in parameter file '" << input << "'"
                  << (in_case.empty() ? "" : ", sweep case " + in_case)
                  << ":\n";
        print();
      };
      try
        {
          if (!std::ifstream(input))
            throw Parameters::ExcInvalidInput("cannot read parameter file '" +
                                              input + "'");
          Case base;
          read_case(input, base);
          cases = make_cases(base.parameters);
          top   = base.parameters.output.directory;
          for (auto &c : cases)
            {
              in_case = c.name;
              if (!c.name.empty())
                c.settings.push_back(
                  {"Output", "Output directory", (top / c.name).string()});
              read_case(input, c);
            }
        }
      catch (ExceptionBase &e) // ParameterHandler's: show only its message
        {
          report([&] { e.print_info(std::cerr); });
          return false;
        }
      catch (std::exception &e)
        {
          report([&] { std::cerr << e.what() << std::endl; });
          return false;
        }
      return true;
    }


    // A single run: its files go straight into the Output directory.
    int
    run_single(const Case &c, const RunOptions &options, MPI_Comm comm)
    {
      const bool     root = Utilities::MPI::this_mpi_process(comm) == 0;
      const fs::path dir(c.parameters.output.directory);
      const bool resume = options.resume && ContactProblem::has_checkpoint(dir);
      std::unique_ptr<CaseLock> lock;
      try
        {
          if (resume)
            {
              if (!ran_with(dir, c))
                throw std::runtime_error(
                  "cannot resume in '" + dir.string() +
                  "': its run had other parameters (parameters.prm)");
            }
          else
            {
              if (options.resume && fs::exists(dir / "parameters.prm"))
                throw std::runtime_error(
                  "nothing to resume in '" + dir.string() +
                  "': it holds no checkpoint (the run finished, or was "
                  "killed before its first checkpoint); rerun it with "
                  "--overwrite");
              OutputWriter::prepare_directory(dir.string(),
                                              options.overwrite,
                                              comm);
            }
          std::string error;
          const auto  state =
            take_lock(lock, (dir / ".lock").string(), comm, error, 5);
          if (state == LockState::busy)
            throw std::runtime_error("another viscoslide is running in '" +
                                     dir.string() + "'; nothing was changed");
          if (state == LockState::error)
            throw std::runtime_error(error);
          if (!resume)
            write_provenance(c, comm);
        }
      catch (std::exception &e)
        {
          if (root)
            std::cerr << "viscoslide: " << e.what() << std::endl;
          return 1;
        }
      if (root)
        std::cout << version_string() << ", "
                  << Utilities::MPI::n_mpi_processes(comm)
                  << " MPI process(es)\n";
      Progress          progress(1, 1);
      const std::string failure = run_case(c, progress, comm, resume, options);
      if (root)
        try
          {
            write_status(dir, failure);
          }
        catch (std::exception &e)
          {
            std::cerr << "viscoslide: " << e.what() << std::endl;
          }
      if (!failure.empty() && root)
        std::cerr << "\nviscoslide: run failed:\n" << failure << std::endl;
      return failure.empty() ? 0 : 2;
    }


    // Which cases of a sweep run: those never finished, and those the user
    // asked to redo; a finished case whose parameters differ from the
    // file's is refused, so that one table never mixes two studies. Also
    // keeps the sweep's file as sweep.prm. Returns the error, if any.
    std::string
    select_cases(const std::string       &input,
                 const std::vector<Case> &cases,
                 const fs::path          &top,
                 const RunOptions        &options,
                 std::vector<char>       &to_run)
    {
      std::error_code ec;
      fs::create_directories(top, ec);
      if (ec)
        return "cannot create output directory '" + top.string() +
               "': " + ec.message();
      using Redo = RunOptions::Redo;
      for (std::size_t k = 0; k < cases.size(); ++k)
        {
          const fs::path dir    = top / cases[k].name;
          const Status   status = read_status(dir);
          if (status.state.empty())
            continue; // never run, or interrupted: run (again)
          const bool same = ran_with(dir, cases[k]);
          if (!same && !options.overwrite)
            return "case folder '" + dir.string() +
                   "' holds a case run with other parameters; choose "
                   "another 'Output/Output directory' or run with "
                   "--overwrite";
          to_run[k] =
            !same || options.overwrite || options.redo == Redo::all ||
            (options.redo == Redo::failed && status.state == "failed");
        }
      try
        {
          const std::string text =
            "# " + version_string() + "\n" + read_file(input);
          if (read_file(top / "sweep.prm") != text)
            write_atomically(top / "sweep.prm", text);
        }
      catch (std::exception &e)
        {
          return e.what();
        }
      return "";
    }


    // What a group of processes does with case k of a sweep.
    enum class CaseOutcome
    {
      ran,
      running_elsewhere,
      finished_elsewhere
    };

    // Case k of a sweep in its own folder, under its lock: a case another
    // process holds, or one that another invocation finished since the
    // cases were chosen (its status changed from `signature`), is left
    // alone. An interrupted case resumes from its checkpoint if asked to
    // and its parameters are those of the file, otherwise it starts again.
    CaseOutcome
    run_sweep_case(const std::size_t        k,
                   const std::vector<Case> &cases,
                   const fs::path          &top,
                   const std::string       &signature,
                   const RunOptions        &options,
                   Progress                &progress,
                   MPI_Comm                 comm)
    {
      const bool     root = Utilities::MPI::this_mpi_process(comm) == 0;
      const Case    &c    = cases[k];
      const fs::path dir  = top / c.name;
      std::unique_ptr<CaseLock> lock;
      std::string               failure;
      const auto                state =
        take_lock(lock, lock_file(top, c.name), comm, failure, 2);
      if (state == LockState::busy)
        return CaseOutcome::running_elsewhere;
      if (Utilities::MPI::broadcast(comm,
                                    root && state == LockState::held &&
                                      status_signature(dir) != signature,
                                    0))
        return CaseOutcome::finished_elsewhere;

      progress.start_case(k + 1, c.name);
      const bool resume = options.resume && read_status(dir).state.empty() &&
                          ContactProblem::has_checkpoint(dir) &&
                          ran_with(dir, c);
      try
        {
          std::error_code ec; // prepare_directory() reports the failure
          if (root && !resume && failure.empty())
            fs::remove_all(dir, ec);
          if (!resume && failure.empty())
            {
              OutputWriter::prepare_directory(dir.string(), true, comm);
              write_provenance(c, comm);
            }
        }
      catch (std::exception &e)
        {
          failure = e.what();
        }
      failure = Utilities::MPI::broadcast(comm, failure, 0);
      if (root)
        {
          std::cout << "\n=== case " << k + 1 << "/" << cases.size() << " "
                    << c.name << ":";
          for (const auto &s : c.settings)
            if (s.section != "Output" && !s.value.empty())
              std::cout << " " << s.entry << " = " << s.value << ";";
          std::cout << std::endl;
        }
      if (failure.empty())
        failure = run_case(c, progress, comm, resume, options);
      if (!root)
        return CaseOutcome::ran;
      try
        {
          write_status(dir, failure);
          write_sweep_table(top, cases);
        }
      catch (std::exception &e)
        {
          std::cerr << "viscoslide: " << e.what() << std::endl;
        }
      std::cout << "case " << k + 1 << "/" << cases.size() << " " << c.name
                << ": " << (failure.empty() ? "done" : "FAILED: " + failure)
                << "  [" << progress.report(1.) << "]" << std::endl;
      return CaseOutcome::ran;
    }


    // The cases of the sweep that this invocation considers, run by groups
    // of processes (options.jobs) side by side: each group takes the next
    // case whose lock is free.
    void
    run_cases(const std::vector<Case>        &cases,
              const fs::path                 &top,
              const std::vector<char>        &to_run,
              const std::vector<std::string> &signatures,
              const RunOptions               &options,
              MPI_Comm                        comm)
    {
      const unsigned int n_procs = Utilities::MPI::n_mpi_processes(comm);
      const unsigned int rank    = Utilities::MPI::this_mpi_process(comm);
      const unsigned int jobs    = options.jobs;
      MPI_Comm           group;
      MPI_Comm_split(comm, rank * jobs / n_procs, rank, &group);
      const bool group_root = Utilities::MPI::this_mpi_process(group) == 0;

      // Each group runs about its share of the cases; the estimate of the
      // time left is that of this group's share.
      const unsigned int n_to_run = std::count(to_run.begin(), to_run.end(), 1);
      Progress           progress(cases.size(), (n_to_run + jobs - 1) / jobs);
      for (std::size_t k = 0; k < cases.size(); ++k)
        {
          std::string said;
          if (to_run[k])
            switch (run_sweep_case(
              k, cases, top, signatures[k], options, progress, group))
              {
                case CaseOutcome::ran:
                  break;
                case CaseOutcome::running_elsewhere:
                  said = "running in another process, skipped";
                  break;
                case CaseOutcome::finished_elsewhere:
                  said = "finished by another process, skipped";
                  break;
              }
          else if (options.only_case == 0 || options.only_case == k + 1)
            said = read_status(top / cases[k].name).state + " earlier, skipped";
          if (group_root && !said.empty() && (jobs == 1 || rank == 0))
            std::cout << "case " << k + 1 << "/" << cases.size() << " "
                      << cases[k].name << ": " << said << std::endl;
        }
      MPI_Comm_free(&group);
      MPI_Barrier(comm);
    }


    int
    run_sweep(const std::string       &input,
              const std::vector<Case> &cases,
              const fs::path          &top,
              const RunOptions        &options,
              MPI_Comm                 comm)
    {
      const bool        root = Utilities::MPI::this_mpi_process(comm) == 0;
      std::vector<char> to_run(cases.size(), 1);
      std::vector<std::string> signatures(cases.size());
      std::string              error;
      if (options.only_case > cases.size())
        error = "--case " + std::to_string(options.only_case) +
                ": the study has " + std::to_string(cases.size()) + " cases";
      else if (root)
        error = select_cases(input, cases, top, options, to_run);
      for (std::size_t k = 0; k < cases.size(); ++k)
        {
          if (options.only_case != 0 && options.only_case != k + 1)
            to_run[k] = 0;
          if (root)
            signatures[k] = status_signature(top / cases[k].name);
        }
      error      = Utilities::MPI::broadcast(comm, error, 0);
      to_run     = Utilities::MPI::broadcast(comm, to_run, 0);
      signatures = Utilities::MPI::broadcast(comm, signatures, 0);
      if (!error.empty())
        {
          if (root)
            std::cerr << "viscoslide: " << error << std::endl;
          return 1;
        }

      const unsigned int n_to_run = std::count(to_run.begin(), to_run.end(), 1);
      if (root)
        std::cout << version_string() << ", "
                  << Utilities::MPI::n_mpi_processes(comm) << " MPI process(es)"
                  << (options.jobs > 1
                        ? ", " + std::to_string(options.jobs) +
                            " cases at once (their output in their log.txt)"
                        : "")
                  << "\nSweep of " << cases.size() << " cases into '"
                  << top.string() << "': " << n_to_run << " to run\n";
      run_cases(cases, top, to_run, signatures, options, comm);

      // The table also when every case was skipped, and the verdict on
      // the cases this invocation considered.
      std::string failed, elsewhere;
      if (root)
        {
          write_sweep_table(top, cases);
          for (std::size_t k = 0; k < cases.size(); ++k)
            {
              const auto &name = cases[k].name;
              if ((options.only_case != 0 && options.only_case != k + 1) ||
                  read_status(top / name).state == "done")
                continue;
              if (read_status(top / name).state.empty() &&
                  running_elsewhere(top, name))
                elsewhere += " " + name;
              else
                failed += " " + name;
            }
          std::cout << "\nSweep finished: " << top.string()
                    << "/steady_state.csv" << std::endl;
          if (!elsewhere.empty())
            std::cout << "still running in another process:" << elsewhere
                      << std::endl;
          if (!failed.empty())
            std::cerr << "viscoslide: these cases failed (reasons in "
                      << (top / "steady_state.csv").string() << "):" << failed
                      << std::endl;
        }
      failed = Utilities::MPI::broadcast(comm, failed, 0);
      return failed.empty() ? 0 : 2;
    }
  } // namespace


  int
  run_parameter_file(const std::string &input,
                     const RunOptions  &requested,
                     MPI_Comm           comm)
  {
    // No more groups than processes.
    RunOptions options = requested;
    options.jobs =
      std::min(options.jobs, Utilities::MPI::n_mpi_processes(comm));
    std::vector<Case> cases;
    fs::path          top; // the Output directory
    if (!read_cases(input, cases, top, comm))
      return 1;
    if (options.dry_run)
      {
        if (Utilities::MPI::this_mpi_process(comm) == 0)
          for (const auto &c : cases)
            {
              std::cout << (top / c.name).string() << " "
                        << std::hash<std::string>()(
                             case_identity(c.parameter_text))
                        << std::endl;
              for (const auto &note : c.parameters.notes)
                std::cout << "  " << note << std::endl;
            }
        return 0;
      }
    if (cases.size() == 1 && cases[0].name.empty())
      return run_single(cases[0], options, comm);
    return run_sweep(input, cases, top, options, comm);
  }
} // namespace viscoslide

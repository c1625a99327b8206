// SPDX-License-Identifier: LGPL-2.1-or-later
#include <deal.II/base/parameter_handler.h>

#include <viscoslide/boundary_element/solver.h>
#include <viscoslide/contact_problem.h>
#include <viscoslide/driver/case_folder.h>
#include <viscoslide/driver/case_lock.h>
#include <viscoslide/driver/driver.h>
#include <viscoslide/driver/run_record.h>
#include <viscoslide/io/output.h>
#include <viscoslide/io/parameters.h>
#include <viscoslide/io/steady_state_table.h>
#include <viscoslide/steady_state/run.h>

#include <algorithm>
#include <chrono>
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
    using namespace Study;

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
          CaseParts   parts(c.parameters, comm, &progress);
          const auto &sliding = c.parameters.sliding;
          if (sliding.solver == Parameters::SlidingSolver::boundary_element)
            {
              if (c.parameters.geometry.dimension == 3)
                BoundaryElementSolver<3>(parts).run();
              else
                BoundaryElementSolver<2>(parts).run();
            }
          else if (sliding.solver == Parameters::SlidingSolver::steady_state &&
                   sliding.speed > 0)
            run_steady_state(parts, resume);
          else // the transient solver, and an approach without sliding
            ContactProblem(parts).run(resume);
          const PeakMemory memory = peak_memory(comm);
          if (log &&
              c.parameters.output.verbosity != Parameters::Verbosity::quiet)
            std::cout << "Peak memory: " << memory.total << " GB in "
                      << Utilities::MPI::n_mpi_processes(comm)
                      << " processes (largest " << memory.largest << " GB)"
                      << std::endl;
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

    // One invocation's run of a study, as every group of its processes
    // sees it: the cases, which of them it considers, their verdicts when
    // it started, and when that was.
    struct StudyRun
    {
      const std::vector<Case>              &cases;
      const fs::path                       &top;
      const std::vector<char>              &to_run;
      const std::vector<std::string>       &signatures;
      const RunOptions                     &options;
      std::chrono::steady_clock::time_point start =
        std::chrono::steady_clock::now();

      // The study's progress over every group of the invocation, e.g.
      // "2 of 6 cases done, 3.1 min elapsed, ~6.2 min left": the cases it
      // considers whose verdict has been written since it started.
      std::string
      progress() const
      {
        unsigned int n = 0, done = 0;
        for (std::size_t k = 0; k < cases.size(); ++k)
          if (to_run[k])
            {
              ++n;
              const fs::path dir = top / cases[k].name;
              done += !read_status(dir).state.empty() &&
                      status_signature(dir) != signatures[k];
            }
        const double elapsed = std::chrono::duration<double>(
                                 std::chrono::steady_clock::now() - start)
                                 .count();
        std::string text = std::to_string(done) + " of " + std::to_string(n) +
                           " cases done, " + format_duration(elapsed) +
                           " elapsed";
        if (done > 0 && done < n)
          text +=
            ", ~" + format_duration(elapsed / done * (n - done)) + " left";
        return text;
      }
    };

    // Takes case k's folder for a fresh run (or keeps it to resume) and
    // writes its provenance; returns the error, if any, on every process.
    std::string
    prepare_case_folder(const Case     &c,
                        const fs::path &dir,
                        const bool      resume,
                        MPI_Comm        comm)
    {
      std::string failure;
      try
        {
          std::error_code ec; // prepare_directory() reports the failure
          if (Utilities::MPI::this_mpi_process(comm) == 0 && !resume)
            fs::remove_all(dir, ec);
          if (!resume)
            {
              OutputWriter::prepare_directory(dir.string(), true, comm);
              write_provenance(c, comm);
            }
        }
      catch (std::exception &e)
        {
          failure = e.what();
        }
      return Utilities::MPI::broadcast(comm, failure, 0);
    }

    // Case k of a sweep in its own folder, under its lock: a case another
    // process holds, or one that another invocation finished since the
    // cases were chosen (its status changed from its signature), is left
    // alone. An interrupted case resumes from its checkpoint if asked to
    // and its parameters are those of the file, otherwise it starts again.
    // `group` names the group of processes in the report (empty: one
    // group).
    CaseOutcome
    run_sweep_case(const std::size_t  k,
                   const StudyRun    &study,
                   const std::string &group,
                   Progress          &progress,
                   MPI_Comm           comm)
    {
      const bool     root = Utilities::MPI::this_mpi_process(comm) == 0;
      const Case    &c    = study.cases[k];
      const fs::path dir  = study.top / c.name;
      std::unique_ptr<CaseLock> lock;
      std::string               failure;
      const auto                state =
        take_lock(lock, lock_file(study.top, c.name), comm, failure, 2);
      if (state == LockState::busy)
        return CaseOutcome::running_elsewhere;
      if (Utilities::MPI::broadcast(comm,
                                    root && state == LockState::held &&
                                      status_signature(dir) !=
                                        study.signatures[k],
                                    0))
        return CaseOutcome::finished_elsewhere;

      progress.start_case(k + 1, c.name);
      const bool resume =
        study.options.resume && read_status(dir).state.empty() &&
        ContactProblem::has_checkpoint(dir) && ran_with(dir, c);
      if (failure.empty())
        failure = prepare_case_folder(c, dir, resume, comm);
      if (root)
        {
          std::cout << "\n=== case " << k + 1 << "/" << study.cases.size()
                    << " " << c.name << group << ":";
          for (const auto &s : c.settings)
            if (s.section != "Output" && !s.value.empty())
              std::cout << " " << s.entry << " = " << s.value << ";";
          std::cout << std::endl;
        }
      if (failure.empty())
        failure = run_case(c, progress, comm, resume, study.options);
      if (!root)
        return CaseOutcome::ran;
      try
        {
          write_status(dir, failure);
          write_sweep_table(study.top, study.cases);
        }
      catch (std::exception &e)
        {
          std::cerr << "viscoslide: " << e.what() << std::endl;
        }
      std::cout << "case " << k + 1 << "/" << study.cases.size() << " "
                << c.name << ": "
                << (failure.empty() ? "done" : "FAILED: " + failure) << group
                << "  [" << study.progress() << "]" << std::endl;
      return CaseOutcome::ran;
    }


    // The cases of the sweep that this invocation considers, run by groups
    // of processes (options.jobs) side by side: each group takes the next
    // case whose lock is free. A case another group of this invocation
    // took is its own; only cases run or finished by another invocation
    // are said to be skipped, once every group is done.
    void
    run_cases(const StudyRun &study, MPI_Comm comm)
    {
      const auto        &cases   = study.cases;
      const unsigned int n_procs = Utilities::MPI::n_mpi_processes(comm);
      const unsigned int rank    = Utilities::MPI::this_mpi_process(comm);
      const unsigned int jobs    = study.options.jobs;
      const int          color   = rank * jobs / n_procs;
      MPI_Comm           group;
      MPI_Comm_split(comm, color, rank, &group);
      const bool speaker = Utilities::MPI::this_mpi_process(group) == 0 &&
                           (jobs == 1 || rank == 0);
      const std::string group_name =
        jobs > 1 ? " in group " + std::to_string(color + 1) : "";

      // The solver's own progress lines (in log.txt when jobs > 1) estimate
      // this group's share of the cases.
      const unsigned int n_to_run =
        std::count(study.to_run.begin(), study.to_run.end(), 1);
      Progress         progress(cases.size(), (n_to_run + jobs - 1) / jobs);
      std::vector<int> ran_by(cases.size(), -1);
      std::vector<std::pair<std::size_t, std::string>> elsewhere;
      for (std::size_t k = 0; k < cases.size(); ++k)
        if (study.to_run[k])
          switch (run_sweep_case(k, study, group_name, progress, group))
            {
              case CaseOutcome::ran:
                ran_by[k] = color;
                break;
              case CaseOutcome::running_elsewhere:
                elsewhere.emplace_back(k, "running in another process");
                break;
              case CaseOutcome::finished_elsewhere:
                elsewhere.emplace_back(k, "finished by another process");
                break;
            }
        else if (speaker && (study.options.only_case == 0 ||
                             study.options.only_case == k + 1))
          std::cout << "case " << k + 1 << "/" << cases.size() << " "
                    << cases[k].name << ": "
                    << read_status(study.top / cases[k].name).state
                    << " earlier, skipped" << std::endl;
      MPI_Comm_free(&group);
      MPI_Allreduce(
        MPI_IN_PLACE, ran_by.data(), ran_by.size(), MPI_INT, MPI_MAX, comm);
      for (const auto &[k, said] : elsewhere)
        if (speaker && ran_by[k] < 0)
          std::cout << "case " << k + 1 << "/" << cases.size() << " "
                    << cases[k].name << ": " << said << ", skipped"
                    << std::endl;
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
      run_cases({cases, top, to_run, signatures, options}, comm);

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

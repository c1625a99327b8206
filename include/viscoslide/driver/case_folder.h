// SPDX-License-Identifier: LGPL-2.1-or-later
// A case's folder in a study: its verdict (status), the parameters it ran
// with (its identity, for --resume and for refusing to mix two studies),
// its lock, its provenance files, and the study's steady_state.csv
// gathered from the folders.
#ifndef viscoslide_case_folder_h
#define viscoslide_case_folder_h

#include <deal.II/base/mpi.h>

#include <viscoslide/driver/case_lock.h>
#include <viscoslide/driver/study.h>

#include <filesystem>
#include <memory>
#include <string>
#include <vector>

namespace viscoslide
{
  namespace Study
  {
    namespace fs = std::filesystem;

    // A one-line reason for a CSV cell.
    std::string
    one_line(const std::string &text);

    // The verdict of a run in its folder: "done", or "failed" and the
    // reason on the next line.
    void
    write_status(const fs::path &dir, const std::string &failure);

    std::string
    read_file(const fs::path &path);

    // What identifies a case's run: its parameters without comment lines
    // and without the Sweep section.
    std::string
    case_identity(const std::string &text);

    // Whether the run in `dir` had the case's parameters (its
    // parameters.prm, compared as case_identity() does).
    bool
    ran_with(const fs::path &dir, const Case &c);

    struct Status
    {
      std::string state; // "" (not run or interrupted), "done", "failed"
      std::string reason;
    };

    Status
    read_status(const fs::path &folder);

    // A case's verdict and when it was written: a change between choosing
    // the cases to run and starting one means that another invocation ran
    // it meanwhile.
    std::string
    status_signature(const fs::path &folder);

    // The lock of case `name`, beside its folder (which a fresh run
    // deletes).
    std::string
    lock_file(const fs::path &top, const std::string &name);

    bool
    running_elsewhere(const fs::path &top, const std::string &name);

    enum class LockState
    {
      held,
      busy,
      error
    };

    // Takes the lock on the first process of `comm`; every process learns
    // the outcome (and in `error` why the lock could not be tried).
    LockState
    take_lock(std::unique_ptr<CaseLock> &lock,
              const std::string         &file,
              MPI_Comm                   comm,
              std::string               &error,
              double                     patience = 0);

    // The sweep's steady_state.csv, rebuilt from the case folders after
    // each case: a row per case and speed, or one row naming the reason
    // for a case that failed before writing any.
    void
    write_sweep_table(const fs::path          &directory,
                      const std::vector<Case> &cases);

    // parameters.prm (with the version), parameters.json and version.txt
    // in the case's folder.
    void
    write_provenance(const Case &c, MPI_Comm comm);
  } // namespace Study
} // namespace viscoslide

#endif

// SPDX-License-Identifier: LGPL-2.1-or-later
// The driver: turns a parameter file into one run or into a sweep over the
// product of the lists of its Sweep section (and of a transient run's
// speeds), runs each case in its own folder, and keeps the sweep's
// steady_state.csv up to date. See doc/sweeps.md.
#ifndef viscoslide_driver_h
#define viscoslide_driver_h

#include <deal.II/base/mpi.h>

#include <string>

namespace viscoslide
{
  struct RunOptions
  {
    // Replace the results of an earlier run (a single run), or rerun every
    // case of a sweep, even one run with other parameters.
    bool overwrite = false;
    // Continue a killed run, or the unfinished cases of a sweep, from the
    // checkpoint in its folder (parameters must be unchanged).
    bool resume = false;
    // Which finished cases of a sweep run again.
    enum class Redo
    {
      none,
      failed,
      all
    } redo = Redo::none;
    // Check the file and list the cases (folder and checksum of their
    // parameters) without running or writing anything.
    bool dry_run = false;
    // Groups of processes that run the cases of a study side by side, each
    // case on one group (the processes are split evenly).
    unsigned int jobs = 1;
    // Run only this case (1-based, in the order of --dry-run) of a study,
    // for the job arrays of a batch scheduler; 0: every case.
    unsigned int only_case = 0;
    // As typed, for the record of each run (run.json).
    std::string command_line;
  };

  // Runs the parameter file `input` (.prm or .json). Returns the exit code:
  // 0 when every case ran, 1 for bad input (nothing was run), 2 when a run
  // or some cases of a sweep failed (the others are complete).
  int
  run_parameter_file(const std::string &input,
                     const RunOptions  &options,
                     MPI_Comm           comm);
} // namespace viscoslide

#endif

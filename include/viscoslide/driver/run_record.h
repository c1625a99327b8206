// SPDX-License-Identifier: LGPL-2.1-or-later
// run.json: what a run was (command line, host, processes, times, the
// version and the state of the source tree read when it ran, the mesh),
// beside the run's parameters.prm and log.txt (doc/outputs.md).
#ifndef viscoslide_run_record_h
#define viscoslide_run_record_h

#include <deal.II/base/mpi.h>

#include <chrono>
#include <string>

namespace viscoslide
{
  // The peak resident memory (VmHWM) of the processes of `comm` so far, in
  // GB: summed over them and the largest one's. Collective.
  struct PeakMemory
  {
    double total, largest;
  };
  PeakMemory
  peak_memory(MPI_Comm comm);

  class RunRecord
  {
  public:
    // Writes run.json into `directory` with the status "running" (on the
    // first process of `comm`; the others do nothing).
    RunRecord(const std::string &directory,
              const std::string &command_line,
              MPI_Comm           comm);

    // Rewrites it with the end time, the wall time, the status ("done" or
    // "failed"), the size of the last mesh read from the run's tables and
    // the peak memory. Collective.
    void
    finish(const std::string &status) const;

  private:
    // end, wall, mesh and memory are JSON values (null while the run goes
    // on).
    void
    write(const std::string &status,
          const std::string &end,
          const std::string &wall,
          const std::string &mesh,
          const std::string &memory) const;

    MPI_Comm                              comm;
    std::string                           directory, command_line, start;
    unsigned int                          n_processes;
    bool                                  root;
    std::chrono::steady_clock::time_point clock_start;
  };
} // namespace viscoslide

#endif

// SPDX-License-Identifier: LGPL-2.1-or-later
// The viscoslide command line; the work is done by run_parameter_file()
// (driver.h).
#include <deal.II/base/mpi.h>
#include <deal.II/base/parameter_handler.h>

#include <viscoslide/driver/driver.h>
#include <viscoslide/io/output.h>
#include <viscoslide/io/parameters.h>
#include <viscoslide/numerics/blas_kernels.h>

#include <algorithm>
#include <fstream>
#include <iostream>

namespace
{
  const char *usage =
    "Usage: viscoslide [--overwrite] [--resume] [--redo failed|all] "
    "[--dry-run]\n"
    "                  [--jobs N] [--case K] PARAMETER_FILE.prm|.json\n"
    "       viscoslide --print-parameters [prm|json]\n"
    "       viscoslide --help | --version\n"
    "\n"
    "Simulates a rigid cylinder pressed into (and later sliding on) a\n"
    "standard linear viscoelastic half-plane or bonded layer with\n"
    "Lennard-Jones adhesion (plane strain, deal.II finite elements).\n"
    "\n"
    "  PARAMETER_FILE      the run's parameters; entries not given keep\n"
    "                      their defaults (see --print-parameters)\n"
    "  --overwrite         allow writing into an output directory that\n"
    "                      already holds results (a sweep: rerun all)\n"
    "  --resume            continue a killed run (each unfinished case of a\n"
    "                      sweep) from its last checkpoint (Output/\n"
    "                      Checkpoint every), with the same parameters\n"
    "  --redo failed|all   a sweep reruns its failed (or all) finished\n"
    "                      cases; by default they are skipped\n"
    "  --dry-run           check the file, list the case folders (with a\n"
    "                      checksum of each case's parameters and what\n"
    "                      the program will change or doubts) and stop\n"
    "  --jobs N            run N cases of a study at once, each on its own\n"
    "                      share of the MPI processes (N <= processes)\n"
    "  --case K            run only case K (1, 2, ... as --dry-run lists\n"
    "                      them), e.g. the task index of a job array\n"
    "A case another invocation is running (its lock file .NAME.lock is\n"
    "held) is skipped, never touched.\n"
    "  --print-parameters  print every entry with default and documentation\n"
    "\n"
    "Run in parallel with: mpirun -np N viscoslide FILE.prm\n";

  // The positive whole number after option args[i], or 0.
  int
  whole_number_after(const std::vector<std::string> &args, const std::size_t i)
  {
    try
      {
        return i + 1 < args.size()
                 ? std::max(viscoslide::Utilities::string_to_int(args[i + 1]),
                            0)
                 : 0;
      }
    catch (...)
      {
        return 0;
      }
  }

  // Reads the options and the parameter file's name. Returns -1 to run,
  // otherwise the exit code after printing (help, version, the parameters,
  // or what was wrong).
  int
  parse_command_line(const std::vector<std::string> &args,
                     const bool                      root,
                     viscoslide::RunOptions         &options,
                     std::string                    &input)
  {
    using namespace viscoslide;
    auto fail = [&](const std::string &message) {
      if (root)
        std::cerr << message;
      return 1;
    };
    for (std::size_t i = 0; i < args.size(); ++i)
      {
        if (args[i] == "--help" || args[i] == "-h" || args[i] == "--version")
          {
            if (root)
              std::cout << (args[i] == "--version" ? version_string() + "\n"
                                                   : std::string(usage));
            return 0;
          }
        if (args[i] == "--print-parameters")
          {
            ParameterHandler prm;
            Parameters::AllParameters::declare(prm);
            const bool json = i + 1 < args.size() && args[i + 1] == "json";
            if (root)
              prm.print_parameters(std::cout,
                                   json ? ParameterHandler::JSON
                                        : ParameterHandler::PRM);
            return 0;
          }
        if (args[i] == "--overwrite")
          options.overwrite = true;
        else if (args[i] == "--resume")
          options.resume = true;
        else if (args[i] == "--dry-run")
          options.dry_run = true;
        else if (args[i] == "--redo")
          {
            if (i + 1 >= args.size() ||
                (args[i + 1] != "failed" && args[i + 1] != "all"))
              return fail("viscoslide: --redo needs 'failed' or 'all'\n");
            options.redo = args[++i] == "all" ? RunOptions::Redo::all
                                              : RunOptions::Redo::failed;
          }
        else if (args[i] == "--jobs" || args[i] == "--case")
          {
            const int n = whole_number_after(args, i);
            if (n < 1)
              return fail("viscoslide: " + args[i] +
                          " needs a positive whole number\n");
            (args[i] == "--jobs" ? options.jobs : options.only_case) = n;
            ++i;
          }
        else if (!args[i].empty() && args[i][0] == '-')
          return fail("viscoslide: unknown option '" + args[i] + "'\n\n" +
                      usage);
        else if (input.empty())
          input = args[i];
        else
          return fail("viscoslide: more than one parameter file given\n");
      }
    if (input.empty())
      return fail(usage);
    if (options.resume && options.overwrite)
      return fail("viscoslide: --resume continues a run, --overwrite "
                  "starts it again: give one of them\n");
    return -1;
  }
} // namespace

int
main(int argc, char *argv[])
{
  using namespace viscoslide;
  use_native_blas_kernels(argv);
  Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  MPI_Comm                         comm = MPI_COMM_WORLD;
  const bool root = Utilities::MPI::this_mpi_process(comm) == 0;

  RunOptions options;
  for (int i = 0; i < argc; ++i)
    {
      const std::string a = argv[i];
      const bool quote    = a.empty() || a.find_first_of(" \t'\"") != a.npos;
      options.command_line += (i ? " " : "") + (quote ? "'" + a + "'" : a);
    }
  std::string input;
  const int   exit_code = parse_command_line(
    std::vector<std::string>(argv + 1, argv + argc), root, options, input);
  if (exit_code >= 0)
    return exit_code;
  return run_parameter_file(input, options, comm);
}

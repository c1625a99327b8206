// The viscoslide driver: reads a parameter file, prepares the output
// directory, records the parameters actually used, and runs the problem.
#include <deal.II/base/mpi.h>
#include <deal.II/base/parameter_handler.h>

#include <viscoslide/contact_problem.h>
#include <viscoslide/output.h>
#include <viscoslide/parameters.h>

#include <fstream>
#include <iostream>

namespace
{
  const char *usage =
    "Usage: viscoslide [--overwrite] PARAMETER_FILE.prm|.json\n"
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
    "                      already holds results\n"
    "  --print-parameters  print every entry with default and documentation\n"
    "\n"
    "Run in parallel with: mpirun -np N viscoslide FILE.prm\n";
}

int
main(int argc, char *argv[])
{
  using namespace viscoslide;
  Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  MPI_Comm                         comm = MPI_COMM_WORLD;
  const bool root = Utilities::MPI::this_mpi_process(comm) == 0;

  std::vector<std::string> args(argv + 1, argv + argc);
  bool                     overwrite = false;
  std::string              input;
  for (std::size_t i = 0; i < args.size(); ++i)
    {
      if (args[i] == "--help" || args[i] == "-h")
        {
          if (root)
            std::cout << usage;
          return 0;
        }
      if (args[i] == "--version")
        {
          if (root)
            std::cout << version_string() << std::endl;
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
        overwrite = true;
      else if (!args[i].empty() && args[i][0] == '-')
        {
          if (root)
            std::cerr << "viscoslide: unknown option '" << args[i] << "'\n\n"
                      << usage;
          return 1;
        }
      else if (input.empty())
        input = args[i];
      else
        {
          if (root)
            std::cerr << "viscoslide: more than one parameter file given\n";
          return 1;
        }
    }
  if (input.empty())
    {
      if (root)
        std::cerr << usage;
      return 1;
    }

  ParameterHandler          prm;
  Parameters::AllParameters parameters;
  try
    {
      Parameters::AllParameters::declare(prm);
      if (!std::ifstream(input))
        throw Parameters::ExcInvalidInput("cannot read parameter file '" +
                                          input + "'");
      prm.parse_input(input);
      parameters.parse(prm);
      OutputWriter::prepare_directory(parameters.output.directory,
                                      overwrite,
                                      comm);
    }
  catch (ExceptionBase &e) // ParameterHandler's: show only its message
    {
      if (root)
        {
          std::cerr << "viscoslide: error in parameter file '" << input
                    << "':\n";
          e.print_info(std::cerr);
        }
      return 1;
    }
  catch (std::exception &e)
    {
      if (root)
        std::cerr << "viscoslide: error in parameter file '" << input << "':\n"
                  << e.what() << std::endl;
      return 1;
    }

  try
    {
      if (root)
        {
          const std::string dir = parameters.output.directory + "/";
          std::ofstream     out(dir + "parameters.prm");
          out << "# " << version_string() << "\n";
          prm.print_parameters(out, ParameterHandler::PRM);
          std::ofstream json(dir + "parameters.json");
          prm.print_parameters(json, ParameterHandler::JSON);
          std::ofstream(dir + "version.txt") << version_string() << "\n";
          std::cout << version_string() << ", "
                    << Utilities::MPI::n_mpi_processes(comm)
                    << " MPI process(es)\n";
        }
      ContactProblem problem(parameters, comm);
      problem.run();
    }
  catch (std::exception &e)
    {
      // Failures of the solver are collective, so every process ends here.
      if (root)
        std::cerr << "\nviscoslide: run failed:\n" << e.what() << std::endl;
      return 2;
    }
  return 0;
}

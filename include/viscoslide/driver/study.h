// SPDX-License-Identifier: LGPL-2.1-or-later
// The cases of a study: a parameter file read once, the product of the
// lists of its Sweep section (and of a transient run's speeds) turned into
// cases, each with the entries it changes and its folder, each checked
// before any runs (doc/sweeps.md).
#ifndef viscoslide_study_h
#define viscoslide_study_h

#include <viscoslide/io/parameters.h>

#include <deal.II/base/mpi.h>

#include <filesystem>
#include <string>
#include <vector>

namespace viscoslide
{
  namespace Study
  {
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
    read_case(const std::string &input, Case &c);

    // The product of the sweep lists. A list of one entry is applied but
    // does not appear in the folder names.
    std::vector<Case>
    make_cases(const Parameters::AllParameters &p);

    // Reads the file and every case of its sweep into `cases`, and the
    // Output directory into `top`. Every case is checked before any runs:
    // a bad value in a list must not surface hours into a sweep. Returns
    // false (after saying why on the first process) on bad input.
    bool
    read_cases(const std::string     &input,
               std::vector<Case>     &cases,
               std::filesystem::path &top,
               MPI_Comm               comm);
  } // namespace Study
} // namespace viscoslide

#endif

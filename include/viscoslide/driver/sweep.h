// SPDX-License-Identifier: LGPL-2.1-or-later
// The 'Sweep' section: the lists whose product is a study, each case a run
// of its own in its own folder (doc/sweeps.md). An empty list leaves the
// entry of its own section alone.
#ifndef viscoslide_sweep_h
#define viscoslide_sweep_h

#include <viscoslide/io/input.h>
#include <viscoslide/physics/loading.h>

#include <string>
#include <vector>

namespace viscoslide
{
  namespace Parameters
  {
    struct Sweep
    {
      std::vector<double>        tabor_parameters;
      std::vector<std::string>   thicknesses; // numbers or "half-plane"
      std::vector<double>        approaches;
      std::vector<double>        loads;
      std::vector<Control>       controls;
      std::vector<SlidingSolver> solvers;
      std::vector<double>        spring_stiffnesses;
      std::vector<std::string>   shapes;
      std::vector<double>        temperatures;

      static void
      declare(ParameterHandler &prm);
      void
      parse(ParameterHandler &prm);
    };
  } // namespace Parameters
} // namespace viscoslide

#endif

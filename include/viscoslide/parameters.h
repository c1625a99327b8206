// SPDX-License-Identifier: LGPL-2.1-or-later
// All run-time parameters of one case, grouped as in step-44: one struct
// per section of the parameter file, each declared and parsed beside the
// class it configures (output.h, material.h, interaction_law.h,
// indenter.h, mesh.h, loading.h, newton.h, boundary_element/grid.h,
// sweep.h, units.h). Every quantity a user types is dimensionless, in the
// units of ../doc/conventions.md (lengths in eps, times in the chosen time
// constant tau, stresses in E0*, see scales.h), unless the Units section
// gives the case in SI units, which parse() converts once.
#ifndef viscoslide_parameters_h
#define viscoslide_parameters_h

#include <viscoslide/boundary_element/grid.h>
#include <viscoslide/indenter.h>
#include <viscoslide/input.h>
#include <viscoslide/interaction_law.h>
#include <viscoslide/loading.h>
#include <viscoslide/material.h>
#include <viscoslide/mesh.h>
#include <viscoslide/newton.h>
#include <viscoslide/output.h>
#include <viscoslide/scales.h>
#include <viscoslide/sweep.h>
#include <viscoslide/units.h>

#include <string>
#include <vector>

namespace viscoslide
{
  namespace Parameters
  {
    // declare() declares every section; parse() reads a file, checks ranges and
    // cross-entry consistency (case_setup.h), and throws ExcInvalidInput
    // with the entry name and value on the first violation.
    struct AllParameters
    {
      Output          output;
      Material        material;
      Adhesion        adhesion;
      IndenterProfile indenter;
      Geometry        geometry;
      Loading         loading;
      Mesh            mesh;
      Sliding         sliding;
      Solver          solver;
      BoundaryElement boundary_element;
      Sweep           sweep;
      Units           units;

      // What the program changed in the case or doubts about it, said
      // once when the case starts (for example the block widened to hold
      // the wake).
      std::vector<std::string> notes;

      static void
      declare(ParameterHandler &prm);
      void
      parse(ParameterHandler &prm);
    };
  } // namespace Parameters
} // namespace viscoslide

#endif

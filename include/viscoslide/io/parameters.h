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
#include <viscoslide/driver/sweep.h>
#include <viscoslide/io/input.h>
#include <viscoslide/io/output.h>
#include <viscoslide/numerics/mesh.h>
#include <viscoslide/numerics/newton.h>
#include <viscoslide/physics/indenter.h>
#include <viscoslide/physics/interaction_law.h>
#include <viscoslide/physics/loading.h>
#include <viscoslide/physics/material.h>
#include <viscoslide/physics/scales.h>
#include <viscoslide/physics/units.h>

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

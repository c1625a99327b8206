// SPDX-License-Identifier: LGPL-2.1-or-later
// The parts of one case that every solver shares, built once by the driver
// from the case's parameters and handed to the solver the case names: the
// reduced units, the solid, the interaction law, the indenter, the output
// folder's writer and the steady_state.csv table.
#ifndef viscoslide_case_h
#define viscoslide_case_h

#include <deal.II/base/mpi.h>

#include <viscoslide/io/output.h>
#include <viscoslide/io/parameters.h>
#include <viscoslide/io/steady_state_table.h>
#include <viscoslide/physics/indenter.h>
#include <viscoslide/physics/interaction_law.h>
#include <viscoslide/physics/material.h>
#include <viscoslide/physics/scales.h>

#include <memory>

namespace viscoslide
{
  struct CaseParts
  {
    // `progress`, if given, is the sweep driver's case k of n and time
    // estimate, appended to the solvers' report lines.
    CaseParts(const Parameters::AllParameters &prm,
              MPI_Comm                         comm,
              Progress                        *progress = nullptr);

    const Parameters::AllParameters      &prm;
    MPI_Comm                              comm;
    const Scales                          scales;
    const ViscoelasticSolid               material;
    const std::unique_ptr<InteractionLaw> law;
    const std::unique_ptr<Indenter>       indenter;
    OutputWriter                          writer;
    SteadyStateTable                      steady_state_table;
    Progress                             *progress;
  };
} // namespace viscoslide

#endif

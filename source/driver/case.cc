// SPDX-License-Identifier: LGPL-2.1-or-later
#include <viscoslide/driver/case.h>

namespace viscoslide
{
  CaseParts::CaseParts(const Parameters::AllParameters &prm,
                       MPI_Comm                         comm,
                       Progress                        *progress)
    : prm(prm)
    , comm(comm)
    , scales(prm)
    , material(make_solid(prm, scales))
    , law(create_interaction_law(prm.adhesion.law, scales.dgamma, scales.eps))
    , indenter(
        create_indenter(prm.indenter, scales.R, prm.geometry.domain_width))
    , writer(prm.output.directory, comm, prm.output.field_format)
    , steady_state_table(prm, scales, writer.path("steady_state.csv"), comm)
    , progress(progress)
  {
  }
} // namespace viscoslide

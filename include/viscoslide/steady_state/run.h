// SPDX-License-Identifier: LGPL-2.1-or-later
// A case of the steady-state solver: the finite-element approach of the
// transient solver (ContactProblem::approach()), whose block, surface
// coupling and relaxed state the steady-state solver then takes over, and
// the stations of Sliding/Sliding speed and Load path by continuation
// (doc/steady_state.md). Chosen by the driver for Sliding/Solver =
// steady-state with a positive speed.
#ifndef viscoslide_steady_state_run_h
#define viscoslide_steady_state_run_h

#include <viscoslide/driver/case.h>

namespace viscoslide
{
  // With `resume`, from the checkpoint of its last converged station
  // instead of a new approach.
  void
  run_steady_state(CaseParts &parts, bool resume);
} // namespace viscoslide

#endif

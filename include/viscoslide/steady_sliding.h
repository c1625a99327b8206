// SPDX-License-Identifier: LGPL-2.1-or-later
// What every solver of the steady sliding state offers (the finite-element
// SteadyStateSolver and the BoundaryElementSolver), and the loop over the
// stations of a run that both share: the listed speeds, then the loads of
// Sliding/Load path, each with its row in steady_state.csv and its profile
// (implemented in source/steady_sliding.cc).
#ifndef viscoslide_steady_sliding_h
#define viscoslide_steady_sliding_h

#include <deal.II/base/conditional_ostream.h>

#include <viscoslide/io/output.h>
#include <viscoslide/io/parameters.h>
#include <viscoslide/io/postprocessing.h>
#include <viscoslide/io/steady_state_table.h>

#include <functional>
#include <string>

namespace viscoslide
{
  using namespace dealii;

  class SteadySliding
  {
  public:
    virtual ~SteadySliding() = default;

    // Continues the steady state from its present speed to V_hat, calling
    // on_converged after every converged continuation step. Returns false
    // if a step could not be solved; the state is then the last converged
    // one.
    virtual bool
    continue_to(double V_hat, const std::function<void()> &on_converged) = 0;

    // Follows the steady state at the current speed to a new load: F_n
    // under force control, delta under displacement control (internal
    // units).
    virtual bool
    continue_to_load(double                       target,
                     const std::function<void()> &on_converged) = 0;

    virtual double
    speed() const = 0;
    virtual double
    approach() const = 0;
    virtual const SurfaceQuantities &
    quantities() const = 0;
    // The dissipation rate of the whole solid (internal units).
    virtual double
    dissipation_rate() const = 0;
    // Newton iterations of the last converged step.
    virtual unsigned int
    newton_iterations() const = 0;
    // Unknowns of the discretisation.
    virtual unsigned long
    n_unknowns() const = 0;
    virtual bool
    force_control() const = 0;
    // Whether two processes may take a list of speeds from both ends, one
    // up from the first, the other down from the last: for a solver each
    // of whose processes holds the whole problem, and that reaches any
    // speed directly from rest.
    virtual bool
    from_both_ends() const
    {
      return false;
    }

    virtual void
    write_profile(const std::string &path) const = 0;
    // Fields over the solid, if the solver has them.
    virtual void
    write_fields(OutputWriter &writer, unsigned int counter) const = 0;
  };

  // The stations of Sliding/Sliding speed and Sliding/Load path, one after
  // the other by continuation: a row of `table` and a profile for each,
  // fields if asked, and continuation.csv with every converged step. A
  // station that cannot be reached gets its row with steady = 0 (values of
  // the last converged state, whose V_hat, delta and F_n it shows), the
  // continuation goes on to the next one, and at the end std::runtime_error
  // names the stations missed.
  // Where a continuation resumes: the station after the last converged
  // one, and the rows its tables keep.
  struct StationCheckpoint
  {
    unsigned int next_station      = 0;
    std::size_t  continuation_rows = 0;
    std::size_t  table_rows        = 0;
  };

  // Whether run_stations takes the speeds from both ends: two or more
  // processes, a solver that can, a list of speeds and no Load path
  // (which continues from the last speed).
  bool
  stations_from_both_ends(const SteadySliding             &solver,
                          const Parameters::AllParameters &prm,
                          MPI_Comm                         comm);

  // Runs the stations of Sliding speed (then Load path) from
  // start.next_station on, with a row per station in `table` and one per
  // converged step in continuation.csv; `checkpoint`, if given, is called
  // after each converged station. Where stations_from_both_ends(), process
  // 0 takes the speeds from the first up, process 1 from the last down
  // (each writing its stations' profiles), until they meet; process 0
  // writes the rows, process 1's when both are done; any further
  // processes wait.
  void
  run_stations(
    SteadySliding                                        &solver,
    Parameters::SlidingSolver                             kind,
    const Parameters::AllParameters                      &prm,
    const Scales                                         &scales,
    OutputWriter                                         &writer,
    SteadyStateTable                                     &table,
    Progress                                             *progress,
    ConditionalOStream                                   &out,
    MPI_Comm                                              comm,
    const StationCheckpoint                              &start      = {},
    const std::function<void(const StationCheckpoint &)> &checkpoint = {});
} // namespace viscoslide

#endif

#include <viscoslide/contact_problem.h>
#include <viscoslide/steady_state/run.h>
#include <viscoslide/steady_state/solver.h>

namespace viscoslide
{
  void
  run_steady_state(CaseParts &parts, const bool resume)
  {
    const auto    &prm = parts.prm;
    ContactProblem approach(parts);
    if (!resume)
      approach.approach();
    const ContactProblem::HandOver start = approach.hand_over();
    SteadyStateSolver              steady(prm,
                             parts.scales,
                             parts.material,
                             start.coupling,
                             start.postprocessor,
                             start.triangulation,
                             start.timer);
    StationCheckpoint              station;
    if (resume)
      station = steady.read_checkpoint(parts.writer.path(""));
    else
      {
        steady.initialize(start.dof_handler,
                          start.solution,
                          start.delta,
                          start.s);
        if (prm.sliding.control != Parameters::Control::displacement)
          start.coupling.hold_force(
            start.normal_force,
            SurfaceCoupling::spring_stiffness_of(prm, parts.scales),
            start.delta);
      }
    ConditionalOStream pcout(std::cout,
                             Utilities::MPI::this_mpi_process(parts.comm) ==
                                 0 &&
                               prm.output.verbosity !=
                                 Parameters::Verbosity::quiet);
    pcout << "Steady sliding at V_hat = " << prm.sliding.speed << " under "
          << Parameters::to_string(prm.sliding.control)
          << " control, by continuation from the "
          << (resume ? "checkpoint" : "relaxed state") << std::endl;
    std::function<void(const StationCheckpoint &)> checkpoint;
    if (prm.output.checkpoint_every > 0)
      checkpoint = [&](const StationCheckpoint &s) {
        steady.write_checkpoint(parts.writer.path(""), s);
      };
    run_stations(steady,
                 Parameters::SlidingSolver::steady_state,
                 prm,
                 parts.scales,
                 parts.writer,
                 parts.steady_state_table,
                 parts.progress,
                 pcout,
                 parts.comm,
                 station,
                 checkpoint);
    approach.finish();
  }
} // namespace viscoslide

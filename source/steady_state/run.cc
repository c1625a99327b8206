// SPDX-License-Identifier: LGPL-2.1-or-later
#include <viscoslide/contact_problem.h>
#include <viscoslide/io/checkpoint.h>
#include <viscoslide/numerics/mesh.h>
#include <viscoslide/steady_state/run.h>
#include <viscoslide/steady_state/solver.h>

namespace viscoslide
{
  namespace
  {
    // The first process's screen, unless Output/Verbosity is quiet.
    ConditionalOStream
    screen(const CaseParts &parts)
    {
      return ConditionalOStream(std::cout,
                                Utilities::MPI::this_mpi_process(parts.comm) ==
                                    0 &&
                                  parts.prm.output.verbosity !=
                                    Parameters::Verbosity::quiet);
    }


    // The stations of Sliding/Sliding speed and Load path from a started
    // solver, or from its checkpoint.
    template <int dim>
    void
    run_stations_of(SteadyStateSolver<dim>  &steady,
                    CaseParts               &parts,
                    const StationCheckpoint &station,
                    const bool               resume)
    {
      const auto        &prm   = parts.prm;
      ConditionalOStream pcout = screen(parts);
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
    }


    // Force or spring control from the present state on: the force held is
    // the present one.
    template <int dim>
    void
    hold_present_force(const Parameters::AllParameters &prm,
                       const Scales                    &scales,
                       SurfaceCoupling<dim>            &coupling,
                       const double                     normal_force,
                       const double                     delta)
    {
      if (prm.sliding.control != Parameters::Control::displacement)
        coupling.hold_force(normal_force,
                            SurfaceCoupling<dim>::spring_stiffness_of(prm,
                                                                      scales),
                            delta);
    }


    // In 2D the transient solver approaches and hands its block over.
    void
    run_2d(CaseParts &parts, const bool resume)
    {
      const auto    &prm = parts.prm;
      ContactProblem approach(parts);
      if (!resume)
        approach.approach();
      const ContactProblem::HandOver start = approach.hand_over();
      SteadyStateSolver<2>           steady(prm,
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
          hold_present_force(
            prm, parts.scales, start.coupling, start.normal_force, start.delta);
        }
      run_stations_of(steady, parts, station, resume);
      approach.finish();
    }


    // The 3D approach at rest from Loading/Initial approach to Final
    // approach, the law's attraction switched on there (homotopy, if the
    // law is adhesive), then the force held or brought to the Target load.
    void
    approach_at_rest(SteadyStateSolver<3>            &steady,
                     SurfaceCoupling<3>              &coupling,
                     AttractionHomotopy              *homotopy,
                     const Parameters::AllParameters &prm,
                     const Scales                    &scales)
    {
      const auto   nothing = [] {};
      const double last    = prm.loading.final_approach;
      // In steps of Approach increment: a whole step into the traction
      // law's wall costs Newton many iterations to climb out of.
      for (double d = prm.loading.initial_approach; d < last;)
        {
          d = std::min(last, d + prm.loading.increment);
          if (!steady.continue_to_load(d * scales.eps, nothing))
            throw std::runtime_error(
              "the approach at rest did not converge at delta_hat = " +
              std::to_string(d) +
              " on its way to 'Loading/Final "
              "approach' = " +
              std::to_string(last));
        }
      if (homotopy && !steady.continue_in_attraction(
                        [&](const double s) { homotopy->set_attraction(s); }))
        throw std::runtime_error(
          "the adhesive contact at rest did not follow the law's "
          "attraction at 'Loading/Final approach' = " +
          std::to_string(last) +
          " (a larger approach gives a wider contact to start from)");
      hold_present_force(prm,
                         scales,
                         coupling,
                         steady.quantities().normal_force,
                         steady.approach());
      if (coupling.force_control() && prm.loading.has_target_load() &&
          !steady.continue_to_load(prm.loading.target_load * scales.force,
                                   nothing))
        throw std::runtime_error(
          "the approach at rest did not converge on its way to "
          "'Loading/Target load' = " +
          std::to_string(prm.loading.target_load));
    }


    // In 3D the steady-state solver approaches at rest (V_hat = 0, the
    // relaxed solid) itself: under displacement control from
    // Loading/Initial approach to Final approach (an adhesive law on its
    // repulsive wall alone, then with its attraction switched on there),
    // then, under force control with a Target load, in the force to it.
    void
    run_3d(CaseParts &parts, const bool resume)
    {
      const auto                             &prm    = parts.prm;
      const Scales                           &scales = parts.scales;
      ConditionalOStream                      pcout  = screen(parts);
      TimerOutput                             timer(parts.comm,
                        pcout,
                        TimerOutput::never,
                        TimerOutput::wall_times);
      parallel::distributed::Triangulation<3> triangulation(
        parts.comm, Triangulation<3>::limit_level_difference_at_vertices);
      // An adhesive law comes in with its attraction off (see
      // AttractionHomotopy) unless the state is read from a checkpoint.
      std::unique_ptr<AttractionHomotopy> homotopy;
      const InteractionLaw               *law = parts.law.get();
      if (prm.adhesion.adhesive())
        {
          homotopy = std::make_unique<AttractionHomotopy>(prm.adhesion.law,
                                                          scales.dgamma,
                                                          scales.eps);
          homotopy->set_attraction(resume ? 1. : 0.);
          law = homotopy.get();
        }
      const SurfacePostprocessor<3> postprocessor(
        *law,
        *parts.indenter,
        scales.eps,
        prm.adhesion.contact_gap,
        prm.adhesion.face_quadrature_points,
        top_boundary<3>,
        prm.geometry.elongation);
      SurfaceCoupling<3> coupling(
        prm, scales, *law, *parts.indenter, postprocessor, parts.comm);
      SteadyStateSolver<3> steady(prm,
                                  scales,
                                  parts.material,
                                  coupling,
                                  postprocessor,
                                  triangulation,
                                  timer);
      StationCheckpoint    station;
      if (resume)
        station = steady.read_checkpoint(parts.writer.path(""));
      else
        {
          make_block(triangulation, prm);
          coupling.hold_approach();
          steady.initialize_at_rest(prm.loading.initial_approach * scales.eps,
                                    0.);
          pcout << "Initial mesh: " << triangulation.n_global_active_cells()
                << " cells, " << steady.n_unknowns() << " dofs" << std::endl;
          approach_at_rest(steady, coupling, homotopy.get(), prm, scales);
        }
      run_stations_of(steady, parts, station, resume);
      Checkpoint::remove(parts.writer.path(""), parts.comm);
      timer.print_wall_time_statistics(parts.comm);
    }
  } // namespace


  void
  run_steady_state(CaseParts &parts, const bool resume)
  {
    if (parts.prm.geometry.dimension == 3)
      run_3d(parts, resume);
    else
      run_2d(parts, resume);
  }
} // namespace viscoslide

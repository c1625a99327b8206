// SPDX-License-Identifier: LGPL-2.1-or-later
// ContactProblem: construction and the loading program (approach, hold,
// sliding, retraction), stepped by advance_to().
#include <deal.II/base/utilities.h>

#include <deal.II/fe/fe_q.h>

#include <viscoslide/contact_problem.h>
#include <viscoslide/io/checkpoint.h>
#include <viscoslide/numerics/mesh.h>

#include <cmath>
#include <filesystem>

namespace viscoslide
{
  ContactProblem::ContactProblem(CaseParts &parts)
    : prm(parts.prm)
    , mpi_communicator(parts.comm)
    , pcout(std::cout,
            Utilities::MPI::this_mpi_process(mpi_communicator) == 0 &&
              prm.output.verbosity != Parameters::Verbosity::quiet)
    , timer(mpi_communicator,
            pcout,
            TimerOutput::never,
            TimerOutput::wall_times)
    , scales(parts.scales)
    , material(parts.material)
    , law(*parts.law)
    , indenter(*parts.indenter)
    , postprocessor(law,
                    indenter,
                    scales.eps,
                    prm.adhesion.contact_gap,
                    prm.adhesion.face_quadrature_points,
                    top_boundary<dim>)
    , coupling(prm, scales, law, indenter, postprocessor, mpi_communicator)
    , triangulation(mpi_communicator,
                    Triangulation<dim>::limit_level_difference_at_vertices)
    , fe(FE_Q<dim>(2), dim)
    , dof_handler(triangulation)
    , quadrature(3)
    , history_fe(QGauss<1>(3))
    , history_dof_handler(triangulation)
    , history(n_arm_stress_components * material.n_arms() + 1)
    , linear_solver(timer, mpi_communicator)
    , writer(parts.writer)
    , steady_state_table(parts.steady_state_table)
    , progress(parts.progress)
    , approach_progress(prm.loading.final_approach,
                        prm.loading.increment,
                        prm.loading.target_load)
  {
    // The history field's nodes are the Gauss points of the cell
    // quadrature; find which node is which point once.
    const auto &support = history_fe.get_unit_support_points();
    for (unsigned int q = 0; q < quadrature.size(); ++q)
      for (unsigned int i = 0; i < support.size(); ++i)
        if (support[i].distance(quadrature.point(q)) < 1e-12)
          quadrature_to_history_dof.push_back(i);
    AssertDimension(quadrature_to_history_dof.size(), quadrature.size());
  }


  std::string
  ContactProblem::name(const Phase phase)
  {
    static const char *const names[] = {
      "start", "approach", "load", "hold", "slide", "retract"};
    return names[static_cast<unsigned int>(phase)];
  }


  // One trial step from the committed state. Along a smooth branch the
  // secant predictor, with the nodes it would press into the indenter held
  // back, saves most of the Newton iterations; if it does not help, Newton
  // starts from the last state.
  int
  ContactProblem::solve_step(const LoadState &trial)
  {
    const double ratio =
      (trial.s != committed.s && last_increment_s != 0.)
        ? (trial.s - committed.s) / last_increment_s
        : (last_increment_delta != 0.
             ? (trial.delta - committed.delta) / last_increment_delta
             : 0.);
    if (ratio != 0. && std::abs(ratio) <= 4.)
      {
        const auto                    backup = solution;
        TrilinosWrappers::MPI::Vector predicted(locally_owned_dofs,
                                                mpi_communicator);
        predicted = solution;
        TrilinosWrappers::MPI::Vector increment(locally_owned_dofs,
                                                mpi_communicator);
        increment = last_increment;
        predicted.add(ratio, increment);
        LoadState predicted_state = trial;
        if (coupling.force_control())
          predicted_state.delta += ratio * last_increment_delta;
        coupling.limit_predicted_closing(dof_handler,
                                         constraints,
                                         backup,
                                         committed.delta,
                                         committed.s,
                                         predicted,
                                         predicted_state.delta,
                                         predicted_state.s);
        solution      = predicted;
        const int its = solve_newton(predicted_state);
        if (its >= 0)
          return its;
        solution = backup;
      }
    return solve_newton(trial);
  }


  // Steps from the committed state to `target`, in as few substeps as
  // Newton allows. Each accepted substep is solved on a mesh adapted to its
  // own solution, committed and recorded.
  bool
  ContactProblem::advance_to(const LoadState &target, const Phase phase)
  {
    const LoadState start    = committed;
    const double    span     = std::abs(target.delta - start.delta);
    double          done     = 0.;
    double          fraction = 1.;
    unsigned int    cuts     = 0;
    auto            at       = [&](const double f) {
      LoadState s;
      s.delta = start.delta + f * (target.delta - start.delta);
      s.s     = start.s + f * (target.s - start.s);
      s.time  = start.time + f * (target.time - start.time);
      return s;
    };

    while (done < 1. - 1e-12)
      {
        fraction           = std::min(fraction, 1. - done);
        LoadState trial    = at(done + fraction);
        trial.dt           = std::isfinite(target.dt)
                               ? trial.time - at(done).time
                               : std::numeric_limits<double>::infinity();
        const auto backup  = solution;
        bool       relaxed = false;
        int        its     = solve_step(trial);
        if (its < 0)
          {
            solution = backup;
            // Steps that do not change delta (hold, sliding) are cut down
            // to 1/64; a step that changes nothing (the start) is not cut.
            const bool moves = target.s != start.s || target.time != start.time;
            if (span > 0
                  ? fraction * span > prm.loading.minimum_increment * 1.0001
                  : moves && fraction > 1. / 64.)
              {
                fraction *= 0.5;
                ++cuts;
                continue;
              }
            pcout << "   Instability at delta_hat = " << trial.delta
                  << ": relaxing to the new branch\n";
            its     = relax_to_equilibrium(trial);
            relaxed = true;
            if (its < 0)
              return false;
          }
        // Under force control delta is part of the converged state. After
        // a jump the contact edges may have moved by hundreds of eps into
        // coarse cells, where an edge stops that a resolved surface would
        // carry on: there the mesh follows the solution until it no longer
        // changes (doc/model.md, Adaptive mesh).
        const unsigned int cycles =
          relaxed && prm.mesh.max_adaptation_cycles > 0
            ? std::max(64u, prm.mesh.max_adaptation_cycles)
            : prm.mesh.max_adaptation_cycles;
        const int more = resolve_on_adapted_meshes(
          cycles,
          [this] { return adapt_mesh(); },
          [this] {
            const LoadState converged = current;
            const int       its       = solve_newton(converged);
            return its >= 0 ? its : relax_to_equilibrium(converged);
          });
        if (more < 0)
          return false;
        commit_history();
        done += fraction;
        last_newton_iterations = its + more;
        last_step_cuts         = cuts;
        last_step_relaxed      = relaxed;
        record_step(phase);
        cuts = 0;
        fraction *= 2.; // try to recover the full increment
      }
    return true;
  }


  void
  ContactProblem::abort_run(const LoadState &target)
  {
    write_profile("surface_profile_last_converged.csv");
    throw std::runtime_error(
      "Newton failed at step " + std::to_string(step_number) +
      " (delta_hat = " + std::to_string(target.delta) +
      ", s_over_eps = " + std::to_string(target.s) +
      ", time_over_tau = " + std::to_string(target.time) +
      ") even after cutting the step and relaxing to a new branch; the "
      "last converged surface profile is in "
      "surface_profile_last_converged.csv");
  }


  void
  ContactProblem::ramp(const Phase phase, const double to)
  {
    const double       inf  = std::numeric_limits<double>::infinity();
    const double       v    = prm.loading.approach_speed;
    const double       from = committed.delta;
    const unsigned int n =
      std::max(1.,
               std::ceil(std::abs(to - from) / prm.loading.increment - 1e-9));
    for (unsigned int k = 1; k <= n; ++k)
      {
        LoadState target = committed;
        target.delta     = from + (to - from) * k / n;
        target.dt = v > 0 ? std::abs(target.delta - committed.delta) / v : inf;
        target.time = committed.time + (v > 0 ? target.dt : 0.);
        if (!advance_to(target, phase))
          abort_run(target);
      }
  }


  // The paper fixes some cases by their load F_hat, reached by a
  // displacement-controlled approach. Approach in the usual steps until
  // F_n (which rises with delta once contact is made) passes the target,
  // then solve that step again with F_n held at the target and delta free.
  void
  ContactProblem::approach_to_load()
  {
    const double       F    = prm.loading.target_load * scales.force;
    const double       from = committed.delta, to = prm.loading.final_approach;
    const unsigned int n =
      std::max(1., std::ceil((to - from) / prm.loading.increment - 1e-9));
    bool passed = false;
    for (unsigned int k = 1; k <= n && !passed; ++k)
      {
        LoadState target = committed;
        target.delta     = from + (to - from) * k / n;
        if (!advance_to(target, Phase::approach))
          abort_run(target);
        passed =
          last_quantities.minimum_gap < prm.adhesion.contact_gap * scales.eps &&
          last_quantities.normal_force >= F;
      }
    if (!passed)
      throw Parameters::ExcInvalidInput(
        "'Loading/Target load' = " + CsvTable::format(prm.loading.target_load) +
        " was not reached by 'Loading/Final approach' = " +
        CsvTable::format(to) + " (F_n_hat there: " +
        CsvTable::format(last_quantities.normal_force / scales.force) +
        "); raise the Final approach");
    coupling.hold_force(F);
    if (!advance_to(committed, Phase::load))
      abort_run(committed);
    coupling.hold_approach();
    pcout << "Load F_hat = " << prm.loading.target_load
          << " reached at delta_hat = " << committed.delta / scales.eps
          << std::endl;
  }


  void
  ContactProblem::hold()
  {
    const double       t0 = committed.time, T = prm.loading.hold_time;
    const unsigned int n     = prm.loading.hold_steps;
    const double       first = std::min(1e-3, T / n);
    for (unsigned int k = 1; k <= n; ++k)
      {
        LoadState target = committed;
        target.time =
          t0 + (n == 1 ? T : first * std::pow(T / first, (k - 1.) / (n - 1.)));
        target.dt = target.time - committed.time;
        if (!advance_to(target, Phase::hold))
          abort_run(target);
      }
  }


  void
  ContactProblem::approach()
  {
    open_approach_table(false);
    make_block(triangulation, prm);
    setup_system();
    committed.delta = prm.loading.initial_approach;
    current         = committed;
    refine_initial_mesh();
    pcout << "Initial mesh: " << triangulation.n_global_active_cells()
          << " cells, " << dof_handler.n_dofs() << " dofs" << std::endl;

    LoadState first = committed;
    if (!advance_to(first, Phase::start))
      abort_run(first);
    if (prm.loading.has_target_load())
      approach_to_load();
    else
      ramp(Phase::approach, prm.loading.final_approach);
    if (prm.loading.hold_time > 0)
      hold();
  }


  void
  ContactProblem::run(const bool resume)
  {
    // The approach and the hold; a resumed run has them behind it.
    if (resume)
      {
        read_checkpoint();
        open_approach_table(true);
      }
    else
      approach();
    if (!prm.sliding.program.empty())
      run_program(resume);
    else if (prm.sliding.speed > 0)
      slide(resume);
    if (prm.loading.retract)
      ramp(Phase::retract, prm.loading.retract_to);
    write_profile("surface_profile_final.csv");
    if (prm.output.write_fields &&
        (prm.output.fields_every == 0 ||
         (step_number - 1) % prm.output.fields_every != 0))
      write_fields();
    finish();
  }


  void
  ContactProblem::finish()
  {
    // A finished run needs its checkpoint no more.
    Checkpoint::remove(writer.path(""), mpi_communicator);
    timer.print_wall_time_statistics(mpi_communicator);
  }
} // namespace viscoslide

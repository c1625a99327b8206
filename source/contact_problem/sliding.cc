// SPDX-License-Identifier: LGPL-2.1-or-later
// ContactProblem: the sliding phase, by time stepping until steady state
// (slide()), or the state handed to the steady-state solver (hand_over()).
#include <viscoslide/contact_problem.h>

#include <algorithm>
#include <cstdio>

namespace viscoslide
{
  // How far to slide and over which window to judge steady state, from the
  // contact length L0 after the approach.
  void
  ContactProblem::plan_slide()
  {
    const double V     = prm.sliding.speed * scales.eps / scales.tau_ref;
    const double h_min = prm.mesh.finest_cell;
    auto        &plan  = slide_plan;
    plan.L0            = std::max(last_quantities.contact_length, 10. * h_min);
    const double tau_c = scales.tau_arm / prm.material.E0_over_Einf;
    // The relaxation length V tau_c sets the transient, but only as far
    // as it is comparable to the contact: faster than that, the material
    // crosses the contact unrelaxed and the contact is nearly steady once
    // the material deformed during the approach has left it. Nearly: the
    // approach's imprint in the wake recovers over V tau_c and still pulls
    // on the contact, by a few % in mu at V_hat = 100 with adhesion
    // (doc/steady_state.md); a 1 % answer there needs a window of V tau_c
    // (Sliding/Steady-state window) or the steady-state solver. The cap
    // keeps sweeps affordable.
    const double relaxation_length = std::min(V * tau_c, 4. * plan.L0);
    plan.distance                  = prm.sliding.max_distance > 0
                                       ? prm.sliding.max_distance
                                       : 4. * plan.L0 + 30. * relaxation_length;
    plan.window                    = prm.sliding.steady_window > 0
                                       ? prm.sliding.steady_window
                                       : std::max(plan.L0, 2. * relaxation_length);
    plan.s0                        = committed.s;
    if (plan.s0 + plan.distance + 2. * plan.L0 > prm.geometry.domain_width / 2)
      throw Parameters::ExcInvalidInput(
        "'Geometry/Domain width' = " +
        std::to_string(prm.geometry.domain_width) + " is too small to slide " +
        std::to_string(plan.distance) +
        " eps and stay 2 L = " + std::to_string(2 * plan.L0) +
        " eps away from the lateral boundary; it must be at least " +
        std::to_string(2 * (plan.s0 + plan.distance + 2 * plan.L0)) +
        " (or set 'Sliding/Maximum sliding distance')");
  }


  ContactProblem::SlideSample
  ContactProblem::window_mean(const double from, const double to) const
  {
    SlideSample mean{};
    std::size_t n = 0;
    for (const auto &x : samples)
      if (x.s > from && x.s <= to)
        {
          for (unsigned int k = 0; k < SlideSample::n_values; ++k)
            mean.value[k] += x.value[k];
          ++n;
        }
    for (double &v : mean.value)
      v /= std::max<std::size_t>(n, 1);
    return mean;
  }


  // Steady state: the means of the controlled quantity's conjugate (Fn or
  // delta), Ft and L over the two halves of the last window of sliding
  // differ by less than the tolerance relative to their size (or a floor
  // for small values). Means, not single steps: with adhesion the contact
  // edges jump from node to node, and Ft flickers with the period
  // of the finest cell by up to tens of percent where V tau is below it,
  // about a steady mean.
  bool
  ContactProblem::window_is_steady() const
  {
    using Sample      = SlideSample;
    const auto  &plan = slide_plan;
    const double end  = committed.s;
    if (end - plan.s0 < plan.window + plan.L0)
      return false;
    const Sample first  = window_mean(end - plan.window, end - plan.window / 2),
                 second = window_mean(end - plan.window / 2, end);
    const bool         force     = coupling.force_control();
    const unsigned int judged[3] = {force ? Sample::delta
                                          : Sample::normal_force,
                                    Sample::tangential_force,
                                    Sample::contact_length};
    const double floor[3] = {force ? scales.eps : 1e-3 * scales.force,
                             1e-3 *
                                 std::abs(second.value[Sample::normal_force]) +
                               1e-6 * scales.force,
                             prm.mesh.finest_cell};
    for (unsigned int k = 0; k < 3; ++k)
      {
        const double size = std::max({floor[k],
                                      std::abs(first.value[judged[k]]),
                                      std::abs(second.value[judged[k]])});
        if (std::abs(second.value[judged[k]] - first.value[judged[k]]) >
            prm.sliding.steady_tolerance * size)
          return false;
      }
    return true;
  }


  double
  ContactProblem::window_balance() const
  {
    using Sample = SlideSample;
    const Sample mean =
      window_mean(committed.s - slide_plan.window, committed.s);
    return energy_balance(mean.value[Sample::tangential_force],
                          mean.value[Sample::normal_force],
                          prm.sliding.speed * scales.eps / scales.tau_ref,
                          mean.value[Sample::dissipation_rate]);
  }


  // The steady values are the means over the last window (over all of the
  // sliding if it was shorter).
  void
  ContactProblem::report_slide(const bool steady)
  {
    using Sample = SlideSample;
    const Sample mean =
      window_mean(committed.s - slide_plan.window, committed.s);
    SurfaceQuantities q = last_quantities;
    q.normal_force      = mean.value[Sample::normal_force];
    q.contact_set_tangential_force =
      mean.value[Sample::contact_set_tangential_force];
    q.tangential_force = mean.value[Sample::tangential_force];
    q.contact_length   = mean.value[Sample::contact_length];
    steady_state_table.add_row(prm.sliding.speed,
                               mean.value[Sample::delta],
                               q,
                               mean.value[Sample::dissipation_rate],
                               steady,
                               committed.s - slide_plan.s0,
                               Parameters::SlidingSolver::transient,
                               pcout);
  }


  // Phase 2 of the paper: the profile h(x - s) moves with s = V t over the
  // fixed surface until Fn (or delta), Ft and L are steady over a window.
  // A resumed run starts from the plan, the samples and the control of
  // its checkpoint.
  void
  ContactProblem::slide(const bool resumed)
  {
    const double V  = prm.sliding.speed * scales.eps / scales.tau_ref;
    const double ds = prm.sliding.increment * prm.mesh.finest_cell;
    const double dt = ds / V;
    if (!resumed)
      {
        plan_slide();
        if (prm.sliding.control != Parameters::Control::displacement)
          coupling.hold_force(last_quantities.normal_force,
                              SurfaceCoupling<dim>::spring_stiffness_of(prm,
                                                                        scales),
                              committed.delta);
        samples.clear();
        history_rows = 0;
      }
    open_history_table(resumed);
    const auto &plan = slide_plan;
    if (resumed && progress != nullptr)
      progress->resume_case((committed.s - plan.s0) / plan.distance);
    pcout << (resumed ? "Resuming sliding" : "Sliding")
          << " at V_hat = " << prm.sliding.speed << " under "
          << Parameters::to_string(prm.sliding.control) << " control: up to "
          << plan.distance << " eps in steps of " << ds << " eps, steady over "
          << plan.window << " eps" << std::endl;

    // Steady: the window has settled and the energy balances over it.
    bool         steady = false, settled = false, balanced = false;
    unsigned int checkpointed_row = history_rows;
    while (committed.s - plan.s0 < plan.distance - 1e-9 * ds && !steady)
      {
        LoadState target = committed;
        target.s += ds;
        target.time += dt;
        target.dt = dt;
        if (!advance_to(target, Phase::slide))
          {
            // The case ends with the last converged state as its row,
            // flagged not steady; the reason is the exception's.
            if (!samples.empty())
              report_slide(false);
            abort_run(target);
          }
        const auto &q = last_quantities;
        samples.push_back({committed.s,
                           {committed.delta,
                            q.normal_force,
                            q.contact_set_tangential_force,
                            q.tangential_force,
                            q.contact_length,
                            last_dissipation_rate}});
        settled = window_is_steady();
        // NaN (not judged) passes.
        balanced = settled && !(std::abs(window_balance()) >
                                prm.sliding.balance_tolerance);
        steady   = settled && balanced;
        if (!steady && prm.output.checkpoint_every > 0 &&
            history_rows >= checkpointed_row + prm.output.checkpoint_every)
          {
            write_checkpoint();
            checkpointed_row = history_rows;
          }
      }

    report_slide(steady);
    write_profile("surface_profile_steady.csv");
    say_slide_verdict(settled, balanced);
    coupling.hold_approach();
  }


  // Whether the slide ended steady, and if not which of the two tests
  // (the window settled, the energy balanced over it) it failed.
  void
  ContactProblem::say_slide_verdict(const bool settled,
                                    const bool balanced) const
  {
    const bool steady = settled && balanced;
    pcout << (steady ? "Steady state" : "NO steady state") << " after "
          << committed.s - slide_plan.s0 << " eps";
    if (!settled)
      pcout << ": the window has not settled to 'Sliding/Steady-state "
               "tolerance' = "
            << prm.sliding.steady_tolerance;
    else if (!balanced)
      pcout << ": the window has settled, but the energy balances only to "
            << 100 * window_balance()
            << " % ('Sliding/Energy balance tolerance' = "
            << prm.sliding.balance_tolerance
            << "): the wake is still changing, or the mesh does not resolve "
               "V tau and the contact edges";
    pcout << std::endl;
  }


  LoadState
  ContactProblem::program_step(const Parameters::ProgramSegment &segment,
                               const double                      done) const
  {
    const double ds     = prm.sliding.increment * prm.mesh.finest_cell;
    const double left   = segment.length - done;
    LoadState    target = committed;
    if (segment.rest())
      {
        // The slide step's time at the fastest speed of the program, then
        // half the rest so far: about six steps per decade of time.
        double fastest = 0.;
        for (const auto &other : prm.sliding.program)
          fastest = std::max(fastest, std::abs(other.speed));
        target.dt = std::min(left, std::max(ds / fastest, 0.5 * done));
      }
    else
      {
        const double step = std::min(ds, left);
        target.s += (segment.speed > 0 ? step : -step) * scales.eps;
        target.dt = step / std::abs(segment.speed) * scales.tau_ref;
      }
    target.time += target.dt;
    return target;
  }


  double
  ContactProblem::sliding_speed() const
  {
    const auto &program = prm.sliding.program;
    if (program.empty())
      return prm.sliding.speed;
    // after the program the indenter rests
    return program_segment < program.size() ? program[program_segment].speed
                                            : 0.;
  }


  double
  ContactProblem::program_fraction() const
  {
    const auto &program = prm.sliding.program;
    if (program_segment >= program.size())
      return 1.;
    return (program_segment + segment_done / program[program_segment].length) /
           program.size();
  }


  void
  ContactProblem::run_program(const bool resumed)
  {
    const auto &program = prm.sliding.program;
    if (!resumed)
      {
        // The lateral boundaries two contact lengths away, as slide()
        // asks, at the program's farthest excursion.
        const double L0 =
          std::max(last_quantities.contact_length, 10. * prm.mesh.finest_cell);
        double s = committed.s;
        for (unsigned int k = 0; k < program.size(); ++k)
          {
            s += program[k].displacement();
            if (std::abs(s) + 2. * L0 > prm.geometry.domain_width / 2)
              throw Parameters::ExcInvalidInput(
                program[k].name(k) + " takes the contact, " +
                Parameters::num(L0) +
                " eps long, within 2 L of the block's "
                "lateral boundary; 'Geometry/Domain width' must be at least " +
                Parameters::num(2 * (std::abs(s) + 2 * L0)));
          }
        if (prm.sliding.control != Parameters::Control::displacement)
          coupling.hold_force(last_quantities.normal_force,
                              SurfaceCoupling<dim>::spring_stiffness_of(prm,
                                                                        scales),
                              committed.delta);
        program_segment = 0;
        segment_done    = 0.;
        history_rows    = 0;
      }
    open_history_table(resumed);
    if (resumed && progress != nullptr)
      progress->resume_case(program_fraction());
    unsigned int checkpointed_row = history_rows;
    while (program_segment < program.size())
      {
        const auto &segment = program[program_segment];
        pcout << "Segment " << program_segment + 1 << "/" << program.size()
              << ": " << segment.text << " under "
              << Parameters::to_string(prm.sliding.control) << " control"
              << (segment_done > 0 ? " (resumed part-way)" : "") << std::endl;
        while (segment_done < segment.length * (1. - 1e-12))
          {
            const LoadState target = program_step(segment, segment_done);
            const double    length =
              segment.rest() ? target.dt / scales.tau_ref
                                : std::abs(target.s - committed.s) / scales.eps;
            if (!advance_to(target, Phase::slide))
              abort_run(target);
            segment_done += length;
            if (prm.output.checkpoint_every > 0 &&
                history_rows >= checkpointed_row + prm.output.checkpoint_every)
              {
                write_checkpoint();
                checkpointed_row = history_rows;
              }
          }
        ++program_segment;
        segment_done = 0.;
        if (prm.output.checkpoint_every > 0 && program_segment < program.size())
          {
            write_checkpoint();
            checkpointed_row = history_rows;
          }
      }
    write_profile("surface_profile_program_end.csv");
    coupling.hold_approach();
  }


  ContactProblem::HandOver
  ContactProblem::hand_over()
  {
    return {triangulation,
            coupling,
            postprocessor,
            timer,
            dof_handler,
            solution,
            committed.delta,
            committed.s,
            last_quantities.normal_force};
  }
} // namespace viscoslide

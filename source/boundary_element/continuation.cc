// SPDX-License-Identifier: LGPL-2.1-or-later
// BoundaryElementSolver: steps in approach, speed and load, each from the
// equilibrium before with its secant predictor.
#include <viscoslide/boundary_element/solver.h>

#include <algorithm>
#include <cmath>

namespace viscoslide
{
  template <int dim>
  void
  BoundaryElementSolver<dim>::predict(const SurfaceState &at_state,
                                      const unsigned int  generation_at,
                                      const SurfaceState &before,
                                      const double        ratio)
  {
    // The secant from the step before, then no predicted gap below the
    // smaller of its present one and eps: a point that the step before
    // drew into contact would otherwise be extrapolated deep into the
    // repulsive wall (and without a step before, the contact moved with
    // delta), where the traction is huge and Newton's method crawls back.
    // On a grid made for this step (its predictor) the state is the grid's.
    const bool secant = ratio != 0. && std::abs(ratio) <= 2;
    if (secant && control.force_controlled)
      state.set_approach(state.delta + ratio * (at_state.delta - before.delta));
    for (unsigned int j = 0;
         generation_at == grid->generation() && j < state.gap.size();
         ++j)
      {
        // u moved along its secant, u_at - u_before; the indenter's height
        // cancels from it.
        if (secant)
          state.gap[j] -= ratio * ((before.delta - at_state.delta) +
                                   (before.gap[j] - at_state.gap[j]));
        state.gap[j] =
          std::max(state.gap[j], std::min(at_state.gap[j], scales.eps));
      }
  }


  template <int dim>
  bool
  BoundaryElementSolver<dim>::follow(const double from,
                                     const double to,
                                     const double step,
                                     const double min_step,
                                     const std::function<void(double)> &set,
                                     const std::function<void()> &on_converged,
                                     const std::function<bool()> &done)
  {
    double at = from, size = step;
    // A moving grid's contact edges at the step before, for their secant;
    // on such a grid a shorter step is cheaper than the relaxation, which
    // moves the edges by a fraction of eps per step.
    const bool  moving = grid->follows_contact();
    StepBefore &before = step_before;
    while (at != to)
      {
        const bool         last     = std::abs(to - at) <= size * (1 + 1e-9);
        const double       next     = last ? to : at + (to > at ? size : -size);
        const SurfaceState at_state = state;
        const unsigned int generation_at = grid->generation();
        const auto         placement_at  = grid->placement();
        const std::pair<double, double> edges_at{last_quantities.x_trail,
                                                 last_quantities.x_lead};
        set(next);
        const double ratio = !before.valid ? 0.
                             : before.from_rest
                               ? std::exp(next - at) - 1
                               : (next - at) / (at - before.at);
        if (moving && before.valid)
          grid->predict(edges_at, before.edges, ratio, state);
        const auto secant = [&] {
          predict(at_state,
                  generation_at,
                  before.state,
                  before.valid && before.generation == grid->generation() &&
                      before.state.gap.size() == state.gap.size()
                    ? ratio
                    : 0.);
        };
        // A coarse grid's step, relaxed only if Newton's method fails on
        // it and then on the fine grid from the secant: the coarse
        // relaxation is the cheaper where a step crosses the friction
        // peak, the secant where the coarse Newton merely stalls.
        const bool nested = !moving && grid->coarse_placement() != nullptr;
        const bool coarse =
          nested && predict_on_coarse(at, next, at_state, set, false);
        if (!coarse)
          secant();
        int its = solve(!moving && (coarse || !nested));
        if (its < 0 && nested && !coarse)
          {
            if (placement_at)
              grid->regrid(*placement_at, state);
            state = at_state;
            if (!predict_on_coarse(at, next, at_state, set, true))
              secant();
            its = solve();
          }
        if (its >= 0)
          {
            before = {true, false, at, at_state, generation_at, edges_at};
            at     = next;
            on_converged();
            if (done())
              return true;
            size = std::min(step, 2 * size);
            continue;
          }
        if (placement_at)
          grid->regrid(*placement_at, state);
        state = at_state;
        set(at);
        size /= 2;
        if (size < min_step)
          return false;
      }
    return true;
  }


  template <int dim>
  bool
  BoundaryElementSolver<dim>::predict_on_coarse(
    const double                       at,
    const double                       next,
    const SurfaceState                &at_state,
    const std::function<void(double)> &set,
    const bool                         relax)
  {
    const auto coarse = grid->coarse_placement();
    if (!coarse)
      return false;
    const auto fine = grid->placement();
    const auto back = [&](const bool ok) {
      grid->regrid(*fine, state);
      state = at_state;
      set(next);
      return ok;
    };
    // The coarse equilibrium at the start: the step before's, or solved
    // from the fine one's values at the coarse points.
    grid->regrid(*coarse, state);
    if (coarse_step.valid && std::abs(coarse_step.at - at) < 1e-12)
      state = coarse_step.state;
    else
      {
        set(at);
        if (solve_on_grid(false) < 0)
          return back(false);
        coarse_step = {true, at, state};
      }
    set(next);
    if (solve_on_grid(relax) < 0)
      {
        coarse_step.valid = false;
        return back(false);
      }
    SurfaceState now = state, before = coarse_step.state;
    coarse_step = {true, next, now};
    back(true);
    if (!grid->carry(*coarse, now) || !grid->carry(*coarse, before))
      return false;
    state.delta += now.delta - before.delta;
    for (unsigned int j = 0; j < state.gap.size(); ++j)
      state.gap[j] = std::max(state.gap[j] + now.gap[j] - before.gap[j],
                              std::min(at_state.gap[j], scales.eps));
    // The band about the predicted contact, rather than a second solve on
    // a new band after the first.
    update_quantities();
    grid->follow(last_quantities, traction, false, state);
    return true;
  }


  template <int dim>
  void
  BoundaryElementSolver<dim>::set_speed(const double V)
  {
    V_hat = V;
    grid->set_speed(V_hat * scales.eps / scales.tau_ref);
  }


  template <int dim>
  bool
  BoundaryElementSolver<dim>::start_sliding(const double target)
  {
    // The first speed: the one whose relaxation length is a tenth of the
    // grid spacing for the slowest arm, or slower. The creep it switches on
    // changes the work of adhesion at the edges by a fraction that grows
    // with V tau over the cohesive zone, and a wide contact answers such a
    // change by translating (and resizing) by that fraction of
    // R sqrt(w / (E a)): at Tabor parameter 1000 and R_hat 1e7, thousands
    // of eps at that speed, far beyond the reach of the linearization
    // about rest. The response is linear in V near rest, so a slower first
    // speed makes the step as small as Newton's method needs; the
    // continuation in log V then takes the decades back with its secant.
    double             start        = std::min(target,
                            0.1 * grid->spacing() /
                              (scales.eps / scales.tau_ref *
                               material.longest_relaxation_time()));
    const SurfaceState rest         = state;
    const auto         placement_at = grid->placement();
    const StepBefore   at_rest{true,
                             true,
                             0.,
                             rest,
                             grid->generation(),
                             {last_quantities.x_trail, last_quantities.x_lead}};
    // Only a grid whose edges are unknowns can follow the translation;
    // another relaxes across the first step as before.
    const unsigned int n_slower = grid->n_motions() > 0 ? 8 : 0;
    for (unsigned int k = 0; k <= n_slower; ++k, start /= 10)
      {
        set_speed(start);
        // Without relaxation but at the slowest: a failure is the cue to go
        // slower, not to relax across the jump.
        if (solve(k == n_slower) >= 0)
          {
            step_before = at_rest;
            return true;
          }
        if (placement_at)
          grid->regrid(*placement_at, state);
        state = rest;
        if (k < n_slower)
          pcout << "  the first speed V_hat " << V_hat
                << " did not converge from rest; trying " << start / 10
                << std::endl;
      }
    set_speed(0);
    return false;
  }


  template <int dim>
  bool
  BoundaryElementSolver<dim>::from_both_ends() const
  {
    return !grid->follows_contact();
  }


  template <int dim>
  bool
  BoundaryElementSolver<dim>::continue_to(
    const double                 target,
    const std::function<void()> &on_converged)
  {
    grid->fit_to_speed(std::max(V_hat, target), state);
    // The factorization of the speed before stays a good preconditioner
    // (it is renewed when GMRES needs too many iterations with it).
    const auto set = [this, target](const double log_V) {
      set_speed(std::abs(log_V - std::log(target)) < 1e-12 ? target
                                                           : std::exp(log_V));
    };
    if (V_hat == 0)
      {
        step_before = {};
        coarse_step = {};
        // From the relaxed state: directly, or else from the speed whose
        // relaxation length is a tenth of the grid spacing for the slowest
        // arm (a spectrum's may be decades slower than the time unit of
        // V_hat). A grid that follows the contact is about a contact
        // thousands of eps wide, and the creep at its edges moves them by
        // many cells in a direct jump, where Newton's method fails and the
        // relaxation takes minutes: it starts slow.
        // A band refined about the rest contact (start.cc) is kept while
        // the first speed's zone lies within it, a cell off its middle at
        // the trailing edge, where the error of the nested grid's
        // coarse-fine border reaches the zone: the band is made again
        // about the first speed's contact.
        const bool band_at_rest = grid->coarse_placement() != nullptr;
        const auto first_speed  = [&] {
          if (band_at_rest &&
              grid->follow(last_quantities, traction, true, state))
            solve();
          on_converged();
        };
        if (!grid->follows_contact())
          {
            set(std::log(target));
            if (solve() >= 0)
              {
                first_speed();
                return true;
              }
          }
        if (!start_sliding(target))
          return false;
        first_speed();
      }
    // A line per step short of the target: from a slow start the
    // continuation crosses decades before the first station.
    const auto report = [&] {
      if (V_hat != target)
        pcout << "  continuation: V_hat " << V_hat << " on the way to "
              << target << " (" << last_newton_iterations
              << " Newton iterations)" << std::endl;
      on_converged();
    };
    return follow(std::log(V_hat),
                  std::log(target),
                  std::log(prm.sliding.continuation_factor),
                  1e-3,
                  set,
                  report);
  }


  template <int dim>
  bool
  BoundaryElementSolver<dim>::continue_to_load(
    const double                 target,
    const std::function<void()> &on_converged)
  {
    const bool   force    = control.force_controlled;
    const double from     = force ? control.target_force : state.delta;
    const double distance = std::abs(target - from);
    step_before           = {};
    coarse_step           = {};
    return follow(
      from,
      target,
      distance / 10,
      distance * 1e-4,
      [this, force](const double v) {
        if (force)
          control.target_force = v;
        else
          state.set_approach(v);
      },
      on_converged);
  }


  template <int dim>
  void
  BoundaryElementSolver<dim>::move_indenter(const double                 to,
                                            const std::string           &phase,
                                            const std::function<void()> &report,
                                            const std::function<bool()> &done)
  {
    step_before = {};
    coarse_step = {};
    if (!follow(
          state.delta,
          to * scales.eps,
          prm.loading.increment * scales.eps,
          prm.loading.minimum_increment * scales.eps,
          [this](const double d) { state.set_approach(d); },
          report,
          done))
      throw std::runtime_error(
        "the boundary-element solver failed in the " + phase +
        " at delta_hat = " + CsvTable::format(approach() / scales.eps) +
        " (Newton's method and the relaxation did not converge with "
        "the Minimum approach increment)");
  }


  // The class is instantiated in solver.cc; here the members this file
  // defines.
#define VISCOSLIDE_INSTANTIATE(dim)                                       \
  template void BoundaryElementSolver<dim>::predict(const SurfaceState &, \
                                                    unsigned int,         \
                                                    const SurfaceState &, \
                                                    double);              \
  template bool BoundaryElementSolver<dim>::follow(                       \
    double,                                                               \
    double,                                                               \
    double,                                                               \
    double,                                                               \
    const std::function<void(double)> &,                                  \
    const std::function<void()> &,                                        \
    const std::function<bool()> &);                                       \
  template bool BoundaryElementSolver<dim>::predict_on_coarse(            \
    double,                                                               \
    double,                                                               \
    const SurfaceState &,                                                 \
    const std::function<void(double)> &,                                  \
    bool);                                                                \
  template void BoundaryElementSolver<dim>::set_speed(double);            \
  template bool BoundaryElementSolver<dim>::from_both_ends() const;       \
  template bool BoundaryElementSolver<dim>::start_sliding(double);        \
  template bool BoundaryElementSolver<dim>::continue_to(                  \
    double, const std::function<void()> &);                               \
  template bool BoundaryElementSolver<dim>::continue_to_load(             \
    double, const std::function<void()> &);                               \
  template void BoundaryElementSolver<dim>::move_indenter(                \
    double,                                                               \
    const std::string &,                                                  \
    const std::function<void()> &,                                        \
    const std::function<bool()> &);
  VISCOSLIDE_INSTANTIATE(2)
  VISCOSLIDE_INSTANTIATE(3)
#undef VISCOSLIDE_INSTANTIATE
} // namespace viscoslide

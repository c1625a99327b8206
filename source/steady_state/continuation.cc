// SPDX-License-Identifier: LGPL-2.1-or-later
// SteadyStateSolver: one step of speed or load, and the continuation in
// speed, in load and through the attraction before contact.
#include <viscoslide/numerics/newton.h>
#include <viscoslide/steady_state/solver.h>

#include <cmath>
#include <sstream>

namespace viscoslide
{
  namespace
  {
    std::string
    label(const std::string &name, const double value)
    {
      std::ostringstream os;
      os << name << " = " << value;
      return os.str();
    }
  } // namespace


  // Solves the steady state after the speed or the load moved, from the
  // last converged state: Newton, else pseudo-transient relaxation (a
  // contact edge may have to jump: always at the first speed, where the
  // trailing edge leaves the approach branch), then the mesh adaptation
  // cycles. Returns the Newton iterations; -1 if the step failed (the
  // caller restores the state it started from and shortens the step); -2
  // if it failed on an adapted mesh, where that state no longer fits.
  template <int dim>
  int
  SteadyStateSolver<dim>::solve_step(const std::string                   &what,
                                     const TrilinosWrappers::MPI::Vector &last,
                                     const double last_delta,
                                     const bool   relax)
  {
    int its = coupling.newton(newton_system(), pcout);
    if (its < 0 && !relax)
      return -1;
    if (its < 0)
      {
        solution = last;
        delta    = last_delta;
        {
          TimerOutput::Scope t(timer, "steady: relaxation");
          its = coupling.relax(newton_system(), pcout);
        }
        if (its < 0)
          return -1;
        pcout << "  steady " << what << ": reached by relaxation" << std::endl;
      }
    {
      TrilinosWrappers::MPI::Vector increment(locally_owned_dofs,
                                              mpi_communicator),
        start(locally_owned_dofs, mpi_communicator);
      increment = solution;
      start     = last;
      increment.add(-1., start);
      last_increment.reinit(solution);
      last_increment = increment;
    }
    const int more = resolve_on_adapted_meshes(
      prm.mesh.max_adaptation_cycles,
      [this] { return adapt_mesh(); },
      [this] { return solve_newton_or_relax(); });
    if (more < 0)
      {
        pcout << "Steady state: Newton failed at " << what
              << " after adapting the mesh" << std::endl;
        return -2;
      }
    its += more;
    last_newton_iterations = its;
    update_quantities();
    pcout << "  steady V_hat " << std::setw(11) << V_hat << "  delta_hat "
          << std::setw(10) << delta / scales.eps << "  F_hat " << std::setw(11)
          << last_quantities.normal_force / scales.force << "  mu "
          << std::setw(11)
          << std::abs(last_quantities.tangential_force /
                      last_quantities.normal_force)
          << "  " << contact_column(dim) << " " << std::setw(11)
          << last_quantities.contact_length / scales.contact << "  Newton "
          << its << "  dofs " << dof_handler.n_dofs();
    if (use_direct_solver())
      pcout << "  factorizations " << linear_solver.factorizations
            << "  surface solves " << linear_solver.surface_solves << std::endl;
    else
      pcout << "  GMRES solves " << iterative_solver.solves << "  iterations "
            << iterative_solver.iterations << "  preconditioners "
            << iterative_solver.setups << std::endl;
    return its;
  }


  template <int dim>
  bool
  SteadyStateSolver<dim>::continue_to(const double                 target,
                                      const std::function<void()> &on_converged)
  {
    // The first speed: relaxation length V tau a tenth of the finest cell,
    // so that the relaxed start is close to its solution.
    double first =
      0.1 * prm.mesh.finest_cell / material.longest_relaxation_time();
    const double largest_step = std::log(prm.sliding.continuation_factor);
    double       step         = largest_step;
    while (V_hat != target)
      {
        double next;
        if (V_hat == 0.)
          next = std::min(target, first);
        else if (target > V_hat)
          next = std::min(target, V_hat * std::exp(step));
        else
          next = std::max(target, V_hat * std::exp(-step));

        adapt_mesh(expected_edges(next));
        const TrilinosWrappers::MPI::Vector backup(solution);
        const double                        delta0 = delta, V0 = V_hat;
        V_hat         = next;
        const int its = solve_step(label("V_hat", next), backup, delta0);
        if (its == -2)
          return false;
        if (its < 0)
          {
            solution = backup;
            delta    = delta0;
            V_hat    = V0;
            step *= 0.5;
            if (V0 == 0.)
              first *= std::exp(-step); // the first speed has no ratio
            if (step < std::log(1.01))
              {
                pcout << "Steady state: Newton failed at V_hat = " << next
                      << " even in steps of 1 %; last converged V_hat = " << V0
                      << std::endl;
                return false;
              }
            continue;
          }
        record_edges();
        last_load_step = {};
        on_converged();
        step = std::min(largest_step, 2. * step);
      }
    return true;
  }


  template <int dim>
  bool
  SteadyStateSolver<dim>::continue_in(const double         from,
                                      const double         to,
                                      double               step,
                                      double               last_step,
                                      const StepAttempt   &attempt,
                                      const ValueCallback &undo,
                                      const ValueCallback &accepted,
                                      const ValueCallback &failed)
  {
    const double whole = std::abs(to - from);
    for (double value = from; value != to;)
      {
        const double next =
          to > value ? std::min(to, value + step) : std::max(to, value - step);
        const TrilinosWrappers::MPI::Vector backup(solution);
        const double                        this_step = next - value;
        // In 3D a relaxation costs several Newton solves per pseudo-step:
        // shorter steps first.
        const int its = attempt(next,
                                last_step != 0. ? this_step / last_step : 0.,
                                backup,
                                dim == 2 || step < 0.1 * whole);
        if (its == -2)
          return false;
        if (its < 0)
          {
            solution = backup;
            undo(value);
            step *= 0.5;
            if (step < 1e-3 * whole)
              {
                failed(next);
                return false;
              }
            continue;
          }
        accepted(next);
        last_step = this_step;
        value     = next;
        step      = std::min(whole, 2. * step);
      }
    return true;
  }


  // Continuation in the controlled quantity at the current speed: F_n under
  // force control, delta under displacement control. Steps are linear (the
  // load may change sign): the whole way first, or four times the last
  // load step's change of the controlled quantity (the approach's, when
  // force control takes over from it) where the predictor extrapolates
  // that step; halved on failure down to a thousandth of the way, doubled
  // again after each success.
  template <int dim>
  bool
  SteadyStateSolver<dim>::continue_to_load(
    const double                 target,
    const std::function<void()> &on_converged)
  {
    edge_spans.clear(); // they follow the speed
    const bool   force      = coupling.force_control();
    double      &controlled = force ? coupling.held_force() : delta;
    const double unit       = force ? scales.force : scales.eps;
    const double start = controlled, whole = std::abs(target - start);
    // of the controlled quantity over the last converged load step
    const double last_step =
      force ? last_load_step.force : last_load_step.delta;
    double     delta0 = delta, force0 = coupling.held_force(), load0 = 0.;
    const auto what = [&](const double value) {
      return label(force ? "F_hat" : "delta_hat", value / unit);
    };
    return continue_in(
      start,
      target,
      last_step != 0. ? std::min(whole, 4. * std::abs(last_step)) : whole,
      last_step,
      [&](const double                         next,
          const double                         ratio,
          const TrilinosWrappers::MPI::Vector &backup,
          const bool                           relax) {
        delta0     = delta;
        force0     = coupling.held_force();
        load0      = last_quantities.normal_force;
        controlled = next;
        predict_load_step(ratio, backup, delta0);
        return solve_step(what(next), backup, force ? delta0 : next, relax);
      },
      [&](double) {
        delta                 = delta0;
        coupling.held_force() = force0;
      },
      [&](double) {
        on_converged();
        last_load_step = {delta - delta0, last_quantities.normal_force - load0};
      },
      [&](const double next) {
        pcout << "Steady state: Newton failed at " << what(next)
              << " even in steps of a thousandth of the way from "
              << start / unit << std::endl;
      });
  }


  // Steps in the attraction s: a quarter of the way first (the contact
  // widens severalfold), halved on failure (the relaxation only once they
  // are short) down to a thousandth, doubled again after each success;
  // each from the secant of the last.
  template <int dim>
  bool
  SteadyStateSolver<dim>::continue_in_attraction(
    const std::function<void(double)> &set_attraction)
  {
    // The load step's size carries over to the load continuation after
    // this one, its increment does not.
    const auto load_step = last_load_step;
    pcout << "Switching the law's attraction on at delta_hat = "
          << delta / scales.eps << " (the approach came in on its wall)"
          << std::endl;
    double     attraction = 0.;
    const bool done       = continue_in(
      0.,
      1.,
      0.25,
      0.,
      [&](const double                         next,
          const double                         ratio,
          const TrilinosWrappers::MPI::Vector &backup,
          const bool                           relax) {
        set_attraction(next);
        predict_load_step(ratio, backup, delta);
        return solve_step(label("attraction", next), backup, delta, relax);
      },
      set_attraction,
      [&](const double next) {
        pcout << "  the line above: attraction " << next << std::endl;
        attraction = next;
      },
      [&](const double next) {
        pcout << "Steady state: Newton failed at attraction " << next
              << " even in steps of a thousandth; last converged " << attraction
              << std::endl;
      });
    if (!done)
      return false;
    last_load_step = load_step;
    last_increment.clear();
    return true;
  }


  // The secant through the last converged step, scaled by `ratio` (none if
  // 0), with the surface held out of the indenter's repulsive wall: a step
  // that starts inside the wall costs Newton one iteration per factor of
  // about 2.6 in the residual (measured on the 3D approach), as Newton on
  // a power law of the gap does.
  template <int dim>
  void
  SteadyStateSolver<dim>::predict_load_step(
    const double                         ratio,
    const TrilinosWrappers::MPI::Vector &last,
    const double                         last_delta)
  {
    TrilinosWrappers::MPI::Vector predicted(locally_owned_dofs,
                                            mpi_communicator);
    predicted = solution;
    if (ratio != 0. && std::abs(ratio) <= 4. &&
        last_increment.size() == solution.size())
      {
        TrilinosWrappers::MPI::Vector increment(locally_owned_dofs,
                                                mpi_communicator);
        increment = last_increment;
        predicted.add(ratio, increment);
        if (coupling.force_control())
          delta += ratio * last_load_step.delta;
      }
    coupling.limit_predicted_closing(
      dof_handler, constraints, last, last_delta, s, predicted, delta, s);
    solution = predicted;
  }



  template class SteadyStateSolver<2>;
  template class SteadyStateSolver<3>;
} // namespace viscoslide

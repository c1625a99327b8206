// SPDX-License-Identifier: LGPL-2.1-or-later
// BoundaryElementSolver: the start of a case. The approach, a sequence of
// relaxed (V = 0) states in delta to the Target load or the Final
// approach; or, on a grid that follows the contact, the JKR contact of the
// relaxed solid at the Target load (doc/boundary_element.md, Approach,
// controls and references; Graded grid, Start).
#include <deal.II/lac/lapack_full_matrix.h>

#include <viscoslide/boundary_element/grid.h>
#include <viscoslide/boundary_element/solver.h>
#include <viscoslide/case_setup/common.h>

#include <algorithm>
#include <cmath>

namespace viscoslide
{
  template <int dim>
  void
  BoundaryElementSolver<dim>::start()
  {
    TimerOutput::Scope t(timer, "boundary element: approach");
    CsvTable           table(writer.path("approach.csv"),
                   {"step",
                              "phase",
                              "delta_hat",
                              "F_n_hat",
                              contact_column(dim),
                              "min_gap_over_eps",
                              "newton_iterations",
                              "n_dofs"},
                   version_string() +
                     "; forces per unit length in (pi dgamma^2 E0* R)^(1/3)",
                   comm,
                   scales.si_columns);
    unsigned int       step    = 0;
    const AddRow       add_row = [&](const std::string &phase) {
      const auto &q = last_quantities;
      table.add_row(
        {{"step", std::to_string(step++)},
         {"phase", phase},
         {"delta_hat", CsvTable::format(approach() / scales.eps)},
         {"F_n_hat", CsvTable::format(q.normal_force / scales.force)},
         {contact_column(dim),
          CsvTable::format(q.contact_length / scales.contact)},
         {"min_gap_over_eps", CsvTable::format(q.minimum_gap / scales.eps)},
         {"newton_iterations", std::to_string(last_newton_iterations)},
         {"n_dofs", std::to_string(n_unknowns())}});
    };
    // A grid that follows the contact has no contact to follow before
    // there is one: it starts from the JKR contact. So does the sphere on
    // a grid that refines about the contact where the load is all the case
    // asks of the approach: on its coarse cells the jump into a contact
    // hundreds of cells wide relaxes slowly, and not at all where the
    // adhesive zone is a fraction of a cell.
    if (grid->follows_contact() || starts_from_jkr_sphere())
      {
        start_from_jkr_contact();
        add_row("load");
        return;
      }
    approach_phase(add_row);
  }


  template <int dim>
  void
  BoundaryElementSolver<dim>::approach_phase(const AddRow &add_row)
  {
    const double F    = prm.loading.target_load * scales.force;
    bool         done = false;
    grid->fit_to_speed(0., state);
    set_law_range(approach_law_range());
    if (law_range > scales.eps)
      pcout << "Approach with the law's range " << law_range / scales.eps
            << " eps (the same work of adhesion): the grid's cells are too "
               "coarse for the jump into contact with the adhesive zone at "
               "eps"
            << std::endl;
    control.hold_approach();
    state.set_approach(prm.loading.initial_approach * scales.eps);
    if (solve() < 0)
      throw std::runtime_error(
        "the boundary-element solver found no equilibrium at the initial "
        "approach delta_hat = " +
        CsvTable::format(prm.loading.initial_approach));
    add_row("start");
    ApproachProgress progress(prm.loading.final_approach,
                              prm.loading.increment,
                              prm.loading.target_load);
    auto             report = [&] {
      add_row("approach");
      pcout << "Approach delta_hat = " << approach() / scales.eps
            << ": F_n_hat = " << last_quantities.normal_force / scales.force
            << ", " << contact_column(dim) << " = "
            << last_quantities.contact_length / scales.contact << " ("
            << last_newton_iterations << " Newton iterations)  ["
            << progress.report(approach() / scales.eps,
                               last_quantities.normal_force / scales.force)
            << "]" << std::endl;
      done =
        prm.loading.has_target_load() &&
        last_quantities.minimum_gap < prm.adhesion.contact_gap * law_range &&
        last_quantities.normal_force >= F;
    };
    move_indenter(prm.loading.final_approach, "approach", report, [&done] {
      return done;
    });
    if (prm.loading.has_target_load())
      hold_target_load(done, add_row);
    if (law_range > scales.eps)
      settle_law_range(add_row);
    if (prm.loading.retract)
      {
        control.hold_approach();
        retract(add_row);
      }
  }


  // Under force control, the approach step that passed the Target load
  // (`reached`) solved again with F_n held at exactly that load.
  template <int dim>
  void
  BoundaryElementSolver<dim>::hold_target_load(const bool    reached,
                                               const AddRow &add_row)
  {
    const double F = prm.loading.target_load * scales.force;
    if (!reached)
      throw Parameters::ExcInvalidInput(
        "'Loading/Target load' = " + CsvTable::format(prm.loading.target_load) +
        " was not reached by 'Loading/Final approach' = " +
        CsvTable::format(prm.loading.final_approach) + " (F_n_hat there: " +
        CsvTable::format(last_quantities.normal_force / scales.force) +
        "); raise the Final approach");
    control.hold_force(F);
    grid->preconditioner().reset();
    if (solve() < 0)
      throw std::runtime_error("the boundary-element solver could not "
                               "hold the Target load after the approach");
    add_row("load");
    pcout << "Load F_hat = " << prm.loading.target_load
          << " reached at delta_hat = " << approach() / scales.eps << std::endl;
  }


  // The zone's width grows as the law's range squared at the same dgamma
  // (adhesive_zone, case_setup/common.h), the contact hardly (JKR's
  // depends on dgamma alone): a range that puts min_approach_cells across
  // the zone lets the jump into contact converge on coarse cells.
  template <int dim>
  double
  BoundaryElementSolver<dim>::approach_law_range() const
  {
    const double zone = CaseSetup::internal::adhesive_zone(prm) * scales.eps;
    return scales.eps *
           std::max(1., std::sqrt(min_approach_cells * grid->spacing() / zone));
  }


  // At the load reached (the Target load, or under displacement control the
  // force at the Final approach, held while the range shrinks and then the
  // Final approach taken again), on the grid refined about the contact.
  template <int dim>
  void
  BoundaryElementSolver<dim>::settle_law_range(const AddRow &add_row)
  {
    const bool held = control.force_controlled;
    if (!held)
      control.hold_force(last_quantities.normal_force);
    grid->refine_at_rest();
    shrink_law_range(law_range, "after the approach");
    if (!held)
      {
        control.hold_approach();
        move_indenter(prm.loading.final_approach, "approach", [] {});
      }
    add_row("load");
  }


  // Unloading in steps of the Approach increment down to Retract to; the
  // minimum force on the way is the pull-off force under displacement
  // control. The jump out of contact is relaxed as the jump in is.
  template <int dim>
  void
  BoundaryElementSolver<dim>::retract(const AddRow &add_row)
  {
    const auto report = [&] {
      add_row("retract");
      pcout << "Retract delta_hat = " << approach() / scales.eps
            << ": F_n_hat = " << last_quantities.normal_force / scales.force
            << ", " << contact_column(dim) << " = "
            << last_quantities.contact_length / scales.contact << std::endl;
    };
    move_indenter(prm.loading.retract_to, "retraction", report);
  }


  template <int dim>
  bool
  BoundaryElementSolver<dim>::starts_from_jkr_sphere() const
  {
    return dim == 3 && grid->refines_about_contact() &&
           prm.loading.has_target_load() && !prm.loading.retract &&
           prm.indenter.shape == "parabola" && prm.geometry.elongation == 1.;
  }


  template <int dim>
  void
  BoundaryElementSolver<dim>::start_from_jkr_contact()
  {
    // The JKR contact of the relaxed solid (E0* = 1): its width 2a in
    // plane strain (cylinder_jkr_half_width, grid.h), its radius on the
    // sphere.
    const double P = prm.loading.target_load * scales.force;
    const double a = dim == 2
                       ? cylinder_jkr_half_width(P, scales.dgamma, scales.R)
                       : sphere_jkr_radius(P, scales.dgamma, scales.R);
    if (!std::isfinite(a))
      throw Parameters::ExcInvalidInput(
        "'Loading/Target load' = " + CsvTable::format(prm.loading.target_load) +
        " is below the JKR pull-off force of the relaxed contact, from which "
        "the start on this grid is made");
    Vector<double> q, u;
    const double   delta =
      dim == 2 ? discrete_jkr_contact(a, P, q, u) : jkr_sphere(a, q, u);
    // Newton's method from this contact converges for Tabor parameters up
    // to about 10, and crawls beyond (the adhesive zone must form at each
    // edge, a short-range jump); on a grid whose cells are coarse for the
    // zone it does not converge at all (approach_law_range). A larger one
    // is reached by continuation in the law's range: the same law with
    // range l > eps and the same dgamma, so that the contact is nearly the
    // same (JKR's depends on dgamma alone) while the zone is l^2 times
    // wider; l then shrinks to eps in steps of 0.7, each equilibrium the
    // start of the next.
    const double range = std::max(approach_law_range(),
                                  scales.eps * prm.adhesion.tabor_parameter /
                                    start_tabor_parameter);
    set_law_range(range);
    // The contact at the law's equilibrium gap, the range.
    state.delta = delta - (range - scales.eps);
    state.set_displacement(u, grid->at().h, scales.eps);
    // Inside, the gap at which the law gives that traction (at most its
    // peak), so that the residual u - C q(g) starts small.
    const auto start_gap = gap_for_traction(traction_law(), range);
    for (unsigned int j = 0; j < q.size(); ++j)
      if (q[j] != 0.)
        state.gap[j] = start_gap(q[j]);
    control.hold_force(P);
    pcout << "Start: the JKR contact of the relaxed solid at F_hat = "
          << prm.loading.target_load << ", " << contact_column(dim) << " = "
          << (dim == 2 ? 2 * a / scales.R : M_PI * a * a / scales.contact);
    if (range > scales.eps)
      pcout << ", the law's range from " << range / scales.eps << " eps";
    pcout << std::endl;
    // A law wider than the case's is shrunk where its zone is resolved: on
    // a grid that refines about the contact, that refined at rest. With
    // the case's own law the rest state stays on the coarse cells, and the
    // band is made about the first speed's contact (a band about the rest
    // contact is a cell off the trailing edge's zone at V_hat 0.01, which
    // puts mu 1 % lower on 0.5-eps cells divided 5 x 5).
    if (range > scales.eps)
      grid->refine_at_rest();
    shrink_law_range(range, "from the JKR contact at the Target load");
  }


  // On the grid about the contact, the traction of the points |x_j| < a
  // that holds their gap at eps (u_j = h_j - delta) under the load P, delta
  // unknown: the discrete JKR contact, its adhesive edges from the width
  // alone. The displacements are thousands of eps at R_hat 1e6, so that
  // the state must come from the grid's own compliance to be within a
  // fraction of eps of an equilibrium. Those points are the contiguous
  // [first, first + m) of the sorted x. Returns delta.
  template <int dim>
  double
  BoundaryElementSolver<dim>::discrete_jkr_contact(const double    a,
                                                   const double    P,
                                                   Vector<double> &q,
                                                   Vector<double> &u)
  {
    grid->place_about(-a, a, state);
    const auto        &p = grid->at();
    const unsigned int first =
      std::lower_bound(p.x.begin(), p.x.end(), -a) - p.x.begin();
    const unsigned int m =
      std::lower_bound(p.x.begin(), p.x.end(), a) - p.x.begin() - first;
    const FullMatrix<double> c = grid->block(first, m);
    LAPACKFullMatrix<double> system(m + 1, m + 1);
    Vector<double>           rhs(m + 1);
    for (unsigned int i = 0; i < m; ++i)
      {
        for (unsigned int j = 0; j < m; ++j)
          system(i, j) = c(i, j);
        system(i, m) = 1.;
        system(m, i) = -p.area[first + i] / scales.sigma_max;
        rhs[i]       = p.h[first + i];
      }
    rhs[m] = P / scales.sigma_max;
    system.compute_lu_factorization();
    system.solve(rhs);
    q.reinit(grid->size());
    for (unsigned int i = 0; i < m; ++i)
      q[first + i] = rhs[i];
    grid->apply(q, u);
    return rhs[m];
  }


  // Johnson, Kendall and Roberts' pressure on the paraboloid's contact of
  // radius a (Johnson, Contact Mechanics, 5.4), the Hertz part and the
  // flat punch's adhesive one,
  //     p(r) = (2a/(pi R)) s - sqrt(2 dgamma/(pi a)) / s,
  // s = sqrt(1 - r^2/a^2),
  // at the points (the adhesive part's edge singularity cut at half a cell
  // from the edge). Returns delta, the mean of h - u over the contact,
  // whose points the traction holds near the surface.
  template <int dim>
  double
  BoundaryElementSolver<dim>::jkr_sphere(const double    a,
                                         Vector<double> &q,
                                         Vector<double> &u)
  {
    grid->fit_to_speed(0., state);
    const auto  &p   = grid->at();
    const double cut = std::min(1., grid->spacing() / a);
    q.reinit(grid->size());
    for (unsigned int j = 0; j < q.size(); ++j)
      {
        const double rho2 = (p.x[j] * p.x[j] + p.y[j] * p.y[j]) / (a * a);
        if (rho2 >= 1)
          continue;
        const double s = std::sqrt(std::max(1 - rho2, cut));
        q[j]           = -(2 * a / (M_PI * scales.R) * s -
                 std::sqrt(2 * scales.dgamma / (M_PI * a)) / s);
      }
    grid->apply(q, u);
    double sum = 0, n = 0;
    for (unsigned int j = 0; j < q.size(); ++j)
      if (q[j] != 0.)
        {
          sum += p.h[j] - u[j];
          n += 1;
        }
    return sum / n;
  }


  template <int dim>
  void
  BoundaryElementSolver<dim>::shrink_law_range(double             range,
                                               const std::string &from)
  {
    const auto fail = [this, &from](const double at) {
      return std::runtime_error(
        "the boundary-element solver found no equilibrium " + from +
        " (Newton's method and the relaxation did not converge at the "
        "law's range " +
        CsvTable::format(at / scales.eps) + " eps)");
    };
    if (solve() < 0)
      throw fail(range);
    // Each step shrinks the range by `factor`; a step that fails is taken
    // again shorter, and only a step of a few percent is given the
    // relaxation, which crawls.
    double factor = 0.7;
    while (range > scales.eps)
      {
        const SurfaceState   at_state = state;
        const Vector<double> gaps_at = gaps, traction_at = traction;
        const auto           placement_at = grid->placement();
        const double         next = std::max(scales.eps, factor * range);
        // The contact's gap shrinks with the range: delta follows, so that
        // the next law finds the contact at its own equilibrium gap; where
        // the surfaces are nearer than the old law's peak, the gap is where
        // the new law gives the old traction (the wall's stiffness grows as
        // 1/range^2: at the old gaps the pressure under the contact would
        // jump).
        const double peak = gap_for_traction(traction_law(), range)(1e300);
        set_law_range(next);
        const auto next_gap = gap_for_traction(traction_law(), next);
        state.set_approach(state.delta + range - next);
        for (unsigned int j = 0; j < state.gap.size(); ++j)
          if (gaps_at[j] < peak)
            state.gap[j] = next_gap(traction_at[j]);
        const bool last_resort = factor > 0.95;
        if (solve(last_resort) >= 0)
          {
            range  = next;
            factor = std::max(0.7, factor * factor);
            pcout << "  the law's range " << range / scales.eps << " eps, "
                  << state.gap.size() << " points, " << contact_column(dim)
                  << " = " << last_quantities.contact_length / scales.contact
                  << std::endl;
            continue;
          }
        if (last_resort)
          throw fail(next);
        set_law_range(range);
        if (placement_at)
          grid->regrid(*placement_at, state);
        state = at_state;
        assemble(false); // the gaps and tractions the next step starts from
        factor = std::sqrt(factor);
      }
  }


  template <int dim>
  std::function<double(double)>
  BoundaryElementSolver<dim>::gap_for_traction(const InteractionLaw &law,
                                               const double range) const
  {
    // The law rises from its repulsive wall through 0 at the range to its
    // peak: found once, then each traction's gap by bisection below it.
    double peak = range;
    for (double g = range; g < 3 * range; g += 1e-3 * range)
      if (law.traction(g) > law.traction(peak))
        peak = g;
    return [&law, range, peak](const double q) {
      double lo = 0.2 * range, hi = peak;
      for (unsigned int k = 0; k < 100; ++k)
        {
          const double mid                  = 0.5 * (lo + hi);
          (law.traction(mid) < q ? lo : hi) = mid;
        }
      return 0.5 * (lo + hi);
    };
  }


  template <int dim>
  void
  BoundaryElementSolver<dim>::set_law_range(const double range)
  {
    law_range = range;
    ranged_law.reset();
    if (range != scales.eps)
      ranged_law =
        create_interaction_law(prm.adhesion.law, scales.dgamma, range);
    grid->preconditioner().reset();
  }


  // The class is instantiated in solver.cc; here the members this file
  // defines.
#define VISCOSLIDE_INSTANTIATE(dim)                                             \
  template void   BoundaryElementSolver<dim>::start();                          \
  template void   BoundaryElementSolver<dim>::approach_phase(const AddRow &);   \
  template void   BoundaryElementSolver<dim>::hold_target_load(bool,            \
                                                             const AddRow &); \
  template void   BoundaryElementSolver<dim>::retract(const AddRow &);          \
  template void   BoundaryElementSolver<dim>::start_from_jkr_contact();         \
  template bool   BoundaryElementSolver<dim>::starts_from_jkr_sphere() const;   \
  template double BoundaryElementSolver<dim>::discrete_jkr_contact(             \
    double, double, Vector<double> &, Vector<double> &);                        \
  template double BoundaryElementSolver<dim>::jkr_sphere(double,                \
                                                         Vector<double> &,      \
                                                         Vector<double> &);     \
  template double BoundaryElementSolver<dim>::approach_law_range() const;       \
  template void   BoundaryElementSolver<dim>::settle_law_range(const AddRow &); \
  template void   BoundaryElementSolver<dim>::shrink_law_range(                 \
    double, const std::string &);                                             \
  template std::function<double(double)>                                        \
  BoundaryElementSolver<dim>::gap_for_traction(const InteractionLaw &, double)  \
    const;                                                                      \
  template void BoundaryElementSolver<dim>::set_law_range(double);
  VISCOSLIDE_INSTANTIATE(2)
  VISCOSLIDE_INSTANTIATE(3)
#undef VISCOSLIDE_INSTANTIATE
} // namespace viscoslide

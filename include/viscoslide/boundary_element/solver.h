// SPDX-License-Identifier: LGPL-2.1-or-later
// The boundary-element solver of the steady sliding state
// (Sliding/Solver = boundary-element; doc/boundary_element.md).
//
// Only the top surface is discretised, on a surface grid (surface_grid.h:
// periodic, isolated or graded), which owns everything that depends on
// where its points are. In the indenter's frame the steady state solves
//     u = C q(g),   g_j = eps + h(x_j) - delta - u_j,
// with C the grid's viscoelastic surface compliance at the sliding speed
// and q the traction law, plus, under force control, the load equation
// integral of -q = F_n with delta unknown. This class is the same for
// every grid: Newton's method (newton.h) with its linear systems by GMRES
// on the grid's preconditioner, where the grid has motions of its own
// (the graded grid's contact edges) with them among the unknowns; the
// start (the approach, a sequence of relaxed states, or the JKR contact
// where the grid follows the contact); the continuation in speed and load.
//
// The implementation: solver.cc (the run, the residual, GMRES, Newton),
// moving_grid.cc (Newton with the grid's motions), continuation.cc
// (steps in approach, speed and load), start.cc (the approach and the JKR
// start), output.cc (the profile).
#ifndef viscoslide_boundary_element_solver_h
#define viscoslide_boundary_element_solver_h

#include <deal.II/base/conditional_ostream.h>
#include <deal.II/base/timer.h>
#include <deal.II/lac/vector.h>

#include <viscoslide/boundary_element/surface_grid.h>
#include <viscoslide/driver/case.h>
#include <viscoslide/io/output.h>
#include <viscoslide/io/parameters.h>
#include <viscoslide/io/steady_state_table.h>
#include <viscoslide/numerics/newton.h>
#include <viscoslide/physics/indenter.h>
#include <viscoslide/physics/interaction_law.h>
#include <viscoslide/physics/load_control.h>
#include <viscoslide/physics/material.h>
#include <viscoslide/steady_sliding.h>

#include <functional>
#include <memory>
#include <vector>

namespace viscoslide
{
  using namespace dealii;

  // The grid a case asks for: graded (Boundary element/Grid), the
  // isolated window of the 3D half-space, else periodic. [solver.cc]
  template <int dim>
  std::unique_ptr<SurfaceGrid<dim>>
  make_surface_grid(const CaseParts &parts, ConditionalOStream &out);


  template <int dim>
  class BoundaryElementSolver : public SteadySliding
  {
  public:
    explicit BoundaryElementSolver(CaseParts &parts);
    ~BoundaryElementSolver();

    // The start (the approach to Loading/Target load or to the Final
    // approach, or the JKR contact), then the stations; writes
    // steady_state.csv, continuation.csv and the profiles. Throws
    // std::runtime_error if a station was missed. [solver.cc]
    void
    run();

    // SteadySliding [continuation.cc]
    bool
    continue_to(double                       V_hat,
                const std::function<void()> &on_converged) override;
    bool
    continue_to_load(double                       target,
                     const std::function<void()> &on_converged) override;
    double
    speed() const override
    {
      return V_hat;
    }
    double
    approach() const override
    {
      return state.delta;
    }
    const SurfaceQuantities &
    quantities() const override
    {
      return last_quantities;
    }
    double
    dissipation_rate() const override
    {
      return grid->dissipation_rate(traction);
    }
    unsigned int
    newton_iterations() const override
    {
      return last_newton_iterations;
    }
    unsigned long
    n_unknowns() const override
    {
      return state.gap.size() + (control.force_controlled ? 1 : 0);
    }
    bool
    force_control() const override
    {
      return control.force_controlled;
    }
    // Every process holds the whole problem, and a grid that does not
    // follow the contact jumps from rest to any speed (one that does
    // starts slow). [continuation.cc]
    bool
    from_both_ends() const override;
    // [output.cc]
    void
    write_profile(const std::string &path) const override;
    void
    write_fields(OutputWriter &, unsigned int) const override
    {
    }

  private:
    // --- Newton's method [solver.cc]

    // Newton's method (then, where the grid has motions, with them among
    // the unknowns), then, if `relax`, pseudo-transient relaxation, at the
    // present speed, control and delta or load; on failure the state is
    // restored. Returns the iterations or -1. A grid that follows the
    // contact is made anew about the edges found until they lie where it
    // is finest.
    int
    solve(bool relax = true);
    int
    solve_on_grid(bool relax);
    NewtonProblem
    newton_problem();
    // The state moved by alpha times Newton's update.
    void
    step_state(double alpha);
    // The gaps, tractions and their tangent, the residual u - C q with the
    // load equation last; with the matrix, assemble_matrix().
    void
    assemble(bool with_matrix);
    // At the state assemble() last saw: the residual's rounding error (once
    // per solve) and the preconditioner.
    void
    assemble_matrix();
    double
    residual_norm() const;
    void
    compute_update();
    // The Jacobian (and the load row) applied to `src`.
    void
    jacobian_vmult(Vector<double> &dst, const Vector<double> &src) const;
    // GMRES on the Jacobian (and the load row) for `rhs`.
    void
    solve_linearized(const Vector<double> &rhs, Vector<double> &solution);
    // GMRES on `op` with `preconditioner` for `rhs`, counted in the
    // statistics, the grid's preconditioner told how it went.
    using LinearMap =
      std::function<void(Vector<double> &, const Vector<double> &)>;
    void
    run_gmres(const LinearMap      &op,
              const LinearMap      &preconditioner,
              const Vector<double> &rhs,
              Vector<double>       &solution);
    // The measures of the present state.
    void
    update_quantities();

    // --- Newton's method with the grid's motions [moving_grid.cc]

    // The grid moves with its motions (the graded grid: each edge's cells
    // and gaps translated, the cells between stretched), and one equation
    // per motion (its pin) holds its edge where the grid is finest. An
    // edge's adhesive zone then moves as a whole, as one unknown, instead
    // of through the cells of a fixed grid, where its translation is nearly
    // singular (a neutral mode of a wide contact) and non-linear (the cells
    // grow away from the edge). Starts from a grid recentred on the state's
    // edges. Returns the iterations or -1, the state then restored.
    int
    solve_moving_grid();
    NewtonProblem
    moving_grid_problem();
    // The residual's derivatives along the motions (with the matrix) and
    // the pins' misfits.
    void
    assemble_moving_grid(bool with_matrix);
    void
    compute_moving_grid_update();
    // The largest update, in finest cells, that Newton's method takes as
    // round-off where no step reduces a residual at the round-off (on a
    // grid whose edges are unknowns, with the motions).
    static constexpr double negligible_update = 0.1;
    // The change of pin e's gap by an update v of the displacements and
    // delta (the gaps move with the grid).
    double
    pin_change(const Vector<double> &v, unsigned int e) const;

    // --- Continuation [continuation.cc]

    // The converged state a step before the present one, for the secant
    // predictor. It outlives a call of follow(): the speeds of a list are
    // one continuation, and the first step towards a station is predicted
    // as the others are (without it, on a grid whose edges are unknowns,
    // Newton's method must find the contact's whole translation, and at
    // Tabor parameters of 1000 it then takes steps of about 1 % in V).
    struct StepBefore
    {
      bool valid = false;
      // The state before is rest (V_hat = 0), from which the response is
      // linear in V: the step's ratio is then exp(next - at) - 1 (the
      // parameter is log V).
      bool                      from_rest = false;
      double                    at        = 0;
      SurfaceState              state;
      unsigned int              generation = 0;
      std::pair<double, double> edges;
    };
    StepBefore step_before;
    // On a grid that refines a coarse one: the coarse grid's equilibrium
    // at the step's start, kept from the step before.
    struct CoarseStep
    {
      bool         valid = false;
      double       at    = 0;
      SurfaceState state;
    };
    CoarseStep coarse_step;
    // The predictor of a step from `at` (state at_state) to `next` on such
    // a grid: the step taken on the coarse grid, whose change in the
    // displacements (smooth, where the gaps are not) is added to at_state
    // (nested iteration, as Brandt's full multigrid starts each level from
    // the coarser one); the band is then made about the predicted contact
    // where it has left the refined cells. False where the coarse grid
    // fails or there is none (the grid and state then as they were); the
    // coarse step relaxes where Newton's method fails if `relax`.
    bool
    predict_on_coarse(double                             at,
                      double                             next,
                      const SurfaceState                &at_state,
                      const std::function<void(double)> &set,
                      bool                               relax);
    // Steps the control parameter from its present value to `to` through
    // set(value), in steps no larger than `step` (halved where Newton
    // fails, down to `min_step`), calling on_converged after each and
    // stopping early once done() holds; from step_before where valid.
    bool
    follow(
      double                             from,
      double                             to,
      double                             step,
      double                             min_step,
      const std::function<void(double)> &set,
      const std::function<void()>       &on_converged,
      const std::function<bool()>       &done = [] { return false; });
    // The secant predictor of a step `ratio` times as long as the one
    // before, from the state at its start (on the grid of generation_at)
    // and the one before.
    void
    predict(const SurfaceState &at_state,
            unsigned int        generation_at,
            const SurfaceState &before,
            double              ratio);
    // delta to delta_hat = `to` in Approach increments, cut down to the
    // Minimum approach increment where a step fails.
    void
    move_indenter(
      double                       to,
      const std::string           &phase,
      const std::function<void()> &report,
      const std::function<bool()> &done = [] { return false; });
    void
    set_speed(double V_hat);
    // From rest to the first speed of the continuation towards `target`
    // (slower by decades where a step from rest fails).
    bool
    start_sliding(double target);

    // --- The start [start.cc]

    using AddRow = std::function<void(const std::string &)>;
    // The approach, or the JKR start where the grid follows the contact.
    void
    start();
    void
    approach_phase(const AddRow &add_row);
    void
    hold_target_load(bool reached, const AddRow &add_row);
    void
    retract(const AddRow &add_row);
    // Whether the case starts from the JKR contact of the sphere (start).
    bool
    starts_from_jkr_sphere() const;
    // The JKR contact of the relaxed solid at the Target load: on the 2D
    // grid about it the discrete JKR contact of the grid's compliance, on
    // the 3D grid Johnson's pressure; then the law's range shrunk to eps.
    void
    start_from_jkr_contact();
    // The tractions q of the two, their displacements u = C q, and delta
    // (returned).
    double
    discrete_jkr_contact(double          a,
                         double          P,
                         Vector<double> &q,
                         Vector<double> &u);
    double
    jkr_sphere(double a, Vector<double> &q, Vector<double> &u);
    // The law's range in the approach: eps, or wider where the grid's
    // cells would put fewer than min_approach_cells across the adhesive
    // zone (approach_phase).
    double
    approach_law_range() const;
    // After an approach with a wider law: the law's range shrunk to eps at
    // the load reached, on the grid refined about the contact.
    void
    settle_law_range(const AddRow &add_row);
    // The law's range shrunk from `range` to eps in steps, each
    // equilibrium the start of the next; `from` says from which state, for
    // the message of a failure.
    void
    shrink_law_range(double range, const std::string &from);
    // The start's continuation in the traction law's range: the law of
    // the case with range `range` and the same dgamma; the case's own at
    // eps.
    void
    set_law_range(double range);
    // The gap at which `law`, of range `range`, gives a traction q, on
    // its branch from the repulsive wall to its peak (the peak's gap for q
    // above the peak), as a function of q; `law` must outlive it.
    std::function<double(double)>
    gap_for_traction(const InteractionLaw &law, double range) const;
    const InteractionLaw &
    traction_law() const
    {
      return ranged_law ? *ranged_law : law;
    }
    // The Tabor parameter up to which Newton's method converges from the
    // discrete JKR contact.
    static constexpr double start_tabor_parameter = 8;
    // The fewest cells across the adhesive zone with which the jump into
    // contact converges: 1.43 did (Tabor parameter 3 on 0.5-eps cells),
    // 0.24 did not (10 on the same cells).
    static constexpr double min_approach_cells = 1.4;

    const Parameters::AllParameters &prm;
    MPI_Comm                         comm;
    ConditionalOStream               pcout;
    TimerOutput                      timer;
    const Scales                    &scales;
    const ViscoelasticSolid         &material;
    const InteractionLaw            &law;
    std::unique_ptr<InteractionLaw>  ranged_law;
    double                           law_range; // eps but in the start
    OutputWriter                    &writer;
    SteadyStateTable                &steady_state_table;
    Progress                        *progress;

    std::unique_ptr<SurfaceGrid<dim>> grid;
    SurfaceState                      state;
    double                            V_hat = 0;
    LoadControl                       control;

    // Newton's work: gaps, displacements u, tractions (q, attraction > 0),
    // their tangent, the residual u - C q with the load equation last, the
    // update (of u and delta), the
    // iterate a line search starts from, the surface dashpot of relax()
    // and its anchor; the rounding error of residual_norm() at the last
    // Jacobian, which Newton's method takes as its tolerance where it is
    // larger; the relative tolerance Newton's method asks of the next
    // linear solve (0: GMRES's own, 1e-8).
    Vector<double> gaps, displacement, traction, tangent, residual, update;
    SurfaceState   start_of_step;
    double         dashpot = 0, round_off = 0, forcing = 0;
    bool           round_off_due = true; // round_off made at a solve's start
    Vector<double> anchor;
    // solve_moving_grid(): the residual's derivative along each motion,
    // the pins' misfits, the motions' update, and the grid and gaps a line
    // search starts from.
    std::vector<Vector<double>> motion_columns;
    std::vector<double>         pin_misfit, motion_update;
    std::shared_ptr<const typename SurfaceGrid<dim>::Placement> placement0;
    Vector<double>                                              gaps0;

    // GMRES iterations and solves, for the statistics at the end.
    unsigned long gmres_iterations = 0, gmres_solves = 0;

    SurfaceQuantities last_quantities{};
    unsigned int      last_newton_iterations = 0;
  };
} // namespace viscoslide

#endif

// The boundary-element solver of the steady sliding state
// (Sliding/Solver = boundary-element; doc/boundary_element.md).
//
// Only the top surface is discretised: the vertical displacement u_j at
// the points x_j of a uniform periodic grid centred on the indenter's
// apex, a line of points in plane strain (dim = 2), a plane of them in 3D
// (the indenter then the body of revolution of its profile); or, in plane
// strain on the half-plane, at the centres of the cells of a grid graded
// about the contact edges (Boundary element/Grid = graded;
// graded_compliance.h), which follows the edges and starts from the JKR
// contact at the Target load. In the
// indenter's frame the steady state solves
//     u = C q(g),   g_j = eps + h(x_j) - delta - u_j,
// with C the viscoelastic surface compliance at the sliding speed
// (compliance.h) and q the traction law, plus, under force control, the
// load equation integral of -q = F_n with delta unknown. Newton's method
// (newton.h) solves it, its linear systems by GMRES, preconditioned in 2D
// by the dense Jacobian of the points near the contact
// (window_preconditioner.h), in 3D by multigrid on the surface grid
// (multigrid_preconditioner.h); the approach
// is a sequence of relaxed (V = 0) states, the speeds and loads follow by
// continuation, as in the finite-element steady-state solver.
//
// The implementation: solver.cc (grid, Newton, continuation, the run),
// output.cc (surface quantities and profiles).
#ifndef viscoslide_boundary_element_solver_h
#define viscoslide_boundary_element_solver_h

#include <deal.II/base/conditional_ostream.h>
#include <deal.II/base/timer.h>
#include <deal.II/lac/lapack_full_matrix.h>
#include <deal.II/lac/vector.h>

#include <viscoslide/boundary_element/compliance.h>
#include <viscoslide/boundary_element/graded_compliance.h>
#include <viscoslide/boundary_element/isolated_compliance.h>
#include <viscoslide/boundary_element/multigrid_preconditioner.h>
#include <viscoslide/case.h>
#include <viscoslide/indenter.h>
#include <viscoslide/interaction_law.h>
#include <viscoslide/load_control.h>
#include <viscoslide/material.h>
#include <viscoslide/newton.h>
#include <viscoslide/output.h>
#include <viscoslide/parameters.h>
#include <viscoslide/steady_sliding.h>
#include <viscoslide/steady_state_table.h>

#include <array>
#include <functional>
#include <memory>
#include <vector>

namespace viscoslide
{
  using namespace dealii;

  template <int dim>
  class BoundaryElementSolver : public SteadySliding
  {
  public:
    explicit BoundaryElementSolver(CaseParts &parts);
    ~BoundaryElementSolver();

    // The approach to Loading/Target load (or to the Final approach), then
    // the stations; writes steady_state.csv, continuation.csv and the
    // profiles. Throws std::runtime_error if a station was missed.
    // [solver.cc]
    void
    run();

    // SteadySliding [solver.cc]
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
      return delta;
    }
    const SurfaceQuantities &
    quantities() const override
    {
      return last_quantities;
    }
    double
    dissipation_rate() const override;
    unsigned int
    newton_iterations() const override
    {
      return last_newton_iterations;
    }
    unsigned long
    n_unknowns() const override
    {
      return u.size() + (control.force_controlled ? 1 : 0);
    }
    bool
    force_control() const override
    {
      return control.force_controlled;
    }
    // [output.cc]
    void
    write_profile(const std::string &path) const override;
    void
    write_fields(OutputWriter &, unsigned int) const override
    {
    }

  private:
    // The grid for the period this speed needs (Boundary element/Period):
    // rebuilt when it must grow or can shrink four-fold, the state carried
    // over at equal x. In 3D the period across the track is the Domain
    // width. [solver.cc]
    void
    fit_period(double V_hat);
    void
    make_grid(const std::array<unsigned int, dim - 1> &shape);
    // The graded grid of cells between `boundaries`, made for contact
    // edges at `edges`, the state's gaps interpolated onto it (from x -
    // shift(x) if given). [solver.cc]
    void
    make_graded_grid(const std::vector<double>           &new_boundaries,
                     const std::pair<double, double>     &edges,
                     const std::function<double(double)> &shift = {});
    // The graded grid's cells between `new_boundaries`, made for contact
    // edges at `edges`, with the gaps `gap` (delta kept): the compliance
    // `kept` if given (made for these boundaries), else a new one.
    // [solver.cc]
    void
    set_graded_cells(const std::vector<double>       &new_boundaries,
                     const std::pair<double, double> &edges,
                     const Vector<double>            &gap,
                     std::unique_ptr<Compliance>      kept = {});
    // make_graded_grid about contact edges at trail and lead, the grid
    // reaching margin_factor times the contact's width (at least 50 eps)
    // beyond each. [solver.cc]
    void
    make_graded_grid_about(double                               trail,
                           double                               lead,
                           const std::function<double(double)> &shift = {});
    // The predictor of a continuation step on the graded grid: the edges
    // extrapolated from the two steps before (`ratio` the step's length
    // over the last one's), a grid about them, and the state's gaps moved
    // with the edges, so that each edge's adhesive zone arrives whole
    // where it is predicted (the secant of u at fixed x would smear it).
    // [solver.cc]
    void
    predict_graded_grid(const std::pair<double, double> &edges,
                        const std::pair<double, double> &edges_before,
                        double                           ratio);
    // Whether the contact edges of the present state lie where the
    // graded grid's cells are finest (and no traction reaches its ends);
    // if not, or `always`, a new grid about them. Returns whether it made
    // one. [solver.cc]
    bool
    refit_graded_grid(bool always);
    // The graded grid's start: the JKR contact of the relaxed solid at the
    // Target load, solved with the traction law. [solver.cc]
    void
    start_from_jkr_contact();
    // The start's continuation in the traction law's range
    // (start_from_jkr_contact): the law of the case with range `range`
    // and the same dgamma; the case's own at eps. [solver.cc]
    void
    set_law_range(double range);
    // The gap at which `law`, of range `range`, gives a traction q, on
    // its branch from the repulsive wall to its peak (the peak's gap for q
    // above the peak), as a function of q; `law` must outlive it.
    // [solver.cc]
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
    // In 3D a half-space is the isolated contact's (isolated_compliance.h),
    // a layer periodic. [solver.cc]
    bool
    isolated_half_space() const;
    // The compliance (and the multigrid's) at sliding speed V. [solver.cc]
    void
    set_compliance_speed(double V);
    // The preconditioner for the present Jacobian. [solver.cc]
    void
    update_preconditioner();

    // Newton's method (on a graded grid, then with the edges among the
    // unknowns), then, if `relax`, pseudo-transient relaxation, at the
    // present speed, control and delta or load; on failure the state is
    // restored. Returns the iterations or -1. A graded grid is made anew
    // about the edges found until they lie where it is finest.
    // [solver.cc]
    int
    solve(bool relax = true);
    int
    solve_on_grid(bool relax);
    // Newton's method on the graded grid with the two contact edges among
    // the unknowns (edge_following.cc): the grid moves with them, each
    // edge's cells and gaps translated, the cells between stretched, and
    // one equation per edge holds the gap at the contact threshold where
    // the grid is finest. An edge's adhesive zone then moves as a whole,
    // as one unknown, instead of through the cells of a fixed grid, where
    // its translation is nearly singular (a neutral mode of a wide
    // contact) and non-linear (the cells grow away from the edge). Starts
    // from a grid recentred on the state's edges. Returns the iterations
    // or -1, the state then restored.
    int
    solve_following_edges();
    NewtonProblem
    edge_following_problem();
    void
    assemble_following_edges(bool with_matrix);
    void
    compute_edge_following_update();
    // The boundaries `from`, made for edges `from_edges`, moved with the
    // edges by d_trail and d_lead (edge_shift, grid.h).
    // [edge_following.cc]
    static std::vector<double>
    moved_boundaries(const std::vector<double>       &from,
                     const std::pair<double, double> &from_edges,
                     double                           d_trail,
                     double                           d_lead);
    NewtonProblem
    newton_problem();
    void
    assemble(bool with_matrix);
    double
    residual_norm() const;
    void
    compute_update();
    // GMRES on the Jacobian (and the load row) for `rhs`. [solver.cc]
    void
    solve_linearized(const Vector<double> &rhs, Vector<double> &solution);
    // Steps the control parameter from its present value to `to` through
    // set(value), in steps no larger than `step` (halved where Newton
    // fails, down to `min_step`), calling on_converged after each and
    // stopping early once done() holds.
    bool
    follow(
      double                             from,
      double                             to,
      double                             step,
      double                             min_step,
      const std::function<void(double)> &set,
      const std::function<void()>       &on_converged,
      const std::function<bool()>       &done = [] { return false; });
    void
    approach_phase();
    void
    hold_target_load(bool                                            reached,
                     const std::function<void(const std::string &)> &add_row);
    void
    retract(const std::function<void(const std::string &)> &add_row);
    void
    move_indenter(
      double                       to,
      const std::string           &phase,
      const std::function<void()> &report,
      const std::function<bool()> &done = [] { return false; });

    // The traction q_j, its tangent dq/dg and the gaps. [output.cc]
    void
    update_quantities();
    // In 3D: the area where the gap is below gc. [output.cc]
    double
    contact_area(double gc) const;
    // In 3D: the map of the surface about the contact as VTK image data.
    // [output.cc]
    void
    write_map(const std::string &path, const std::string &what) const;

    const Parameters::AllParameters &prm;
    MPI_Comm                         comm;
    ConditionalOStream               pcout;
    TimerOutput                      timer;
    const Scales                    &scales;
    const ViscoelasticSolid         &material;
    const InteractionLaw            &law;
    std::unique_ptr<InteractionLaw>  ranged_law;
    double                           law_range; // eps but in the start
    const Indenter                  &indenter;
    OutputWriter                    &writer;
    SteadyStateTable                &steady_state_table;
    Progress                        *progress;

    // The grid: shape = (n_x) or (n_y, n_x) points, x_j = (j mod n_x -
    // n_x/2) dx and in 3D y_j = (j div n_x - n_y/2) dx, each standing for
    // the area dA = dx^(dim-1); the indenter's h and dh/dx there; and the
    // solid its compliance describes: during the approach of a half-plane
    // the block of Domain height on a rigid base, as in the finite
    // elements (doc/boundary_element.md, Approach). The graded grid:
    // n_x cells between `boundaries`, x_j their centres, area_j their
    // widths, made for the edges at grid_edges; dx its finest cell.
    const double              dx, dA;
    const bool                graded;
    std::vector<double>       area, boundaries;
    std::pair<double, double> grid_edges{0., 0.};
    // The boundaries at grid_edges: the focus of each edge.
    std::array<unsigned int, 2> focus{};
    double                      margin_factor = 0.5;
    // Counts the grids made, so that a secant predictor spans one grid.
    unsigned int                      grid_generation = 0;
    std::array<unsigned int, dim - 1> shape{};
    Parameters::Substrate             substrate;
    double                            thickness;
    // periodic (SurfaceCompliance<dim>) or isolated (3D half-space)
    std::unique_ptr<Compliance> compliance;
    std::vector<double>         x, y, h, slope;

    // The state.
    Vector<double> u;
    double         delta = 0;
    double         V_hat = 0;
    LoadControl    control;

    // Newton's work: gaps, tractions (q, attraction > 0), their tangent,
    // the residual u - C q with the load equation last, the update, the
    // iterate a line search starts from, the surface dashpot of relax().
    Vector<double> gaps, traction, tangent, residual, update, u0;
    double         delta0 = 0, dashpot = 0;
    // The rounding error of residual_norm() at the last Jacobian (graded
    // grid): Newton's method takes it as its tolerance where it is larger.
    double         round_off = 0;
    Vector<double> anchor;
    // solve_following_edges(): the residual's derivative along each edge's
    // motion, the gap equations' misfits, the edges' update, and the grid
    // and gaps a line search starts from.
    std::array<Vector<double>, 2> edge_columns;
    std::array<double, 2>         pin_misfit{}, edge_update{};
    std::vector<double>           boundaries0;
    std::pair<double, double>     grid_edges0;
    Vector<double>                gaps0;

    // The preconditioner: the Jacobian of the window [first, first + m) of
    // points near the contact, factorized, with the load equation bordered.
    // GMRES on it gets slower as the iterate moves away from where it was
    // made; it is renewed once the last GMRES cost more than the average
    // per solve since it was made, factorization included (the renewal
    // that minimises that average), or did not converge. The costs are
    // counted work, not wall times [solver.cc].
    // In 3D the multigrid of the grid, updated at every Jacobian.
    class WindowPreconditioner;
    std::unique_ptr<WindowPreconditioner>  preconditioner;
    std::unique_ptr<SurfaceMultigrid<dim>> multigrid;
    unsigned int                           solves_since_factorization = 0;
    double work_since_factorization = 0., last_gmres_work = 0.;
    bool   last_gmres_converged = true;

    // GMRES iterations and solves, for the statistics at the end.
    unsigned long gmres_iterations = 0, gmres_solves = 0;

    SurfaceQuantities last_quantities{};
    unsigned int      last_newton_iterations = 0;
  };
} // namespace viscoslide

#endif

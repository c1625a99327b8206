// The finite element problem: a plane-strain standard-linear-solid block
// whose top surface interacts with a rigid indenter through a traction-gap
// law. Read it like step-18 and step-42: setup_system(), assemble(),
// solve_newton(), commit_history(), adapt_mesh() and output each live in one
// function of contact_problem.cc.
#ifndef viscoslide_contact_problem_h
#define viscoslide_contact_problem_h

#include <deal.II/base/conditional_ostream.h>
#include <deal.II/base/quadrature_lib.h>
#include <deal.II/base/timer.h>

#include <deal.II/distributed/tria.h>

#include <deal.II/dofs/dof_handler.h>

#include <deal.II/fe/fe_dgq.h>
#include <deal.II/fe/fe_system.h>

#include <deal.II/lac/affine_constraints.h>
#include <deal.II/lac/trilinos_precondition.h>
#include <deal.II/lac/trilinos_solver.h>
#include <deal.II/lac/trilinos_sparse_matrix.h>
#include <deal.II/lac/trilinos_vector.h>

#include <viscoslide/indenter.h>
#include <viscoslide/interaction_law.h>
#include <viscoslide/material.h>
#include <viscoslide/newton.h>
#include <viscoslide/output.h>
#include <viscoslide/parameters.h>
#include <viscoslide/postprocessing.h>

#include <array>
#include <memory>

namespace viscoslide
{
  using namespace dealii;

  // Where the loading program stands: approach delta, indenter position s,
  // time and the length of the step that led here (infinity: relaxed).
  struct LoadState
  {
    double delta = 0.;
    double s     = 0.;
    double time  = 0.;
    double dt    = std::numeric_limits<double>::infinity();
  };

  class ContactProblem
  {
  public:
    static constexpr unsigned int dim = 2;

    // `progress`, if given, is appended to the per-step report lines (the
    // sweep driver's case k of n and time estimate); a resumed run tells it
    // how much of the case its checkpoint holds.
    ContactProblem(const Parameters::AllParameters &parameters,
                   MPI_Comm                         mpi_communicator,
                   Progress                        *progress = nullptr);

    // Approach, optional hold, optional retraction; writes all outputs.
    // With `resume`, continues the transient sliding phase from the
    // checkpoint in the output directory instead (doc/restart.md).
    void
    run(bool resume = false);

    // Whether `directory` holds a complete checkpoint of a sliding run.
    static bool
    has_checkpoint(const std::string &directory);

    // The columns of steady_state.csv, so that the sweep driver can write
    // a row for a case that failed before writing its own.
    static std::vector<std::string>
    steady_state_columns();

  private:
    // Components of the quadrature-point history: the stress of each arm
    // (xx, yy, xy, zz of arm k at 4 k ... 4 k + 3), then the energy
    // dissipated so far per unit volume.
    enum ArmStressComponent
    {
      h_xx,
      h_yy,
      h_xy,
      h_zz,
      n_arm_stress_components
    };
    unsigned int
    dissipated_energy() const
    {
      return n_arm_stress_components * material.n_arms();
    }

    void
    setup_system();
    void
    assemble(bool with_matrix);
    // Factorizes (direct) or preconditions (iterative) system_matrix once;
    // solve() may then be called for several right-hand sides.
    void
    prepare_linear_solver();
    void
    solve(const TrilinosWrappers::MPI::Vector &rhs,
          TrilinosWrappers::MPI::Vector       &x);
    // The Newton update (newton_update, and delta_update under force
    // control) from the assembled system.
    void
    solve_newton_system();
    double
    residual_norm() const;

    // Newton's method for the state `target` from the current iterate.
    // Returns the iterations used, or -1 if it did not converge.
    int
    solve_newton(const LoadState &target);
    // The callbacks of newton() and relax() for this problem; u0 and
    // delta0 keep the iterate a line search starts from.
    NewtonProblem
    newton_problem(TrilinosWrappers::MPI::Vector &u0, double &delta0);
    // Lands on the new branch after a surface instability by damped
    // pseudo-time stepping. Returns the total Newton iterations or -1.
    int
    relax_to_equilibrium(const LoadState &target);
    // Solves one step of the loading program, cutting it when Newton fails,
    // and adapting the mesh to its solution. Returns false only if nothing
    // worked.
    bool
    advance_to(const LoadState &target, const std::string &phase);
    // Approach until F_n passes Loading/Target load, then hold exactly that
    // load for one force-controlled solve.
    void
    approach_to_load();

    void
    read_cell_history(const DoFHandler<dim>::active_cell_iterator &cell,
                      std::vector<double>                         &values,
                      std::vector<types::global_dof_index>        &dofs) const;
    // Arm stress of one arm at quadrature point q from the values of
    // read_cell_history().
    ArmStress
    arm_stress_at(const std::vector<double> &history_values,
                  unsigned int               arm,
                  unsigned int               q) const;
    void
    commit_history();
    bool
    adapt_mesh();
    void
    refine_initial_mesh();

    void
    record_step(const std::string &phase);
    void
    write_fields();
    void
    write_profile(const std::string &filename);

    const Parameters::AllParameters &prm;
    MPI_Comm                         mpi_communicator;
    ConditionalOStream               pcout;
    TimerOutput                      timer;

    const Scales                          scales;
    const ViscoelasticSolid               material;
    const std::unique_ptr<InteractionLaw> law;
    const std::unique_ptr<Indenter>       indenter;

    parallel::distributed::Triangulation<dim> triangulation;
    const FESystem<dim>                       fe;
    DoFHandler<dim>                           dof_handler;
    const QGauss<dim>                         quadrature;
    const QGauss<dim - 1>                     face_quadrature;

    // The history lives in a discontinuous field whose nodes are the Gauss
    // points of `quadrature`, so that SolutionTransfer carries it through
    // refinement and coarsening and the serializer can checkpoint it.
    const FE_DGQArbitraryNodes<dim> history_fe;
    DoFHandler<dim>                 history_dof_handler;
    std::vector<unsigned int>       quadrature_to_history_dof;

    IndexSet                  locally_owned_dofs, locally_relevant_dofs;
    AffineConstraints<double> constraints;

    TrilinosWrappers::SparseMatrix system_matrix;
    TrilinosWrappers::MPI::Vector  solution;     // ghosted, current iterate
    TrilinosWrappers::MPI::Vector  old_solution; // ghosted, last committed
    TrilinosWrappers::MPI::Vector  system_rhs;
    TrilinosWrappers::MPI::Vector  newton_update;
    TrilinosWrappers::MPI::Vector  relaxation_anchor;    // ghosted
    double                         surface_damping = 0.; // relax() only
    // Change of the solution over the last committed step and the change of
    // delta it came with: the secant predictor of the next step.
    TrilinosWrappers::MPI::Vector last_increment; // ghosted
    double                        last_increment_delta = 0.;
    double                        last_increment_s     = 0.;

    // One vector per history component, non-ghosted (DG dofs of a cell are
    // owned by its owner).
    std::vector<TrilinosWrappers::MPI::Vector> history;

    LoadState committed; // state of old_solution/history
    LoadState current;   // state `solution` is an equilibrium of

    // Residual scale of the last assembly: total |surface traction| force.
    double traction_scale;

    // Force control: delta is an unknown and Fn(u, delta) = target_force the
    // extra equation. Assembly then also provides the border of the Newton
    // system, b = dR/d delta = (dFn/du)^T, d = dFn/d delta, and the force
    // mismatch.
    // Spring control is force control with a target that follows delta:
    // target_force + spring_stiffness (spring_delta - delta).
    bool                          force_control    = false;
    double                        target_force     = 0.;
    double                        spring_stiffness = 0.;
    double                        spring_delta     = 0.;
    TrilinosWrappers::MPI::Vector delta_coupling; // b
    double                        delta_stiffness = 0.;
    double                        force_mismatch  = 0.;
    double                        delta_update    = 0.;

    std::unique_ptr<TrilinosWrappers::SolverDirect>    direct_solver;
    std::unique_ptr<TrilinosWrappers::PreconditionAMG> amg;

    // Sliding phase, by time stepping or by the steady-state solver.
    void
    slide(bool resumed = false);
    void
    slide_steady();
    // steady_state.csv: a row for the sliding case (for each listed speed
    // with the steady-state solver); the file is created by the first row.
    std::unique_ptr<CsvTable> steady_state_table;
    void
    write_steady_state(double                   V_hat,
                       double                   delta,
                       const SurfaceQuantities &quantities,
                       double                   dissipation_rate,
                       bool                     steady,
                       double                   distance,
                       const std::string       &solver);
    [[noreturn]] void
                      abort_run(const LoadState &target);
    SurfaceQuantities last_quantities{};
    double            last_dissipation_rate = 0.;
    double
                              total_dissipation_rate() const;
    std::unique_ptr<CsvTable> history_table;

    SurfacePostprocessor      postprocessor;
    OutputWriter              writer;
    std::unique_ptr<CsvTable> approach_table;

    Progress *progress;
    // Sliding distance of the transient run so far and its maximum, for
    // the progress report.
    double slid = 0., slide_distance = 0.;

    // The transient sliding phase: where it started, the contact length
    // after the approach, how far it may go and over which window steady
    // state is judged; the samples of Fn (or delta), Ft and L so far, and
    // the rows of history.csv. All of it is in a checkpoint.
    struct SlidePlan
    {
      double s0 = 0., L0 = 0., distance = 0., window = 0.;
    } slide_plan;
    struct SlideSample
    {
      enum
      {
        delta,
        normal_force,
        tangential_force,
        profile_force,
        contact_length,
        dissipation_rate,
        n_values
      };
      double s = 0., value[n_values] = {};
    };
    std::vector<SlideSample> samples;
    unsigned int             history_rows = 0, approach_rows = 0;

    // Checkpoint and restart (doc/restart.md): the mesh with solution,
    // history and predictor attached (p4est serialization), and the
    // scalars of the sliding phase in a text file; written into
    // checkpoint.tmp/ and then renamed to checkpoint/.
    void
    write_checkpoint();
    void
    read_checkpoint();
    std::vector<TrilinosWrappers::MPI::Vector>
    ghosted_history() const;

    unsigned int step_number;
    unsigned int last_newton_iterations;
    unsigned int last_step_cuts;
    bool         last_step_relaxed;
  };
} // namespace viscoslide

#endif

// SPDX-License-Identifier: LGPL-2.1-or-later
// The transient finite element problem: a plane-strain viscoelastic block
// whose top surface interacts with a rigid indenter through a traction-gap
// law, loaded by approach, hold, sliding (the indenter profile moves over
// the surface) and retraction. Read it like step-18 and step-42. Its
// implementation is split by concern over source/contact_problem/, as
// ASPECT splits its Simulator; each declaration below names its file.
// The surface terms and the control of the indenter are the
// SurfaceCoupling's (surface_coupling.h), shared with the steady-state
// solver (steady_state/solver.h), which run() hands the sliding phase to
// when Sliding/Solver = steady-state.
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

#include <viscoslide/driver/case.h>
#include <viscoslide/io/output.h>
#include <viscoslide/io/parameters.h>
#include <viscoslide/io/postprocessing.h>
#include <viscoslide/io/steady_state_table.h>
#include <viscoslide/numerics/linear_solver.h>
#include <viscoslide/physics/indenter.h>
#include <viscoslide/physics/interaction_law.h>
#include <viscoslide/physics/material.h>
#include <viscoslide/surface_coupling.h>

#include <boost/serialization/access.hpp>

#include <limits>
#include <memory>
#include <vector>

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

    template <class Archive>
    void
    serialize(Archive &ar, const unsigned int)
    {
      ar &delta &s &time &dt;
    }
  };

  class ContactProblem
  {
    friend class boost::serialization::access;

  public:
    static constexpr unsigned int dim = 2;

    // The case's shared parts; its progress, if any, is appended to the
    // per-step report lines, and a resumed run tells it how much of the
    // case its checkpoint holds. [core.cc]
    explicit ContactProblem(CaseParts &parts);

    // Approach, optional hold, sliding, optional retraction; writes all
    // outputs. With `resume`, continues the transient sliding phase from
    // the checkpoint in the output directory instead (doc/restart.md).
    // [core.cc]
    void
    run(bool resume = false);

    // The approach and the hold alone, on a new block: where the
    // steady-state solver starts from (steady_state/run.h). [core.cc]
    void
    approach();

    // What the steady-state solver takes over after approach(): the block,
    // the surface coupling and the relaxed state of the approach. Nothing
    // of the transient solution is used afterwards. [sliding.cc]
    struct HandOver
    {
      parallel::distributed::Triangulation<dim> &triangulation;
      SurfaceCoupling<dim>                      &coupling;
      const SurfacePostprocessor<dim>           &postprocessor;
      TimerOutput                               &timer;
      const DoFHandler<dim>                     &dof_handler;
      const TrilinosWrappers::MPI::Vector       &solution;
      double                                     delta, s, normal_force;
    };
    HandOver
    hand_over();

    // A finished run: its checkpoint removed, the timer's report printed.
    // [core.cc]
    void
    finish();

    // Whether `directory` holds a complete checkpoint of a sliding run.
    // [checkpoint_restart.cc]
    static bool
    has_checkpoint(const std::string &directory);

  private:
    // The phases of the loading program, named in approach.csv.
    enum class Phase
    {
      start,
      approach,
      load,
      hold,
      slide,
      retract
    };
    static std::string
    name(Phase phase);

    // --- the loading program [core.cc]

    // Solves one step of the loading program, cutting it when Newton fails,
    // and adapting the mesh to its solution. Returns false only if nothing
    // worked.
    bool
    advance_to(const LoadState &target, Phase phase);
    // One step from the committed state, predicted along the secant of the
    // last step where that helps; the Newton iterations or -1.
    int
    solve_step(const LoadState &trial);
    // From the committed delta to `to` in Loading/Approach increment steps.
    void
    ramp(Phase phase, double to);
    // Approach until F_n passes Loading/Target load, then hold exactly that
    // load for one force-controlled solve.
    void
    approach_to_load();
    // Loading/Hold time in geometrically growing steps.
    void
    hold();
    [[noreturn]] void
    abort_run(const LoadState &target);

    // --- the system and Newton's method [assembly.cc]

    void
    setup_system();
    // Residual -R(u) and, if asked, the consistent tangent dR/du.
    void
    assemble(bool with_matrix);
    // A cell's part of -R: minus the divergence of the stress of the
    // strains and the history advanced over the step. [assembly.cc]
    void
    add_stress_terms(const FEValues<dim>                        &fe_values,
                     const std::vector<SymmetricTensor<2, dim>> &strain,
                     const std::vector<SymmetricTensor<2, dim>> &old_strain,
                     const std::vector<double>                  &history_values,
                     const std::vector<ViscoelasticSolid::StepFactors> &factors,
                     Vector<double> &cell_rhs) const;
    // The bulk part of the tangent, the same for every Newton iteration of
    // a time step: made once per time step and mesh.
    void
    assemble_bulk();
    // MUMPS (linear_solver) or, beyond 'Direct solver limit', GMRES
    // with AMG.
    bool
    use_direct_solver() const;
    void
    solve_iteratively(const TrilinosWrappers::MPI::Vector &rhs,
                      TrilinosWrappers::MPI::Vector       &x);
    void
    solve_newton_system();
    SurfaceCoupling<dim>::System
    newton_system();
    // Newton's method for the state `target` from the current iterate.
    // Returns the iterations used, or -1 if it did not converge.
    int
    solve_newton(const LoadState &target);
    // Lands on the new branch after a surface instability by damped
    // pseudo-time stepping. Returns the pseudo-steps used or -1.
    int
    relax_to_equilibrium(const LoadState &target);

    // --- the quadrature-point history [history.cc]

    // Components of the history: the stress of each arm (xx, yy, xy, zz of
    // arm k at 4 k ... 4 k + 3), then the energy dissipated so far per unit
    // volume.
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
    read_cell_history(const DoFHandler<dim>::active_cell_iterator &cell,
                      std::vector<double>                         &values,
                      std::vector<types::global_dof_index>        &dofs) const;
    // Arm stress of one arm at quadrature point q from the values of
    // read_cell_history().
    ArmStress
    arm_stress_at(const std::vector<double> &history_values,
                  unsigned int               arm,
                  unsigned int               q) const;
    // Accepts the current state: updates the history, the secant
    // predictor and the committed state.
    void
    commit_history();
    // The history with the ghost values SolutionTransfer needs.
    std::vector<TrilinosWrappers::MPI::Vector>
    ghosted_history() const;
    // integral of D dA at the committed state.
    double
    total_dissipation_rate() const;

    // --- the mesh [refinement.cc]

    bool
    adapt_mesh();
    void
    refine_initial_mesh();

    // --- the sliding phase [sliding.cc]

    void
    slide(bool resumed = false);
    // The Sliding/Program instead of slide(): its segments in turn, a
    // checkpoint after each (with Output/Checkpoint every > 0), from the
    // segment and the part of it a resumed run's checkpoint holds.
    // [sliding.cc]
    void
    run_program(bool resumed = false);
    // The next step of a segment, `done` of it behind: a slide's step of
    // Sliding increment finest cells, or a rest's time step, growing
    // geometrically from a slide step's time so that the relaxation
    // right after the stop is resolved. Cut to the segment's end.
    LoadState
    program_step(const Parameters::ProgramSegment &segment, double done) const;
    // The sliding speed (V_hat) of the step under way: the segment's in a
    // program, else the Sliding speed. [sliding.cc]
    double
    sliding_speed() const;
    // The part of the program done, from its segment and the part of that.
    // [sliding.cc]
    double
    program_fraction() const;
    // Sets slide_plan from the state after the approach.
    void
    plan_slide();
    // The means of the samples with from < s <= to.
    struct SlideSample;
    SlideSample
    window_mean(double from, double to) const;
    bool
    window_is_steady() const;
    // The energy balance F_t V / D - 1 over the last window (NaN where not
    // judged: energy_balance() of steady_state_table.h).
    double
    window_balance() const;
    // The steady_state.csv row of the last window.
    void
    report_slide(bool steady);
    // The line that ends a slide: steady, or which test it failed.
    void
    say_slide_verdict(bool settled, bool balanced) const;

    // --- checkpoint and restart [checkpoint_restart.cc]

    void
    write_checkpoint();
    void
    read_checkpoint();

    // --- output [output.cc]

    // approach.csv and history.csv: new, or continued after the rows of a
    // checkpoint.
    void
    open_approach_table(bool resume);
    void
    open_history_table(bool resume);
    std::unique_ptr<CsvTable>
    open_table(const std::string              &name,
               const std::vector<std::string> &columns,
               bool                            resume,
               unsigned int                    keep_rows,
               const std::string              &units) const;
    void
    record_step(Phase phase);
    void
    add_history_row();
    void
    add_approach_row(Phase phase);
    void
    print_step(Phase phase);
    void
    write_fields();
    // At the quadrature points of `cell` (fe_values reinit there, with
    // gradients): the stress components xx, yy, xy, zz, the dissipation
    // rate and the energy dissipated so far per unit volume.
    static constexpr unsigned int n_quadrature_fields = 6;
    void
    quadrature_fields(const FEValues<dim>                         &fe_values,
                      const DoFHandler<dim>::active_cell_iterator &cell,
                      std::vector<std::vector<double>> &fields) const;
    void
    write_profile(const std::string &filename);

    const Parameters::AllParameters &prm;
    MPI_Comm                         mpi_communicator;
    ConditionalOStream               pcout;
    TimerOutput                      timer;

    const Scales                   &scales;
    const ViscoelasticSolid        &material;
    const InteractionLaw           &law;
    const Indenter                 &indenter;
    const SurfacePostprocessor<dim> postprocessor;
    SurfaceCoupling<dim>            coupling;

    parallel::distributed::Triangulation<dim> triangulation;
    const FESystem<dim>                       fe;
    DoFHandler<dim>                           dof_handler;
    const QGauss<dim>                         quadrature;

    // The history lives in a discontinuous field whose nodes are the Gauss
    // points of `quadrature`, so that SolutionTransfer carries it through
    // refinement and coarsening and the serializer can checkpoint it.
    const FE_DGQArbitraryNodes<dim> history_fe;
    DoFHandler<dim>                 history_dof_handler;
    std::vector<unsigned int>       quadrature_to_history_dof;

    IndexSet                  locally_owned_dofs, locally_relevant_dofs;
    AffineConstraints<double> constraints;

    TrilinosWrappers::SparseMatrix system_matrix;
    // The matrix of the bulk terms, and the time step it was made for (-1:
    // none on this mesh).
    TrilinosWrappers::SparseMatrix bulk_matrix;
    double                         bulk_dt = -1.;
    TrilinosWrappers::MPI::Vector  solution;     // ghosted, current iterate
    TrilinosWrappers::MPI::Vector  old_solution; // ghosted, last committed
    TrilinosWrappers::MPI::Vector  system_rhs;
    TrilinosWrappers::MPI::Vector  newton_update;
    // Change of the solution over the last committed step and the change of
    // delta and s it came with: the secant predictor of the next step.
    TrilinosWrappers::MPI::Vector last_increment; // ghosted
    double                        last_increment_delta = 0.;
    double                        last_increment_s     = 0.;

    // One vector per history component, non-ghosted (DG dofs of a cell are
    // owned by its owner).
    std::vector<TrilinosWrappers::MPI::Vector> history;

    LoadState committed; // state of old_solution/history
    LoadState current;   // state `solution` is an equilibrium of

    ReusedFactorization                                linear_solver;
    std::unique_ptr<TrilinosWrappers::PreconditionAMG> amg;

    OutputWriter             &writer;
    std::unique_ptr<CsvTable> approach_table;
    std::unique_ptr<CsvTable> history_table;
    SteadyStateTable         &steady_state_table;
    SurfaceQuantities         last_quantities{};
    double                    last_dissipation_rate = 0.;

    Progress        *progress;
    ApproachProgress approach_progress;
    // The program's segment under way and how much of it (eps or tau) is
    // done.
    unsigned int program_segment = 0;
    double       segment_done    = 0.;

    // The transient sliding phase: where it started, the contact length
    // after the approach, how far it may go and over which window steady
    // state is judged; the samples of delta, Fn, Ft and L so far.
    struct SlidePlan
    {
      double s0 = 0., L0 = 0., distance = 0., window = 0.;

      template <class Archive>
      void
      serialize(Archive &ar, const unsigned int)
      {
        ar &s0 &L0 &distance &window;
      }
    } slide_plan;
    struct SlideSample
    {
      enum
      {
        delta,
        normal_force,
        contact_set_tangential_force,
        tangential_force,
        contact_length,
        dissipation_rate,
        n_values
      };
      double s = 0., value[n_values] = {};

      template <class Archive>
      void
      serialize(Archive &ar, const unsigned int)
      {
        ar &s &value;
      }
    };
    std::vector<SlideSample> samples;

    unsigned int step_number            = 0;
    unsigned int history_rows           = 0;
    unsigned int approach_rows          = 0;
    unsigned int last_newton_iterations = 0;
    unsigned int last_step_cuts         = 0;
    bool         last_step_relaxed      = false;

    // Every scalar a resumed sliding phase needs, for the checkpoint.
    template <class Archive>
    void
    serialize(Archive &ar, const unsigned int)
    {
      ar &step_number &history_rows &approach_rows &committed;
      ar &last_increment_delta &last_increment_s   &coupling;
      ar &slide_plan                               &samples;
      ar &program_segment                          &segment_done;
    }
  };
} // namespace viscoslide

#endif

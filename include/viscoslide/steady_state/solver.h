// SPDX-License-Identifier: LGPL-2.1-or-later
// The steady sliding state solved directly, in the frame of the indenter.
//
// There the material flows with velocity -V e_x under the indenter, which
// sits still at x = s. The Maxwell arm is written through its viscous strain
// eps_v, h = C1 : (eps(u) - eps_v), and its evolution
// d eps_v/dt = (eps - eps_v)/tau becomes the stationary advection-reaction
// equation
//     -V tau d(eps_v)/dx + eps_v = eps(u),  eps_v = 0 where material enters
// (x = +W/2). eps_v is a discontinuous field (FE_DGQ, upwind fluxes as in
// step-12) next to the Q2 displacement in one FESystem; equilibrium with
// the surface traction law and this equation are solved together by
// Newton's method (plus delta under force control, as in the transient
// solver). doc/steady_state.md has the formulation and its limits.
//
// The implementation is split over source/steady_state/: solver.cc (setup,
// the start from the relaxed state, Newton's method and the continuation
// in speed and load), assembly.cc (the equations), output.cc (dissipation,
// profiles, fields and the rows of the stations). The surface terms and the
// control of the indenter are the SurfaceCoupling's, shared with the
// transient solver.
#ifndef viscoslide_steady_state_solver_h
#define viscoslide_steady_state_solver_h

#include <deal.II/base/conditional_ostream.h>
#include <deal.II/base/quadrature_lib.h>
#include <deal.II/base/timer.h>

#include <deal.II/distributed/tria.h>

#include <deal.II/dofs/dof_handler.h>

#include <deal.II/fe/fe_interface_values.h>
#include <deal.II/fe/fe_system.h>

#include <deal.II/lac/affine_constraints.h>
#include <deal.II/lac/full_matrix.h>
#include <deal.II/lac/trilinos_solver.h>
#include <deal.II/lac/trilinos_sparse_matrix.h>
#include <deal.II/lac/trilinos_vector.h>

#include <viscoslide/io/output.h>
#include <viscoslide/io/parameters.h>
#include <viscoslide/io/postprocessing.h>
#include <viscoslide/io/steady_state_table.h>
#include <viscoslide/numerics/linear_solver.h>
#include <viscoslide/physics/material.h>
#include <viscoslide/steady_sliding.h>
#include <viscoslide/steady_state/iterative_solver.h>
#include <viscoslide/surface_coupling.h>

#include <array>
#include <functional>
#include <memory>

namespace viscoslide
{
  using namespace dealii;

  // The same code in 2D (plane strain, a cylinder) and 3D (a body of
  // revolution); u_y below is the vertical displacement, u_z in 3D.
  template <int dim>
  class SteadyStateSolver : public SteadySliding
  {
  public:
    // The solver takes over the coupling (whose control the caller sets
    // after initialize()) and the triangulation. [solver.cc]
    SteadyStateSolver(const Parameters::AllParameters           &prm,
                      const Scales                              &scales,
                      const ViscoelasticSolid                   &material,
                      SurfaceCoupling<dim>                      &coupling,
                      const SurfacePostprocessor<dim>           &postprocessor,
                      parallel::distributed::Triangulation<dim> &triangulation,
                      TimerOutput                               &timer);
    ~SteadyStateSolver();

    // Starts from a relaxed equilibrium: the displacement u of a
    // FESystem(FE_Q(2), dim) on the same triangulation, at approach delta with
    // the indenter at s; eps_v is the cell-wise L2 projection of eps(u),
    // the relaxed state. [solver.cc]
    void
    initialize(const DoFHandler<dim>               &displacement_dofs,
               const TrilinosWrappers::MPI::Vector &u,
               double                               delta,
               double                               s);

    // Starts without a transient solver, as the 3D case does: the block at
    // rest and undeformed (u = 0, eps_v = 0) at approach delta with the
    // indenter at s, the mesh refined about the apex. [solver.cc]
    void
    initialize_at_rest(double delta, double s);

    // Continues the steady state from its present speed to V_hat in steps
    // no larger than the Continuation factor (shorter where Newton fails),
    // adapting the mesh to the contact edges at each speed. Returns false
    // if a step could not be solved; the state is then the last converged
    // one, at speed(). [solver.cc]
    bool
    continue_to(double                       V_hat,
                const std::function<void()> &on_converged) override;

    // Follows the steady state at the current speed to a new load: F_n
    // under force control, delta under displacement control (SI units),
    // by continuation in steps; false if a step cannot be solved.
    // [solver.cc]
    bool
    continue_to_load(double                       target,
                     const std::function<void()> &on_converged) override;

    // Follows the steady state at the current speed and approach as the
    // law's attraction grows from 0 to 1 (AttractionHomotopy, through
    // `set_attraction`), by continuation in steps; false if a step cannot
    // be solved. [solver.cc]
    bool
    continue_in_attraction(const std::function<void(double)> &set_attraction);

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
    // integral of D over the block [output.cc]
    double
    dissipation_rate() const override;
    // At the quadrature points of the cell where fe_values stands: the
    // dissipation density D, then the stress (2D: xx, yy, xy and zz; 3D:
    // xx, yy, zz, xy, xz, yz), from the equations' strains (the arms see
    // Pi eps(u)). [output.cc]
    static constexpr unsigned int n_quadrature_fields = dim == 2 ? 5 : 7;
    void
    quadrature_fields(const FEValues<dim>              &fe_values,
                      std::vector<std::vector<double>> &fields) const;
    // Newton iterations of the last converged speed (re-solves after mesh
    // adaptation included).
    unsigned int
    newton_iterations() const override
    {
      return last_newton_iterations;
    }
    unsigned long
    n_unknowns() const override
    {
      return dof_handler.n_dofs();
    }
    bool
    force_control() const override
    {
      return coupling.force_control();
    }

    // [output.cc]
    // A checkpoint after a converged station, in `directory` (replaced
    // only once the new one is complete), and the state it restores in
    // place of initialize(): the mesh and the solution through p4est, and
    // the continuation's scalars (doc/restart.md).
    void
    write_checkpoint(const std::string       &directory,
                     const StationCheckpoint &station) const;
    StationCheckpoint
    read_checkpoint(const std::string &directory);

    void
    write_profile(const std::string &path) const override;
    // Displacement, viscous strain, stress and D over the block, and the
    // surface pressure and gap, as VTU/PVTU through the writer. [output.cc]
    void
    write_fields(OutputWriter &writer, unsigned int counter) const override;

  private:
    using CellIterator = typename DoFHandler<dim>::active_cell_iterator;

    // Whether face f of a cell carries a viscous-strain flux: beta is along
    // x, so the faces normal to x alone, faces 0 and 1 of the block's
    // axis-parallel cells.
    static bool
    carries_flux(const CellIterator &, const unsigned int f)
    {
      return f < 2;
    }

    // [solver.cc]
    void
    setup_system();
    // [assembly.cc]: the residual and Jacobian: the surface terms of
    // SurfaceCoupling on the matrix of the linear terms, which
    // assemble_bulk() makes once per speed and mesh on MeshWorker::mesh_loop
    // as in step-12: cells, the upwind fluxes of the interior faces, the
    // outflow boundary.
    void
    assemble(bool with_matrix);
    void
    assemble_bulk();
    struct AssemblyCoefficients;
    AssemblyCoefficients
    assembly_coefficients() const;
    struct AssemblyScratch;
    struct AssemblyCopy;
    void
    strain_gradients(const AssemblyCoefficients &coefficients,
                     AssemblyScratch            &scratch) const;
    void
    assemble_cell(const CellIterator         &cell,
                  const AssemblyCoefficients &coefficients,
                  AssemblyScratch            &scratch,
                  AssemblyCopy               &copy) const;
    void
    assemble_boundary(const CellIterator         &cell,
                      unsigned int                face_no,
                      const AssemblyCoefficients &coefficients,
                      AssemblyScratch            &scratch,
                      AssemblyCopy               &copy) const;
    void
    assemble_interface(const CellIterator         &cell,
                       unsigned int                face_no,
                       unsigned int                subface_no,
                       const CellIterator         &neighbor,
                       unsigned int                neighbor_face_no,
                       unsigned int                neighbor_subface_no,
                       const AssemblyCoefficients &coefficients,
                       AssemblyScratch            &scratch,
                       AssemblyCopy               &copy) const;
    // The flux block of assemble_interface() on the face where `fe_iv`
    // stands, and on which side the upwind cell lies.
    void
    face_block(const FEInterfaceValues<dim> &fe_iv,
               const AssemblyCoefficients   &coefficients,
               bool                         &upwind_is_mine,
               FullMatrix<double>           &matrix) const;
    // [solver.cc]
    // Whether the Newton systems go to the direct solver: Solver/Linear
    // solver, where 'automatic' takes it in 2D (MUMPS's fill grows like
    // n log n there) and in 3D up to Direct solver limit unknowns.
    bool
    use_direct_solver() const;
    void
    solve_newton_system();
    typename SurfaceCoupling<dim>::System
    newton_system();
    // Newton's method, else pseudo-transient relaxation, at the present
    // V_hat and load; the iterations used or -1.
    int
    solve_newton_or_relax();
    // What continue_in() does with one step: set the parameter to `next`,
    // start from the secant of the last step times `ratio`, solve from the
    // converged state `last` (relaxing on a Newton failure if `relax`);
    // solve_step()'s code.
    using StepAttempt =
      std::function<int(double                               next,
                        double                               ratio,
                        const TrilinosWrappers::MPI::Vector &last,
                        bool                                 relax)>;
    using ValueCallback = std::function<void(double)>;
    // A continuation in one parameter from `from` to `to`: steps of `step`
    // first (`last_step` the one before, for the secant), each by
    // `attempt`; a failed step restores the solution, calls `undo` with the
    // last converged value and is halved, down to a thousandth of the way
    // (then `failed` with the step's value, and false); a converged one
    // calls `accepted` with its value and doubles. The relaxation only for
    // steps below a tenth of the way in 3D. False also if a step failed on
    // an adapted mesh.
    bool
    continue_in(double               from,
                double               to,
                double               step,
                double               last_step,
                const StepAttempt   &attempt,
                const ValueCallback &undo,
                const ValueCallback &accepted,
                const ValueCallback &failed);
    // One step of a continuation from the converged state `last`: Newton
    // from the present solution, else the relaxation from `last` at
    // approach `last_delta` (the step's own under displacement control),
    // then the mesh adaptation cycles (without `relax`, a Newton failure
    // fails the step: a shorter one is cheaper than the relaxation); the
    // iterations, -1 if the step failed, -2 if it failed on an adapted
    // mesh.
    int
    solve_step(const std::string                   &what,
               const TrilinosWrappers::MPI::Vector &last,
               double                               last_delta,
               bool                                 relax = true);
    // The start of a load step from the converged state `last`: the last
    // step's increment times `ratio`, the surface kept out of the wall.
    void
    predict_load_step(double                               ratio,
                      const TrilinosWrappers::MPI::Vector &last,
                      double                               last_delta);
    // Adapts the mesh to the contact edges of the solution and to the
    // intervals `expected` (see expected_edges()); whether it changed.
    bool
    adapt_mesh(const SurfaceRegions<dim> &expected = {});
    // Where the contact edges are expected at speed `next`: the sweep of
    // each edge from its extent at the present speed to its extrapolation
    // in log V_hat from the last two speeds (none before two are known).
    // Refined ahead of the solve, this region spares the re-solves on
    // adapted meshes that an edge moving out of its fine cells costs. In
    // 3D none yet: the mesh follows the edges after each solve.
    SurfaceRegions<dim>
    expected_edges(double next) const;
    // Records the extent of the contact edges at the converged present
    // speed.
    void
    record_edges();
    void
    update_quantities();

    const Parameters::AllParameters           &prm;
    const Scales                              &scales;
    const ViscoelasticSolid                   &material;
    SurfaceCoupling<dim>                      &coupling;
    const SurfacePostprocessor<dim>           &postprocessor;
    parallel::distributed::Triangulation<dim> &triangulation;
    TimerOutput                               &timer;
    MPI_Comm                                   mpi_communicator;
    ConditionalOStream                         pcout;

    // Components: the displacement, then the viscous strain of each
    // Maxwell arm (viscous_strain.h).
    const unsigned int    n_strain_components;
    const FESystem<dim>   fe;
    DoFHandler<dim>       dof_handler;
    const QGauss<dim>     quadrature;
    const QGauss<dim - 1> flux_quadrature; // vertical faces (upwind fluxes)
    // Local dofs of the first viscous-strain component.
    std::vector<unsigned int> strain_basis;

    IndexSet                       locally_owned_dofs, locally_relevant_dofs;
    AffineConstraints<double>      constraints;
    TrilinosWrappers::SparseMatrix system_matrix;
    // The matrix of the linear terms, and the speed it was made for (-1:
    // none on this mesh).
    TrilinosWrappers::SparseMatrix bulk_matrix;
    double                         bulk_speed = -1.;
    TrilinosWrappers::MPI::Vector  solution; // ghosted
    TrilinosWrappers::MPI::Vector  system_rhs, newton_update;
    ReusedFactorization            linear_solver;
    SteadyIterativeSolver<dim>     iterative_solver;

    double V_hat = 0.;
    double delta = 0.;
    double s     = 0.;

    // The extent of the two contact edges (the ends of the faces in the
    // edge band left and right of their middle) at the last two converged
    // speeds (kept by checkpoints).
    struct EdgeSpan
    {
      double                log_speed;
      std::array<double, 4> ends; // left edge's two, right edge's two

      template <class Archive>
      void
      serialize(Archive &ar, const unsigned int)
      {
        ar &log_speed &ends;
      }
    };
    std::vector<EdgeSpan> edge_spans;

    // The change of the solution (ghosted) over the last converged step,
    // before its mesh adaptation, carried through them; and of delta and
    // F_n over it if it was a load step (zero after a speed step).
    TrilinosWrappers::MPI::Vector last_increment;
    struct
    {
      double delta = 0., force = 0.;
    } last_load_step;

    SurfaceQuantities last_quantities{};
    unsigned int      last_newton_iterations = 0;
  };
} // namespace viscoslide

#endif

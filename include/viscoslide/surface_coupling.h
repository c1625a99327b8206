// SPDX-License-Identifier: LGPL-2.1-or-later
// The coupling of the block's top surface to the rigid indenter: the one
// place where the surface physics of every solver is written (implemented
// in source/surface_coupling.cc).
//
//  * The traction law's face term -<p(g), v_y>_top and its tangent, with
//    the gap g = h(x - s) - delta - u_y (doc/conventions.md). In 3D u_y is
//    read as the vertical u_z and h(x - s) as the body of revolution
//    (apex_distance()); the component is vertical<dim> throughout.
//  * The control of the indenter. Displacement: delta is given. Force: delta
//    is an unknown and F_n(u, delta) = F0 the extra equation. Spring: force
//    control with F0 + k (delta0 - delta) as the target. Force control
//    borders the Newton system, which solve_bordered() solves.
//  * The surface dashpot of the pseudo-transient relaxation (relax()), by
//    which a solver lands on a new branch after a contact edge jumped.
//  * The contact edges that the adaptive mesh follows.
//
// A solver assembles its bulk terms and, on every top face, calls
// add_face_terms(); copy_local_to_global() per cell and finish_assembly()
// at the end complete the force-control border. newton() and relax() then
// drive the solver's System.
#ifndef viscoslide_surface_coupling_h
#define viscoslide_surface_coupling_h

#include <deal.II/base/conditional_ostream.h>
#include <deal.II/base/quadrature_lib.h>

#include <deal.II/distributed/tria.h>

#include <deal.II/dofs/dof_handler.h>

#include <deal.II/fe/fe_values.h>

#include <deal.II/lac/affine_constraints.h>
#include <deal.II/lac/full_matrix.h>
#include <deal.II/lac/trilinos_vector.h>
#include <deal.II/lac/vector.h>

#include <viscoslide/io/parameters.h>
#include <viscoslide/io/postprocessing.h>
#include <viscoslide/numerics/linear_solver.h>
#include <viscoslide/numerics/newton.h>
#include <viscoslide/physics/indenter.h>
#include <viscoslide/physics/interaction_law.h>
#include <viscoslide/physics/load_control.h>

#include <boost/serialization/access.hpp>

#include <functional>

namespace viscoslide
{
  using namespace dealii;

  template <int dim>
  class SurfaceCoupling
  {
    friend class boost::serialization::access;

  public:
    using VectorType = TrilinosWrappers::MPI::Vector;

    SurfaceCoupling(const Parameters::AllParameters &prm,
                    const Scales                    &scales,
                    const InteractionLaw            &law,
                    const Indenter                  &indenter,
                    const SurfacePostprocessor<dim> &postprocessor,
                    MPI_Comm                         comm);

    // --- control of the indenter

    // Displacement control: delta is given (load_control.h).
    void
    hold_approach()
    {
      control.hold_approach();
    }
    // Force control at F_n = normal_force; with a spring (stiffness in
    // force per unit length per length of approach) the target is
    // normal_force + spring_stiffness (spring_delta - delta).
    void
    hold_force(const double normal_force,
               const double spring_stiffness = 0.,
               const double spring_delta     = 0.)
    {
      control.hold_force(normal_force, spring_stiffness, spring_delta);
    }
    bool
    force_control() const
    {
      return control.force_controlled;
    }
    // The F_n held under force control, for continuation in the load.
    double &
    held_force()
    {
      return control.target_force;
    }
    // The approach at which the spring of Sliding/Control = spring is
    // relaxed (kept by checkpoints).
    double
    spring_reference() const
    {
      return control.spring_delta;
    }
    // The spring of Sliding/Control = spring; 0 for the other controls.
    static double
    spring_stiffness_of(const Parameters::AllParameters &prm,
                        const Scales                    &scales);

    const InteractionLaw &
    law() const
    {
      return traction_law;
    }
    const Indenter &
    indenter() const
    {
      return profile;
    }

    // --- assembly

    // Quadrature and update flags of the FEFaceValues that
    // add_face_terms() is given.
    const Quadrature<dim - 1> &
    face_quadrature() const
    {
      return quadrature;
    }
    static UpdateFlags
    face_update_flags()
    {
      return update_values | update_quadrature_points | update_JxW_values;
    }

    // What the top faces of one cell contribute besides the cell's
    // residual and matrix: the column b = dR/d delta of the border, and
    // their force, its derivative by delta and |traction|.
    struct LocalTerms
    {
      Vector<double> coupling;
      double         force = 0., stiffness = 0., abs_force = 0.;

      void
      reinit(unsigned int dofs_per_cell);
    };

    // Sizes the border for the solver's dofs; after every setup.
    void
    reinit(const IndexSet &locally_owned_dofs);
    // Zeroes what copy_local_to_global() accumulates.
    void
    start_assembly();
    // Adds, on the top face `face_values` is reinit'ed on (component
    // vertical<dim> of the solver's element is u_y),
    //   -<p(g), v_y> + c <u_y - u_y^anchor, v_y>
    // to cell_rhs (as -R) and its tangent to cell_matrix. The dashpot term
    // acts only during relax().
    void
    add_face_terms(const FEFaceValuesBase<dim> &face_values,
                   const VectorType            &solution,
                   double                       delta,
                   double                       s,
                   bool                         with_matrix,
                   FullMatrix<double>          &cell_matrix,
                   Vector<double>              &cell_rhs,
                   LocalTerms                  &local) const;
    // Adds a cell's local system (its matrix only if with_matrix) to the
    // solver's system, and its border terms to the coupling's.
    void
    copy_local_to_global(const LocalTerms         &local,
                         const FullMatrix<double> &cell_matrix,
                         const Vector<double>     &cell_rhs,
                         const std::vector<types::global_dof_index> &dofs,
                         const AffineConstraints<double> &constraints,
                         bool                             with_matrix,
                         TrilinosWrappers::SparseMatrix  &matrix,
                         VectorType                      &rhs);
    // Compresses the solver's system after the copies; sums the coupling's
    // terms over the processes; under force control the mismatch
    // F_n - target and its derivative by delta.
    void
    finish_assembly(double                          delta,
                    bool                            with_matrix,
                    TrilinosWrappers::SparseMatrix &matrix,
                    VectorType                     &rhs);

    // --- Newton's method

    // |R| and, under force control, the force mismatch.
    double
    residual_norm(const VectorType &rhs) const;

    // Solves K x = b for the solver's Jacobian K as assembled last.
    using LinearSolve = std::function<void(const VectorType &b, VectorType &x)>;
    // The Newton update of the bordered system
    //   [K   b] [du    ]   [-R]
    //   [b^T d] [ddelta] = [-G],   G = F_n - target,
    // with two solves of K (one under displacement control). `update` is
    // not yet distributed to constrained dofs.
    void
    solve_bordered(const LinearSolve &solve,
                   const VectorType  &rhs,
                   VectorType        &update);
    // The same with the direct solver, which takes the border into its
    // own solve (ReusedFactorization::solve_bordered).
    void
    solve_bordered(ReusedFactorization                  &solver,
                   const TrilinosWrappers::SparseMatrix &matrix,
                   const VectorType                     &rhs,
                   VectorType                           &update);

    // A solver's system as Newton's method sees it.
    struct System
    {
      VectorType       &solution; // ghosted iterate
      double           &delta;    // part of the iterate under force control
      const VectorType &update;   // from compute_update()
      const VectorType &rhs;      // -R of the last assembly
      std::function<void(bool with_matrix)> assemble;
      std::function<void()>                 compute_update;
    };
    // Newton's method with line search (newton()); the iterations used or
    // -1.
    int
    newton(const System &system, ConditionalOStream &out);
    // After a jump-in or jump-out no equilibrium is near the last one and
    // Newton cannot get there: relax() (newton.h) follows the fictitious
    // dynamics of the surface dashpot, whose initial stiffness is that of
    // the traction law's wall, with pseudo-steps that move the surface by
    // about half an eps. The pseudo-steps used or -1.
    int
    relax(const System &system, ConditionalOStream &out);

    // A predictor extrapolates the surface nodes that closed onto the
    // indenter in the last step as if they closed again, deep into the
    // traction law's wall, from where Newton climbs out by about a tenth of
    // the gap per iteration. So no surface node of `predicted` (at delta,
    // s) is left closer than the smaller of eps and its gap in `last` (at
    // last_delta, last_s). `last` is ghosted, `predicted` not; both live on
    // `dof_handler`, whose element's component vertical<dim> is u_y.
    void
    limit_predicted_closing(const DoFHandler<dim>           &dof_handler,
                            const AffineConstraints<double> &constraints,
                            const VectorType                &last,
                            double                           last_delta,
                            double                           last_s,
                            VectorType                      &predicted,
                            double                           delta,
                            double                           s) const;

    // Points `solver` at the surface of a solver's iterate, whose
    // references it keeps: the unknowns of surface_unknowns(), the window
    // of surface_window() and the model of window_model().
    void
    attach(ReusedFactorization             &solver,
           const DoFHandler<dim>           &dof_handler,
           const AffineConstraints<double> &constraints,
           const VectorType                &solution,
           const double                    &delta,
           const double                    &s) const;

    // Collective: the face terms of add_face_terms() on the rows of the
    // window T (global indices, ascending) as functions of the unknowns of
    // T and of delta, for ReusedFactorization's Newton iterations on T
    // (the unknowns outside T held). Without terms within relax().
    WindowModel
    window_model(const DoFHandler<dim>           &dof_handler,
                 const AffineConstraints<double> &constraints,
                 const VectorType                &solution,
                 double                           delta,
                 double                           s,
                 const std::vector<int>          &T) const;

    // The locally owned unknowns the face terms act on: u_y (component
    // vertical<dim> of the element of `dof_handler`) on the top surface,
    // less the constrained ones. Two Jacobians that differ in their surface
    // terms alone differ only on these rows and columns (ReusedFactorization).
    IndexSet
    surface_unknowns(const DoFHandler<dim>           &dof_handler,
                     const AffineConstraints<double> &constraints) const;
    // The gap, in eps, that bounds surface_window().
    static constexpr double window_gap = 20.;
    // The most surface unknowns that make the relaxation's window: a dense
    // LU on 1500 (2.2 GFlop) costs about as much as the sparse
    // factorization of a Newton matrix at the figures' resolution (1.8
    // GFlop at 76 000 unknowns).
    static constexpr std::size_t whole_window = 1500;
    // Those of them where the traction law is stiff at the iterate
    // (`solution` at delta, s; ghosted): the gap below window_gap, or below
    // twice the smallest gap before contact. Beyond it the Lennard-Jones
    // tangent, about 8 dgamma/eps^2 (eps/g)^4, is below 1e-5 of its wall's
    // (16 dgamma/eps^2) and changes little from one Newton iteration to the
    // next. While relax() runs, all of them, up to whole_window of them: its
    // dashpot acts everywhere.
    IndexSet
    surface_window(const DoFHandler<dim>           &dof_handler,
                   const AffineConstraints<double> &constraints,
                   const VectorType                &solution,
                   double                           delta,
                   double                           s) const;

    // --- the mesh

    // The contact edges: the regions of the top faces whose gap lies in
    // the Mesh edge band, on every process; before contact the point under
    // the apex.
    SurfaceRegions<dim>
    contact_edges(const DoFHandler<dim> &dof_handler,
                  const VectorType      &solution,
                  double                 delta,
                  double                 s) const;
    // Flags the cells at the contact edges, and at the intervals
    // `expected` where a solver expects them next, for
    // flag_cells_near_edges(). Returns whether the mesh will change.
    bool
    flag_contact_edges(parallel::distributed::Triangulation<dim> &triangulation,
                       const DoFHandler<dim>                     &dof_handler,
                       const VectorType                          &solution,
                       double                                     delta,
                       double                                     s,
                       const SurfaceRegions<dim> &expected = {}) const;

    // The control's state, for a checkpoint.
    template <class Archive>
    void
    serialize(Archive &ar, const unsigned int)
    {
      ar &control;
    }

  private:
    NewtonProblem
    newton_problem(const System &system);
    // The gap at a surface point p displaced vertically by u.
    double
    gap_at(const Point<dim> &p, double u, double delta, double s) const;
    // The traction p(g) and dp/dg there.
    std::pair<double, double>
    law_at(const Point<dim> &p, double u, double delta, double s) const;
    // The residual norm Newton's method accepts.
    double
    tolerance() const;
    // Calls f(dof, p) for the locally owned, unconstrained vertical
    // unknowns of the top surface, p their support point; a node shared by
    // several faces once per face.
    template <typename Function>
    void
    for_each_surface_unknown(const DoFHandler<dim>           &dof_handler,
                             const AffineConstraints<double> &constraints,
                             const Function                  &f) const;

    const Parameters::AllParameters &prm;
    const Scales                    &scales;
    const InteractionLaw            &traction_law;
    const Indenter                  &profile;
    const SurfacePostprocessor<dim> &postprocessor;
    MPI_Comm                         comm;
    const QGauss<dim - 1>            quadrature;

    LoadControl control;

    VectorType delta_coupling; // b
    double     force = 0., delta_stiffness = 0., abs_force = 0.;
    double     force_mismatch = 0., delta_update = 0.;
    // Residual scale of the last assembly: the total |traction| force.
    double traction_scale = 0.;

    double     surface_damping = 0.;    // relax() only
    bool       relaxing        = false; // within relax()
    VectorType relaxation_anchor;       // ghosted

    // The iterate a line search starts from.
    VectorType u0;
    double     delta0 = 0.;
  };
} // namespace viscoslide

#endif

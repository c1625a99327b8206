// SPDX-License-Identifier: LGPL-2.1-or-later
// The surface terms of the traction law and the load control, assembled
// into the system, and the law at a surface point.
#include <viscoslide/numerics/mesh.h>
#include <viscoslide/numerics/mpi_gather.h>
#include <viscoslide/surface_coupling.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <map>

namespace viscoslide
{


  template <int dim>
  SurfaceCoupling<dim>::SurfaceCoupling(
    const Parameters::AllParameters &prm,
    const Scales                    &scales,
    const InteractionLaw            &law,
    const Indenter                  &indenter,
    const SurfacePostprocessor<dim> &postprocessor,
    MPI_Comm                         comm)
    : prm(prm)
    , scales(scales)
    , traction_law(law)
    , profile(indenter)
    , postprocessor(postprocessor)
    , comm(comm)
    , quadrature(prm.adhesion.face_quadrature_points)
  {
  }


  template <int dim>
  double
  SurfaceCoupling<dim>::spring_stiffness_of(
    const Parameters::AllParameters &prm,
    const Scales                    &scales)
  {
    return prm.sliding.control == Parameters::Control::spring
             ? prm.sliding.spring_stiffness * scales.force / scales.eps
             : 0.;
  }


  template <int dim>
  void
  SurfaceCoupling<dim>::LocalTerms::reinit(const unsigned int dofs_per_cell)
  {
    coupling.reinit(dofs_per_cell);
    force = stiffness = abs_force = 0.;
  }


  template <int dim>
  void
  SurfaceCoupling<dim>::reinit(const IndexSet &locally_owned_dofs)
  {
    delta_coupling.reinit(locally_owned_dofs, comm);
  }


  template <int dim>
  void
  SurfaceCoupling<dim>::start_assembly()
  {
    if (control.force_controlled)
      delta_coupling = 0;
    force = delta_stiffness = abs_force = 0.;
  }


  template <int dim>
  void
  SurfaceCoupling<dim>::add_face_terms(const FEFaceValuesBase<dim> &face_values,
                                       const VectorType            &solution,
                                       const double                 delta,
                                       const double                 s,
                                       const bool                   with_matrix,
                                       FullMatrix<double>          &cell_matrix,
                                       Vector<double>              &cell_rhs,
                                       LocalTerms                  &local) const
  {
    const FEValuesExtractors::Scalar uy(vertical<dim>);
    const unsigned int               n_q = face_values.n_quadrature_points;
    const unsigned int               n   = face_values.dofs_per_cell;
    std::vector<double>              u_y(n_q), anchor_u_y(n_q), phi_y(n);
    face_values[uy].get_function_values(solution, u_y);
    if (surface_damping > 0)
      face_values[uy].get_function_values(relaxation_anchor, anchor_u_y);
    for (unsigned int q = 0; q < n_q; ++q)
      {
        const auto [p, dp_dg] =
          law_at(face_values.quadrature_point(q), u_y[q], delta, s);
        double       traction  = p;
        double       stiffness = dp_dg;
        const double JxW       = face_values.JxW(q);
        local.abs_force += std::abs(traction) * JxW;
        local.force -= traction * JxW;
        local.stiffness += dp_dg * JxW;
        if (surface_damping > 0)
          {
            traction -= surface_damping * (u_y[q] - anchor_u_y[q]);
            stiffness += surface_damping;
          }
        for (unsigned int i = 0; i < n; ++i)
          phi_y[i] = face_values[uy].value(i, q);
        for (unsigned int i = 0; i < n; ++i)
          {
            cell_rhs(i) += traction * phi_y[i] * JxW;
            local.coupling(i) += dp_dg * phi_y[i] * JxW;
            if (with_matrix)
              for (unsigned int j = 0; j < n; ++j)
                cell_matrix(i, j) += stiffness * phi_y[i] * phi_y[j] * JxW;
          }
      }
  }


  template <int dim>
  void
  SurfaceCoupling<dim>::copy_local_to_global(
    const LocalTerms                           &local,
    const FullMatrix<double>                   &cell_matrix,
    const Vector<double>                       &cell_rhs,
    const std::vector<types::global_dof_index> &dofs,
    const AffineConstraints<double>            &constraints,
    const bool                                  with_matrix,
    TrilinosWrappers::SparseMatrix             &matrix,
    VectorType                                 &rhs)
  {
    if (with_matrix)
      constraints.distribute_local_to_global(
        cell_matrix, cell_rhs, dofs, matrix, rhs);
    else
      constraints.distribute_local_to_global(cell_rhs, dofs, rhs);
    force += local.force;
    delta_stiffness += local.stiffness;
    abs_force += local.abs_force;
    if (control.force_controlled)
      constraints.distribute_local_to_global(local.coupling,
                                             dofs,
                                             delta_coupling);
  }


  template <int dim>
  void
  SurfaceCoupling<dim>::finish_assembly(const double delta,
                                        const bool   with_matrix,
                                        TrilinosWrappers::SparseMatrix &matrix,
                                        VectorType                     &rhs)
  {
    if (with_matrix)
      matrix.compress(VectorOperation::add);
    rhs.compress(VectorOperation::add);
    traction_scale = Utilities::MPI::sum(abs_force, comm);
    if (!control.force_controlled)
      return;
    delta_coupling.compress(VectorOperation::add);
    // Under spring control the force to hold follows delta.
    force_mismatch = control.mismatch(Utilities::MPI::sum(force, comm), delta);
    delta_stiffness =
      Utilities::MPI::sum(delta_stiffness, comm) + control.spring_stiffness;
  }


  template <int dim>
  double
  SurfaceCoupling<dim>::gap_at(const Point<dim> &p,
                               const double      u,
                               const double      delta,
                               const double      s) const
  {
    return gap(profile, scales.eps, delta, s, p, u, prm.geometry.elongation);
  }


  template <int dim>
  std::pair<double, double>
  SurfaceCoupling<dim>::law_at(const Point<dim> &p,
                               const double      u,
                               const double      delta,
                               const double      s) const
  {
    const double g = gap_at(p, u, delta, s);
    return {traction_law.traction(g), traction_law.derivative(g)};
  }


  template <int dim>
  double
  SurfaceCoupling<dim>::tolerance() const
  {
    // One loaded finest cell, so that a contact-free state converges too.
    const double floor = scales.sigma_max * prm.mesh.finest_cell;
    return prm.solver.newton_tolerance * (traction_scale + floor);
  }


  template <int dim>
  void
  SurfaceCoupling<dim>::attach(ReusedFactorization             &solver,
                               const DoFHandler<dim>           &dof_handler,
                               const AffineConstraints<double> &constraints,
                               const VectorType                &solution,
                               const double                    &delta,
                               const double                    &s) const
  {
    solver.reinit(
      surface_unknowns(dof_handler, constraints),
      [&, this] {
        return surface_window(dof_handler, constraints, solution, delta, s);
      },
      [&, this](const std::vector<int> &T) {
        return window_model(dof_handler, constraints, solution, delta, s, T);
      });
  }

  template class SurfaceCoupling<2>;
  template class SurfaceCoupling<3>;
} // namespace viscoslide

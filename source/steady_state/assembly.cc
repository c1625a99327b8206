// SteadyStateSolver: the equations of the steady sliding state, their
// residual and Jacobian, assembled on MeshWorker::mesh_loop (step-12).
#include <deal.II/fe/fe_interface_values.h>
#include <deal.II/fe/fe_values.h>

#include <deal.II/lac/full_matrix.h>

#include <deal.II/meshworker/mesh_loop.h>

#include <viscoslide/mesh.h>
#include <viscoslide/steady_state/solver.h>
#include <viscoslide/steady_state/viscous_strain.h>

namespace viscoslide
{
  using ViscousStrain::components_per_arm;
  using ViscousStrain::first_component;

  // What every cell and face of one assembly shares. Per strain component
  // c of arm k: the arm's relaxation length V tau_k, the advection
  // coefficient of -V tau_k d/dx written as the vector beta = (-V tau_k, 0)
  // of beta . grad, and the row scale E_k (the arm modulus, which makes the
  // strain rows forces).
  struct SteadyStateSolver::AssemblyCoefficients
  {
    std::vector<double>       ell, row_scale;
    SymmetricTensor<4, 2>     C0, C_sum;
    std::vector<unsigned int> component; // of each local dof
    // The local dofs of each strain component.
    std::vector<std::vector<unsigned int>> strain_dofs;
  };


  // FEValues objects and work arrays; copied per thread by mesh_loop.
  struct SteadyStateSolver::AssemblyScratch
  {
    AssemblyScratch(const FiniteElement<2> &fe,
                    const Quadrature<2>    &quadrature,
                    const Quadrature<1>    &top_quadrature,
                    const Quadrature<1>    &flux_quadrature)
      : fe_values(fe,
                  quadrature,
                  update_values | update_gradients | update_JxW_values)
      , top_values(fe, top_quadrature, SurfaceCoupling::face_update_flags())
      , interface_values(fe,
                         flux_quadrature,
                         update_values | update_normal_vectors |
                           update_JxW_values)
      , strain(quadrature.size())
      , projected_strain(quadrature.size())
      , grad_phi_q(quadrature.size())
      , projected_grad_q(quadrature.size())
      , grad_phi(quadrature.size(), fe.n_dofs_per_cell())
      , projected_grad(quadrature.size(), fe.n_dofs_per_cell())
      , e(fe.n_components() - first_component,
          std::vector<double>(quadrature.size()))
      , eps_v(e.size() / components_per_arm)
      , C_arm_i(e.size() / components_per_arm)
    {
    }

    AssemblyScratch(const AssemblyScratch &other)
      : AssemblyScratch(other.fe_values.get_fe(),
                        other.fe_values.get_quadrature(),
                        other.top_values.get_quadrature(),
                        other.interface_values.get_quadrature())
    {
    }

    FEValues<2>                        fe_values;
    FEFaceValues<2>                    top_values;
    FEInterfaceValues<2>               interface_values;
    std::vector<SymmetricTensor<2, 2>> strain, projected_strain, grad_phi_q,
      projected_grad_q;
    Table<2, SymmetricTensor<2, 2>>    grad_phi, projected_grad;
    std::vector<std::vector<double>>   e; // eps_v of each component
    std::vector<SymmetricTensor<2, 2>> eps_v, C_arm_i; // of each arm
  };


  // A cell's rows, and the rows of the faces assembled with it.
  struct SteadyStateSolver::AssemblyCopy
  {
    struct Face
    {
      std::vector<types::global_dof_index> rows, columns;
      FullMatrix<double>                   matrix;
    };

    explicit AssemblyCopy(const unsigned int n)
      : cell_matrix(n, n)
      , cell_rhs(n)
      , dofs(n)
    {
      surface.reinit(n);
    }

    FullMatrix<double>                   cell_matrix;
    Vector<double>                       cell_rhs;
    std::vector<types::global_dof_index> dofs;
    SurfaceCoupling::LocalTerms          surface;
    std::vector<Face>                    faces;
  };


  // Residual -R and, if asked, the Jacobian dR/dx of
  //   R_u(v) = (C0 eps(u) + sum_k C_k (Pi eps(u) - eps_v,k), eps(v))
  //            + (surface terms of SurfaceCoupling)
  //   R_e(w) = E_k [ sum_K ((eps_v - eps(u), w)_K - (eps_v, beta . grad w)_K)
  //            + sum_F <(beta . n) eps_v^upwind, [w]>_F ]
  // for each strain component of each arm k: the upwind DG form of
  // beta . grad eps_v,k + eps_v,k = eps(u), beta = (-V tau_k, 0), as in
  // step-12. eps_v^upwind is the value on the side that beta leaves
  // (beta . n > 0); where material enters the block (x = +W/2) it is 0.
  void
  SteadyStateSolver::assemble(const bool with_matrix)
  {
    TimerOutput::Scope t(timer,
                         with_matrix ? "steady: assemble"
                                     : "steady: assemble residual");
    if (with_matrix)
      {
        system_matrix = 0;
        linear_solver.matrix_changed(V_hat);
      }
    system_rhs = 0;
    coupling.start_assembly();

    AssemblyCoefficients coefficients;
    coefficients.ell.resize(n_strain_components);
    coefficients.row_scale.resize(n_strain_components);
    for (unsigned int c = 0; c < n_strain_components; ++c)
      {
        const unsigned int arm = c / components_per_arm;
        coefficients.ell[c] =
          V_hat * scales.eps / scales.tau_ref * material.relaxation_time(arm);
        coefficients.row_scale[c] = material.arm_modulus(arm);
      }
    coefficients.C0    = material.relaxed_stiffness();
    coefficients.C_sum = material.arm_stiffness(0);
    for (unsigned int a = 1; a < material.n_arms(); ++a)
      coefficients.C_sum += material.arm_stiffness(a);
    coefficients.strain_dofs.resize(n_strain_components);
    for (unsigned int i = 0; i < fe.n_dofs_per_cell(); ++i)
      {
        const unsigned int c = fe.system_to_component_index(i).first;
        coefficients.component.push_back(c);
        if (c >= first_component)
          coefficients.strain_dofs[c - first_component].push_back(i);
      }

    using Iterator = DoFHandler<dim>::active_cell_iterator;
    const auto cell_worker =
      [&](const Iterator &cell, AssemblyScratch &scratch, AssemblyCopy &copy) {
        assemble_cell(cell, coefficients, with_matrix, scratch, copy);
      };
    const auto boundary_worker = [&](const Iterator  &cell,
                                     const unsigned   f,
                                     AssemblyScratch &scratch,
                                     AssemblyCopy    &copy) {
      assemble_boundary(cell, f, coefficients, with_matrix, scratch, copy);
    };
    const auto face_worker = [&](const Iterator  &cell,
                                 const unsigned   f,
                                 const unsigned   sf,
                                 const Iterator  &neighbor,
                                 const unsigned   nf,
                                 const unsigned   nsf,
                                 AssemblyScratch &scratch,
                                 AssemblyCopy    &copy) {
      assemble_interface(
        cell, f, sf, neighbor, nf, nsf, coefficients, scratch, copy);
    };
    const auto copier = [&](const AssemblyCopy &copy) {
      coupling.copy_local_to_global(copy.surface, copy.dofs, constraints);
      if (with_matrix)
        constraints.distribute_local_to_global(copy.cell_matrix,
                                               copy.cell_rhs,
                                               copy.dofs,
                                               system_matrix,
                                               system_rhs);
      else
        constraints.distribute_local_to_global(copy.cell_rhs,
                                               copy.dofs,
                                               system_rhs);
      // The viscous strain is discontinuous and free of constraints, so
      // the flux blocks go to the system directly. The flux is linear in
      // eps_v: its residual is the block times the upwind values.
      Vector<double> upwind_values, rhs;
      for (const auto &face : copy.faces)
        {
          upwind_values.reinit(face.columns.size());
          rhs.reinit(face.rows.size());
          solution.extract_subvector_to(face.columns.begin(),
                                        face.columns.end(),
                                        upwind_values.begin());
          face.matrix.vmult(rhs, upwind_values);
          rhs *= -1.;
          system_rhs.add(face.rows, rhs);
          if (with_matrix)
            system_matrix.add(face.rows, face.columns, face.matrix);
        }
    };

    // Each locally owned cell assembles its own rows only, also on faces
    // with ghost neighbours: every interior face twice, once from each
    // side (assemble_interface() skips the ghost side).
    auto flags =
      MeshWorker::assemble_own_cells | MeshWorker::assemble_boundary_faces;
    if (V_hat > 0.)
      flags |= MeshWorker::assemble_own_interior_faces_both |
               MeshWorker::assemble_ghost_faces_both;
    MeshWorker::mesh_loop(dof_handler.begin_active(),
                          dof_handler.end(),
                          cell_worker,
                          copier,
                          AssemblyScratch(fe,
                                          quadrature,
                                          coupling.face_quadrature(),
                                          flux_quadrature),
                          AssemblyCopy(fe.n_dofs_per_cell()),
                          flags,
                          boundary_worker,
                          face_worker);

    if (with_matrix)
      system_matrix.compress(VectorOperation::add);
    system_rhs.compress(VectorOperation::add);
    coupling.finish_assembly(delta);
  }


  // The bulk: elasticity of the relaxed spring and the arms, and the
  // reaction and advection terms of the viscous strain inside the cell.
  void
  SteadyStateSolver::assemble_cell(
    const DoFHandler<dim>::active_cell_iterator &cell,
    const AssemblyCoefficients                  &coefficients,
    const bool                                   with_matrix,
    AssemblyScratch                             &scratch,
    AssemblyCopy                                &copy) const
  {
    const auto &ell = coefficients.ell, &row_scale = coefficients.row_scale;
    const auto &C0 = coefficients.C0, &C_sum = coefficients.C_sum;
    const auto &component                      = coefficients.component;
    const FEValues<dim>             &fe_values = scratch.fe_values;
    const FEValuesExtractors::Vector displacement(0);
    const unsigned int n = fe.n_dofs_per_cell(), n_q = quadrature.size();
    const unsigned int n_arms           = material.n_arms();
    auto              &strain           = scratch.strain;
    auto              &projected_strain = scratch.projected_strain;
    auto              &grad_phi_q       = scratch.grad_phi_q;
    auto              &projected_grad_q = scratch.projected_grad_q;

    copy.cell_matrix = 0;
    copy.cell_rhs    = 0;
    copy.surface.reinit(n);
    copy.faces.clear();
    cell->get_dof_indices(copy.dofs);
    scratch.fe_values.reinit(cell);
    fe_values[displacement].get_function_symmetric_gradients(solution, strain);
    for (unsigned int c = 0; c < n_strain_components; ++c)
      fe_values[FEValuesExtractors::Scalar(first_component + c)]
        .get_function_values(solution, scratch.e[c]);

    // The arm sees the projection Pi eps(u) (viscous_strain.h).
    const FullMatrix<double> P =
      ViscousStrain::projection(fe_values, strain_basis);
    ViscousStrain::project(P, strain, projected_strain);
    for (unsigned int i = 0; i < n; ++i)
      if (component[i] < first_component)
        {
          for (unsigned int q = 0; q < n_q; ++q)
            grad_phi_q[q] = fe_values[displacement].symmetric_gradient(i, q);
          ViscousStrain::project(P, grad_phi_q, projected_grad_q);
          for (unsigned int q = 0; q < n_q; ++q)
            {
              scratch.grad_phi(q, i)       = grad_phi_q[q];
              scratch.projected_grad(q, i) = projected_grad_q[q];
            }
        }

    auto &eps_v = scratch.eps_v, &C_arm_i = scratch.C_arm_i;
    for (unsigned int q = 0; q < n_q; ++q)
      {
        SymmetricTensor<2, dim> sigma = C0 * strain[q];
        for (unsigned int a = 0; a < n_arms; ++a)
          {
            const auto &e = scratch.e;
            const auto  c = components_per_arm * a;
            eps_v[a] = ViscousStrain::tensor(e[c][q], e[c + 1][q], e[c + 2][q]);
            sigma +=
              material.arm_stiffness(a) * (projected_strain[q] - eps_v[a]);
          }
        const double JxW = fe_values.JxW(q);
        for (unsigned int i = 0; i < n; ++i)
          if (component[i] < first_component)
            {
              const auto &grad_phi_i = scratch.grad_phi(q, i);
              copy.cell_rhs(i) -= sigma * grad_phi_i * JxW;
              if (!with_matrix)
                continue;
              const auto C0_i    = C0 * grad_phi_i;
              const auto C_sum_i = C_sum * grad_phi_i;
              for (unsigned int a = 0; a < n_arms; ++a)
                C_arm_i[a] = material.arm_stiffness(a) * grad_phi_i;
              for (unsigned int j = 0; j < n; ++j)
                if (component[j] < first_component)
                  copy.cell_matrix(i, j) +=
                    (C0_i * scratch.grad_phi(q, j) +
                     C_sum_i * scratch.projected_grad(q, j)) *
                    JxW;
                else
                  {
                    const unsigned int c = component[j] - first_component;
                    copy.cell_matrix(i, j) -=
                      (C_arm_i[c / components_per_arm] *
                       ViscousStrain::unit(c % components_per_arm)) *
                      fe_values.shape_value(j, q) * JxW;
                  }
            }
          else
            {
              const unsigned int c  = component[i] - first_component;
              const unsigned int cc = c % components_per_arm;
              const double       ec =
                ViscousStrain::component(eps_v[c / components_per_arm], cc);
              const double phi_i   = fe_values.shape_value(i, q);
              const double phi_x_i = fe_values.shape_grad(i, q)[0];
              copy.cell_rhs(i) -=
                row_scale[c] *
                (ell[c] * ec * phi_x_i +
                 (ec - ViscousStrain::component(strain[q], cc)) * phi_i) *
                JxW;
              if (with_matrix)
                for (unsigned int j = 0; j < n; ++j)
                  {
                    if (component[j] < first_component)
                      copy.cell_matrix(i, j) -=
                        row_scale[c] *
                        ViscousStrain::component(scratch.grad_phi(q, j), cc) *
                        phi_i * JxW;
                    else if (component[j] == component[i])
                      copy.cell_matrix(i, j) +=
                        row_scale[c] * (ell[c] * phi_x_i + phi_i) *
                        fe_values.shape_value(j, q) * JxW;
                  }
            }
      }
  }


  // The top surface's traction terms, and on the outflow boundary
  // (beta . n > 0, x = -W/2) the outflow flux with the cell's own value.
  // Inflow (x = +W/2) brings eps_v = 0: no term.
  void
  SteadyStateSolver::assemble_boundary(
    const DoFHandler<dim>::active_cell_iterator &cell,
    const unsigned int                           face_no,
    const AssemblyCoefficients                  &coefficients,
    const bool                                   with_matrix,
    AssemblyScratch                             &scratch,
    AssemblyCopy                                &copy) const
  {
    if (cell->face(face_no)->boundary_id() == top_boundary)
      {
        scratch.top_values.reinit(cell, face_no);
        coupling.add_face_terms(scratch.top_values,
                                solution,
                                delta,
                                s,
                                with_matrix,
                                copy.cell_matrix,
                                copy.cell_rhs,
                                copy.surface);
        return;
      }
    if (V_hat == 0.)
      return;
    scratch.interface_values.reinit(cell, face_no);
    const auto         &values = scratch.interface_values.get_fe_face_values(0);
    std::vector<double> e(values.n_quadrature_points);
    for (unsigned int c = 0; c < n_strain_components; ++c)
      {
        const auto &dofs = coefficients.strain_dofs[c];
        values[FEValuesExtractors::Scalar(first_component + c)]
          .get_function_values(solution, e);
        for (unsigned int q = 0; q < values.n_quadrature_points; ++q)
          {
            const double beta_n =
              -coefficients.ell[c] * values.normal_vector(q)[0];
            if (beta_n <= 0)
              continue;
            const double scale =
              coefficients.row_scale[c] * beta_n * values.JxW(q);
            for (const unsigned int i : dofs)
              {
                const double w = values.shape_value(i, q);
                copy.cell_rhs(i) -= scale * e[q] * w;
                if (with_matrix)
                  for (const unsigned int j : dofs)
                    copy.cell_matrix(i, j) +=
                      scale * values.shape_value(j, q) * w;
              }
          }
      }
  }


  // The upwind flux through an interior face, for the rows of `cell`
  // only: a locally owned cell sees each of its faces once, and the face's
  // other side is assembled from the neighbour (mesh_loop's "both" flags).
  // FEInterfaceValues pairs the quadrature points of hanging faces.
  void
  SteadyStateSolver::assemble_interface(
    const DoFHandler<dim>::active_cell_iterator &cell,
    const unsigned int                           face_no,
    const unsigned int                           subface_no,
    const DoFHandler<dim>::active_cell_iterator &neighbor,
    const unsigned int                           neighbor_face_no,
    const unsigned int                           neighbor_subface_no,
    const AssemblyCoefficients                  &coefficients,
    AssemblyScratch                             &scratch,
    AssemblyCopy                                &copy) const
  {
    // Only the rows of a locally owned cell; and beta is horizontal, so a
    // horizontal face carries no flux (checked before the costly reinit).
    const Tensor<1, dim> along =
      cell->face(face_no)->vertex(1) - cell->face(face_no)->vertex(0);
    if (!cell->is_locally_owned() || std::abs(along[0]) > std::abs(along[1]))
      return;
    FEInterfaceValues<dim> &fe_iv = scratch.interface_values;
    fe_iv.reinit(cell,
                 face_no,
                 subface_no,
                 neighbor,
                 neighbor_face_no,
                 neighbor_subface_no);
    // The faces are straight: beta . n has one sign on a face.
    const bool  upwind_is_mine = fe_iv.normal(0)[0] < 0; // beta . n > 0
    const auto &mine           = fe_iv.get_fe_face_values(0);
    const auto &upwind = fe_iv.get_fe_face_values(upwind_is_mine ? 0 : 1);

    // Rows: the strain dofs of `cell`; columns: those of the upwind cell.
    const auto                          &strain_dofs = coefficients.strain_dofs;
    const unsigned int                   m           = strain_dofs[0].size();
    std::vector<types::global_dof_index> mine_dofs(fe.n_dofs_per_cell()),
      upwind_dofs(fe.n_dofs_per_cell());
    cell->get_dof_indices(mine_dofs);
    (upwind_is_mine ? cell : neighbor)->get_dof_indices(upwind_dofs);
    AssemblyCopy::Face face;
    face.matrix.reinit(n_strain_components * m, n_strain_components * m);
    for (unsigned int c = 0; c < n_strain_components; ++c)
      for (const unsigned int i : strain_dofs[c])
        {
          face.rows.push_back(mine_dofs[i]);
          face.columns.push_back(upwind_dofs[i]);
        }

    for (unsigned int q = 0; q < fe_iv.n_quadrature_points; ++q)
      for (unsigned int c = 0; c < n_strain_components; ++c)
        {
          const double beta_n = -coefficients.ell[c] * fe_iv.normal(q)[0];
          const double scale =
            coefficients.row_scale[c] * beta_n * fe_iv.JxW(q);
          for (unsigned int a = 0; a < m; ++a)
            {
              const double w = mine.shape_value(strain_dofs[c][a], q);
              for (unsigned int b = 0; b < m; ++b)
                face.matrix(c * m + a, c * m + b) +=
                  scale * upwind.shape_value(strain_dofs[c][b], q) * w;
            }
        }
    copy.faces.push_back(std::move(face));
  }
} // namespace viscoslide

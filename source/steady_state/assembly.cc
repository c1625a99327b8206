// SPDX-License-Identifier: LGPL-2.1-or-later
// SteadyStateSolver: the equations of the steady sliding state, their
// residual and Jacobian, assembled on MeshWorker::mesh_loop (step-12).
#include <deal.II/fe/fe_interface_values.h>
#include <deal.II/fe/fe_values.h>
#include <deal.II/grid/filtered_iterator.h>

#include <deal.II/lac/full_matrix.h>

#include <deal.II/meshworker/mesh_loop.h>

#include <viscoslide/numerics/mesh.h>
#include <viscoslide/steady_state/solver.h>
#include <viscoslide/steady_state/viscous_strain.h>

#include <array>
#include <cmath>
#include <map>

namespace viscoslide
{
  using ViscousStrain::components_per_arm;
  using ViscousStrain::first_component;

  namespace
  {
    // The number of values that describe a cell's shape: the offsets of
    // its vertices from the first.
    template <int dim>
    constexpr unsigned int
      shape_size = (GeometryInfo<dim>::vertices_per_cell - 1) * dim;
  } // namespace

  // What every cell and face of one assembly shares. Per strain component
  // c of arm k: the arm's relaxation length V tau_k, the advection
  // coefficient of -V tau_k d/dx written as the vector beta = (-V tau_k, 0)
  // of beta . grad, and the row scale E_k (the arm modulus, which makes the
  // strain rows forces).
  template <int dim>
  struct SteadyStateSolver<dim>::AssemblyCoefficients
  {
    std::vector<double>                  ell, row_scale;
    SymmetricTensor<4, dim>              C0, C_sum;
    std::vector<SymmetricTensor<4, dim>> C_arm;
    std::vector<unsigned int>            component; // of each local dof
    // The local dofs of each strain component.
    std::vector<std::vector<unsigned int>> strain_dofs;
    // The resolution of a cell's shape (see AssemblyScratch).
    double shape_quantum;
  };


  namespace
  {
    // The offsets of a cell's vertices from its first, in units of the
    // shape quantum: equal for two cells of one shape.
    template <int dim, typename Iterator, typename Coefficients>
    std::array<long long, shape_size<dim>>
    shape_of(const Iterator &cell, const Coefficients &coefficients)
    {
      std::array<long long, shape_size<dim>> shape;
      for (unsigned int v = 1; v < GeometryInfo<dim>::vertices_per_cell; ++v)
        for (unsigned int d = 0; d < dim; ++d)
          shape[dim * (v - 1) + d] =
            std::llround((cell->vertex(v)[d] - cell->vertex(0)[d]) /
                         coefficients.shape_quantum);
      return shape;
    }
  } // namespace


  // FEValues objects and work arrays; copied per thread by mesh_loop.
  template <int dim>
  struct SteadyStateSolver<dim>::AssemblyScratch
  {
    AssemblyScratch(const FiniteElement<dim>  &fe,
                    const Quadrature<dim>     &quadrature,
                    const Quadrature<dim - 1> &flux_quadrature)
      : fe_values(fe,
                  quadrature,
                  update_values | update_gradients | update_JxW_values)
      , interface_values(fe,
                         flux_quadrature,
                         update_values | update_gradients |
                           update_normal_vectors | update_JxW_values)
      , grad_phi_q(quadrature.size())
      , projected_grad_q(quadrature.size())
      , grad_phi(quadrature.size(), fe.n_dofs_per_cell())
      , projected_grad(quadrature.size(), fe.n_dofs_per_cell())
      , C_arm_i((fe.n_components() - ViscousStrain::first_component<dim>) /
                ViscousStrain::components_per_arm<dim>)
    {
    }

    AssemblyScratch(const AssemblyScratch &other)
      : AssemblyScratch(other.fe_values.get_fe(),
                        other.fe_values.get_quadrature(),
                        other.interface_values.get_quadrature())
    {
    }

    // The cell matrices by cell shape: the bulk operator is the same in
    // every cell of one shape (a homogeneous solid and a constant speed),
    // and the graded mesh has few shapes among its thousands of cells. A
    // shape is the offsets of its vertices from the first, in units of
    // shape_quantum.
    std::map<std::array<long long, shape_size<dim>>, FullMatrix<double>>
      matrix_of_shape;
    // The same for the flux blocks of interior faces, by the shapes of the
    // two cells, their offset and the face numbers.
    struct FaceBlock
    {
      bool               upwind_is_mine = false;
      FullMatrix<double> matrix;
    };
    static constexpr unsigned int pair_size = 2 * shape_size<dim> + dim + 4;
    std::map<std::array<long long, pair_size>, FaceBlock> block_of_pair;
    FEValues<dim>                                         fe_values;
    FEInterfaceValues<dim>                                interface_values;
    std::vector<SymmetricTensor<2, dim>> grad_phi_q, projected_grad_q;
    Table<2, SymmetricTensor<2, dim>>    grad_phi, projected_grad;
    std::vector<SymmetricTensor<2, dim>> C_arm_i; // of each arm
  };


  // A cell's matrix, and the blocks of the faces assembled with it.
  template <int dim>
  struct SteadyStateSolver<dim>::AssemblyCopy
  {
    struct Face
    {
      std::vector<types::global_dof_index> rows, columns;
      FullMatrix<double>                   matrix;
    };

    explicit AssemblyCopy(const unsigned int n)
      : cell_matrix(n, n)
      , dofs(n)
    {
    }

    FullMatrix<double>                   cell_matrix;
    std::vector<types::global_dof_index> dofs;
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
  // (beta . n > 0); where material enters the block (x = +W/2) it is 0 in
  // 2D and the relaxed strain eps(u) in 3D (assemble_boundary).
  // All but the surface terms are linear in the unknowns: their matrix A is
  // assembled once per speed and mesh (assemble_bulk), their residual is
  // -A x, and each Newton iteration assembles the surface alone.
  template <int dim>
  void
  SteadyStateSolver<dim>::assemble(const bool with_matrix)
  {
    if (bulk_speed != V_hat)
      assemble_bulk();
    TimerOutput::Scope t(timer,
                         with_matrix ? "steady: assemble"
                                     : "steady: assemble residual");
    if (with_matrix)
      {
        linear_solver.load_bulk(bulk_matrix, system_matrix, V_hat);
        iterative_solver.matrix_changed(V_hat,
                                        V_hat *
                                          material.longest_relaxation_time() /
                                          prm.mesh.finest_cell);
      }
    TrilinosWrappers::MPI::Vector x(locally_owned_dofs, mpi_communicator);
    x = solution;
    bulk_matrix.vmult(system_rhs, x);
    system_rhs *= -1.;
    constraints.set_zero(system_rhs);

    coupling.start_assembly();
    FEFaceValues<dim>                         top_values(fe,
                                 coupling.face_quadrature(),
                                 SurfaceCoupling<dim>::face_update_flags());
    const unsigned int                        n = fe.n_dofs_per_cell();
    FullMatrix<double>                        cell_matrix(n, n);
    Vector<double>                            cell_rhs(n);
    typename SurfaceCoupling<dim>::LocalTerms surface;
    std::vector<types::global_dof_index>      dofs(n);
    for (const auto &cell : dof_handler.active_cell_iterators())
      if (cell->is_locally_owned() && cell->at_boundary())
        for (const unsigned int f : cell->face_indices())
          if (is_top_face(cell, f))
            {
              cell_matrix = 0;
              cell_rhs    = 0;
              surface.reinit(n);
              top_values.reinit(cell, f);
              coupling.add_face_terms(top_values,
                                      solution,
                                      delta,
                                      s,
                                      with_matrix,
                                      cell_matrix,
                                      cell_rhs,
                                      surface);
              cell->get_dof_indices(dofs);
              coupling.copy_local_to_global(surface,
                                            cell_matrix,
                                            cell_rhs,
                                            dofs,
                                            constraints,
                                            with_matrix,
                                            system_matrix,
                                            system_rhs);
            }
    coupling.finish_assembly(delta, with_matrix, system_matrix, system_rhs);
  }


  // The coefficients of the bulk at the present speed: each strain
  // component's relaxation length and row scale, the stiffnesses, and
  // which shape functions belong to which component.
  template <int dim>
  typename SteadyStateSolver<dim>::AssemblyCoefficients
  SteadyStateSolver<dim>::assembly_coefficients() const
  {
    AssemblyCoefficients coefficients;
    coefficients.ell.resize(n_strain_components);
    coefficients.row_scale.resize(n_strain_components);
    for (unsigned int c = 0; c < n_strain_components; ++c)
      {
        const unsigned int arm = c / components_per_arm<dim>;
        coefficients.ell[c] =
          V_hat * scales.eps / scales.tau_ref * material.relaxation_time(arm);
        coefficients.row_scale[c] = material.arm_modulus(arm);
      }
    // A ten-billionth of the finest cell: the vertices' rounding is far
    // below it, a change of shape that matters far above it.
    coefficients.shape_quantum = 1e-10 * prm.mesh.finest_cell;
    coefficients.C0            = material.relaxed_stiffness_of<dim>();
    for (unsigned int a = 0; a < material.n_arms(); ++a)
      coefficients.C_arm.push_back(material.arm_stiffness_of<dim>(a));
    coefficients.C_sum = coefficients.C_arm[0];
    for (unsigned int a = 1; a < material.n_arms(); ++a)
      coefficients.C_sum += coefficients.C_arm[a];
    coefficients.strain_dofs.resize(n_strain_components);
    for (unsigned int i = 0; i < fe.n_dofs_per_cell(); ++i)
      {
        const unsigned int c = fe.system_to_component_index(i).first;
        coefficients.component.push_back(c);
        if (c >= first_component<dim>)
          coefficients.strain_dofs[c - first_component<dim>].push_back(i);
      }

    return coefficients;
  }


  // The matrix of the linear terms at the present speed, on MeshWorker's
  // mesh_loop: cells, the upwind fluxes of the interior faces, the outflow
  // boundary.
  template <int dim>
  void
  SteadyStateSolver<dim>::assemble_bulk()
  {
    TimerOutput::Scope t(timer, "steady: assemble bulk");
    bulk_matrix = 0;

    const AssemblyCoefficients coefficients = assembly_coefficients();

    using Iterator = CellIterator;
    const auto cell_worker =
      [&](const Iterator &cell, AssemblyScratch &scratch, AssemblyCopy &copy) {
        assemble_cell(cell, coefficients, scratch, copy);
      };
    const auto boundary_worker = [&](const Iterator  &cell,
                                     const unsigned   f,
                                     AssemblyScratch &scratch,
                                     AssemblyCopy    &copy) {
      assemble_boundary(cell, f, coefficients, scratch, copy);
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
    // The viscous strain is discontinuous and free of constraints, so the
    // flux blocks go to the matrix directly.
    const auto copier = [&](const AssemblyCopy &copy) {
      constraints.distribute_local_to_global(copy.cell_matrix,
                                             copy.dofs,
                                             bulk_matrix);
      for (const auto &face : copy.faces)
        bulk_matrix.add(face.rows, face.columns, face.matrix);
    };

    // Each locally owned cell assembles its own rows only, also on faces
    // with ghost neighbours: every interior face twice, once from each
    // side.
    auto flags =
      MeshWorker::assemble_own_cells | MeshWorker::assemble_boundary_faces;
    if (V_hat > 0.)
      flags |= MeshWorker::assemble_own_interior_faces_both |
               MeshWorker::assemble_ghost_faces_both;
    // Over the locally owned cells only: mesh_loop calls the copier after
    // every cell it visits, and on a ghost or artificial cell, where no
    // worker runs, it would add the previous cell's matrix once more.
    MeshWorker::mesh_loop(filter_iterators(dof_handler.active_cell_iterators(),
                                           IteratorFilters::LocallyOwnedCell()),
                          cell_worker,
                          copier,
                          AssemblyScratch(fe, quadrature, flux_quadrature),
                          AssemblyCopy(fe.n_dofs_per_cell()),
                          flags,
                          boundary_worker,
                          face_worker);
    bulk_matrix.compress(VectorOperation::add);
    bulk_speed = V_hat;
  }


  // eps(phi_i) and the projection Pi eps(phi_i) that the arm sees
  // (viscous_strain.h) at each quadrature point of the cell scratch's
  // FEValues was reinitialized on, for the displacement shape functions.
  template <int dim>
  void
  SteadyStateSolver<dim>::strain_gradients(
    const AssemblyCoefficients &coefficients,
    AssemblyScratch            &scratch) const
  {
    const FEValues<dim>             &fe_values = scratch.fe_values;
    const FEValuesExtractors::Vector displacement(0);
    const unsigned int               n_q        = quadrature.size();
    auto                            &grad_phi_q = scratch.grad_phi_q;
    auto                    &projected_grad_q   = scratch.projected_grad_q;
    const FullMatrix<double> P =
      ViscousStrain::projection(fe_values, strain_basis);
    for (unsigned int i = 0; i < fe.n_dofs_per_cell(); ++i)
      if (coefficients.component[i] < first_component<dim>)
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
  }


  // The bulk: elasticity of the relaxed spring and the arms, and the
  // reaction and advection terms of the viscous strain inside the cell.
  template <int dim>
  void
  SteadyStateSolver<dim>::assemble_cell(
    const CellIterator         &cell,
    const AssemblyCoefficients &coefficients,
    AssemblyScratch            &scratch,
    AssemblyCopy               &copy) const
  {
    const auto &ell = coefficients.ell, &row_scale = coefficients.row_scale;
    const auto &C0 = coefficients.C0, &C_sum = coefficients.C_sum;
    const auto &component                      = coefficients.component;
    const FEValues<dim>             &fe_values = scratch.fe_values;
    const FEValuesExtractors::Vector displacement(0);
    const unsigned int n = fe.n_dofs_per_cell(), n_q = quadrature.size();
    const unsigned int n_arms = material.n_arms();

    copy.faces.clear();
    cell->get_dof_indices(copy.dofs);
    const auto shape = shape_of<dim>(cell, coefficients);
    if (const auto known = scratch.matrix_of_shape.find(shape);
        known != scratch.matrix_of_shape.end())
      {
        copy.cell_matrix = known->second;
        return;
      }
    copy.cell_matrix = 0;
    scratch.fe_values.reinit(cell);
    strain_gradients(coefficients, scratch);

    auto &C_arm_i = scratch.C_arm_i;
    for (unsigned int q = 0; q < n_q; ++q)
      {
        const double JxW = fe_values.JxW(q);
        for (unsigned int i = 0; i < n; ++i)
          if (component[i] < first_component<dim>)
            {
              const auto &grad_phi_i = scratch.grad_phi(q, i);
              const auto  C0_i       = C0 * grad_phi_i;
              const auto  C_sum_i    = C_sum * grad_phi_i;
              for (unsigned int a = 0; a < n_arms; ++a)
                C_arm_i[a] = coefficients.C_arm[a] * grad_phi_i;
              for (unsigned int j = 0; j < n; ++j)
                if (component[j] < first_component<dim>)
                  copy.cell_matrix(i, j) +=
                    (C0_i * scratch.grad_phi(q, j) +
                     C_sum_i * scratch.projected_grad(q, j)) *
                    JxW;
                else
                  {
                    const unsigned int c = component[j] - first_component<dim>;
                    copy.cell_matrix(i, j) -=
                      (C_arm_i[c / components_per_arm<dim>] *
                       ViscousStrain::unit<dim>(c % components_per_arm<dim>)) *
                      fe_values.shape_value(j, q) * JxW;
                  }
            }
          else
            {
              const unsigned int c       = component[i] - first_component<dim>;
              const unsigned int cc      = c % components_per_arm<dim>;
              const double       phi_i   = fe_values.shape_value(i, q);
              const double       phi_x_i = fe_values.shape_grad(i, q)[0];
              for (unsigned int j = 0; j < n; ++j)
                if (component[j] < first_component<dim>)
                  copy.cell_matrix(i, j) -=
                    row_scale[c] *
                    ViscousStrain::component(scratch.grad_phi(q, j), cc) *
                    phi_i * JxW;
                else if (component[j] == component[i])
                  copy.cell_matrix(i, j) += row_scale[c] *
                                            (ell[c] * phi_x_i + phi_i) *
                                            fe_values.shape_value(j, q) * JxW;
            }
      }
    scratch.matrix_of_shape.emplace(shape, copy.cell_matrix);
  }


  // On the outflow boundary (beta . n > 0, x = -W/2) the outflow flux with
  // the cell's own value. Inflow (x = +W/2): in 2D eps_v = 0, the state far
  // upstream, which the wide block's inflow face (some 100 contact widths
  // away) nearly carries: no term. In 3D the block is a deep column whose
  // free sides leave it compressed by the load uniformly along x; material
  // entering it has relaxed to that, eps_v = eps(u). (eps_v = 0 there left
  // the compression to relax inside the column, a dissipation that grows
  // with its depth: it doubled the friction at V_hat 10 on a column 200 eps
  // wide and 10 000 deep.) The top surface is SurfaceCoupling's
  // (assemble()).
  template <int dim>
  void
  SteadyStateSolver<dim>::assemble_boundary(
    const CellIterator         &cell,
    const unsigned int          face_no,
    const AssemblyCoefficients &coefficients,
    AssemblyScratch            &scratch,
    AssemblyCopy               &copy) const
  {
    if (V_hat == 0. || is_top_face(cell, face_no))
      return;
    scratch.interface_values.reinit(cell, face_no);
    const auto &values = scratch.interface_values.get_fe_face_values(0);
    const FEValuesExtractors::Vector displacement(0);
    for (unsigned int c = 0; c < n_strain_components; ++c)
      {
        const auto &dofs = coefficients.strain_dofs[c];
        for (unsigned int q = 0; q < values.n_quadrature_points; ++q)
          {
            const double beta_n =
              -coefficients.ell[c] * values.normal_vector(q)[0];
            const double scale =
              coefficients.row_scale[c] * beta_n * values.JxW(q);
            if (beta_n > 0)
              for (const unsigned int i : dofs)
                for (const unsigned int j : dofs)
                  copy.cell_matrix(i, j) +=
                    scale * values.shape_value(j, q) * values.shape_value(i, q);
            else if (beta_n < 0 && dim == 3)
              for (const unsigned int i : dofs)
                for (unsigned int j = 0; j < fe.n_dofs_per_cell(); ++j)
                  if (coefficients.component[j] < first_component<dim>)
                    copy.cell_matrix(i, j) +=
                      scale *
                      ViscousStrain::component(
                        values[displacement].symmetric_gradient(j, q),
                        c % components_per_arm<dim>) *
                      values.shape_value(i, q);
          }
      }
  }


  // The upwind flux through an interior face, for the rows of `cell`
  // only: a locally owned cell sees each of its faces once, and the face's
  // other side is assembled from the neighbour (mesh_loop's "both" flags).
  // FEInterfaceValues pairs the quadrature points of hanging faces.
  template <int dim>
  void
  SteadyStateSolver<dim>::assemble_interface(
    const CellIterator         &cell,
    const unsigned int          face_no,
    const unsigned int          subface_no,
    const CellIterator         &neighbor,
    const unsigned int          neighbor_face_no,
    const unsigned int          neighbor_subface_no,
    const AssemblyCoefficients &coefficients,
    AssemblyScratch            &scratch,
    AssemblyCopy               &copy) const
  {
    // mesh_loop visits the locally owned cells only (assemble_bulk).
    if (!carries_flux(cell, face_no))
      return;
    // The block depends on the pair's geometry alone (see
    // AssemblyScratch::matrix_of_shape).
    constexpr unsigned int n          = shape_size<dim>;
    const auto             mine_shape = shape_of<dim>(cell, coefficients);
    const auto             other      = shape_of<dim>(neighbor, coefficients);
    std::array<long long, AssemblyScratch::pair_size> pair;
    std::copy(mine_shape.begin(), mine_shape.end(), pair.begin());
    std::copy(other.begin(), other.end(), pair.begin() + n);
    for (unsigned int d = 0; d < dim; ++d)
      pair[2 * n + d] =
        std::llround((neighbor->vertex(0)[d] - cell->vertex(0)[d]) /
                     coefficients.shape_quantum);
    pair[2 * n + dim]          = face_no;
    pair[2 * n + dim + 1]      = subface_no;
    pair[2 * n + dim + 2]      = neighbor_face_no;
    pair[2 * n + dim + 3]      = neighbor_subface_no;
    const auto &strain_dofs    = coefficients.strain_dofs;
    const auto [known, is_new] = scratch.block_of_pair.try_emplace(pair);
    auto &block                = known->second;
    if (is_new)
      {
        scratch.interface_values.reinit(cell,
                                        face_no,
                                        subface_no,
                                        neighbor,
                                        neighbor_face_no,
                                        neighbor_subface_no);
        face_block(scratch.interface_values,
                   coefficients,
                   block.upwind_is_mine,
                   block.matrix);
      }

    // Rows: the strain dofs of `cell`; columns: those of the upwind cell.
    std::vector<types::global_dof_index> mine_dofs(fe.n_dofs_per_cell()),
      upwind_dofs(fe.n_dofs_per_cell());
    cell->get_dof_indices(mine_dofs);
    (block.upwind_is_mine ? cell : neighbor)->get_dof_indices(upwind_dofs);
    typename AssemblyCopy::Face face;
    for (unsigned int c = 0; c < n_strain_components; ++c)
      for (const unsigned int i : strain_dofs[c])
        {
          face.rows.push_back(mine_dofs[i]);
          face.columns.push_back(upwind_dofs[i]);
        }
    face.matrix = block.matrix;
    copy.faces.push_back(std::move(face));
  }


  template <int dim>
  void
  SteadyStateSolver<dim>::face_block(const FEInterfaceValues<dim> &fe_iv,
                                     const AssemblyCoefficients   &coefficients,
                                     bool               &upwind_is_mine,
                                     FullMatrix<double> &matrix) const
  {
    // The faces are straight: beta . n has one sign on a face.
    upwind_is_mine          = fe_iv.normal(0)[0] < 0; // beta . n > 0
    const auto &mine        = fe_iv.get_fe_face_values(0);
    const auto &upwind      = fe_iv.get_fe_face_values(upwind_is_mine ? 0 : 1);
    const auto &strain_dofs = coefficients.strain_dofs;
    const unsigned int m    = strain_dofs[0].size();
    matrix.reinit(n_strain_components * m, n_strain_components * m);
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
                matrix(c * m + a, c * m + b) +=
                  scale * upwind.shape_value(strain_dofs[c][b], q) * w;
            }
        }
  }


  template class SteadyStateSolver<2>;
  template class SteadyStateSolver<3>;
} // namespace viscoslide

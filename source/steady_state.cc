#include <deal.II/base/utilities.h>

#include <deal.II/distributed/solution_transfer.h>

#include <deal.II/dofs/dof_tools.h>

#include <deal.II/fe/fe_dgq.h>
#include <deal.II/fe/fe_q.h>
#include <deal.II/fe/fe_values.h>

#include <deal.II/lac/dynamic_sparsity_pattern.h>
#include <deal.II/lac/full_matrix.h>
#include <deal.II/lac/solver_control.h>
#include <deal.II/lac/solver_gmres.h>
#include <deal.II/lac/sparsity_tools.h>

#include <deal.II/numerics/data_out.h>
#include <deal.II/numerics/data_postprocessor.h>
#include <deal.II/numerics/vector_tools.h>

#include <viscoslide/mesh.h>
#include <viscoslide/newton.h>
#include <viscoslide/steady_state.h>

#include <cmath>
#include <iomanip>
#include <sstream>

namespace viscoslide
{
  namespace
  {
    // FESystem components: displacement, then the viscous strain of each
    // Maxwell arm (xx, yy, xy of arm k at 2 + 3 k ... 4 + 3 k).
    constexpr unsigned int first_strain_component = 2;
    constexpr unsigned int components_per_arm     = 3;

    // Strain component c (xx, yy, xy) of a symmetric tensor.
    double
    strain_component(const SymmetricTensor<2, 2> &t, const unsigned int c)
    {
      return c == 0 ? t[0][0] : (c == 1 ? t[1][1] : t[0][1]);
    }

    SymmetricTensor<2, 2>
    unit_strain(const unsigned int c)
    {
      SymmetricTensor<2, 2> t;
      if (c == 2)
        t[0][1] = 1.;
      else
        t[c][c] = 1.;
      return t;
    }

    SymmetricTensor<2, 2>
    strain_tensor(const double xx, const double yy, const double xy)
    {
      SymmetricTensor<2, 2> t;
      t[0][0] = xx;
      t[1][1] = yy;
      t[0][1] = xy;
      return t;
    }

    // The L2 projection onto the viscous-strain space of a cell, acting on
    // values at the quadrature points: (Pi f)(q) = sum_q' P(q, q') f(q'),
    // basis = the local dofs of one strain component. The arm sees
    // Pi eps(u), the part of the strain that eps_v can represent: then
    // eps_v = Pi eps(u) is exactly the relaxed state, and a degree below 2
    // (which cannot hold the strain of Q2) adds no spurious arm stress.
    FullMatrix<double>
    strain_projection(const FEValues<2>               &fe_values,
                      const std::vector<unsigned int> &basis)
    {
      const unsigned int n_q = fe_values.n_quadrature_points, m = basis.size();
      FullMatrix<double> mass(m, m), P(n_q, n_q);
      for (unsigned int a = 0; a < m; ++a)
        for (unsigned int b = 0; b < m; ++b)
          for (unsigned int q = 0; q < n_q; ++q)
            mass(a, b) += fe_values.shape_value(basis[a], q) *
                          fe_values.shape_value(basis[b], q) * fe_values.JxW(q);
      mass.gauss_jordan();
      for (unsigned int q = 0; q < n_q; ++q)
        for (unsigned int r = 0; r < n_q; ++r)
          {
            double sum = 0.;
            for (unsigned int a = 0; a < m; ++a)
              for (unsigned int b = 0; b < m; ++b)
                sum += fe_values.shape_value(basis[a], q) * mass(a, b) *
                       fe_values.shape_value(basis[b], r);
            P(q, r) = sum * fe_values.JxW(r);
          }
      return P;
    }

    template <typename T>
    void
    project(const FullMatrix<double> &P,
            const std::vector<T>     &f,
            std::vector<T>           &pf)
    {
      for (unsigned int q = 0; q < P.m(); ++q)
        {
          pf[q] = T();
          for (unsigned int r = 0; r < P.n(); ++r)
            pf[q] += P(q, r) * f[r];
        }
    }

    // Viscous strain of one arm from the values of all components.
    SymmetricTensor<2, 2>
    viscous_strain(const Vector<double> &v, const unsigned int arm)
    {
      const unsigned int c = first_strain_component + components_per_arm * arm;
      return strain_tensor(v[c], v[c + 1], v[c + 2]);
    }

    // Stress and dissipation density from u and eps_v, for DataOut. They
    // use eps(u), not its projection: exact for degree 2.
    class SteadyFields : public DataPostprocessor<2>
    {
    public:
      explicit SteadyFields(const ViscoelasticSolid &material)
        : material(material)
      {
      }

      void
      evaluate_vector_field(
        const DataPostprocessorInputs::Vector<2> &inputs,
        std::vector<Vector<double>>              &computed) const override
      {
        for (unsigned int q = 0; q < inputs.solution_values.size(); ++q)
          {
            const auto &v = inputs.solution_values[q];
            const auto &g = inputs.solution_gradients[q];
            const auto  strain =
              strain_tensor(g[0][0], g[1][1], 0.5 * (g[0][1] + g[1][0]));
            ArmStress h;
            double    rate = 0.;
            for (unsigned int k = 0; k < material.n_arms(); ++k)
              {
                const auto h_k =
                  material.arm_stress(k, strain - viscous_strain(v, k));
                h += h_k;
                rate += material.dissipation_rate(k, h_k);
              }
            const auto sigma = material.stress(strain, h);
            computed[q](0)   = sigma[0][0];
            computed[q](1)   = sigma[1][1];
            computed[q](2)   = sigma[0][1];
            computed[q](3)   = material.stress_zz(strain, h);
            computed[q](4)   = rate;
          }
      }

      std::vector<std::string>
      get_names() const override
      {
        return {"stress_xx",
                "stress_yy",
                "stress_xy",
                "stress_zz",
                "dissipation_rate"};
      }

      UpdateFlags
      get_needed_update_flags() const override
      {
        return update_values | update_gradients;
      }

    private:
      const ViscoelasticSolid &material;
    };
  } // namespace


  SteadyStateSolver::SteadyStateSolver(
    const Parameters::AllParameters         &prm,
    const Scales                            &scales,
    const ViscoelasticSolid                 &material,
    const InteractionLaw                    &law,
    const Indenter                          &indenter,
    const SurfacePostprocessor              &postprocessor,
    parallel::distributed::Triangulation<2> &triangulation,
    TimerOutput                             &timer)
    : prm(prm)
    , scales(scales)
    , material(material)
    , law(law)
    , indenter(indenter)
    , postprocessor(postprocessor)
    , triangulation(triangulation)
    , timer(timer)
    , mpi_communicator(triangulation.get_communicator())
    , pcout(std::cout,
            dealii::Utilities::MPI::this_mpi_process(mpi_communicator) == 0)
    , n_strain_components(components_per_arm * material.n_arms())
    , fe(FE_Q<dim>(2),
         dim,
         FE_DGQ<dim>(prm.sliding.viscous_strain_degree),
         n_strain_components)
    , dof_handler(triangulation)
    , quadrature(std::max(3, prm.sliding.viscous_strain_degree + 2))
    , face_quadrature(prm.adhesion.face_quadrature_points)
    , flux_quadrature(std::max(3, prm.sliding.viscous_strain_degree + 2))
  {
    for (unsigned int i = 0; i < fe.n_dofs_per_cell(); ++i)
      if (fe.system_to_component_index(i).first == first_strain_component)
        strain_basis.push_back(i);
  }


  SteadyStateSolver::~SteadyStateSolver() = default;


  void
  SteadyStateSolver::setup_system()
  {
    TimerOutput::Scope t(timer, "steady: setup");
    dof_handler.distribute_dofs(fe);
    locally_owned_dofs = dof_handler.locally_owned_dofs();
    DoFTools::extract_locally_relevant_dofs(dof_handler, locally_relevant_dofs);

    constraints.clear();
    constraints.reinit(locally_relevant_dofs);
    DoFTools::make_hanging_node_constraints(dof_handler, constraints);
    VectorTools::interpolate_boundary_values(
      dof_handler,
      bottom_boundary,
      Functions::ZeroFunction<dim>(fe.n_components()),
      constraints,
      fe.component_mask(FEValuesExtractors::Vector(0)));
    constraints.close();

    // Everything couples inside a cell; across faces only the upwind flux
    // of each viscous-strain component.
    const unsigned int           n_c = fe.n_components();
    Table<2, DoFTools::Coupling> cell_coupling(n_c, n_c),
      face_coupling(n_c, n_c);
    for (unsigned int c = 0; c < n_c; ++c)
      for (unsigned int d = 0; d < n_c; ++d)
        {
          cell_coupling(c, d) = DoFTools::always;
          face_coupling(c, d) = (c == d && c >= first_strain_component)
                                  ? DoFTools::always
                                  : DoFTools::none;
        }
    DynamicSparsityPattern dsp(locally_relevant_dofs);
    DoFTools::make_flux_sparsity_pattern(
      dof_handler,
      dsp,
      constraints,
      false,
      cell_coupling,
      face_coupling,
      dealii::Utilities::MPI::this_mpi_process(mpi_communicator));
    SparsityTools::distribute_sparsity_pattern(dsp,
                                               locally_owned_dofs,
                                               mpi_communicator,
                                               locally_relevant_dofs);
    direct_solver.reset(); // it refers to the old matrix
    system_matrix.reinit(locally_owned_dofs,
                         locally_owned_dofs,
                         dsp,
                         mpi_communicator);
    solution.reinit(locally_owned_dofs,
                    locally_relevant_dofs,
                    mpi_communicator);
    system_rhs.reinit(locally_owned_dofs, mpi_communicator);
    newton_update.reinit(system_rhs);
    delta_coupling.reinit(system_rhs);
  }


  // u is copied dof by dof (same Q2 element); eps_v is the cell-wise L2
  // projection of eps(u), the relaxed state (V = 0) of the viscous strain.
  void
  SteadyStateSolver::initialize(const DoFHandler<dim>               &u_dofs,
                                const TrilinosWrappers::MPI::Vector &u,
                                const double                         delta,
                                const double                         s)
  {
    setup_system();
    this->delta = delta;
    this->s     = s;
    V_hat       = 0.;

    const FiniteElement<dim> &u_fe = u_dofs.get_fe();
    FEValues<dim> values(fe, quadrature, update_values | update_JxW_values);
    FEValues<dim> u_values(u_fe, quadrature, update_gradients);
    const FEValuesExtractors::Vector displacement(0);

    const unsigned int n = fe.n_dofs_per_cell(), n_q = quadrature.size();
    std::vector<types::global_dof_index> dofs(n);
    Vector<double>                       u_local(u_fe.n_dofs_per_cell());
    std::vector<SymmetricTensor<2, dim>> strain(n_q);
    // The DG dofs of one component, and their local mass matrix.
    std::vector<std::vector<unsigned int>> strain_dofs(n_strain_components);
    for (unsigned int i = 0; i < n; ++i)
      if (const unsigned int c = fe.system_to_component_index(i).first;
          c >= first_strain_component)
        strain_dofs[c - first_strain_component].push_back(i);
    const unsigned int m = strain_dofs[0].size();
    FullMatrix<double> mass(m, m);
    Vector<double>     rhs(m), coefficients(m);

    TrilinosWrappers::MPI::Vector x(locally_owned_dofs, mpi_communicator);
    for (const auto &cell : dof_handler.active_cell_iterators())
      if (cell->is_locally_owned())
        {
          const DoFHandler<dim>::active_cell_iterator u_cell(&triangulation,
                                                             cell->level(),
                                                             cell->index(),
                                                             &u_dofs);
          values.reinit(cell);
          u_values.reinit(u_cell);
          u_cell->get_dof_values(u, u_local);
          u_values[displacement].get_function_symmetric_gradients(u, strain);
          cell->get_dof_indices(dofs);

          for (unsigned int i = 0; i < n; ++i)
            {
              const auto [base, k] = fe.system_to_base_index(i);
              if (base.first == 0 && locally_owned_dofs.is_element(dofs[i]))
                x(dofs[i]) =
                  u_local(u_fe.component_to_system_index(base.second, k));
            }
          for (unsigned int c = 0; c < n_strain_components; ++c)
            {
              mass          = 0;
              rhs           = 0;
              const auto &d = strain_dofs[c];
              for (unsigned int q = 0; q < n_q; ++q)
                for (unsigned int a = 0; a < m; ++a)
                  {
                    const double wa = values.shape_value(d[a], q);
                    rhs(a) +=
                      strain_component(strain[q], c % components_per_arm) * wa *
                      values.JxW(q);
                    for (unsigned int b = 0; b < m; ++b)
                      mass(a, b) +=
                        wa * values.shape_value(d[b], q) * values.JxW(q);
                  }
              mass.gauss_jordan();
              mass.vmult(coefficients, rhs);
              for (unsigned int a = 0; a < m; ++a)
                x(dofs[d[a]]) = coefficients(a);
            }
        }
    x.compress(VectorOperation::insert);
    constraints.distribute(x);
    solution = x;
    update_quantities();
  }


  void
  SteadyStateSolver::hold_force(const double normal_force, const double spring)
  {
    force_control    = true;
    target_force     = normal_force;
    spring_stiffness = spring;
    spring_delta     = delta;
  }


  // Residual -R and, if asked, the Jacobian dR/dx of
  //   R_u(v)  = (C0 eps(u) + sum_k C_k (eps(u) - eps_v,k), eps(v))
  //             - <p(g), v_y>_top
  //   R_e(w)  = E_k sum_K [ (V tau_k eps_v, dw/dx)_K + (eps_v - eps(u), w)_K
  //             + V tau_k <eps_v, w>_left(K)
  //             - V tau_k <eps_v^right, w>_right(K) ]
  // for each strain component of each arm k: the upwind DG form of
  // -V tau_k d(eps_v,k)/dx + eps_v,k = eps(u), in which a cell's right face
  // is its inflow face (material moves towards -x) and eps_v^right the value
  // on the right neighbour (0 at x = +W/2). The arm modulus E_k makes R_e a
  // force.
  void
  SteadyStateSolver::assemble(const bool with_matrix)
  {
    TimerOutput::Scope t(timer,
                         with_matrix ? "steady: assemble"
                                     : "steady: assemble residual");
    if (with_matrix)
      {
        system_matrix         = 0;
        factorization_current = false;
      }
    system_rhs = 0;
    if (force_control)
      delta_coupling = 0;
    double force = 0., delta_stiff = 0., abs_force = 0.;

    // Per strain component: the arm's relaxation length V tau_k and its
    // row scale E_k.
    const unsigned int  n_arms = material.n_arms();
    std::vector<double> ell(n_strain_components),
      row_scale(n_strain_components);
    for (unsigned int c = 0; c < n_strain_components; ++c)
      {
        const unsigned int arm = c / components_per_arm;
        ell[c] =
          V_hat * scales.eps / scales.tau_ref * material.relaxation_time(arm);
        row_scale[c] = material.arm_modulus(arm);
      }
    const SymmetricTensor<4, 2> &C0    = material.relaxed_stiffness();
    SymmetricTensor<4, 2>        C_sum = material.arm_stiffness(0);
    for (unsigned int a = 1; a < n_arms; ++a)
      C_sum += material.arm_stiffness(a);

    const UpdateFlags face_flags =
      update_values | update_quadrature_points | update_JxW_values;
    FEValues<dim> fe_values(
      fe, quadrature, update_values | update_gradients | update_JxW_values);
    FEFaceValues<dim> top_values(fe, face_quadrature, face_flags);
    FEFaceValues<dim> face_values(fe, flux_quadrature, face_flags),
      neighbor_face_values(fe, flux_quadrature, face_flags);
    FESubfaceValues<dim> subface_values(fe, flux_quadrature, face_flags),
      neighbor_subface_values(fe, flux_quadrature, face_flags);
    const FEValuesExtractors::Vector        displacement(0);
    const FEValuesExtractors::Scalar        uy(1);
    std::vector<FEValuesExtractors::Scalar> strain_x;
    for (unsigned int c = 0; c < n_strain_components; ++c)
      strain_x.emplace_back(first_strain_component + c);

    const unsigned int n = fe.n_dofs_per_cell(), n_q = quadrature.size();
    FullMatrix<double> cell_matrix(n, n), flux_matrix(n, n);
    Vector<double>     cell_rhs(n), cell_coupling(n);
    std::vector<types::global_dof_index> dofs(n), neighbor_dofs(n);
    std::vector<SymmetricTensor<2, dim>> strain(n_q), projected_strain(n_q),
      grad_phi(n), projected_grad(n), grad_phi_q(n_q), projected_grad_q(n_q);
    Table<2, SymmetricTensor<2, dim>> grad_phi_table(n_q, n),
      projected_grad_table(n_q, n);
    std::vector<std::vector<double>> e(n_strain_components,
                                       std::vector<double>(n_q));
    std::vector<double>              e_face(n_q);
    std::vector<double>              u_y(face_quadrature.size()),
      anchor_u_y(face_quadrature.size());
    std::vector<double> phi(n), phi_x(n), phi_y(n);
    // Component of each local dof: 0, 1 displacement, 2.. strain.
    std::vector<unsigned int> component(n);
    for (unsigned int i = 0; i < n; ++i)
      component[i] = fe.system_to_component_index(i).first;
    std::vector<SymmetricTensor<2, dim>> eps_v(n_arms), C_arm_i(n_arms);

    // The inflow term of the cell's right face: mine is this cell's side,
    // theirs the right neighbour's, on matching quadrature points.
    auto inflow = [&](const FEFaceValuesBase<dim>                 &mine,
                      const FEFaceValuesBase<dim>                 &theirs,
                      const DoFHandler<dim>::active_cell_iterator &neighbor) {
      flux_matrix = 0;
      for (unsigned int c = 0; c < n_strain_components; ++c)
        {
          theirs[strain_x[c]].get_function_values(solution, e_face);
          for (unsigned int q = 0; q < mine.n_quadrature_points; ++q)
            {
              Assert(mine.quadrature_point(q).distance(
                       theirs.quadrature_point(q)) < 1e-8 * scales.R,
                     ExcInternalError());
              const double JxW = mine.JxW(q);
              for (unsigned int i = 0; i < n; ++i)
                if (component[i] == first_strain_component + c)
                  {
                    const double w = mine.shape_value(i, q);
                    cell_rhs(i) += row_scale[c] * ell[c] * e_face[q] * w * JxW;
                    if (with_matrix)
                      for (unsigned int j = 0; j < n; ++j)
                        if (component[j] == component[i])
                          flux_matrix(i, j) -= row_scale[c] * ell[c] *
                                               theirs.shape_value(j, q) * w *
                                               JxW;
                  }
            }
        }
      if (with_matrix)
        {
          neighbor->get_dof_indices(neighbor_dofs);
          constraints.distribute_local_to_global(flux_matrix,
                                                 dofs,
                                                 neighbor_dofs,
                                                 system_matrix);
        }
    };

    for (const auto &cell : dof_handler.active_cell_iterators())
      if (cell->is_locally_owned())
        {
          cell_matrix   = 0;
          cell_rhs      = 0;
          cell_coupling = 0;
          cell->get_dof_indices(dofs);
          fe_values.reinit(cell);
          fe_values[displacement].get_function_symmetric_gradients(solution,
                                                                   strain);
          for (unsigned int c = 0; c < n_strain_components; ++c)
            fe_values[strain_x[c]].get_function_values(solution, e[c]);

          const FullMatrix<double> P =
            strain_projection(fe_values, strain_basis);
          project(P, strain, projected_strain);
          for (unsigned int i = 0; i < n; ++i)
            if (component[i] < first_strain_component)
              {
                for (unsigned int q = 0; q < n_q; ++q)
                  grad_phi_q[q] =
                    fe_values[displacement].symmetric_gradient(i, q);
                project(P, grad_phi_q, projected_grad_q);
                for (unsigned int q = 0; q < n_q; ++q)
                  {
                    grad_phi_table(q, i)       = grad_phi_q[q];
                    projected_grad_table(q, i) = projected_grad_q[q];
                  }
              }

          for (unsigned int q = 0; q < n_q; ++q)
            {
              SymmetricTensor<2, dim> sigma = C0 * strain[q];
              for (unsigned int a = 0; a < n_arms; ++a)
                {
                  const unsigned int c = components_per_arm * a;
                  eps_v[a] = strain_tensor(e[c][q], e[c + 1][q], e[c + 2][q]);
                  sigma += material.arm_stiffness(a) *
                           (projected_strain[q] - eps_v[a]);
                }
              const double JxW = fe_values.JxW(q);
              for (unsigned int i = 0; i < n; ++i)
                {
                  grad_phi[i]       = grad_phi_table(q, i);
                  projected_grad[i] = projected_grad_table(q, i);
                  phi[i]            = fe_values.shape_value(i, q);
                  phi_x[i]          = fe_values.shape_grad(i, q)[0];
                }
              for (unsigned int i = 0; i < n; ++i)
                if (component[i] < first_strain_component)
                  {
                    cell_rhs(i) -= sigma * grad_phi[i] * JxW;
                    if (with_matrix)
                      {
                        const auto C0_i    = C0 * grad_phi[i];
                        const auto C_sum_i = C_sum * grad_phi[i];
                        for (unsigned int a = 0; a < n_arms; ++a)
                          C_arm_i[a] = material.arm_stiffness(a) * grad_phi[i];
                        for (unsigned int j = 0; j < n; ++j)
                          {
                            if (component[j] < first_strain_component)
                              cell_matrix(i, j) +=
                                (C0_i * grad_phi[j] +
                                 C_sum_i * projected_grad[j]) *
                                JxW;
                            else
                              {
                                const unsigned int c =
                                  component[j] - first_strain_component;
                                cell_matrix(i, j) -=
                                  (C_arm_i[c / components_per_arm] *
                                   unit_strain(c % components_per_arm)) *
                                  phi[j] * JxW;
                              }
                          }
                      }
                  }
                else
                  {
                    const unsigned int c =
                      component[i] - first_strain_component;
                    const unsigned int cc = c % components_per_arm;
                    const double       ec =
                      strain_component(eps_v[c / components_per_arm], cc);
                    cell_rhs(i) -=
                      row_scale[c] *
                      (ell[c] * ec * phi_x[i] +
                       (ec - strain_component(strain[q], cc)) * phi[i]) *
                      JxW;
                    if (with_matrix)
                      for (unsigned int j = 0; j < n; ++j)
                        {
                          if (component[j] < first_strain_component)
                            cell_matrix(i, j) -=
                              row_scale[c] * strain_component(grad_phi[j], cc) *
                              phi[i] * JxW;
                          else if (component[j] == component[i])
                            cell_matrix(i, j) += row_scale[c] *
                                                 (ell[c] * phi_x[i] + phi[i]) *
                                                 phi[j] * JxW;
                        }
                  }
            }

          for (const unsigned int f : cell->face_indices())
            {
              const auto face = cell->face(f);
              if (face->at_boundary() && face->boundary_id() == top_boundary)
                {
                  top_values.reinit(cell, f);
                  top_values[uy].get_function_values(solution, u_y);
                  if (surface_damping > 0)
                    top_values[uy].get_function_values(relaxation_anchor,
                                                       anchor_u_y);
                  for (unsigned int q = 0; q < face_quadrature.size(); ++q)
                    {
                      const double g         = gap(indenter,
                                           scales.eps,
                                           delta,
                                           s,
                                           top_values.quadrature_point(q)[0],
                                           u_y[q]);
                      double       traction  = law.traction(g);
                      const double dp_dg     = law.derivative(g);
                      double       stiffness = dp_dg;
                      const double JxW       = top_values.JxW(q);
                      abs_force += std::abs(traction) * JxW;
                      force -= traction * JxW;
                      delta_stiff += dp_dg * JxW;
                      if (surface_damping > 0) // relax() only
                        {
                          traction -=
                            surface_damping * (u_y[q] - anchor_u_y[q]);
                          stiffness += surface_damping;
                        }
                      for (unsigned int i = 0; i < n; ++i)
                        phi_y[i] = top_values[uy].value(i, q);
                      for (unsigned int i = 0; i < n; ++i)
                        {
                          cell_rhs(i) += traction * phi_y[i] * JxW;
                          cell_coupling(i) += dp_dg * phi_y[i] * JxW;
                          if (with_matrix)
                            for (unsigned int j = 0; j < n; ++j)
                              cell_matrix(i, j) +=
                                stiffness * phi_y[i] * phi_y[j] * JxW;
                        }
                    }
                }
              if (V_hat == 0.)
                continue;
              // The coarse cells are axis-aligned rectangles in standard
              // orientation: face 0 is the left (outflow), face 1 the right
              // (inflow) one; top and bottom faces carry no flux.
              if (f == 0)
                {
                  face_values.reinit(cell, f);
                  for (unsigned int c = 0; c < n_strain_components; ++c)
                    {
                      face_values[strain_x[c]].get_function_values(solution,
                                                                   e_face);
                      for (unsigned int q = 0; q < flux_quadrature.size(); ++q)
                        for (unsigned int i = 0; i < n; ++i)
                          if (component[i] == first_strain_component + c)
                            {
                              const double w   = face_values.shape_value(i, q);
                              const double JxW = face_values.JxW(q);
                              cell_rhs(i) -=
                                row_scale[c] * ell[c] * e_face[q] * w * JxW;
                              if (with_matrix)
                                for (unsigned int j = 0; j < n; ++j)
                                  if (component[j] == component[i])
                                    cell_matrix(i, j) +=
                                      row_scale[c] * ell[c] *
                                      face_values.shape_value(j, q) * w * JxW;
                            }
                    }
                }
              else if (f == 1 && !face->at_boundary())
                {
                  const unsigned int nf = cell->neighbor_of_neighbor(f);
                  if (face->has_children())
                    for (unsigned int sf = 0; sf < face->n_children(); ++sf)
                      {
                        const auto neighbor =
                          cell->neighbor_child_on_subface(f, sf);
                        subface_values.reinit(cell, f, sf);
                        neighbor_face_values.reinit(neighbor, nf);
                        inflow(subface_values, neighbor_face_values, neighbor);
                      }
                  else if (cell->neighbor_is_coarser(f))
                    {
                      const auto neighbor = cell->neighbor(f);
                      const auto [face_no, subface_no] =
                        cell->neighbor_of_coarser_neighbor(f);
                      face_values.reinit(cell, f);
                      neighbor_subface_values.reinit(neighbor,
                                                     face_no,
                                                     subface_no);
                      inflow(face_values, neighbor_subface_values, neighbor);
                    }
                  else
                    {
                      const auto neighbor = cell->neighbor(f);
                      face_values.reinit(cell, f);
                      neighbor_face_values.reinit(neighbor, nf);
                      inflow(face_values, neighbor_face_values, neighbor);
                    }
                }
            }

          if (force_control)
            constraints.distribute_local_to_global(cell_coupling,
                                                   dofs,
                                                   delta_coupling);
          if (with_matrix)
            constraints.distribute_local_to_global(
              cell_matrix, cell_rhs, dofs, system_matrix, system_rhs);
          else
            constraints.distribute_local_to_global(cell_rhs, dofs, system_rhs);
        }
    if (with_matrix)
      system_matrix.compress(VectorOperation::add);
    system_rhs.compress(VectorOperation::add);
    traction_scale = dealii::Utilities::MPI::sum(abs_force, mpi_communicator);
    if (force_control)
      {
        delta_coupling.compress(VectorOperation::add);
        // Under spring control the force to hold follows delta.
        force_mismatch = dealii::Utilities::MPI::sum(force, mpi_communicator) -
                         target_force -
                         spring_stiffness * (spring_delta - delta);
        delta_stiffness =
          dealii::Utilities::MPI::sum(delta_stiff, mpi_communicator) +
          spring_stiffness;
      }
  }


  // At a given speed and mesh the bulk operator (elasticity, arm and
  // advection of eps_v) is linear: between Newton iterations only the
  // surface traction terms change, on the few hundred dofs near the
  // contact. So the factorization of the first Jacobian at a speed
  // preconditions GMRES for the later ones, which then needs a few
  // iterations instead of a new factorization (about 2 s at 60 000
  // unknowns). A new factorization is made when GMRES does not converge
  // within 'max_reuse_iterations', and whenever speed or mesh change.
  void
  SteadyStateSolver::solve_linear(TrilinosWrappers::MPI::Vector       &x,
                                  const TrilinosWrappers::MPI::Vector &b)
  {
    constexpr unsigned int max_reuse_iterations = 30;
    if (direct_solver && factorized_speed == V_hat && !factorization_current)
      {
        struct Factorization
        {
          TrilinosWrappers::SolverDirect *solver;
          void
          vmult(TrilinosWrappers::MPI::Vector       &dst,
                const TrilinosWrappers::MPI::Vector &src) const
          {
            solver->solve(dst, src);
          }
        } preconditioner{direct_solver.get()};
        SolverControl control(max_reuse_iterations, 1e-10 * b.l2_norm());
        SolverGMRES<TrilinosWrappers::MPI::Vector> gmres(
          control,
          SolverGMRES<TrilinosWrappers::MPI::Vector>::AdditionalData(
            max_reuse_iterations + 2));
        x = 0.;
        try
          {
            gmres.solve(system_matrix, x, b, preconditioner);
            krylov_iterations += control.last_step();
            return;
          }
        catch (const SolverControl::NoConvergence &)
          {
          }
      }
    if (!factorization_current)
      {
        direct_solver         = factorize(system_matrix);
        factorization_current = true;
        factorized_speed      = V_hat;
        ++factorizations;
      }
    direct_solver->solve(x, b);
  }


  // Under force control the bordered system of the transient solver
  // (contact_problem.cc): two solves with one Jacobian.
  void
  SteadyStateSolver::solve_newton_system()
  {
    TimerOutput::Scope            t(timer, "steady: linear solve");
    TrilinosWrappers::MPI::Vector x1(locally_owned_dofs, mpi_communicator);
    solve_linear(x1, system_rhs);
    delta_update = 0.;
    if (force_control)
      {
        TrilinosWrappers::MPI::Vector x2(locally_owned_dofs, mpi_communicator);
        solve_linear(x2, delta_coupling);
        delta_update = (-force_mismatch - (delta_coupling * x1)) /
                       (delta_stiffness - (delta_coupling * x2));
        x1.add(-delta_update, x2);
      }
    constraints.distribute(x1);
    newton_update = x1;
  }


  double
  SteadyStateSolver::residual_norm() const
  {
    const double r = system_rhs.l2_norm();
    return force_control ? std::hypot(r, force_mismatch) : r;
  }


  NewtonProblem
  SteadyStateSolver::newton_problem(TrilinosWrappers::MPI::Vector &u0,
                                    double                        &delta0)
  {
    const double  floor = scales.sigma_max * prm.mesh.finest_cell;
    NewtonProblem problem;
    problem.assemble      = [this](const bool m) { assemble(m); };
    problem.residual_norm = [this] { return residual_norm(); };
    problem.tolerance     = [this, floor] {
      return prm.solver.newton_tolerance * (traction_scale + floor);
    };
    problem.compute_update = [this] { solve_newton_system(); };
    return with_iterate(problem,
                        {solution,
                         delta,
                         newton_update,
                         delta_update,
                         surface_damping,
                         relaxation_anchor},
                        u0,
                        delta0);
  }


  int
  SteadyStateSolver::solve_newton()
  {
    TrilinosWrappers::MPI::Vector u0(locally_owned_dofs, mpi_communicator);
    double                        delta0 = delta;
    return newton(newton_problem(u0, delta0),
                  prm.solver.max_newton_iterations,
                  prm.solver.line_search,
                  prm.solver.verbose,
                  pcout);
  }


  // As in the transient solver (ContactProblem::relax_to_equilibrium):
  // for a speed step across which a contact edge jumps, e.g. the first
  // one, where the trailing edge leaves the approach branch.
  int
  SteadyStateSolver::relax_to_equilibrium()
  {
    TimerOutput::Scope t(timer, "steady: relaxation");
    relaxation_anchor.reinit(solution);
    TrilinosWrappers::MPI::Vector u0(locally_owned_dofs, mpi_communicator);
    double                        delta0 = delta;
    const int                     steps  = relax(newton_problem(u0, delta0),
                            16. * scales.dgamma / (scales.eps * scales.eps),
                            0.5 * scales.eps,
                            prm.solver.max_relaxation_steps,
                            prm.solver.verbose,
                            pcout);
    surface_damping                      = 0.;
    return steps;
  }


  bool
  SteadyStateSolver::adapt_mesh()
  {
    TimerOutput::Scope t(timer, "steady: adapt mesh");
    auto               edges = postprocessor.faces_in_gap_band(dof_handler,
                                                 solution,
                                                 delta,
                                                 s,
                                                 prm.mesh.edge_gap_low,
                                                 prm.mesh.edge_gap_high);
    if (edges.empty())
      edges.emplace_back(s, s);
    if (!flag_cells_near_edges(triangulation, edges, prm))
      return false;

    parallel::distributed::SolutionTransfer<dim, TrilinosWrappers::MPI::Vector>
      transfer(dof_handler);
    transfer.prepare_for_coarsening_and_refinement(solution);
    triangulation.execute_coarsening_and_refinement();
    setup_system();
    TrilinosWrappers::MPI::Vector x(locally_owned_dofs, mpi_communicator);
    transfer.interpolate(x);
    constraints.distribute(x);
    solution = x;
    return true;
  }


  namespace
  {
    std::string
    label(const std::string &name, const double value)
    {
      std::ostringstream os;
      os << name << " = " << value;
      return os.str();
    }
  } // namespace


  // Solves the steady state after the speed or the load moved, from the
  // last converged state: Newton, else pseudo-transient relaxation (a
  // contact edge may have to jump: always at the first speed, where the
  // trailing edge leaves the approach branch), then the mesh adaptation
  // cycles. Returns the Newton iterations; -1 if the step failed (the
  // caller restores the state it started from and shortens the step); -2
  // if it failed on an adapted mesh, where that state no longer fits.
  int
  SteadyStateSolver::solve_step(const std::string &what)
  {
    const TrilinosWrappers::MPI::Vector backup(solution);
    const double                        delta0 = delta;
    int                                 its    = solve_newton();
    if (its < 0)
      {
        solution = backup;
        delta    = delta0;
        its      = relax_to_equilibrium();
        if (its < 0)
          return -1;
        pcout << "  steady " << what << ": reached by relaxation" << std::endl;
      }
    for (unsigned int cycle = 0; cycle < prm.mesh.max_adaptation_cycles;
         ++cycle)
      {
        if (!adapt_mesh())
          break;
        int more = solve_newton();
        if (more < 0)
          more = relax_to_equilibrium();
        if (more < 0)
          {
            pcout << "Steady state: Newton failed at " << what
                  << " after adapting the mesh" << std::endl;
            return -2;
          }
        its += more;
      }
    last_newton_iterations = its;
    update_quantities();
    pcout << "  steady V_hat " << std::setw(11) << V_hat << "  delta_hat "
          << std::setw(10) << delta / scales.eps << "  F_hat " << std::setw(11)
          << last_quantities.normal_force / scales.force << "  mu "
          << std::setw(11)
          << std::abs(last_quantities.tangential_force /
                      last_quantities.normal_force)
          << "  L_hat " << std::setw(11)
          << last_quantities.contact_length / scales.R << "  Newton " << its
          << "  dofs " << dof_handler.n_dofs() << "  factorizations "
          << factorizations << "  GMRES " << krylov_iterations << std::endl;
    return its;
  }


  bool
  SteadyStateSolver::continue_to(const double                 target,
                                 const std::function<void()> &on_converged)
  {
    // The first speed: relaxation length V tau a tenth of the finest cell,
    // so that the relaxed start is close to its solution.
    double first =
      0.1 * prm.mesh.finest_cell / material.longest_relaxation_time();
    const double largest_step = std::log(prm.sliding.continuation_factor);
    double       step         = largest_step;
    while (V_hat != target)
      {
        double next;
        if (V_hat == 0.)
          next = std::min(target, first);
        else if (target > V_hat)
          next = std::min(target, V_hat * std::exp(step));
        else
          next = std::max(target, V_hat * std::exp(-step));

        const TrilinosWrappers::MPI::Vector backup(solution);
        const double                        delta0 = delta, V0 = V_hat;
        V_hat         = next;
        const int its = solve_step(label("V_hat", next));
        if (its == -2)
          return false;
        if (its < 0)
          {
            solution = backup;
            delta    = delta0;
            V_hat    = V0;
            step *= 0.5;
            if (V0 == 0.)
              first *= std::exp(-step); // the first speed has no ratio
            if (step < std::log(1.01))
              {
                pcout << "Steady state: Newton failed at V_hat = " << next
                      << " even in steps of 1 %; last converged V_hat = " << V0
                      << std::endl;
                return false;
              }
            continue;
          }
        on_converged();
        step = std::min(largest_step, 2. * step);
      }
    return true;
  }


  // Continuation in the controlled quantity at the current speed: F_n under
  // force control, delta under displacement control. Steps are linear (the
  // load may change sign): the whole way first, halved on failure down to
  // a thousandth of it, doubled again after each success.
  bool
  SteadyStateSolver::continue_to_load(const double                 target,
                                      const std::function<void()> &on_converged)
  {
    double      &controlled = force_control ? target_force : delta;
    const double unit       = force_control ? scales.force : scales.eps;
    const double start = controlled, whole = std::abs(target - start);
    double       step = whole;
    while (controlled != target)
      {
        const double                        next = target > controlled
                                                     ? std::min(target, controlled + step)
                                                     : std::max(target, controlled - step);
        const TrilinosWrappers::MPI::Vector backup(solution);
        const double delta0 = delta, force0 = target_force;
        controlled = next;
        const std::string what =
          label(force_control ? "F_hat" : "delta_hat", next / unit);
        const int its = solve_step(what);
        if (its == -2)
          return false;
        if (its < 0)
          {
            solution     = backup;
            delta        = delta0;
            target_force = force0;
            step *= 0.5;
            if (step < 1e-3 * whole)
              {
                pcout << "Steady state: Newton failed at " << what
                      << " even in steps of a thousandth of the way from "
                      << start / unit << std::endl;
                return false;
              }
            continue;
          }
        on_converged();
        step = std::min(whole, 2. * step);
      }
    return true;
  }


  void
  SteadyStateSolver::update_quantities()
  {
    last_quantities = postprocessor.integrate(dof_handler, solution, delta, s);
  }


  double
  SteadyStateSolver::dissipation_rate() const
  {
    FEValues<dim> fe_values(
      fe, quadrature, update_values | update_gradients | update_JxW_values);
    const FEValuesExtractors::Vector     displacement(0);
    std::vector<SymmetricTensor<2, dim>> strain(quadrature.size()),
      projected_strain(quadrature.size());
    std::vector<Vector<double>> values(quadrature.size(),
                                       Vector<double>(fe.n_components()));
    double                      rate = 0.;
    for (const auto &cell : dof_handler.active_cell_iterators())
      if (cell->is_locally_owned())
        {
          fe_values.reinit(cell);
          fe_values[displacement].get_function_symmetric_gradients(solution,
                                                                   strain);
          fe_values.get_function_values(solution, values);
          project(strain_projection(fe_values, strain_basis),
                  strain,
                  projected_strain);
          for (unsigned int q = 0; q < quadrature.size(); ++q)
            for (unsigned int a = 0; a < material.n_arms(); ++a)
              rate += material.dissipation_rate(
                        a,
                        material.arm_stress(a,
                                            projected_strain[q] -
                                              viscous_strain(values[q], a))) *
                      fe_values.JxW(q);
        }
    return dealii::Utilities::MPI::sum(rate, mpi_communicator);
  }


  void
  SteadyStateSolver::write_profile(const std::string &path) const
  {
    write_profile_csv(path,
                      postprocessor.profile(dof_handler, solution, delta, s),
                      scales,
                      "steady state, V_hat = " + CsvTable::format(V_hat) +
                        ", delta_hat = " + CsvTable::format(delta),
                      mpi_communicator);
  }


  void
  SteadyStateSolver::write_fields(OutputWriter      &writer,
                                  const unsigned int counter) const
  {
    TimerOutput::Scope       t(timer, "output");
    std::vector<std::string> names{"displacement", "displacement"};
    for (unsigned int a = 0; a < material.n_arms(); ++a)
      for (const std::string c : {"xx", "yy", "xy"})
        names.push_back("viscous_strain_" +
                        (material.n_arms() > 1 ? std::to_string(a + 1) + "_"
                                               : std::string()) +
                        c);
    std::vector<DataComponentInterpretation::DataComponentInterpretation>
      interpretation(fe.n_components(),
                     DataComponentInterpretation::component_is_scalar);
    interpretation[0] = interpretation[1] =
      DataComponentInterpretation::component_is_part_of_vector;
    const SteadyFields fields(material);
    DataOut<dim>       data_out;
    data_out.attach_dof_handler(dof_handler);
    data_out.add_data_vector(solution,
                             names,
                             DataOut<dim>::type_dof_data,
                             interpretation);
    data_out.add_data_vector(solution, fields);
    data_out.build_patches(2);
    writer.write(data_out, "steady", counter, V_hat);
  }
} // namespace viscoslide

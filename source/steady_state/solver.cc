// SPDX-License-Identifier: LGPL-2.1-or-later
// SteadyStateSolver: setup, the start from the relaxed state, Newton's
// method and the mesh adaptation at the contact edges.
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

#include <deal.II/numerics/vector_tools.h>

#include <viscoslide/numerics/mesh.h>
#include <viscoslide/numerics/newton.h>
#include <viscoslide/steady_state/solver.h>
#include <viscoslide/steady_state/viscous_strain.h>

#include <cmath>
#include <iomanip>
#include <sstream>

namespace viscoslide
{
  using ViscousStrain::components_per_arm;
  using ViscousStrain::first_component;


  template <int dim>
  SteadyStateSolver<dim>::SteadyStateSolver(
    const Parameters::AllParameters           &prm,
    const Scales                              &scales,
    const ViscoelasticSolid                   &material,
    SurfaceCoupling<dim>                      &coupling,
    const SurfacePostprocessor<dim>           &postprocessor,
    parallel::distributed::Triangulation<dim> &triangulation,
    TimerOutput                               &timer)
    : prm(prm)
    , scales(scales)
    , material(material)
    , coupling(coupling)
    , postprocessor(postprocessor)
    , triangulation(triangulation)
    , timer(timer)
    , mpi_communicator(triangulation.get_communicator())
    , pcout(std::cout,
            dealii::Utilities::MPI::this_mpi_process(mpi_communicator) == 0)
    , n_strain_components(components_per_arm<dim> * material.n_arms())
    , fe(FE_Q<dim>(2),
         dim,
         FE_DGQ<dim>(prm.sliding.viscous_strain_degree),
         n_strain_components)
    , dof_handler(triangulation)
    , quadrature(std::max(3, prm.sliding.viscous_strain_degree + 2))
    , flux_quadrature(std::max(3, prm.sliding.viscous_strain_degree + 2))
    , linear_solver(timer, mpi_communicator)
    , iterative_solver(timer, mpi_communicator, prm.solver)
  {
    for (unsigned int i = 0; i < fe.n_dofs_per_cell(); ++i)
      if (fe.system_to_component_index(i).first == first_component<dim>)
        strain_basis.push_back(i);
  }


  template <int dim>
  SteadyStateSolver<dim>::~SteadyStateSolver() = default;


  template <int dim>
  void
  SteadyStateSolver<dim>::setup_system()
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
      bottom_boundary<dim>,
      Functions::ZeroFunction<dim>(fe.n_components()),
      constraints,
      fe.component_mask(FEValuesExtractors::Vector(0)));
    constraints.close();

    // Inside a cell the displacement couples to everything, a viscous-strain
    // component to itself; across the vertical faces only the upwind flux
    // of each viscous-strain component. The pattern holds no more: MUMPS
    // orders the unknowns by it, and the couplings that are always zero
    // (those across horizontal faces in particular) made its factors three
    // times larger and its factorization nine times costlier.
    const unsigned int           n_c = fe.n_components();
    Table<2, DoFTools::Coupling> cell_coupling(n_c, n_c),
      face_coupling(n_c, n_c);
    for (unsigned int c = 0; c < n_c; ++c)
      for (unsigned int d = 0; d < n_c; ++d)
        {
          const bool strain_pair =
            c >= first_component<dim> && d >= first_component<dim>;
          cell_coupling(c, d) =
            (!strain_pair || c == d) ? DoFTools::always : DoFTools::none;
          face_coupling(c, d) =
            (strain_pair && c == d) ? DoFTools::always : DoFTools::none;
        }
    DynamicSparsityPattern dsp(locally_relevant_dofs);
    DoFTools::make_flux_sparsity_pattern(
      dof_handler,
      dsp,
      constraints,
      false,
      cell_coupling,
      face_coupling,
      dealii::Utilities::MPI::this_mpi_process(mpi_communicator),
      [](const auto &cell, const unsigned int f) {
        return carries_flux(cell, f);
      });
    SparsityTools::distribute_sparsity_pattern(dsp,
                                               locally_owned_dofs,
                                               mpi_communicator,
                                               locally_relevant_dofs);
    coupling.attach(
      linear_solver, dof_handler, constraints, solution, delta, s);
    system_matrix.reinit(locally_owned_dofs,
                         locally_owned_dofs,
                         dsp,
                         mpi_communicator);
    bulk_matrix.reinit(system_matrix);
    bulk_speed = -1.;
    solution.reinit(locally_owned_dofs,
                    locally_relevant_dofs,
                    mpi_communicator);
    system_rhs.reinit(locally_owned_dofs, mpi_communicator);
    newton_update.reinit(system_rhs);
    last_increment.clear(); // adapt_mesh() transfers it
    coupling.reinit(locally_owned_dofs);
    if (!use_direct_solver())
      iterative_solver.reinit(dof_handler);
  }


  // u is copied dof by dof (same Q2 element); eps_v is the cell-wise L2
  // projection of eps(u), the relaxed state (V = 0) of the viscous strain.
  template <int dim>
  void
  SteadyStateSolver<dim>::initialize(const DoFHandler<dim> &u_dofs,
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
          c >= first_component<dim>)
        strain_dofs[c - first_component<dim>].push_back(i);
    const unsigned int m = strain_dofs[0].size();
    FullMatrix<double> mass(m, m);
    Vector<double>     rhs(m), coefficients(m);

    TrilinosWrappers::MPI::Vector x(locally_owned_dofs, mpi_communicator);
    for (const auto &cell : dof_handler.active_cell_iterators())
      if (cell->is_locally_owned())
        {
          const CellIterator u_cell(&triangulation,
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
                      ViscousStrain::component(strain[q],
                                               c % components_per_arm<dim>) *
                      wa * values.JxW(q);
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



  template <int dim>
  void
  SteadyStateSolver<dim>::initialize_at_rest(const double delta, const double s)
  {
    setup_system();
    this->delta = delta;
    this->s     = s;
    V_hat       = 0.;
    solution    = 0.;
    for (unsigned int i = 0; i < 64 && adapt_mesh(); ++i)
      ;
    update_quantities();
  }


  template <int dim>
  bool
  SteadyStateSolver<dim>::use_direct_solver() const
  {
    using Parameters::LinearSolver;
    return prm.solver.direct_for(dof_handler.n_dofs()) ||
           (dim == 2 && prm.solver.linear_solver == LinearSolver::automatic);
  }


  template <int dim>
  void
  SteadyStateSolver<dim>::solve_newton_system()
  {
    if (use_direct_solver())
      coupling.solve_bordered(linear_solver,
                              system_matrix,
                              system_rhs,
                              newton_update);
    else
      coupling.solve_bordered(
        [this](const auto &b, auto &x) {
          const unsigned int before = iterative_solver.iterations;
          iterative_solver.solve(system_matrix, b, x);
          if (prm.solver.verbose)
            pcout << "        GMRES: " << iterative_solver.iterations - before
                  << " iterations" << std::endl;
        },
        system_rhs,
        newton_update);
    constraints.distribute(newton_update);
  }


  template <int dim>
  typename SurfaceCoupling<dim>::System
  SteadyStateSolver<dim>::newton_system()
  {
    return {solution,
            delta,
            newton_update,
            system_rhs,
            [this](const bool with_matrix) { assemble(with_matrix); },
            [this] { solve_newton_system(); }};
  }


  // Relaxation serves a speed step across which a contact edge jumps, e.g.
  // the first one, where the trailing edge leaves the approach branch.
  template <int dim>
  int
  SteadyStateSolver<dim>::solve_newton_or_relax()
  {
    const int its = coupling.newton(newton_system(), pcout);
    if (its >= 0)
      return its;
    TimerOutput::Scope t(timer, "steady: relaxation");
    return coupling.relax(newton_system(), pcout);
  }


  template <int dim>
  bool
  SteadyStateSolver<dim>::adapt_mesh(const SurfaceRegions<dim> &expected)
  {
    TimerOutput::Scope t(timer, "steady: adapt mesh");
    if (!coupling.flag_contact_edges(
          triangulation, dof_handler, solution, delta, s, expected))
      return false;

    // The last step's increment travels with the solution: the next load
    // step's predictor extrapolates it.
    const bool with_increment = last_increment.size() == solution.size();
    std::vector<const TrilinosWrappers::MPI::Vector *> from{&solution};
    if (with_increment)
      from.push_back(&last_increment);
    parallel::distributed::SolutionTransfer<dim, TrilinosWrappers::MPI::Vector>
      transfer(dof_handler);
    transfer.prepare_for_coarsening_and_refinement(from);
    triangulation.execute_coarsening_and_refinement();
    setup_system();
    std::vector<TrilinosWrappers::MPI::Vector> to(
      from.size(),
      TrilinosWrappers::MPI::Vector(locally_owned_dofs, mpi_communicator));
    std::vector<TrilinosWrappers::MPI::Vector *> to_pointers;
    for (auto &x : to)
      to_pointers.push_back(&x);
    transfer.interpolate(to_pointers);
    for (auto &x : to)
      constraints.distribute(x);
    solution = to[0];
    if (with_increment)
      {
        last_increment.reinit(solution);
        last_increment = to[1];
      }
    return true;
  }


  template <int dim>
  void
  SteadyStateSolver<dim>::record_edges()
  {
    if (dim != 2) // expected_edges() extrapolates in 2D alone
      return;
    const auto edges  = coupling.contact_edges(dof_handler, solution, delta, s);
    double     lowest = edges[0].lower[0], highest = edges[0].upper[0];
    for (const auto &edge : edges)
      {
        lowest  = std::min(lowest, edge.lower[0]);
        highest = std::max(highest, edge.upper[0]);
      }
    const double middle = 0.5 * (lowest + highest);
    EdgeSpan     span{std::log(V_hat), {{highest, lowest, highest, lowest}}};
    for (const auto &edge : edges)
      {
        const double       a = edge.lower[0], b = edge.upper[0];
        const unsigned int side = a + b < 2 * middle ? 0 : 2;
        span.ends[side]         = std::min(span.ends[side], a);
        span.ends[side + 1]     = std::max(span.ends[side + 1], b);
      }
    edge_spans.push_back(span);
    if (edge_spans.size() > 2)
      edge_spans.erase(edge_spans.begin());
  }


  template <int dim>
  SurfaceRegions<dim>
  SteadyStateSolver<dim>::expected_edges(const double next) const
  {
    if (dim != 2 || edge_spans.size() < 2 ||
        edge_spans[1].log_speed == edge_spans[0].log_speed)
      return {};
    const EdgeSpan &last = edge_spans[1], &before = edge_spans[0];
    // Twice the extrapolated move, in the ratio of the step in log V_hat to
    // the last one: the edges found on the coarser cells ahead of them
    // move by more than the converged ones did, and an overshoot costs
    // only cells (measured on the Fig. 9b curve: 40 factorizations against
    // 45 with the plain extrapolation, 58 with none).
    const double ratio = 2. * std::clamp((std::log(next) - last.log_speed) /
                                           (last.log_speed - before.log_speed),
                                         0.,
                                         2.);
    std::array<double, 4> ahead;
    for (unsigned int i = 0; i < 4; ++i)
      ahead[i] = last.ends[i] + ratio * (last.ends[i] - before.ends[i]);
    SurfaceRegions<dim> expected(2);
    for (const unsigned int side : {0, 2})
      {
        expected[side / 2].lower[0] = std::min(last.ends[side], ahead[side]);
        expected[side / 2].upper[0] =
          std::max(last.ends[side + 1], ahead[side + 1]);
      }
    return expected;
  }

  template <int dim>
  void
  SteadyStateSolver<dim>::update_quantities()
  {
    last_quantities = postprocessor.integrate(dof_handler, solution, delta, s);
  }


  template class SteadyStateSolver<2>;
  template class SteadyStateSolver<3>;
} // namespace viscoslide

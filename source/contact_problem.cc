#include <deal.II/base/bounding_box.h>
#include <deal.II/base/utilities.h>

#include <deal.II/distributed/solution_transfer.h>

#include <deal.II/dofs/dof_tools.h>

#include <deal.II/fe/fe_q.h>
#include <deal.II/fe/fe_values.h>

#include <deal.II/grid/grid_generator.h>

#include <deal.II/lac/solver_control.h>
#include <deal.II/lac/solver_gmres.h>
#include <deal.II/lac/sparsity_tools.h>
#include <deal.II/lac/trilinos_precondition.h>
#include <deal.II/lac/trilinos_solver.h>
#include <deal.II/lac/trilinos_sparsity_pattern.h>

#include <deal.II/numerics/data_out.h>
#include <deal.II/numerics/data_out_faces.h>
#include <deal.II/numerics/data_postprocessor.h>
#include <deal.II/numerics/vector_tools.h>

#include <viscoslide/contact_problem.h>

#include <viscoslide/mesh.h>
#include <viscoslide/newton.h>
#include <viscoslide/steady_state.h>

#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <iomanip>
#include <sstream>

namespace viscoslide
{
  namespace
  {
    // The spring of Control = spring in force per unit length per length
    // of approach; 0 for the other controls.
    double
    spring_stiffness_of(const Parameters::AllParameters &prm,
                        const Scales                    &scales)
    {
      return prm.sliding.control == "spring"
               ? prm.sliding.spring_stiffness * scales.force / scales.eps
               : 0.;
    }


    // Surface fields for DataOutFaces: pressure and gap from u_y and x.
    class SurfaceFields : public DataPostprocessor<2>
    {
    public:
      SurfaceFields(const InteractionLaw &law,
                    const Indenter       &indenter,
                    const Scales         &scales,
                    const LoadState      &state)
        : law(law)
        , indenter(indenter)
        , scales(scales)
        , state(state)
      {
      }

      void
      evaluate_vector_field(
        const DataPostprocessorInputs::Vector<2> &inputs,
        std::vector<Vector<double>>              &computed) const override
      {
        for (unsigned int q = 0; q < inputs.solution_values.size(); ++q)
          {
            const double g = gap(indenter,
                                 scales.eps,
                                 state.delta,
                                 state.s,
                                 inputs.evaluation_points[q][0],
                                 inputs.solution_values[q][1]);
            computed[q](0) = -law.traction(g) / scales.sigma_max;
            computed[q](1) = g / scales.eps;
          }
      }

      std::vector<std::string>
      get_names() const override
      {
        return {"p_hat", "gap_over_eps"};
      }

      UpdateFlags
      get_needed_update_flags() const override
      {
        return update_values | update_quadrature_points;
      }

    private:
      const InteractionLaw &law;
      const Indenter       &indenter;
      const Scales         &scales;
      const LoadState      &state;
    };

    // DataOutFaces over the locally owned faces of the top surface only.
    class TopSurfaceDataOut : public DataOutFaces<2>
    {
    public:
      TopSurfaceDataOut()
        : DataOutFaces<2>(true)
      {
      }

      FaceDescriptor
      first_face() override
      {
        for (const auto &cell : this->triangulation->active_cell_iterators())
          if (cell->is_locally_owned())
            if (const auto f = top_face(cell);
                f != numbers::invalid_unsigned_int)
              return {cell, f};
        return {};
      }

      FaceDescriptor
      next_face(const FaceDescriptor &face) override
      {
        auto cell = face.first;
        for (++cell; cell != this->triangulation->end(); ++cell)
          if (cell->is_active() && cell->is_locally_owned())
            if (const auto f = top_face(cell);
                f != numbers::invalid_unsigned_int)
              return {cell, f};
        return {};
      }

    private:
      static unsigned int
      top_face(const Triangulation<2>::cell_iterator &cell)
      {
        for (const unsigned int f : cell->face_indices())
          if (cell->face(f)->at_boundary() &&
              cell->face(f)->boundary_id() == top_boundary)
            return f;
        return numbers::invalid_unsigned_int;
      }
    };

    std::vector<DataComponentInterpretation::DataComponentInterpretation>
    vector_interpretation()
    {
      return {DataComponentInterpretation::component_is_part_of_vector,
              DataComponentInterpretation::component_is_part_of_vector};
    }
  } // namespace


  ContactProblem::ContactProblem(const Parameters::AllParameters &parameters,
                                 MPI_Comm  mpi_communicator,
                                 Progress *progress)
    : prm(parameters)
    , mpi_communicator(mpi_communicator)
    , pcout(std::cout,
            Utilities::MPI::this_mpi_process(mpi_communicator) == 0 &&
              parameters.output.verbosity != "quiet")
    , timer(mpi_communicator,
            pcout,
            TimerOutput::never,
            TimerOutput::wall_times)
    , scales(parameters)
    , material(1. - std::pow(parameters.material.poisson_ratio, 2),
               (1. - std::pow(parameters.material.poisson_ratio, 2)) /
                 parameters.material.E0_over_Einf,
               parameters.material.poisson_ratio,
               scales.tau_arm,
               parameters.material.prony_series)
    , law(create_interaction_law(parameters.adhesion.law,
                                 scales.dgamma,
                                 scales.eps))
    , indenter(create_indenter(parameters.indenter,
                               scales.R,
                               parameters.geometry.domain_width))
    , triangulation(mpi_communicator,
                    Triangulation<dim>::limit_level_difference_at_vertices)
    , fe(FE_Q<dim>(2), dim)
    , dof_handler(triangulation)
    , quadrature(3)
    , face_quadrature(parameters.adhesion.face_quadrature_points)
    , history_fe(QGauss<1>(3))
    , history_dof_handler(triangulation)
    , history(n_arm_stress_components * material.n_arms() + 1)
    , traction_scale(0.)
    , postprocessor(*law,
                    *indenter,
                    scales.eps,
                    parameters.adhesion.contact_gap,
                    parameters.adhesion.face_quadrature_points,
                    top_boundary)
    , writer(parameters.output.directory,
             mpi_communicator,
             parameters.output.field_format)
    , progress(progress)
    , step_number(0)
    , last_newton_iterations(0)
    , last_step_cuts(0)
    , last_step_relaxed(false)
  {
    // The history field's nodes are the Gauss points of the cell
    // quadrature; find which node is which point once.
    const auto &support = history_fe.get_unit_support_points();
    for (unsigned int q = 0; q < quadrature.size(); ++q)
      for (unsigned int i = 0; i < support.size(); ++i)
        if (support[i].distance(quadrature.point(q)) < 1e-12)
          quadrature_to_history_dof.push_back(i);
    AssertDimension(quadrature_to_history_dof.size(), quadrature.size());
  }


  void
  ContactProblem::setup_system()
  {
    TimerOutput::Scope t(timer, "setup");
    dof_handler.distribute_dofs(fe);
    history_dof_handler.distribute_dofs(history_fe);
    locally_owned_dofs = dof_handler.locally_owned_dofs();
    DoFTools::extract_locally_relevant_dofs(dof_handler, locally_relevant_dofs);

    // Hanging nodes, and the base bonded to the rigid foundation.
    constraints.clear();
    constraints.reinit(locally_relevant_dofs);
    DoFTools::make_hanging_node_constraints(dof_handler, constraints);
    VectorTools::interpolate_boundary_values(dof_handler,
                                             bottom_boundary,
                                             Functions::ZeroFunction<dim>(dim),
                                             constraints);
    constraints.close();

    TrilinosWrappers::SparsityPattern sp(locally_owned_dofs,
                                         locally_owned_dofs,
                                         locally_relevant_dofs,
                                         mpi_communicator);
    DoFTools::make_sparsity_pattern(dof_handler,
                                    sp,
                                    constraints,
                                    false,
                                    Utilities::MPI::this_mpi_process(
                                      mpi_communicator));
    sp.compress();
    // The solver objects refer to the old matrix: release them first.
    direct_solver.reset();
    amg.reset();
    system_matrix.reinit(sp);

    solution.reinit(locally_owned_dofs,
                    locally_relevant_dofs,
                    mpi_communicator);
    old_solution.reinit(solution);
    last_increment.reinit(solution);
    system_rhs.reinit(locally_owned_dofs, mpi_communicator);
    delta_coupling.reinit(system_rhs);
    newton_update.reinit(system_rhs);
    for (auto &h : history)
      h.reinit(history_dof_handler.locally_owned_dofs(), mpi_communicator);
  }


  ArmStress
  ContactProblem::arm_stress_at(const std::vector<double> &values,
                                const unsigned int         arm,
                                const unsigned int         q) const
  {
    const unsigned int n     = quadrature.size();
    const unsigned int first = n_arm_stress_components * arm;
    ArmStress          h;
    h.in_plane[0][0] = values[(first + h_xx) * n + q];
    h.in_plane[1][1] = values[(first + h_yy) * n + q];
    h.in_plane[0][1] = values[(first + h_xy) * n + q];
    h.zz             = values[(first + h_zz) * n + q];
    return h;
  }


  // The history values of a cell of dof_handler, component-major:
  // values[c * n_q + q].
  void
  ContactProblem::read_cell_history(
    const DoFHandler<dim>::active_cell_iterator &cell,
    std::vector<double>                         &values,
    std::vector<types::global_dof_index>        &dofs) const
  {
    const DoFHandler<dim>::active_cell_iterator history_cell(
      &triangulation, cell->level(), cell->index(), &history_dof_handler);
    history_cell->get_dof_indices(dofs);
    const unsigned int n = quadrature_to_history_dof.size();
    values.resize(history.size() * n);
    for (unsigned int c = 0; c < history.size(); ++c)
      for (unsigned int q = 0; q < n; ++q)
        values[c * n + q] = history[c](dofs[quadrature_to_history_dof[q]]);
  }


  // Residual -R(u) and, if asked, the consistent tangent dR/du of
  //   R(u)(v) = (sigma(u), eps(v)) - <p_LJ(g(u)), v_y>_top
  //             + c <u_y - u_y^anchor, v_y>_top.
  // The last term only acts during relaxation after an instability
  // (surface_damping = c > 0, see relax()).
  void
  ContactProblem::assemble(const bool with_matrix)
  {
    TimerOutput::Scope t(timer, with_matrix ? "assemble" : "assemble residual");
    if (with_matrix)
      system_matrix = 0;
    system_rhs = 0;
    if (force_control)
      delta_coupling = 0;
    double force = 0., delta_stiff = 0.;

    FEValues<dim>                    fe_values(fe,
                            quadrature,
                            update_gradients | update_JxW_values);
    FEFaceValues<dim>                face_values(fe,
                                  face_quadrature,
                                  update_values | update_quadrature_points |
                                    update_JxW_values);
    const FEValuesExtractors::Vector displacement(0);
    const FEValuesExtractors::Scalar uy(1);

    const unsigned int dofs_per_cell = fe.n_dofs_per_cell();
    const unsigned int n_q           = quadrature.size();
    FullMatrix<double> cell_matrix(dofs_per_cell, dofs_per_cell);
    Vector<double>     cell_rhs(dofs_per_cell), cell_coupling(dofs_per_cell);
    std::vector<types::global_dof_index> local_dofs(dofs_per_cell);
    std::vector<types::global_dof_index> history_dofs(
      history_fe.n_dofs_per_cell());
    std::vector<double>                  history_values;
    std::vector<SymmetricTensor<2, dim>> strain(n_q), old_strain(n_q);
    std::vector<SymmetricTensor<2, dim>> sym_grad_phi(dofs_per_cell);
    std::vector<double>                  u_y(face_quadrature.size()),
      anchor_u_y(face_quadrature.size());
    std::vector<double> phi_y(dofs_per_cell);

    const auto                  factors   = material.step_factors(current.dt);
    const SymmetricTensor<4, 2> C         = material.tangent(factors);
    double                      abs_force = 0.;

    for (const auto &cell : dof_handler.active_cell_iterators())
      if (cell->is_locally_owned())
        {
          cell_matrix   = 0;
          cell_rhs      = 0;
          cell_coupling = 0;
          fe_values.reinit(cell);
          fe_values[displacement].get_function_symmetric_gradients(solution,
                                                                   strain);
          fe_values[displacement].get_function_symmetric_gradients(old_solution,
                                                                   old_strain);
          read_cell_history(cell, history_values, history_dofs);

          for (unsigned int q = 0; q < n_q; ++q)
            {
              ArmStress h;
              for (unsigned int k = 0; k < material.n_arms(); ++k)
                {
                  const ArmStress h_k = material.updated_arm_stress(
                    k,
                    arm_stress_at(history_values, k, q),
                    strain[q] - old_strain[q],
                    factors[k]);
                  h += h_k;
                }
              const SymmetricTensor<2, dim> sigma =
                material.stress(strain[q], h);
              const double JxW = fe_values.JxW(q);
              for (unsigned int i = 0; i < dofs_per_cell; ++i)
                sym_grad_phi[i] =
                  fe_values[displacement].symmetric_gradient(i, q);
              for (unsigned int i = 0; i < dofs_per_cell; ++i)
                {
                  cell_rhs(i) -= sigma * sym_grad_phi[i] * JxW;
                  if (with_matrix)
                    {
                      const SymmetricTensor<2, dim> C_phi_i =
                        C * sym_grad_phi[i];
                      for (unsigned int j = 0; j < dofs_per_cell; ++j)
                        cell_matrix(i, j) += C_phi_i * sym_grad_phi[j] * JxW;
                    }
                }
            }

          for (const unsigned int f : cell->face_indices())
            if (cell->face(f)->at_boundary() &&
                cell->face(f)->boundary_id() == top_boundary)
              {
                face_values.reinit(cell, f);
                face_values[uy].get_function_values(solution, u_y);
                if (surface_damping > 0)
                  face_values[uy].get_function_values(relaxation_anchor,
                                                      anchor_u_y);
                for (unsigned int q = 0; q < face_quadrature.size(); ++q)
                  {
                    const double g         = gap(*indenter,
                                         scales.eps,
                                         current.delta,
                                         current.s,
                                         face_values.quadrature_point(q)[0],
                                         u_y[q]);
                    double       traction  = law->traction(g);
                    const double dp_dg     = law->derivative(g);
                    double       stiffness = dp_dg;
                    const double JxW       = face_values.JxW(q);
                    abs_force += std::abs(traction) * JxW;
                    force -= traction * JxW;
                    delta_stiff += dp_dg * JxW;
                    if (surface_damping > 0)
                      {
                        traction -= surface_damping * (u_y[q] - anchor_u_y[q]);
                        stiffness += surface_damping;
                      }
                    for (unsigned int i = 0; i < dofs_per_cell; ++i)
                      phi_y[i] = face_values[uy].value(i, q);
                    for (unsigned int i = 0; i < dofs_per_cell; ++i)
                      {
                        cell_rhs(i) += traction * phi_y[i] * JxW;
                        cell_coupling(i) += dp_dg * phi_y[i] * JxW;
                        if (with_matrix)
                          for (unsigned int j = 0; j < dofs_per_cell; ++j)
                            cell_matrix(i, j) +=
                              stiffness * phi_y[i] * phi_y[j] * JxW;
                      }
                  }
              }

          cell->get_dof_indices(local_dofs);
          if (force_control)
            constraints.distribute_local_to_global(cell_coupling,
                                                   local_dofs,
                                                   delta_coupling);
          if (with_matrix)
            constraints.distribute_local_to_global(
              cell_matrix, cell_rhs, local_dofs, system_matrix, system_rhs);
          else
            constraints.distribute_local_to_global(cell_rhs,
                                                   local_dofs,
                                                   system_rhs);
        }
    if (with_matrix)
      system_matrix.compress(VectorOperation::add);
    system_rhs.compress(VectorOperation::add);
    traction_scale = Utilities::MPI::sum(abs_force, mpi_communicator);
    if (force_control)
      {
        delta_coupling.compress(VectorOperation::add);
        // Under spring control the force to hold follows delta.
        force_mismatch = Utilities::MPI::sum(force, mpi_communicator) -
                         target_force -
                         spring_stiffness * (spring_delta - current.delta);
        delta_stiffness =
          Utilities::MPI::sum(delta_stiff, mpi_communicator) + spring_stiffness;
      }
  }


  void
  ContactProblem::prepare_linear_solver()
  {
    TimerOutput::Scope t(timer, "linear solve");
    const bool         direct =
      prm.solver.linear_solver == "direct" ||
      (prm.solver.linear_solver == "automatic" &&
       dof_handler.n_dofs() <= prm.solver.direct_solver_limit);
    direct_solver.reset();
    amg.reset();
    if (direct)
      {
        direct_solver = factorize(system_matrix);
      }
    else
      {
        TrilinosWrappers::PreconditionAMG::AdditionalData data;
        std::vector<std::vector<bool>>                    modes;
        DoFTools::extract_constant_modes(dof_handler,
                                         ComponentMask(dim, true),
                                         modes);
        data.constant_modes        = modes;
        data.elliptic              = true;
        data.higher_order_elements = true;
        data.smoother_sweeps       = 2;
        data.aggregation_threshold = 0.02;
        amg = std::make_unique<TrilinosWrappers::PreconditionAMG>();
        amg->initialize(system_matrix, data);
      }
  }


  void
  ContactProblem::solve(const TrilinosWrappers::MPI::Vector &rhs,
                        TrilinosWrappers::MPI::Vector       &x)
  {
    TimerOutput::Scope t(timer, "linear solve");
    x.reinit(locally_owned_dofs, mpi_communicator);
    if (direct_solver)
      direct_solver->solve(x, rhs);
    else
      {
        // The tangent is indefinite where p_LJ' < 0, so GMRES, not CG.
        SolverControl control(2000, 1e-10 * rhs.l2_norm());
        SolverGMRES<TrilinosWrappers::MPI::Vector> solver(
          control,
          SolverGMRES<TrilinosWrappers::MPI::Vector>::AdditionalData(200));
        solver.solve(system_matrix, x, rhs, *amg);
      }
    constraints.distribute(x);
  }


  // Under force control the bordered system
  //   [K   b] [du    ]   [-R]
  //   [b^T d] [ddelta] = [-G],   G = Fn - target,
  // is solved with one factorization of K and two solves.
  void
  ContactProblem::solve_newton_system()
  {
    prepare_linear_solver();
    TrilinosWrappers::MPI::Vector x1;
    solve(system_rhs, x1);
    delta_update = 0.;
    if (force_control)
      {
        TrilinosWrappers::MPI::Vector x2;
        solve(delta_coupling, x2);
        delta_update = (-force_mismatch - (delta_coupling * x1)) /
                       (delta_stiffness - (delta_coupling * x2));
        x1.add(-delta_update, x2);
      }
    newton_update = x1;
  }


  double
  ContactProblem::residual_norm() const
  {
    const double r = system_rhs.l2_norm();
    return force_control ? std::hypot(r, force_mismatch) : r;
  }


  NewtonProblem
  ContactProblem::newton_problem(TrilinosWrappers::MPI::Vector &u0,
                                 double                        &delta0)
  {
    const double floor =
      scales.sigma_max * prm.mesh.finest_cell; // one loaded finest cell
    NewtonProblem problem;
    problem.assemble      = [this](const bool m) { assemble(m); };
    problem.residual_norm = [this] { return residual_norm(); };
    problem.tolerance     = [this, floor] {
      return prm.solver.newton_tolerance * (traction_scale + floor);
    };
    problem.compute_update = [this] { solve_newton_system(); };
    return with_iterate(problem,
                        {solution,
                         current.delta,
                         newton_update,
                         delta_update,
                         surface_damping,
                         relaxation_anchor},
                        u0,
                        delta0);
  }


  int
  ContactProblem::solve_newton(const LoadState &target)
  {
    current = target;
    TrilinosWrappers::MPI::Vector u0(locally_owned_dofs, mpi_communicator);
    double                        delta0 = current.delta;
    return newton(newton_problem(u0, delta0),
                  prm.solver.max_newton_iterations,
                  prm.solver.line_search,
                  prm.solver.verbose,
                  pcout);
  }


  // After a jump-in or jump-out no equilibrium is near the last one, and
  // Newton cannot get there: relax() follows the fictitious dynamics of a
  // surface dashpot instead. Its initial stiffness is that of the traction
  // law's wall, and a pseudo-step should move the surface by about half
  // an eps.
  int
  ContactProblem::relax_to_equilibrium(const LoadState &target)
  {
    TimerOutput::Scope t(timer, "relaxation");
    current = target;
    relaxation_anchor.reinit(solution);
    TrilinosWrappers::MPI::Vector u0(locally_owned_dofs, mpi_communicator);
    double                        delta0 = current.delta;
    const int                     steps  = relax(newton_problem(u0, delta0),
                            16. * scales.dgamma / (scales.eps * scales.eps),
                            0.5 * scales.eps,
                            prm.solver.max_relaxation_steps,
                            prm.solver.verbose,
                            pcout);
    surface_damping                      = 0.;
    return steps;
  }


  // Steps from the committed state to `target`, in as few substeps as
  // Newton allows. Each accepted substep is solved on a mesh adapted to its
  // own solution, committed and recorded.
  bool
  ContactProblem::advance_to(const LoadState &target, const std::string &phase)
  {
    const LoadState start    = committed;
    const double    span     = std::abs(target.delta - start.delta);
    double          done     = 0.;
    double          fraction = 1.;
    unsigned int    cuts     = 0;
    auto            at       = [&](const double f) {
      LoadState s;
      s.delta = start.delta + f * (target.delta - start.delta);
      s.s     = start.s + f * (target.s - start.s);
      s.time  = start.time + f * (target.time - start.time);
      return s;
    };

    while (done < 1. - 1e-12)
      {
        fraction           = std::min(fraction, 1. - done);
        LoadState trial    = at(done + fraction);
        trial.dt           = std::isfinite(target.dt)
                               ? trial.time - at(done).time
                               : std::numeric_limits<double>::infinity();
        const auto backup  = solution;
        bool       relaxed = false;
        int        its     = -1;
        // Along a smooth branch the secant predictor saves most of the
        // Newton iterations; if it does not help, start from the last state.
        const double ratio =
          (trial.s != committed.s && last_increment_s != 0.)
            ? (trial.s - committed.s) / last_increment_s
            : (last_increment_delta != 0.
                 ? (trial.delta - committed.delta) / last_increment_delta
                 : 0.);
        if (ratio != 0. && std::abs(ratio) <= 4.)
          {
            TrilinosWrappers::MPI::Vector predicted(locally_owned_dofs,
                                                    mpi_communicator);
            predicted = solution;
            TrilinosWrappers::MPI::Vector increment(locally_owned_dofs,
                                                    mpi_communicator);
            increment = last_increment;
            predicted.add(ratio, increment);
            solution                  = predicted;
            LoadState predicted_state = trial;
            if (force_control)
              predicted_state.delta += ratio * last_increment_delta;
            its = solve_newton(predicted_state);
            if (its < 0)
              solution = backup;
          }
        if (its < 0)
          its = solve_newton(trial);
        if (its < 0)
          {
            solution = backup;
            // Steps that do not change delta (hold, sliding) are cut down
            // to 1/64; a step that changes nothing (the start) is not cut.
            const bool moves = target.s != start.s || target.time != start.time;
            if (span > 0
                  ? fraction * span > prm.loading.minimum_increment * 1.0001
                  : moves && fraction > 1. / 64.)
              {
                fraction *= 0.5;
                ++cuts;
                continue;
              }
            pcout << "   Instability at delta_hat = " << trial.delta
                  << ": relaxing to the new branch\n";
            its     = relax_to_equilibrium(trial);
            relaxed = true;
            if (its < 0)
              return false;
          }
        for (unsigned int cycle = 0; cycle < prm.mesh.max_adaptation_cycles;
             ++cycle)
          {
            if (!adapt_mesh())
              break;
            const LoadState converged = current; // under force control
                                                 // delta is part of it
            int more = solve_newton(converged);
            if (more < 0)
              more = relax_to_equilibrium(converged);
            if (more < 0)
              return false;
            its += more;
          }
        commit_history();
        done += fraction;
        last_newton_iterations = its;
        last_step_cuts         = cuts;
        last_step_relaxed      = relaxed;
        record_step(phase);
        cuts = 0;
        fraction *= 2.; // try to recover the full increment
      }
    return true;
  }


  void
  ContactProblem::commit_history()
  {
    TimerOutput::Scope t(timer, "history update");
    FEValues<dim>      fe_values(fe, quadrature, update_gradients);
    const FEValuesExtractors::Vector     displacement(0);
    const unsigned int                   n_q = quadrature.size();
    std::vector<types::global_dof_index> history_dofs(
      history_fe.n_dofs_per_cell());
    std::vector<double>                  values;
    std::vector<SymmetricTensor<2, dim>> strain(n_q), old_strain(n_q);
    const auto factors = material.step_factors(current.dt);

    for (const auto &cell : dof_handler.active_cell_iterators())
      if (cell->is_locally_owned())
        {
          fe_values.reinit(cell);
          fe_values[displacement].get_function_symmetric_gradients(solution,
                                                                   strain);
          fe_values[displacement].get_function_symmetric_gradients(old_solution,
                                                                   old_strain);
          read_cell_history(cell, values, history_dofs);
          for (unsigned int q = 0; q < n_q; ++q)
            {
              const auto i = history_dofs[quadrature_to_history_dof[q]];
              double     dissipated = 0.;
              for (unsigned int k = 0; k < material.n_arms(); ++k)
                {
                  const ArmStress old_h = arm_stress_at(values, k, q);
                  const ArmStress h     = material.updated_arm_stress(
                    k, old_h, strain[q] - old_strain[q], factors[k]);
                  const unsigned int first = n_arm_stress_components * k;
                  history[first + h_xx](i) = h.in_plane[0][0];
                  history[first + h_yy](i) = h.in_plane[1][1];
                  history[first + h_xy](i) = h.in_plane[0][1];
                  history[first + h_zz](i) = h.zz;
                  dissipated +=
                    material.dissipated_energy(k, old_h, h, current.dt);
                }
              history[dissipated_energy()](i) += dissipated;
            }
        }
    for (auto &h : history)
      h.compress(VectorOperation::insert);
    TrilinosWrappers::MPI::Vector increment(locally_owned_dofs,
                                            mpi_communicator),
      old(locally_owned_dofs, mpi_communicator);
    increment = solution;
    old       = old_solution;
    increment -= old;
    last_increment       = increment;
    last_increment_delta = current.delta - committed.delta;
    last_increment_s     = current.s - committed.s;
    old_solution         = solution;
    committed            = current;
  }


  // Refines at the contact edges (flag_cells_near_edges()) and transfers
  // solution, last committed solution and history. Returns whether the
  // mesh changed.
  bool
  ContactProblem::adapt_mesh()
  {
    TimerOutput::Scope t(timer, "adapt mesh");
    auto               edges = postprocessor.faces_in_gap_band(dof_handler,
                                                 solution,
                                                 current.delta,
                                                 current.s,
                                                 prm.mesh.edge_gap_low,
                                                 prm.mesh.edge_gap_high);
    if (edges.empty()) // no contact yet: resolve the region under the apex
      edges.emplace_back(current.s, current.s);

    if (!flag_cells_near_edges(triangulation, edges, prm))
      return false;

    parallel::distributed::SolutionTransfer<dim, TrilinosWrappers::MPI::Vector>
      solution_transfer(dof_handler), history_transfer(history_dof_handler);
    solution_transfer.prepare_for_coarsening_and_refinement(
      std::vector<const TrilinosWrappers::MPI::Vector *>{&solution,
                                                         &old_solution,
                                                         &last_increment});
    const auto ghosted = ghosted_history();
    std::vector<const TrilinosWrappers::MPI::Vector *> in;
    for (const auto &h : ghosted)
      in.push_back(&h);
    history_transfer.prepare_for_coarsening_and_refinement(in);

    triangulation.execute_coarsening_and_refinement();
    setup_system();

    TrilinosWrappers::MPI::Vector u(locally_owned_dofs, mpi_communicator),
      u_old(locally_owned_dofs, mpi_communicator),
      du(locally_owned_dofs, mpi_communicator);
    std::vector<TrilinosWrappers::MPI::Vector *> out{&u, &u_old, &du};
    solution_transfer.interpolate(out);
    constraints.distribute(u);
    constraints.distribute(u_old);
    constraints.distribute(du);
    solution       = u;
    old_solution   = u_old;
    last_increment = du;

    std::vector<TrilinosWrappers::MPI::Vector *> history_out;
    for (auto &h : history)
      history_out.push_back(&h);
    history_transfer.interpolate(history_out);
    return true;
  }


  void
  ContactProblem::refine_initial_mesh()
  {
    for (unsigned int i = 0; i < 64 && adapt_mesh(); ++i)
      ;
  }


  // SolutionTransfer needs the history with the ghost values of the
  // cells' neighbours.
  std::vector<TrilinosWrappers::MPI::Vector>
  ContactProblem::ghosted_history() const
  {
    IndexSet relevant;
    DoFTools::extract_locally_relevant_dofs(history_dof_handler, relevant);
    std::vector<TrilinosWrappers::MPI::Vector> ghosted(history.size());
    for (unsigned int c = 0; c < history.size(); ++c)
      {
        ghosted[c].reinit(history_dof_handler.locally_owned_dofs(),
                          relevant,
                          mpi_communicator);
        ghosted[c] = history[c];
      }
    return ghosted;
  }


  // A checkpoint of the transient sliding phase, taken between two steps:
  // the mesh with the committed solution, the predictor and the history
  // attached (the same SolutionTransfer that carries them through
  // refinement serializes them with p4est), and every scalar the sliding
  // loop needs in state.txt, the doubles in hexadecimal so that a resumed
  // run continues bit for bit. It is written into checkpoint.tmp/, which
  // then replaces checkpoint/, so that a kill at any moment leaves one
  // complete checkpoint.
  void
  ContactProblem::write_checkpoint()
  {
    TimerOutput::Scope t(timer, "checkpoint");
    namespace fs       = std::filesystem;
    const fs::path dir = writer.path("checkpoint"),
                   tmp = writer.path("checkpoint.tmp"),
                   old = writer.path("checkpoint.old");
    const bool root = Utilities::MPI::this_mpi_process(mpi_communicator) == 0;
    if (root)
      {
        fs::remove_all(tmp);
        fs::create_directories(tmp);
      }
    MPI_Barrier(mpi_communicator);

    parallel::distributed::SolutionTransfer<dim, TrilinosWrappers::MPI::Vector>
      solution_transfer(dof_handler), history_transfer(history_dof_handler);
    solution_transfer.prepare_for_serialization(
      std::vector<const TrilinosWrappers::MPI::Vector *>{&old_solution,
                                                         &last_increment});
    const auto ghosted = ghosted_history();
    std::vector<const TrilinosWrappers::MPI::Vector *> in;
    for (const auto &h : ghosted)
      in.push_back(&h);
    history_transfer.prepare_for_serialization(in);
    triangulation.save((tmp / "mesh").string());

    if (root)
      {
        std::ostringstream out;
        out << std::hexfloat << "viscoslide-checkpoint 1\n"
            << "step_number " << step_number << "\nhistory_rows "
            << history_rows << "\napproach_rows " << approach_rows
            << "\ncommitted " << committed.delta << " " << committed.s << " "
            << committed.time << " " << committed.dt << "\nlast_increment "
            << last_increment_delta << " " << last_increment_s
            << "\ntarget_force " << target_force << " " << spring_delta
            << "\nplan " << slide_plan.s0 << " " << slide_plan.L0 << " "
            << slide_plan.distance << " " << slide_plan.window << "\nsamples "
            << samples.size() << "\n";
        for (const auto &x : samples)
          {
            out << x.s;
            for (const double v : x.value)
              out << " " << v;
            out << "\n";
          }
        write_atomically((tmp / "state.txt").string(), out.str());
        if (fs::exists(dir))
          fs::rename(dir, old);
        fs::rename(tmp, dir);
        fs::remove_all(old);
      }
    MPI_Barrier(mpi_communicator);
  }


  bool
  ContactProblem::has_checkpoint(const std::string &directory)
  {
    namespace fs = std::filesystem;
    return fs::exists(fs::path(directory) / "checkpoint" / "state.txt");
  }


  // The inverse of write_checkpoint(), in place of setup, approach and the
  // start of the sliding phase. A checkpoint left as checkpoint.old by a
  // kill between the two renames is taken back first.
  void
  ContactProblem::read_checkpoint()
  {
    namespace fs       = std::filesystem;
    const fs::path dir = writer.path("checkpoint");
    const fs::path old = writer.path("checkpoint.old");
    if (Utilities::MPI::this_mpi_process(mpi_communicator) == 0 &&
        !fs::exists(dir) && fs::exists(old))
      fs::rename(old, dir);
    MPI_Barrier(mpi_communicator);
    std::ifstream in(dir / "state.txt");
    if (!in)
      throw Parameters::ExcInvalidInput("no checkpoint to resume from in '" +
                                        dir.string() + "'");
    // operator>> of libstdc++ does not read hexfloats; strtod does.
    auto next = [&](const char *name) {
      std::string word;
      if (name != nullptr && (!(in >> word) || word != name))
        throw Parameters::ExcInvalidInput("checkpoint '" + dir.string() +
                                          "/state.txt' is damaged (expected '" +
                                          name + "')");
      in >> word;
      if (!in)
        throw Parameters::ExcInvalidInput("checkpoint '" + dir.string() +
                                          "/state.txt' is truncated");
      return std::strtod(word.c_str(), nullptr);
    };
    if (next("viscoslide-checkpoint") != 1)
      throw Parameters::ExcInvalidInput("checkpoint '" + dir.string() +
                                        "' has another version");
    step_number          = static_cast<unsigned int>(next("step_number"));
    history_rows         = static_cast<unsigned int>(next("history_rows"));
    approach_rows        = static_cast<unsigned int>(next("approach_rows"));
    committed.delta      = next("committed");
    committed.s          = next(nullptr);
    committed.time       = next(nullptr);
    committed.dt         = next(nullptr);
    last_increment_delta = next("last_increment");
    last_increment_s     = next(nullptr);
    target_force         = next("target_force");
    spring_delta         = next(nullptr);
    slide_plan.s0        = next("plan");
    slide_plan.L0        = next(nullptr);
    slide_plan.distance  = next(nullptr);
    slide_plan.window    = next(nullptr);
    samples.resize(static_cast<std::size_t>(next("samples")));
    for (auto &x : samples)
      {
        x.s = next(nullptr);
        for (double &v : x.value)
          v = next(nullptr);
      }
    current = committed;

    make_block(triangulation, prm);
    triangulation.load((dir / "mesh").string());
    setup_system();
    parallel::distributed::SolutionTransfer<dim, TrilinosWrappers::MPI::Vector>
      solution_transfer(dof_handler), history_transfer(history_dof_handler);
    TrilinosWrappers::MPI::Vector u_old(locally_owned_dofs, mpi_communicator),
      du(locally_owned_dofs, mpi_communicator);
    std::vector<TrilinosWrappers::MPI::Vector *> out{&u_old, &du};
    solution_transfer.deserialize(out);
    old_solution   = u_old;
    solution       = u_old;
    last_increment = du;
    std::vector<TrilinosWrappers::MPI::Vector *> history_out;
    for (auto &h : history)
      history_out.push_back(&h);
    history_transfer.deserialize(history_out);
  }


  void
  ContactProblem::record_step(const std::string &phase)
  {
    TimerOutput::Scope t(timer, "postprocessing");
    const auto         sq = postprocessor.integrate(dof_handler,
                                            solution,
                                            committed.delta,
                                            committed.s);
    last_quantities       = sq;
    last_dissipation_rate = total_dissipation_rate();
    using F               = CsvTable;
    if (phase == "slide")
      {
        ++history_rows;
        const double V = prm.sliding.speed * scales.eps / scales.tau_ref;
        const double rate =
          last_dissipation_rate * scales.tau_ref / (scales.force * scales.eps);
        history_table->add_row(
          {F::format(committed.time / scales.tau_ref),
           F::format(committed.s / scales.eps),
           F::format(committed.delta / scales.eps),
           F::format(sq.normal_force / scales.force),
           F::format(sq.tangential_force / scales.force),
           F::format(sq.profile_force / scales.force),
           F::format(std::abs(sq.tangential_force / sq.normal_force)),
           F::format(sq.contact_length / scales.R),
           F::format(rate),
           F::format(std::abs(last_dissipation_rate / V / sq.normal_force)),
           std::to_string(last_newton_iterations),
           std::to_string(dof_handler.n_dofs())});
      }
    else
      {
        ++approach_rows;
        approach_table->add_row(
          {std::to_string(step_number),
           phase,
           F::format(committed.time / scales.tau_ref),
           F::format(committed.delta / scales.eps),
           F::format(sq.normal_force / scales.force),
           F::format(sq.tangential_force / scales.force),
           F::format(sq.contact_length / scales.R),
           F::format(sq.minimum_gap / scales.eps),
           std::to_string(last_newton_iterations),
           std::to_string(last_step_cuts),
           std::to_string(last_step_relaxed ? 1 : 0),
           std::to_string(dof_handler.n_dofs()),
           std::to_string(triangulation.n_global_active_cells())});
      }
    pcout << "  step " << std::setw(4) << step_number << "  " << std::setw(8)
          << phase << "  delta_hat " << std::setw(9) << committed.delta
          << "  F_hat " << std::setw(12) << sq.normal_force / scales.force
          << "  L_hat " << std::setw(11) << sq.contact_length / scales.R
          << "  Newton " << last_newton_iterations << "  dofs "
          << dof_handler.n_dofs() << (last_step_relaxed ? "  (jump)" : "");
    if (phase == "slide")
      pcout << "  s " << slid << "/" << slide_distance << " eps";
    if (progress != nullptr)
      pcout << "  ["
            << progress->report(phase == "slide" ? slid / slide_distance : 0.)
            << "]";
    pcout << std::endl;

    if (prm.output.profile_every > 0 &&
        step_number % prm.output.profile_every == 0)
      write_profile("surface_profile-" +
                    Utilities::int_to_string(step_number, 5) + ".csv");
    if (prm.output.write_fields && prm.output.fields_every > 0 &&
        step_number % prm.output.fields_every == 0)
      write_fields();
    ++step_number;
  }


  void
  ContactProblem::write_profile(const std::string &filename)
  {
    write_profile_csv(writer.path(filename),
                      postprocessor.profile(
                        dof_handler, solution, committed.delta, committed.s),
                      scales,
                      "delta_hat = " + CsvTable::format(committed.delta) +
                        ", time_over_tau = " + CsvTable::format(committed.time),
                      mpi_communicator);
  }


  // Volume fields (displacement, stress from the quadrature points,
  // dissipation rate and accumulated dissipated energy, MPI subdomain,
  // refinement level) and surface fields (pressure, gap).
  void
  ContactProblem::write_fields()
  {
    TimerOutput::Scope t(timer, "output");
    enum
    {
      s_xx,
      s_yy,
      s_xy,
      s_zz,
      D,
      n_fields
    };
    std::array<TrilinosWrappers::MPI::Vector, n_fields> fields;
    for (auto &f : fields)
      f.reinit(history_dof_handler.locally_owned_dofs(), mpi_communicator);

    FEValues<dim> fe_values(fe, quadrature, update_gradients);
    const FEValuesExtractors::Vector     displacement(0);
    std::vector<SymmetricTensor<2, dim>> strain(quadrature.size());
    std::vector<types::global_dof_index> history_dofs(
      history_fe.n_dofs_per_cell());
    std::vector<double> values;
    for (const auto &cell : dof_handler.active_cell_iterators())
      if (cell->is_locally_owned())
        {
          fe_values.reinit(cell);
          fe_values[displacement].get_function_symmetric_gradients(solution,
                                                                   strain);
          read_cell_history(cell, values, history_dofs);
          for (unsigned int q = 0; q < quadrature.size(); ++q)
            {
              ArmStress h;
              double    rate = 0.;
              for (unsigned int k = 0; k < material.n_arms(); ++k)
                {
                  const ArmStress h_k = arm_stress_at(values, k, q);
                  h += h_k;
                  rate += material.dissipation_rate(k, h_k);
                }
              const auto sigma = material.stress(strain[q], h);
              const auto i     = history_dofs[quadrature_to_history_dof[q]];
              fields[s_xx](i)  = sigma[0][0];
              fields[s_yy](i)  = sigma[1][1];
              fields[s_xy](i)  = sigma[0][1];
              fields[s_zz](i)  = material.stress_zz(strain[q], h);
              fields[D](i)     = rate;
            }
        }
    for (auto &f : fields)
      f.compress(VectorOperation::insert);

    Vector<float> subdomain(triangulation.n_active_cells()),
      level(triangulation.n_active_cells());
    for (const auto &cell : triangulation.active_cell_iterators())
      if (cell->is_locally_owned())
        {
          subdomain(cell->active_cell_index()) = cell->subdomain_id();
          level(cell->active_cell_index())     = cell->level();
        }

    DataOut<dim> data_out;
    data_out.attach_triangulation(triangulation);
    data_out.add_data_vector(dof_handler,
                             solution,
                             std::vector<std::string>(dim, "displacement"),
                             vector_interpretation());
    const char *names[n_fields] = {
      "stress_xx", "stress_yy", "stress_xy", "stress_zz", "dissipation_rate"};
    for (unsigned int f = 0; f < n_fields; ++f)
      data_out.add_data_vector(history_dof_handler, fields[f], names[f]);
    data_out.add_data_vector(history_dof_handler,
                             history[dissipated_energy()],
                             "dissipated_energy");
    // The paper's Fig. 5 shows it in units of dgamma/L (L the present
    // contact length); zero while there is no contact.
    TrilinosWrappers::MPI::Vector energy_hat(history[dissipated_energy()]);
    energy_hat *= last_quantities.contact_length / scales.dgamma;
    data_out.add_data_vector(history_dof_handler,
                             energy_hat,
                             "dissipated_energy_hat");
    data_out.add_data_vector(subdomain, "subdomain");
    data_out.add_data_vector(level, "level");
    data_out.build_patches(2);
    writer.write(data_out, "solution", step_number, committed.time);

    SurfaceFields     surface_fields(*law, *indenter, scales, committed);
    TopSurfaceDataOut surface_out;
    surface_out.attach_dof_handler(dof_handler);
    surface_out.add_data_vector(solution, surface_fields);
    surface_out.build_patches(2);
    writer.write(static_cast<const DataOutFaces<dim> &>(surface_out),
                 "surface",
                 step_number,
                 committed.time);
  }


  void
  ContactProblem::abort_run(const LoadState &target)
  {
    write_profile("surface_profile_last_converged.csv");
    throw std::runtime_error(
      "Newton failed at step " + std::to_string(step_number) +
      " (delta_hat = " + std::to_string(target.delta) +
      ", s_over_eps = " + std::to_string(target.s) +
      ", time_over_tau = " + std::to_string(target.time) +
      ") even after cutting the step and relaxing to a new branch; the "
      "last converged surface profile is in "
      "surface_profile_last_converged.csv");
  }


  // integral of D dA at the committed state.
  double
  ContactProblem::total_dissipation_rate() const
  {
    FEValues<dim> fe_values(fe, quadrature, update_JxW_values);
    std::vector<types::global_dof_index> history_dofs(
      history_fe.n_dofs_per_cell());
    std::vector<double> values;
    double              rate = 0.;
    for (const auto &cell : dof_handler.active_cell_iterators())
      if (cell->is_locally_owned())
        {
          fe_values.reinit(cell);
          read_cell_history(cell, values, history_dofs);
          for (unsigned int q = 0; q < quadrature.size(); ++q)
            for (unsigned int k = 0; k < material.n_arms(); ++k)
              rate +=
                material.dissipation_rate(k, arm_stress_at(values, k, q)) *
                fe_values.JxW(q);
        }
    return Utilities::MPI::sum(rate, mpi_communicator);
  }


  // The paper fixes some cases by their load F_hat, reached by a
  // displacement-controlled approach. Approach in the usual steps until
  // F_n (which rises with delta once contact is made) passes the target,
  // then solve that step again with F_n held at the target and delta free.
  void
  ContactProblem::approach_to_load()
  {
    const double       F    = prm.loading.target_load * scales.force;
    const double       from = committed.delta, to = prm.loading.final_approach;
    const unsigned int n =
      std::max(1., std::ceil((to - from) / prm.loading.increment - 1e-9));
    bool passed = false;
    for (unsigned int k = 1; k <= n && !passed; ++k)
      {
        LoadState target = committed;
        target.delta     = from + (to - from) * k / n;
        if (!advance_to(target, "approach"))
          abort_run(target);
        passed =
          last_quantities.minimum_gap < prm.adhesion.contact_gap * scales.eps &&
          last_quantities.normal_force >= F;
      }
    if (!passed)
      throw Parameters::ExcInvalidInput(
        "'Loading/Target load' = " + CsvTable::format(prm.loading.target_load) +
        " was not reached by 'Loading/Final approach' = " +
        CsvTable::format(to) + " (F_n_hat there: " +
        CsvTable::format(last_quantities.normal_force / scales.force) +
        "); raise the Final approach");
    force_control = true;
    target_force  = F;
    if (!advance_to(committed, "load"))
      abort_run(committed);
    force_control = false;
    pcout << "Load F_hat = " << prm.loading.target_load
          << " reached at delta_hat = " << committed.delta / scales.eps
          << std::endl;
  }


  // Phase 2 of the paper: the profile h(x - s) moves with s = V t over the
  // fixed surface until Fn (or delta), Ft and L are steady over a window.
  // A resumed run starts from the plan and the samples of its checkpoint.
  void
  ContactProblem::slide(const bool resumed)
  {
    const double V     = prm.sliding.speed * scales.eps / scales.tau_ref;
    const double h_min = prm.mesh.finest_cell;
    const std::vector<std::string> columns{"time_over_tau",
                                           "s_over_eps",
                                           "delta_hat",
                                           "F_n_hat",
                                           "F_t_hat",
                                           "F_t_profile_hat",
                                           "mu",
                                           "L_hat",
                                           "dissipation_rate_hat",
                                           "mu_energy",
                                           "newton_iterations",
                                           "n_dofs"};
    const std::string              comment =
      version_string() + "; time unit: " + prm.material.time_constant + " time";
    if (!resumed)
      {
        auto &plan = slide_plan;
        plan.L0    = std::max(last_quantities.contact_length, 10. * h_min);
        const double tau_c = scales.tau_arm / prm.material.E0_over_Einf;
        // The relaxation length V tau_c sets the transient, but only as far
        // as it is comparable to the contact: faster than that, the
        // material crosses the contact unrelaxed and the contact is nearly
        // steady once the material deformed during the approach has left
        // it. Nearly: the approach's imprint in the wake recovers over
        // V tau_c and still pulls on the contact, by a few % in mu at
        // V_hat = 100 with adhesion (doc/steady_state.md); a 1 % answer
        // there needs a window of V tau_c (Sliding/Steady-state window)
        // or the steady-state solver. The cap keeps sweeps affordable.
        const double relaxation_length = std::min(V * tau_c, 4. * plan.L0);
        plan.distance                  = prm.sliding.max_distance > 0
                                           ? prm.sliding.max_distance
                                           : 4. * plan.L0 + 30. * relaxation_length;
        plan.window                    = prm.sliding.steady_window > 0
                                           ? prm.sliding.steady_window
                                           : std::max(plan.L0, 2. * relaxation_length);
        plan.s0                        = committed.s;
        if (plan.s0 + plan.distance + 2. * plan.L0 >
            prm.geometry.domain_width / 2)
          throw Parameters::ExcInvalidInput(
            "'Geometry/Domain width' = " +
            std::to_string(prm.geometry.domain_width) +
            " is too small to slide " + std::to_string(plan.distance) +
            " eps and stay 2 L = " + std::to_string(2 * plan.L0) +
            " eps away from the lateral boundary; it must be at least " +
            std::to_string(2 * (plan.s0 + plan.distance + 2 * plan.L0)) +
            " (or set 'Sliding/Maximum sliding distance')");
        target_force = last_quantities.normal_force;
        spring_delta = committed.delta;
        samples.clear();
        history_rows  = 0;
        history_table = std::make_unique<CsvTable>(writer.path("history.csv"),
                                                   columns,
                                                   comment,
                                                   mpi_communicator);
      }
    else
      history_table = std::make_unique<CsvTable>(writer.path("history.csv"),
                                                 columns,
                                                 history_rows,
                                                 mpi_communicator);
    const auto &plan = slide_plan;
    force_control    = prm.sliding.control != "displacement";
    spring_stiffness = spring_stiffness_of(prm, scales);
    const double ds  = prm.sliding.increment * h_min;
    const double dt  = ds / V;
    slide_distance   = plan.distance;
    slid             = committed.s - plan.s0;
    if (resumed && progress != nullptr)
      progress->resume_case(slid / slide_distance);
    pcout << (resumed ? "Resuming sliding" : "Sliding")
          << " at V_hat = " << prm.sliding.speed << " under "
          << prm.sliding.control << " control: up to " << plan.distance
          << " eps in steps of " << ds << " eps, steady over " << plan.window
          << " eps" << std::endl;

    // Steady state: the means of the controlled quantity's conjugate (Fn
    // or delta), Ft and L over the two halves of the last `window` of
    // sliding differ by less than the tolerance relative to their size (or
    // a floor for small values). Means, not single steps: with adhesion the
    // contact edges jump from node to node, and Ft (eq. 2) flickers with
    // the period of the finest cell by up to tens of percent where V tau is
    // below it, about a steady mean.
    using Sample   = SlideSample;
    auto in_window = [&](const double from, const double to) {
      Sample      mean{};
      std::size_t n = 0;
      for (const auto &x : samples)
        if (x.s > from && x.s <= to)
          {
            for (unsigned int k = 0; k < Sample::n_values; ++k)
              mean.value[k] += x.value[k];
            ++n;
          }
      for (double &v : mean.value)
        v /= std::max<std::size_t>(n, 1);
      return mean;
    };
    auto window_is_steady = [&] {
      const double end = committed.s;
      if (end - plan.s0 < plan.window + plan.L0)
        return false;
      const Sample first  = in_window(end - plan.window, end - plan.window / 2),
                   second = in_window(end - plan.window / 2, end);
      const unsigned int judged[3] = {force_control ? Sample::delta
                                                    : Sample::normal_force,
                                      Sample::tangential_force,
                                      Sample::contact_length};
      const double floor[3] = {force_control ? scales.eps : 1e-3 * scales.force,
                               1e-3 * std::abs(
                                        second.value[Sample::normal_force]) +
                                 1e-6 * scales.force,
                               h_min};
      for (unsigned int k = 0; k < 3; ++k)
        {
          const double size = std::max({floor[k],
                                        std::abs(first.value[judged[k]]),
                                        std::abs(second.value[judged[k]])});
          if (std::abs(second.value[judged[k]] - first.value[judged[k]]) >
              prm.sliding.steady_tolerance * size)
            return false;
        }
      return true;
    };

    // The steady values are the means over the last window (over all of
    // the sliding if it was shorter).
    auto report = [&](const bool steady) {
      const Sample mean   = in_window(committed.s - plan.window, committed.s);
      SurfaceQuantities q = last_quantities;
      q.normal_force      = mean.value[Sample::normal_force];
      q.tangential_force  = mean.value[Sample::tangential_force];
      q.profile_force     = mean.value[Sample::profile_force];
      q.contact_length    = mean.value[Sample::contact_length];
      write_steady_state(prm.sliding.speed,
                         mean.value[Sample::delta],
                         q,
                         mean.value[Sample::dissipation_rate],
                         steady,
                         committed.s - plan.s0,
                         "transient");
    };

    bool         steady           = false;
    unsigned int checkpointed_row = history_rows;
    while (committed.s - plan.s0 < plan.distance - 1e-9 * ds && !steady)
      {
        LoadState target = committed;
        target.s += ds;
        target.time += dt;
        target.dt = dt;
        slid      = target.s - plan.s0;
        if (!advance_to(target, "slide"))
          {
            // The case ends with the last converged state as its row,
            // flagged not steady; the reason is the exception's.
            if (!samples.empty())
              report(false);
            abort_run(target);
          }
        const auto &q = last_quantities;
        samples.push_back({committed.s,
                           {committed.delta,
                            q.normal_force,
                            q.tangential_force,
                            q.profile_force,
                            q.contact_length,
                            last_dissipation_rate}});
        steady = window_is_steady();
        if (!steady && prm.output.checkpoint_every > 0 &&
            history_rows >= checkpointed_row + prm.output.checkpoint_every)
          {
            write_checkpoint();
            checkpointed_row = history_rows;
          }
      }

    report(steady);
    write_profile("surface_profile_steady.csv");
    pcout << (steady ? "Steady state" : "NO steady state") << " after "
          << committed.s - plan.s0 << " eps" << std::endl;
    force_control    = false;
    spring_stiffness = 0.;
  }


  // The steady state solved directly in the indenter's frame, starting
  // from the relaxed state of the approach (see steady_state.h). The
  // triangulation then belongs to the steady-state solver: nothing of the
  // transient solution is used afterwards.
  void
  ContactProblem::slide_steady()
  {
    SteadyStateSolver steady(prm,
                             scales,
                             material,
                             *law,
                             *indenter,
                             postprocessor,
                             triangulation,
                             timer);
    steady.initialize(dof_handler, solution, committed.delta, committed.s);
    if (prm.sliding.control != "displacement")
      steady.hold_force(last_quantities.normal_force,
                        spring_stiffness_of(prm, scales));
    pcout << "Steady sliding at V_hat = " << prm.sliding.speed << " under "
          << prm.sliding.control << " control, by continuation from the "
          << "relaxed state" << std::endl;
    CsvTable table(writer.path("continuation.csv"),
                   {"V_hat",
                    "delta_hat",
                    "F_n_hat",
                    "F_t_hat",
                    "mu",
                    "mu_energy",
                    "L_hat",
                    "newton_iterations",
                    "n_dofs"},
                   version_string() +
                     "; time unit: " + prm.material.time_constant + " time",
                   mpi_communicator);
    // The last converged speed, so that a failure reports it and not the
    // unconverged state.
    double            V_hat = 0., delta = steady.approach(), rate = 0.;
    SurfaceQuantities q            = steady.quantities();
    auto              on_converged = [&] {
      V_hat           = steady.speed();
      delta           = steady.approach();
      q               = steady.quantities();
      rate            = steady.dissipation_rate();
      const double V  = V_hat * scales.eps / scales.tau_ref;
      const double Fn = q.normal_force;
      using F         = CsvTable;
      table.add_row({F::format(V_hat),
                     F::format(delta / scales.eps),
                     F::format(Fn / scales.force),
                     F::format(q.tangential_force / scales.force),
                     F::format(std::abs(q.tangential_force / Fn)),
                     F::format(std::abs(rate / V / Fn)),
                     F::format(q.contact_length / scales.R),
                     std::to_string(steady.newton_iterations()),
                     std::to_string(steady.n_dofs())});
    };

    // The stations of the continuation: the listed speeds, then the loads
    // of the load path at the last speed. A station that cannot be reached
    // gets its row with steady = 0 (values of the last converged state,
    // whose V_hat, delta and F_n it shows), and the continuation goes on
    // from there to the next one.
    const auto  &speeds  = prm.sliding.speeds;
    const auto  &loads   = prm.sliding.load_path;
    const bool   force   = prm.sliding.control != "displacement";
    const double unit    = force ? scales.force : scales.eps;
    const auto   n_total = speeds.size() + loads.size();
    std::string  failed;
    for (unsigned int k = 0; k < n_total; ++k)
      {
        const bool   is_speed = k < speeds.size();
        const double value    = is_speed ? speeds[k] : loads[k - speeds.size()];
        const bool   converged =
          is_speed ? steady.continue_to(value, on_converged)
                     : steady.continue_to_load(value * unit, on_converged);
        write_steady_state(
          V_hat, delta, q, rate, converged, 0., "steady-state");
        if (!converged)
          {
            failed += std::string(failed.empty() ? "" : ", ") +
                      (is_speed ? "V_hat "
                       : force  ? "F_hat "
                                : "delta_hat ") +
                      CsvTable::format(value);
            continue;
          }
        char suffix[16];
        std::snprintf(suffix, sizeof(suffix), "_%02u", k);
        // With a list, a profile per station; the last one also under the
        // name the single-speed run uses.
        if (n_total > 1)
          steady.write_profile(writer.path("surface_profile_steady" +
                                           std::string(suffix) + ".csv"));
        if (k + 1 == n_total)
          steady.write_profile(writer.path("surface_profile_steady.csv"));
        if (prm.output.write_fields)
          steady.write_fields(writer, k);
        if (progress != nullptr)
          pcout << "  "
                << (is_speed ? "V_hat "
                    : force  ? "F_hat "
                             : "delta_hat ")
                << value << " (" << k + 1 << "/" << n_total << ")  ["
                << progress->report((k + 1.) / n_total) << "]" << std::endl;
      }
    if (!failed.empty())
      throw std::runtime_error(
        "The steady-state solver did not converge at " + failed +
        "; their rows in steady_state.csv hold the last converged state "
        "with steady = 0");
  }


  std::vector<std::string>
  ContactProblem::steady_state_columns()
  {
    return {"control",
            "mu_T",
            "R_hat",
            "t_hat",
            "V_hat",
            "delta_hat",
            "F_n_hat",
            "F_t_hat",
            "F_t_profile_hat",
            "mu",
            "mu_energy",
            "L_hat",
            "dissipation_rate_hat",
            "steady",
            "sliding_distance_over_eps",
            "time_constant",
            "solver"};
  }


  void
  ContactProblem::write_steady_state(const double             V_hat,
                                     const double             delta,
                                     const SurfaceQuantities &q,
                                     const double             dissipation_rate,
                                     const bool               steady,
                                     const double             distance,
                                     const std::string       &solver)
  {
    const double V  = V_hat * scales.eps / scales.tau_ref;
    const double Fn = q.normal_force, Ft = q.tangential_force;
    const double mu        = std::abs(Ft / Fn);
    const double mu_energy = std::abs(dissipation_rate / V / Fn);
    using F                = CsvTable;
    if (!steady_state_table)
      steady_state_table =
        std::make_unique<CsvTable>(writer.path("steady_state.csv"),
                                   steady_state_columns(),
                                   version_string(),
                                   mpi_communicator);
    steady_state_table->add_row({prm.sliding.control,
                                 F::format(prm.adhesion.tabor_parameter),
                                 F::format(prm.adhesion.R_over_eps),
                                 prm.geometry.substrate == "layer"
                                   ? F::format(prm.geometry.layer_thickness)
                                   : std::string("half-plane"),
                                 F::format(V_hat),
                                 F::format(delta / scales.eps),
                                 F::format(Fn / scales.force),
                                 F::format(Ft / scales.force),
                                 F::format(q.profile_force / scales.force),
                                 F::format(mu),
                                 F::format(mu_energy),
                                 F::format(q.contact_length / scales.R),
                                 F::format(dissipation_rate * scales.tau_ref /
                                           (scales.force * scales.eps)),
                                 steady ? "1" : "0",
                                 F::format(distance),
                                 prm.material.time_constant,
                                 solver});
    pcout << "mu = " << mu << ", mu_energy = " << mu_energy
          << ", L_hat = " << q.contact_length / scales.R
          << ", F_n_hat = " << Fn / scales.force << std::endl;
    // The traction law is conservative, so in a steady state the work of
    // the x force on the indenter equals the dissipation (physics.md, check
    // 4). Said at every row because a transient can pass its window test
    // while it still carries the approach (doc/steady_state.md, V_hat 100),
    // and a mesh can miss V tau; both show here first. Below mu_energy
    // 1e-3 (elastic limits) the ratio is noise.
    if (mu_energy > 1e-3)
      {
        const double       balance = q.profile_force * V / dissipation_rate - 1;
        std::ostringstream percent;
        percent << std::showpos << std::fixed << std::setprecision(2)
                << 100 * balance << " %";
        pcout << "energy balance: x force on the indenter against "
                 "dissipation / V: "
              << percent.str()
              << (std::abs(balance) > 0.01
                    ? " (more than 1 %: not steady yet, or V tau and the "
                      "contact edges not resolved by the mesh)"
                    : "")
              << std::endl;
      }
  }


  void
  ContactProblem::run(const bool resume)
  {
    const std::string comment =
      version_string() + "; time unit: " + prm.material.time_constant +
      " time; forces per unit length in (pi dgamma^2 E0* R)^(1/3)";
    const std::vector<std::string> approach_columns{"step",
                                                    "phase",
                                                    "time_over_tau",
                                                    "delta_hat",
                                                    "F_n_hat",
                                                    "F_t_hat",
                                                    "L_hat",
                                                    "min_gap_over_eps",
                                                    "newton_iterations",
                                                    "step_cuts",
                                                    "jump",
                                                    "n_dofs",
                                                    "n_cells"};
    if (resume)
      {
        read_checkpoint();
        approach_table = std::make_unique<CsvTable>(writer.path("approach.csv"),
                                                    approach_columns,
                                                    approach_rows,
                                                    mpi_communicator);
        writer.resume_collection("solution", step_number);
        writer.resume_collection("surface", step_number);
        pcout << "Resumed from the checkpoint of step " << step_number - 1
              << ": " << triangulation.n_global_active_cells() << " cells, "
              << dof_handler.n_dofs() << " dofs" << std::endl;
      }
    else
      {
        approach_table = std::make_unique<CsvTable>(writer.path("approach.csv"),
                                                    approach_columns,
                                                    comment,
                                                    mpi_communicator);
        make_block(triangulation, prm);
        setup_system();
        committed.delta = prm.loading.initial_approach;
        current         = committed;
        refine_initial_mesh();
        pcout << "Initial mesh: " << triangulation.n_global_active_cells()
              << " cells, " << dof_handler.n_dofs() << " dofs" << std::endl;
      }

    auto fail = [&](const LoadState &target) { abort_run(target); };

    // The loading program: a list of (phase, target) steps.
    const double inf  = std::numeric_limits<double>::infinity();
    const double v    = prm.loading.approach_speed;
    auto         ramp = [&](const std::string &phase, const double to) {
      const double       from = committed.delta;
      const unsigned int n =
        std::max(1.,
                 std::ceil(std::abs(to - from) / prm.loading.increment - 1e-9));
      for (unsigned int k = 1; k <= n; ++k)
        {
          LoadState target = committed;
          target.delta     = from + (to - from) * k / n;
          target.dt =
            v > 0 ? std::abs(target.delta - committed.delta) / v : inf;
          target.time = committed.time + (v > 0 ? target.dt : 0.);
          if (!advance_to(target, phase))
            fail(target);
        }
    };

    // The approach and the hold; a resumed run has them behind it.
    if (!resume)
      {
        LoadState first = committed;
        if (!advance_to(first, "start"))
          fail(first);
        if (prm.loading.has_target_load())
          approach_to_load();
        else
          ramp("approach", prm.loading.final_approach);
      }
    if (prm.loading.hold_time > 0 && !resume)
      {
        const double       t0 = committed.time, T = prm.loading.hold_time;
        const unsigned int n     = prm.loading.hold_steps;
        const double       first = std::min(1e-3, T / n);
        for (unsigned int k = 1; k <= n; ++k)
          {
            LoadState target = committed;
            target.time =
              t0 +
              (n == 1 ? T : first * std::pow(T / first, (k - 1.) / (n - 1.)));
            target.dt = target.time - committed.time;
            if (!advance_to(target, "hold"))
              fail(target);
          }
      }
    if (prm.sliding.speed > 0 && prm.sliding.solver == "steady-state")
      {
        slide_steady();
        timer.print_wall_time_statistics(mpi_communicator);
        return;
      }
    if (prm.sliding.speed > 0)
      slide(resume);
    if (prm.loading.retract)
      ramp("retract", prm.loading.retract_to);

    write_profile("surface_profile_final.csv");
    if (prm.output.write_fields &&
        (prm.output.fields_every == 0 ||
         (step_number - 1) % prm.output.fields_every != 0))
      write_fields();
    // A finished run needs its checkpoint no more.
    if (Utilities::MPI::this_mpi_process(mpi_communicator) == 0)
      std::filesystem::remove_all(writer.path("checkpoint"));
    timer.print_wall_time_statistics(mpi_communicator);
  }
} // namespace viscoslide

// SPDX-License-Identifier: LGPL-2.1-or-later
#include <viscoslide/mesh.h>
#include <viscoslide/mpi_gather.h>
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


  namespace
  {
    // The point of an axis-parallel face at the unit face point t.
    template <class FaceIterator,
              int dim = FaceIterator::AccessorType::space_dimension>
    Point<dim>
    surface_point(const FaceIterator &face, const Point<dim - 1> &t)
    {
      Point<dim> p = face->vertex(0);
      if constexpr (dim == 2)
        p[0] =
          face->vertex(0)[0] + t[0] * (face->vertex(1)[0] - face->vertex(0)[0]);
      else
        for (unsigned int d = 0; d < dim; ++d)
          p[d] += t[0] * (face->vertex(1)[d] - face->vertex(0)[d]) +
                  t[1] * (face->vertex(2)[d] - face->vertex(0)[d]);
      return p;
    }


    // The top faces that touch a window T, on the first process: per face
    // its m u_y unknowns (position in T or -1, value), then per quadrature
    // point its dim - 1 horizontal coordinates, JxW and the m shape values.
    template <int dim>
    struct WindowFaces
    {
      unsigned int        m = 0, n_q = 0;
      std::vector<double> data;

      unsigned int
      record() const
      {
        return 2 * m + n_q * (dim + m);
      }
    };


    // Gathers them; empty on every process if a face's unknown is
    // constrained (not expected on the top surface).
    template <int dim>
    WindowFaces<dim>
    gather_window_faces(const DoFHandler<dim>               &dof_handler,
                        const AffineConstraints<double>     &constraints,
                        const TrilinosWrappers::MPI::Vector &solution,
                        const Quadrature<dim - 1>           &quadrature,
                        const std::vector<int>              &T,
                        const MPI_Comm                       comm)
    {
      const auto       &fe = dof_handler.get_fe();
      WindowFaces<dim>  faces;
      FEFaceValues<dim> values(fe,
                               quadrature,
                               SurfaceCoupling<dim>::face_update_flags());
      faces.n_q = quadrature.size();
      std::vector<types::global_dof_index> dofs(fe.n_dofs_per_cell());
      const auto position = [&T](const types::global_dof_index i) {
        const auto p = std::lower_bound(T.begin(), T.end(), int(i));
        return (p != T.end() && *p == int(i)) ? int(p - T.begin()) : -1;
      };
      int constrained = 0, m = 0;
      for (const auto &cell : dof_handler.active_cell_iterators())
        for (const auto f : cell->face_indices())
          {
            if (!cell->is_locally_owned() || !is_top_face(cell, f))
              continue;
            cell->get_dof_indices(dofs);
            std::vector<unsigned int> on_face;
            bool                      touches = false;
            for (unsigned int i = 0; i < dofs.size(); ++i)
              if (fe.system_to_component_index(i).first == vertical<dim> &&
                  fe.has_support_on_face(i, f))
                {
                  on_face.push_back(i);
                  touches = touches || position(dofs[i]) >= 0;
                }
            if (!touches)
              continue;
            values.reinit(cell, f);
            m = on_face.size();
            for (const unsigned int i : on_face)
              {
                constrained |= constraints.is_constrained(dofs[i]);
                faces.data.insert(faces.data.end(),
                                  {double(position(dofs[i])),
                                   solution[dofs[i]]});
              }
            for (unsigned int q = 0; q < faces.n_q; ++q)
              {
                for (unsigned int d = 0; d + 1 < dim; ++d)
                  faces.data.push_back(values.quadrature_point(q)[d]);
                faces.data.push_back(values.JxW(q));
                for (const unsigned int i : on_face)
                  faces.data.push_back(
                    values.shape_value_component(i, q, vertical<dim>));
              }
          }
      faces.data = gather_concatenated(comm, faces.data, 0);
      faces.m    = Utilities::MPI::max(m, comm);
      if (Utilities::MPI::max(constrained, comm) != 0)
        faces.data.clear();
      return faces;
    }


    // The terms of add_face_terms() on the rows of T (k of them) with T's
    // unknowns moved by x_T; law(p, u_y) gives the traction and its
    // derivative at the surface point p.
    template <int dim, typename Law>
    WindowTerms
    window_terms(const WindowFaces<dim>       &faces,
                 const unsigned int            k,
                 const dealii::Vector<double> &x_T,
                 const Law                    &law)
    {
      WindowTerms W;
      W.rhs.reinit(k);
      W.border.reinit(k);
      const unsigned int  m = faces.m;
      std::vector<int>    p(m);
      std::vector<double> u(m);
      for (std::size_t face = 0; face + faces.record() <= faces.data.size();
           face += faces.record())
        {
          const double *r = &faces.data[face];
          for (unsigned int j = 0; j < m; ++j)
            {
              p[j] = static_cast<int>(r[2 * j]);
              u[j] = r[2 * j + 1] + (p[j] >= 0 ? x_T(p[j]) : 0.);
            }
          for (unsigned int q = 0; q < faces.n_q; ++q)
            {
              const double *point = r + 2 * m + q * (dim + m);
              Point<dim>    where;
              for (unsigned int d = 0; d + 1 < dim; ++d)
                where[d] = point[d];
              const double  JxW = point[dim - 1];
              const double *phi = point + dim;
              double        u_q = 0.;
              for (unsigned int j = 0; j < m; ++j)
                u_q += phi[j] * u[j];
              const auto [traction, dp_dg] = law(where, u_q);
              W.force -= traction * JxW;
              W.stiffness += dp_dg * JxW;
              for (unsigned int i = 0; i < m; ++i)
                if (p[i] >= 0)
                  {
                    W.rhs(p[i]) += traction * phi[i] * JxW;
                    W.border(p[i]) += dp_dg * phi[i] * JxW;
                    for (unsigned int j = 0; j < m; ++j)
                      if (p[j] >= 0)
                        W.tangent.push_back({static_cast<unsigned int>(p[i]),
                                             static_cast<unsigned int>(p[j]),
                                             dp_dg * phi[i] * phi[j] * JxW});
                  }
            }
        }
      return W;
    }
  } // namespace


  template <int dim>
  WindowModel
  SurfaceCoupling<dim>::window_model(
    const DoFHandler<dim>           &dof_handler,
    const AffineConstraints<double> &constraints,
    const VectorType                &solution,
    const double                     delta,
    const double                     s,
    const std::vector<int>          &T) const
  {
    WindowModel model;
    model.tolerance = tolerance();
    // The relaxation's pseudo-steps, and the Newton iterations that end
    // it, stay single linear solves: the path of a jump through its
    // pseudo-dynamics is sensitive to every step (with the model's
    // compressed steps, seen to cycle between the dashpot and Newton's
    // method on the jump-in of two tests).
    if (relaxing)
      return model;
    const WindowFaces<dim> faces = gather_window_faces(
      dof_handler, constraints, solution, quadrature, T, comm);
    if (Utilities::MPI::this_mpi_process(comm) != 0 || faces.data.empty())
      return model;
    model.terms =
      [this, faces, k = T.size(), delta, s](const dealii::Vector<double> &x_T,
                                            const double                  t) {
        WindowTerms W =
          window_terms(faces, k, x_T, [&](const Point<dim> &p, const double u) {
            return law_at(p, u, delta + t, s);
          });
        // G's spring term under spring control.
        W.force += control.spring_stiffness * t;
        W.stiffness += control.spring_stiffness;
        return W;
      };
    return model;
  }


  template <int dim>
  double
  SurfaceCoupling<dim>::residual_norm(const VectorType &rhs) const
  {
    const double r = rhs.l2_norm();
    return control.force_controlled ? std::hypot(r, force_mismatch) : r;
  }


  template <int dim>
  void
  SurfaceCoupling<dim>::solve_bordered(const LinearSolve &solve,
                                       const VectorType  &rhs,
                                       VectorType        &update)
  {
    VectorType x1;
    x1.reinit(rhs);
    solve(rhs, x1);
    delta_update = 0.;
    if (control.force_controlled)
      {
        VectorType x2;
        x2.reinit(rhs);
        solve(delta_coupling, x2);
        delta_update = (-force_mismatch - (delta_coupling * x1)) /
                       (delta_stiffness - (delta_coupling * x2));
        x1.add(-delta_update, x2);
      }
    update = x1;
  }


  template <int dim>
  void
  SurfaceCoupling<dim>::solve_bordered(
    ReusedFactorization                  &solver,
    const TrilinosWrappers::SparseMatrix &matrix,
    const VectorType                     &rhs,
    VectorType                           &update)
  {
    delta_update = 0.;
    if (control.force_controlled)
      delta_update = solver.solve_bordered(
        matrix, delta_coupling, delta_stiffness, rhs, -force_mismatch, update);
    else
      solver.solve(matrix, rhs, update);
  }


  template <int dim>
  NewtonProblem
  SurfaceCoupling<dim>::newton_problem(const System &system)
  {
    // The line search's start lives here, in the layout of the update.
    u0.reinit(system.update);
    delta0 = system.delta;
    NewtonProblem problem;
    problem.assemble      = system.assemble;
    problem.residual_norm = [this, &system] {
      return residual_norm(system.rhs);
    };
    problem.tolerance      = [this] { return tolerance(); };
    problem.compute_update = system.compute_update;
    return with_iterate(problem,
                        {system.solution,
                         system.delta,
                         system.update,
                         delta_update,
                         surface_damping,
                         relaxation_anchor},
                        u0,
                        delta0);
  }


  template <int dim>
  int
  SurfaceCoupling<dim>::newton(const System &system, ConditionalOStream &out)
  {
    return viscoslide::newton(newton_problem(system),
                              prm.solver.max_newton_iterations,
                              prm.solver.line_search,
                              prm.solver.verbose,
                              out);
  }


  template <int dim>
  int
  SurfaceCoupling<dim>::relax(const System &system, ConditionalOStream &out)
  {
    relaxation_anchor.reinit(system.solution);
    relaxing = true;
    const int steps =
      relax_surface(newton_problem(system), scales, prm.solver, out);
    surface_damping = 0.;
    relaxing        = false;
    return steps;
  }


  template <int dim>
  template <typename Function>
  void
  SurfaceCoupling<dim>::for_each_surface_unknown(
    const DoFHandler<dim>           &dof_handler,
    const AffineConstraints<double> &constraints,
    const Function                  &f) const
  {
    const auto &fe     = dof_handler.get_fe();
    const auto &points = fe.get_unit_face_support_points();
    const auto &owned  = dof_handler.locally_owned_dofs();
    std::vector<types::global_dof_index> dofs(fe.n_dofs_per_face());
    for (const auto &cell : dof_handler.active_cell_iterators())
      for (const auto f_no : cell->face_indices())
        {
          if (!cell->is_locally_owned() || !is_top_face(cell, f_no))
            continue;
          const auto face = cell->face(f_no);
          face->get_dof_indices(dofs);
          for (unsigned int i = 0; i < dofs.size(); ++i)
            if (fe.face_system_to_component_index(i).first == vertical<dim> &&
                owned.is_element(dofs[i]) &&
                !constraints.is_constrained(dofs[i]))
              f(dofs[i], surface_point(face, points[i]));
        }
  }


  template <int dim>
  IndexSet
  SurfaceCoupling<dim>::surface_unknowns(
    const DoFHandler<dim>           &dof_handler,
    const AffineConstraints<double> &constraints) const
  {
    IndexSet unknowns(dof_handler.n_dofs());
    for_each_surface_unknown(dof_handler,
                             constraints,
                             [&](const auto dof, const Point<dim> &) {
                               unknowns.add_index(dof);
                             });
    unknowns.compress();
    return unknowns;
  }


  template <int dim>
  IndexSet
  SurfaceCoupling<dim>::surface_window(
    const DoFHandler<dim>           &dof_handler,
    const AffineConstraints<double> &constraints,
    const VectorType                &solution,
    const double                     delta,
    const double                     s) const
  {
    // The relaxation's dashpot acts on every surface row and changes at
    // every pseudo-step: a window of the whole surface keeps one
    // factorization for all of them, unless the surface is so long (a
    // thin layer's wide block: thousands of unknowns) that the dense LU on
    // it costs more than a factorization at every pseudo-step.
    if (surface_damping > 0)
      {
        IndexSet all = surface_unknowns(dof_handler, constraints);
        if (Utilities::MPI::sum(all.n_elements(), comm) <= whole_window)
          return all;
      }
    std::vector<std::pair<types::global_dof_index, double>> gaps;
    double smallest = std::numeric_limits<double>::max();
    for_each_surface_unknown(dof_handler,
                             constraints,
                             [&](const auto dof, const Point<dim> &p) {
                               const double g =
                                 gap_at(p, solution[dof], delta, s);
                               gaps.emplace_back(dof, g);
                               smallest = std::min(smallest, g);
                             });
    double limit = std::max(window_gap * scales.eps,
                            2. * Utilities::MPI::min(smallest, comm));
    // A 3D contact's window holds a disc of the surface: thousands of
    // unknowns. The dense stage is kept at whole_window of them, those of
    // the smallest gaps, ties ordered by index (a predicted step holds a
    // whole disc at one gap); the rest is exact but for a new
    // factorization where their terms change (ReusedFactorization).
    using Key = std::pair<double, double>; // gap, index
    Key bound{limit, -1.};
    if constexpr (dim == 3)
      {
        // each unknown once: a node shared by several faces was seen on
        // each of them
        const std::map<types::global_dof_index, double> unique(gaps.begin(),
                                                               gaps.end());
        std::vector<Key>                                local;
        for (const auto &[dof, g] : unique)
          if (g < limit)
            local.emplace_back(g, static_cast<double>(dof));
        std::vector<Key> all = gather_concatenated(comm, local, -1);
        if (all.size() > whole_window)
          {
            std::nth_element(all.begin(),
                             all.begin() + whole_window,
                             all.end());
            bound = all[whole_window];
          }
      }
    IndexSet window(dof_handler.n_dofs());
    for (const auto &[dof, g] : gaps)
      if (Key(g, static_cast<double>(dof)) < bound)
        window.add_index(dof);
    window.compress();
    return window;
  }


  template <int dim>
  SurfaceRegions<dim>
  SurfaceCoupling<dim>::contact_edges(const DoFHandler<dim> &dof_handler,
                                      const VectorType      &solution,
                                      const double           delta,
                                      const double           s) const
  {
    auto edges = postprocessor.faces_in_gap_band(dof_handler,
                                                 solution,
                                                 delta,
                                                 s,
                                                 prm.mesh.edge_gap_low,
                                                 prm.mesh.edge_gap_high);
    if (edges.empty())
      {
        SurfaceRegion<dim> apex;
        apex.lower[0] = apex.upper[0] = s;
        edges.push_back(apex);
      }
    return edges;
  }


  template <int dim>
  bool
  SurfaceCoupling<dim>::flag_contact_edges(
    parallel::distributed::Triangulation<dim> &triangulation,
    const DoFHandler<dim>                     &dof_handler,
    const VectorType                          &solution,
    const double                               delta,
    const double                               s,
    const SurfaceRegions<dim>                 &expected) const
  {
    auto edges = contact_edges(dof_handler, solution, delta, s);
    edges.insert(edges.end(), expected.begin(), expected.end());
    return flag_cells_near_edges(triangulation, edges, prm);
  }


  template <int dim>
  void
  SurfaceCoupling<dim>::limit_predicted_closing(
    const DoFHandler<dim>           &dof_handler,
    const AffineConstraints<double> &constraints,
    const VectorType                &last,
    const double                     last_delta,
    const double                     last_s,
    VectorType                      &predicted,
    const double                     delta,
    const double                     s) const
  {
    // Lennard-Jones-like laws pull up to the gap eps, where the traction
    // vanishes; a repulsive wall pushes at every gap, so there no node
    // starts closer than it was.
    const double free_gap = prm.adhesion.adhesive()
                              ? scales.eps
                              : std::numeric_limits<double>::infinity();
    // Each node once (it lies on two faces); every process adds, so that
    // all of them compress alike.
    std::map<types::global_dof_index, double> u_y_change;
    for_each_surface_unknown(
      dof_handler, constraints, [&](const auto dof, const Point<dim> &p) {
        const double floor =
          std::min(free_gap, gap_at(p, last[dof], last_delta, last_s));
        const double g = gap_at(p, predicted[dof], delta, s);
        if (g < floor)
          u_y_change[dof] = g - floor; // opens the gap to floor
      });
    std::vector<types::global_dof_index> indices;
    std::vector<double>                  values;
    for (const auto &[dof, value] : u_y_change)
      {
        indices.push_back(dof);
        values.push_back(value);
      }
    predicted.add(indices, values);
    predicted.compress(VectorOperation::add);
    constraints.distribute(predicted);
  }


  template class SurfaceCoupling<2>;
  template class SurfaceCoupling<3>;
} // namespace viscoslide

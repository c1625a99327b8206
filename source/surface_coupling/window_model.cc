// SPDX-License-Identifier: LGPL-2.1-or-later
// The surface window's model for the reused factorization: the traction
// law's terms on the window's faces as functions of its unknowns.
#include <viscoslide/numerics/mesh.h>
#include <viscoslide/numerics/mpi_gather.h>
#include <viscoslide/surface_coupling.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <map>

namespace viscoslide
{


  namespace
  {
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

  template class SurfaceCoupling<2>;
  template class SurfaceCoupling<3>;
} // namespace viscoslide

// SPDX-License-Identifier: LGPL-2.1-or-later
// The surface's unknowns, the window about the contact, the contact edges
// and the predicted closing of the gap.
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

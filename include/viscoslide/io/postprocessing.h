// SPDX-License-Identifier: LGPL-2.1-or-later
// Quantities of the top surface: forces, contact length, the surface
// profile. Everything here is evaluated from the displacement field and
// the indenter position alone, so the transient and steady-state solvers
// share it.
#ifndef viscoslide_postprocessing_h
#define viscoslide_postprocessing_h

#include <deal.II/base/mpi.h>

#include <deal.II/dofs/dof_handler.h>

#include <deal.II/fe/fe_values.h>

#include <deal.II/lac/trilinos_vector.h>

#include <viscoslide/io/parameters.h>
#include <viscoslide/physics/indenter.h>
#include <viscoslide/physics/interaction_law.h>

#include <string>
#include <vector>

namespace viscoslide
{
  using namespace dealii;

  // Forces are per unit length in 2D, in internal units. In 3D the contact
  // length is the contact area.
  struct SurfaceQuantities
  {
    double normal_force; // Fn = integral of p = -p_LJ (compressive > 0)
    // The x force on the indenter, integral of p h'(x - s) over the whole
    // surface: the friction force (eq. 2 over the whole surface).
    double tangential_force;
    // Eq. 2 restricted to the contact set g < contact gap threshold, as
    // the paper reports it; it misses the process zone's tension.
    double contact_set_tangential_force;
    double contact_length; // measure of {g < contact gap threshold}
    double absolute_force; // integral of |p|, the residual scale
    double minimum_gap;
    // The contact set's extent relative to the apex: its smallest and
    // largest x (the trailing and leading edge when sliding towards +x),
    // and in 3D its half-width across the track (boundary elements).
    double x_trail = 0, x_lead = 0, y_half = 0;
  };

  struct ProfilePoint
  {
    double x, gap, pressure, u_y;
  };

  // u_y below is the vertical displacement, u_z in 3D; x the coordinate
  // along the track. In 3D the profile is the track's centre line y = 0.
  template <int dim>
  class SurfacePostprocessor
  {
  public:
    // In 3D the indenter is stretched across the track by `elongation`
    // (apex_distance()).
    SurfacePostprocessor(const InteractionLaw &law,
                         const Indenter       &indenter,
                         double                eps,
                         double                contact_gap,
                         unsigned int          face_quadrature_points,
                         types::boundary_id    top_boundary,
                         double                elongation = 1.);

    SurfaceQuantities
    integrate(const DoFHandler<dim>               &dof_handler,
              const TrilinosWrappers::MPI::Vector &solution,
              double                               delta,
              double                               s) const;

    // Points along the whole top surface (in 3D its centre line), sorted
    // by x, complete on rank 0 (empty elsewhere).
    std::vector<ProfilePoint>
    profile(const DoFHandler<dim>               &dof_handler,
            const TrilinosWrappers::MPI::Vector &solution,
            double                               delta,
            double                               s) const;

    // The regions of the top faces whose gap range overlaps [g_lo, g_hi],
    // gathered from all processes: the contact edges the mesh follows.
    SurfaceRegions<dim>
    faces_in_gap_band(const DoFHandler<dim>               &dof_handler,
                      const TrilinosWrappers::MPI::Vector &solution,
                      double                               delta,
                      double                               s,
                      double                               g_lo,
                      double                               g_hi) const;

  private:
    // The gap at a surface point p displaced vertically by u.
    double
    gap_at(const Point<dim> &p, double u, double delta, double s) const
    {
      return gap(indenter, eps, delta, s, p, u, elongation);
    }
    // dh/dx at p: the profile's slope along the track.
    double
    slope_at(const Point<dim> &p, double s) const;

    // Calls f(cell, face, points, gap, u_y) with equally spaced samples
    // (5 per direction) on every locally owned top face.
    template <typename Function>
    void
    for_each_sampled_face(const DoFHandler<dim>               &dofs,
                          const TrilinosWrappers::MPI::Vector &u,
                          double                               delta,
                          double                               s,
                          const Function                      &f) const;

    // The contact set's measure and extent from samples on each face.
    struct ContactSet
    {
      double measure = 0., x_trail, x_lead, y_half = 0.;
    };
    void
    add_contact_samples(const FEFaceValues<dim>   &values,
                        const std::vector<double> &u,
                        double                     delta,
                        double                     s,
                        ContactSet                &set,
                        double                    &g_min) const;

    const InteractionLaw    &law;
    const Indenter          &indenter;
    const double             eps;
    const double             contact_gap;
    const unsigned int       n_face_points;
    const types::boundary_id top;
    const double             elongation;
  };

  // The surface profile CSV (x_over_R, gap_over_eps, p_hat, u_y_over_eps)
  // of both solvers; rank 0 writes.
  void
  write_profile_csv(const std::string               &path,
                    const std::vector<ProfilePoint> &points,
                    const Scales                    &scales,
                    const std::string               &comment,
                    MPI_Comm                         comm);
} // namespace viscoslide

#endif

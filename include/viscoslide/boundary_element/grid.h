// SPDX-License-Identifier: LGPL-2.1-or-later
// The 'Boundary element' section: the surface grid of the boundary-element
// solver (boundary_element/solver.h), uniform and periodic or, in plane
// strain on the half-plane, graded about the contact edges; and the
// graded grid's construction.
#ifndef viscoslide_boundary_element_grid_h
#define viscoslide_boundary_element_grid_h

#include <viscoslide/io/input.h>

#include <functional>
#include <utility>
#include <vector>

namespace viscoslide
{
  namespace Parameters
  {
    // automatic is resolved when the case is read
    // (CaseSetup::choose_surface_grid): no grid is made as 'automatic'.
    enum class GridKind
    {
      uniform,
      graded,
      nested,
      automatic
    };
    VISCOSLIDE_CHOICES(GridKind, "uniform", "graded", "nested", "automatic")

    struct BoundaryElement
    {
      GridKind     grid;
      double       grid_spacing;  // eps; 0: half the Finest surface cell
      double       grading_ratio; // of neighbouring cells of the graded grid
      double       period;        // eps; 0: automatic
      double       wake_periods;  // the automatic period, in V tau_c
      unsigned int refinement; // of the nested grid's band cells; 0: automatic
      double       band_width; // eps, of the nested grid's band

      static void
      declare(ParameterHandler &prm);
      void
      parse(ParameterHandler &prm);
    };
  } // namespace Parameters

  // The cell boundaries s_0 < ... < s_n of the graded grid about a contact
  // whose edges are at `trail` < `lead` (any unit): cells of width
  // `finest` at both edges, each `ratio` times its neighbour nearer to an
  // edge, at most a 200th of the contact's width (the interior, where the
  // pressure is smooth on that scale), out to `margin` beyond each edge.
  // Cells growing away from an edge resolve each feature at the relative
  // resolution ratio - 1 of its distance from the edge: the adhesive zone
  // at the edge, a relaxation length V tau from it.
  std::vector<double>
  graded_boundaries(double trail,
                    double lead,
                    double finest,
                    double ratio,
                    double margin);

  // The displacement of a point x of a graded grid made for contact edges
  // at `edges` when the edges move by d_trail and d_lead: rigidly with
  // each edge up to a quarter of the contact's width inside it, linearly
  // over the half between, so that each edge's cells (and the adhesive
  // zone on them) move with it and only coarse cells stretch.
  std::function<double(double)>
  edge_shift(const std::pair<double, double> &edges,
             double                           d_trail,
             double                           d_lead);

  // The half-width a of the JKR contact of a parabolic cylinder of radius
  // R on a solid of plane-strain modulus 1 under the load P per unit
  // length (compressive > 0), on the stable branch of
  //     P(a) = pi a^2/(4R) - sqrt(2 pi dgamma a)
  // (Johnson, Contact Mechanics; Barquins 1988); NaN below the pull-off
  // force, the minimum of P(a).
  double
  cylinder_jkr_half_width(double P, double dgamma, double R);

  // The radius a of the JKR contact of a paraboloid of radius R on a solid
  // of plane-strain modulus E under the load P (compressive > 0), on the
  // stable branch (Johnson, Kendall and Roberts 1971), with J = 3 pi dgamma R:
  //     a^3 = (3R/(4E)) (P + J + sqrt(2 J P + J^2));
  // Hertz's for dgamma = 0, NaN below the pull-off force -J/2.
  double
  sphere_jkr_radius(double P, double dgamma, double R, double E = 1.);

  // The memory of a 3D grid of the boundary elements per point: GMRES
  // keeps up to 102 vectors of the grid, the rest about 40 (measured on
  // the uniform and nested grids: 2.4 and 1.4 kB per point, the window's
  // FFT buffers included, doc/boundary_element.md).
  constexpr double plane_grid_bytes_per_point = 150. * 8.;
} // namespace viscoslide

#endif

// SPDX-License-Identifier: LGPL-2.1-or-later
// The block and its contact-edge refinement, shared by the transient and
// the steady-state solvers.
#ifndef viscoslide_mesh_h
#define viscoslide_mesh_h

#include <deal.II/distributed/tria.h>

#include <viscoslide/io/input.h>

#include <functional>
#include <utility>
#include <vector>

namespace viscoslide
{
  using namespace dealii;

  namespace Parameters
  {
    struct AllParameters;

    enum class Substrate
    {
      half_plane,
      layer
    };
    VISCOSLIDE_CHOICES(Substrate, "half-plane", "layer")

    // The 'Geometry' section: the block or the layer.
    struct Geometry
    {
      static constexpr int default_domain_height = 10000;

      // 2: plane strain, a cylinder on a block; 3: a body of revolution
      // (a sphere) on a half-space or layer, by the boundary elements or
      // the steady-state finite elements (verified on coarse meshes:
      // doc/steady_state.md).
      unsigned int dimension;
      Substrate    substrate;
      double       layer_thickness;
      double       domain_width;
      double       domain_height;
      double       wake_lengths;
      // 3D only: R_y/R of the indenter, whose profile is h of
      // sqrt(x^2 + y^2/elongation), and the surface's extent across the
      // track (0: the Domain width).
      double elongation;
      double domain_length;

      static void
      declare(ParameterHandler &prm);
      void
      parse(ParameterHandler &prm);

      // The extent of the 3D surface across the track (y).
      double
      length() const
      {
        return domain_length > 0 ? domain_length : domain_width;
      }

      // The height of the block actually meshed. The 3D block is by
      // default as deep as it is wide: fixed at its base and free on its
      // sides, a much deeper one bends under the friction force like a
      // cantilever and tilts the surface under the indenter (a column 50
      // times deeper than wide lost a quarter of the friction).
      double
      height() const
      {
        if (substrate == Substrate::layer)
          return layer_thickness;
        return dimension == 3 && domain_height == default_domain_height
                 ? domain_width
                 : domain_height;
      }
    };

    // The 'Mesh' section: the refinement at the contact edges.
    struct Mesh
    {
      double       finest_cell;
      double       grading;
      double       edge_gap_low;
      double       edge_gap_high;
      double       edge_margin; // in eps
      unsigned int max_adaptation_cycles;
      bool         uniform_surface;

      static void
      declare(ParameterHandler &prm);
      void
      parse(ParameterHandler &prm);
    };
  } // namespace Parameters


  // Boundary ids of GridGenerator::subdivided_hyper_rectangle(colorize).
  constexpr types::boundary_id left_boundary  = 0;
  constexpr types::boundary_id right_boundary = 1;
  template <int dim>
  constexpr types::boundary_id bottom_boundary = 2 * dim - 2;
  template <int dim>
  constexpr types::boundary_id top_boundary = 2 * dim - 1;

  // The component of the displacement normal to the top surface: u_y in
  // 2D (the plane of the paper), u_z in 3D (x along the track, y across).
  template <int dim>
  constexpr unsigned int vertical = dim - 1;

  // A region of the top surface: an interval of x in 2D, a rectangle of
  // (x, y) in 3D, given by its lower and upper corners.
  template <int dim>
  struct SurfaceRegion
  {
    Point<dim - 1> lower, upper;
  };
  template <int dim>
  using SurfaceRegions = std::vector<SurfaceRegion<dim>>;

  // Whether face f of `cell` lies on the block's top surface, the only
  // one the indenter acts on.
  template <class CellIterator>
  inline bool
  is_top_face(const CellIterator &cell, const unsigned int f)
  {
    constexpr int dim = std::decay_t<decltype(*cell)>::dimension;
    return cell->face(f)->at_boundary() &&
           cell->face(f)->boundary_id() == top_boundary<dim>;
  }

  // The block -W/2 < x < W/2, -H < y < 0 in square coarse cells; in 3D
  // -W/2 < x < W/2, -L/2 < y < L/2 (L the Geometry's length()),
  // -H < z < 0. The boundary ids are GridGenerator's colours: in 3D the
  // sides across the track are 2 and 3, the bottom 4 and the top 5.
  template <int dim>
  void
  make_block(parallel::distributed::Triangulation<dim> &triangulation,
             const Parameters::AllParameters           &prm);

  // Flags cells for refinement and coarsening so that the cell size is the
  // finest surface cell at the contact edges (x-intervals on the surface)
  // and grows as Mesh grading x distance away from them. The mesh changes
  // only where a cell is coarser than the edges need; it is then refined as
  // if each edge were Mesh/Edge margin wider, and coarsened where cells are
  // two levels finer than that, so that an edge moving by less than the
  // margin leaves the mesh as it is. With Mesh/Uniform
  // surface the whole top counts as an edge. Returns whether any cell on
  // any process will change.
  template <int dim>
  bool
  flag_cells_near_edges(
    parallel::distributed::Triangulation<dim> &triangulation,
    const SurfaceRegions<dim>                 &edges,
    const Parameters::AllParameters           &prm);

  // The cells flag_cells_near_edges makes about a ring of the 3D block's
  // top surface (r_inner <= sqrt(x^2 + y^2) <= r_outer), counted without
  // building the mesh: an estimate (neighbouring cells are not balanced to
  // one level apart, as the mesh is) for refusing a case that will not fit
  // before it starts. Stops counting above `limit`.
  double
  estimated_cells_about_ring(const Parameters::AllParameters &prm,
                             double                           r_inner,
                             double                           r_outer,
                             double                           limit);

  // After a converged solve: adapts the mesh to the new solution and
  // solves again, until the mesh stays or max_cycles times. Returns the
  // iterations of the re-solves, or -1 if one failed.
  int
  resolve_on_adapted_meshes(unsigned int                 max_cycles,
                            const std::function<bool()> &adapt_mesh,
                            const std::function<int()>  &solve);
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
} // namespace viscoslide

#endif

// SPDX-License-Identifier: LGPL-2.1-or-later
#include <deal.II/base/mpi.h>

#include <deal.II/grid/grid_generator.h>

#include <viscoslide/io/parameters.h>
#include <viscoslide/numerics/mesh.h>

#include <algorithm>
#include <cmath>
#include <sstream>
#include <string>

namespace viscoslide
{
  namespace
  {
    unsigned int
    n_coarse_cells(const double length, const double W, const double H)
    {
      return std::max(1., std::round(length / std::min(W, H)));
    }

    // The block's coarse cells along x, y (and z): about square, and in 3D
    // an even number across, so that the track's centre line y = 0 is one
    // of the cells' faces, and in 3D at most half the block's smallest
    // side (one cell as wide as the block, graded towards the contact,
    // held nearly twice the unknowns).
    template <int dim>
    std::vector<unsigned int>
    coarse_subdivisions(const Parameters::AllParameters &prm)
    {
      const double W = prm.geometry.domain_width, H = prm.geometry.height();
      if constexpr (dim == 2)
        return {n_coarse_cells(W, W, H), n_coarse_cells(H, W, H)};
      const double L = prm.geometry.length(), side = std::min({W, L, H}) / 2;
      return {n_coarse_cells(W, side, side),
              2 * n_coarse_cells(L / 2, side, side),
              n_coarse_cells(H, side, side)};
    }
  } // namespace


  template <int dim>
  void
  make_block(parallel::distributed::Triangulation<dim> &triangulation,
             const Parameters::AllParameters           &prm)
  {
    const double W = prm.geometry.domain_width, H = prm.geometry.height();
    if constexpr (dim == 2)
      GridGenerator::subdivided_hyper_rectangle(triangulation,
                                                coarse_subdivisions<2>(prm),
                                                Point<2>(-W / 2, -H),
                                                Point<2>(W / 2, 0),
                                                true);
    else
      {
        const double L = prm.geometry.length();
        GridGenerator::subdivided_hyper_rectangle(triangulation,
                                                  coarse_subdivisions<3>(prm),
                                                  Point<3>(-W / 2, -L / 2, -H),
                                                  Point<3>(W / 2, L / 2, 0),
                                                  true);
      }
  }


  namespace
  {
    // The distance from a box (its lower and upper corners) to a surface
    // region, the region widened by `margin` along the surface; the box's
    // depth below the surface counts in full.
    template <int dim>
    double
    distance_to(const BoundingBox<dim>   &box,
                const SurfaceRegion<dim> &region,
                const double              margin)
    {
      const double depth = std::max(0., -box.upper_bound(dim - 1));
      double       along = 0.;
      for (unsigned int d = 0; d + 1 < dim; ++d)
        {
          const double gap     = std::max({0.,
                                           region.lower[d] - box.upper_bound(d),
                                           box.lower_bound(d) - region.upper[d]});
          const double widened = std::max(0., gap - margin);
          along = dim == 2 ? widened : std::hypot(along, widened);
        }
      return std::hypot(along, depth);
    }

    // The side of the block's coarse cells along x (make_block).
    template <int dim>
    double
    coarse_cell_width(const Parameters::AllParameters &prm)
    {
      return prm.geometry.domain_width / coarse_subdivisions<dim>(prm)[0];
    }

    // The refinement level a cell at distance d from the contact edges
    // needs: the finest surface cell at the edges, growing as Mesh grading
    // x d away from them, in halvings of the coarse cells.
    class LevelRule
    {
    public:
      LevelRule(const Parameters::AllParameters &prm, const double coarse)
        : coarse(coarse)
        , finest(prm.mesh.finest_cell)
        , grading(prm.mesh.grading)
        , max_level(level_of(finest))
      {
      }

      int
      operator()(const double d) const
      {
        return std::clamp(level_of(std::max(finest, grading * d)),
                          0,
                          max_level);
      }

    private:
      int
      level_of(const double h) const
      {
        return static_cast<int>(std::ceil(std::log2(coarse / h) - 1e-9));
      }

      double coarse, finest, grading;
      int    max_level;
    };
  } // namespace


  template <int dim>
  bool
  flag_cells_near_edges(
    parallel::distributed::Triangulation<dim> &triangulation,
    const SurfaceRegions<dim>                 &edges,
    const Parameters::AllParameters           &prm)
  {
    const double        W = prm.geometry.domain_width;
    SurfaceRegions<dim> whole_surface(1);
    whole_surface[0].lower[0] = -W / 2;
    whole_surface[0].upper[0] = W / 2;
    if constexpr (dim == 3)
      {
        whole_surface[0].lower[1] = -prm.geometry.length() / 2;
        whole_surface[0].upper[1] = prm.geometry.length() / 2;
      }
    const LevelRule level_at(prm, coarse_cell_width<dim>(prm));

    bool must_change = false;
    for (const auto &cell : triangulation.active_cell_iterators())
      if (cell->is_locally_owned())
        {
          // The distance to the nearest edge, and to the nearest edge
          // widened by the margin along the surface.
          const auto box = cell->bounding_box();
          double     d = std::numeric_limits<double>::max(), d_wide = d;
          for (const auto &region :
               prm.mesh.uniform_surface ? whole_surface : edges)
            {
              d      = std::min(d, distance_to(box, region, 0.));
              d_wide = std::min(d_wide,
                                distance_to(box, region, prm.mesh.edge_margin));
            }
          const int needed = level_at(d);
          const int wanted = level_at(d_wide);
          if (cell->level() < needed)
            must_change = true;
          if (cell->level() < wanted)
            cell->set_refine_flag();
          else if (cell->level() > wanted + 1)
            cell->set_coarsen_flag();
        }
    if (Utilities::MPI::max(must_change ? 1 : 0,
                            triangulation.get_communicator()) == 0)
      {
        for (const auto &cell : triangulation.active_cell_iterators())
          if (cell->is_locally_owned())
            {
              cell->clear_refine_flag();
              cell->clear_coarsen_flag();
            }
        return false;
      }
    triangulation.prepare_coarsening_and_refinement();
    bool changes = false;
    for (const auto &cell : triangulation.active_cell_iterators())
      if (cell->is_locally_owned() &&
          (cell->refine_flag_set() || cell->coarsen_flag_set()))
        changes = true;
    return Utilities::MPI::max(changes ? 1 : 0,
                               triangulation.get_communicator()) != 0;
  }


  double
  estimated_cells_about_ring(const Parameters::AllParameters &prm,
                             const double                     r_inner,
                             const double                     r_outer,
                             const double                     limit)
  {
    const double W = prm.geometry.domain_width, L = prm.geometry.length(),
                 H = prm.geometry.height();
    const LevelRule level_at(prm, coarse_cell_width<3>(prm));
    // The ring widened by the margin, as flag_cells_near_edges widens each
    // edge; with a uniform surface the whole top is the edge.
    const double inner = prm.mesh.uniform_surface
                           ? 0.
                           : std::max(0., r_inner - prm.mesh.edge_margin),
                 outer = prm.mesh.uniform_surface
                           ? std::hypot(W, L)
                           : r_outer + prm.mesh.edge_margin;
    double     count   = 0;
    const auto refine  = [&](const auto     &self,
                            const Point<3> &lo,
                            const Point<3> &hi,
                            const int       level) -> void {
      if (count > limit)
        return;
      // the box's nearest and farthest distance from the axis, and depth
      const double near_x = std::max({0., lo[0], -hi[0]}),
                   near_y = std::max({0., lo[1], -hi[1]});
      const double far = std::hypot(std::max(std::abs(lo[0]), std::abs(hi[0])),
                                    std::max(std::abs(lo[1]), std::abs(hi[1])));
      const double along =
        std::max({0., inner - far, std::hypot(near_x, near_y) - outer});
      if (level >= level_at(std::hypot(along, std::max(0., -hi[2]))))
        {
          count += 1;
          return;
        }
      const Point<3> mid = 0.5 * (lo + hi);
      for (unsigned int child = 0; child < 8; ++child)
        {
          Point<3> a, b;
          for (unsigned int d = 0; d < 3; ++d)
            {
              const bool upper = (child >> d) & 1;
              a[d]             = upper ? mid[d] : lo[d];
              b[d]             = upper ? hi[d] : mid[d];
            }
          self(self, a, b, level + 1);
        }
    };
    const std::vector<unsigned int> n = coarse_subdivisions<3>(prm);
    const Point<3>                  origin(-W / 2, -L / 2, -H);
    const double                    size[3] = {W / n[0], L / n[1], H / n[2]};
    for (unsigned int i = 0; i < n[0]; ++i)
      for (unsigned int j = 0; j < n[1]; ++j)
        for (unsigned int k = 0; k < n[2]; ++k)
          {
            const Point<3> lo =
              origin + Point<3>(i * size[0], j * size[1], k * size[2]);
            refine(refine, lo, lo + Point<3>(size[0], size[1], size[2]), 0);
          }
    return count;
  }


  template void
  make_block(parallel::distributed::Triangulation<2> &,
             const Parameters::AllParameters &);
  template void
  make_block(parallel::distributed::Triangulation<3> &,
             const Parameters::AllParameters &);
  template bool
  flag_cells_near_edges(parallel::distributed::Triangulation<2> &,
                        const SurfaceRegions<2> &,
                        const Parameters::AllParameters &);
  template bool
  flag_cells_near_edges(parallel::distributed::Triangulation<3> &,
                        const SurfaceRegions<3> &,
                        const Parameters::AllParameters &);


  int
  resolve_on_adapted_meshes(const unsigned int           max_cycles,
                            const std::function<bool()> &adapt_mesh,
                            const std::function<int()>  &solve)
  {
    int its = 0;
    for (unsigned int cycle = 0; cycle < max_cycles && adapt_mesh(); ++cycle)
      {
        const int more = solve();
        if (more < 0)
          return -1;
        its += more;
      }
    return its;
  }


  namespace Parameters
  {
    namespace
    {
      // 'Geometry/Wake lengths': a number, or 'automatic' for the
      // dimension's.
      double
      wake_lengths_of(const std::string &text, const unsigned int dimension)
      {
        if (text == "automatic")
          return dimension == 2 ? 20 : 4;
        std::istringstream in(text);
        double             n = -1;
        in >> n;
        require(in && in.peek() == EOF && n >= 0 && std::isfinite(n),
                "'Geometry/Wake lengths' = '" + text +
                  "' is neither 'automatic' nor a number of wake lengths "
                  "(0 or more)");
        return n;
      }
    } // namespace


    void
    Geometry::declare(ParameterHandler &prm)
    {
      prm.enter_subsection("Geometry");
      prm.declare_entry(
        "Dimension",
        "2",
        Patterns::Integer(2, 3),
        "2: plane strain, the indenter a cylinder (its profile h(x)) on a "
        "block or layer. 3: the indenter the body of revolution h(r) of "
        "its shape (a sphere for 'circle', a paraboloid for 'parabola') on "
        "a half-space or a layer, by Sliding/Solver = boundary-element, or "
        "on a block by steady-state (doc/steady_state.md); forces in 1.5 pi "
        "dgamma R, contact areas in "
        "pi R eps (doc/conventions.md).");
      prm.declare_entry("Substrate",
                        "half-plane",
                        Patterns::Selection(choice_pattern<Substrate>()),
                        "'half-plane': a block of Domain width x Domain "
                        "height, large against the contact, base fixed. "
                        "'layer': a layer of Layer thickness bonded to a "
                        "rigid base.");
      prm.declare_entry("Layer thickness",
                        "100",
                        Patterns::Double(),
                        "t_hat = t/eps, used with Substrate = layer.");
      prm.declare_entry("Domain width",
                        "20000",
                        Patterns::Double(),
                        "W/eps, the lateral extent of the block (x from "
                        "-W/2 to W/2). Lateral sides are traction free.");
      prm.declare_entry(
        "Domain height",
        std::to_string(Geometry::default_domain_height),
        Patterns::Double(),
        "H/eps of the half-plane block. Under displacement "
        "control the approach delta depends on it "
        "logarithmically (plane strain). With Dimension = 3 "
        "the depth of the finite elements' block, by "
        "default (10000) the Domain width: a much deeper "
        "block bends under the friction force "
        "(doc/steady_state.md, In three dimensions, The block).");
      prm.declare_entry(
        "Indenter elongation",
        "1",
        Patterns::Double(0.),
        "Dimension = 3 only: R_y/R, the indenter's radius of curvature "
        "across the track (y) over the one along it (R, set by "
        "Adhesion/R over eps). The profile is h(sqrt(x^2 + y^2/"
        "elongation)) for the shape's h(r): an elliptic paraboloid for "
        "'parabola'; a large elongation approaches the 2D cylinder "
        "(doc/sphere.md).");
      prm.declare_entry(
        "Domain length",
        "0",
        Patterns::Double(0.),
        "Dimension = 3 only: the extent (in eps) of the surface across "
        "the track, y from -length/2 to length/2; 0 takes the Domain "
        "width.");
      prm.declare_entry(
        "Wake lengths",
        "automatic",
        Patterns::Anything(),
        "The steady-state solver needs the wake, the solid relaxing "
        "over V tau_c behind the contact (tau_c the creep time), inside "
        "its block, or it misses part of the friction at high speed. "
        "Under force control it widens the block to at least this many "
        "wake lengths of the fastest listed speed: in 2D the width, and "
        "a half-plane's depth to a quarter of that; in 3D the length "
        "along the track (x) alone. 'automatic': 20 in 2D, 4 in 3D "
        "(doc/model.md, Block and wake; doc/steady_state.md, The "
        "block). The 2D boundary elements approach on the same depth. "
        "Under displacement and spring control the block stays as given "
        "(it sets the reference of delta) and a warning says when it is "
        "too small; a layer is widened under every control. Set 0 to "
        "keep the block as given, for example for a periodic profile "
        "whose wavelength is the width, or with Mesh/Uniform surface "
        "(which keeps it anyway).");
      prm.leave_subsection();
    }



    void
    Geometry::parse(ParameterHandler &prm)
    {
      prm.enter_subsection("Geometry");
      dimension = prm.get_integer("Dimension");
      substrate =
        parse_choice<Substrate>(prm.get("Substrate"), "Geometry/Substrate");
      layer_thickness = prm.get_double("Layer thickness");
      domain_width    = prm.get_double("Domain width");
      domain_height   = prm.get_double("Domain height");
      wake_lengths    = wake_lengths_of(prm.get("Wake lengths"), dimension);
      elongation      = prm.get_double("Indenter elongation");
      domain_length   = prm.get_double("Domain length");
      prm.leave_subsection();
      require(layer_thickness > 0 && std::isfinite(layer_thickness),
              entry("Geometry", "Layer thickness", layer_thickness) +
                " must be positive");
      // What one dimension has and the other has not.
      require(dimension == 3 || (elongation == 1 && domain_length == 0),
              "'Geometry/Indenter elongation' and 'Geometry/Domain length' "
              "are for 'Geometry/Dimension' = 3; in 2D the indenter is a "
              "cylinder and the forces are per unit length: remove them");
      require(elongation > 0 && std::isfinite(elongation),
              entry("Geometry", "Indenter elongation", elongation) +
                " must be positive");
      require(std::isfinite(domain_length),
              entry("Geometry", "Domain length", domain_length) +
                " must be finite");
      require(domain_width > 0 && std::isfinite(domain_width),
              entry("Geometry", "Domain width", domain_width) +
                " must be positive");
      require(domain_height > 0 && std::isfinite(domain_height),
              entry("Geometry", "Domain height", domain_height) +
                " must be positive");
    }


    void
    Mesh::declare(ParameterHandler &prm)
    {
      prm.enter_subsection("Mesh");
      prm.declare_entry("Finest surface cell",
                        "0.5",
                        Patterns::Double(),
                        "Size (in eps) of the finest cells, placed at the "
                        "contact edges. The Lennard-Jones process zone is "
                        "about 0.05 sqrt(R eps) at muT = 6.08 and must be "
                        "resolved by several such cells.");
      prm.declare_entry("Mesh grading",
                        "0.25",
                        Patterns::Double(),
                        "Away from the contact edges the desired cell size "
                        "grows as grading x distance to the nearest edge.");
      prm.declare_entry("Edge gap lower",
                        "1.05",
                        Patterns::Double(),
                        "A top face belongs to a contact edge where its gap "
                        "range overlaps [lower, upper] (in eps).");
      prm.declare_entry("Edge gap upper",
                        "2.5",
                        Patterns::Double(),
                        "See Edge gap lower.");
      prm.declare_entry(
        "Edge margin",
        "8",
        Patterns::Double(0),
        "Distance (in eps) by which a contact edge may move before the "
        "mesh is adapted again: the mesh is refined as if each edge were "
        "this much wider, and changed only where a cell is coarser than "
        "the edge itself needs. Wider "
        "margins mean fewer adaptations, each re-solve, factorization "
        "and transfer saved, for a few more cells.");
      prm.declare_entry("Adaptation cycles per step",
                        "3",
                        Patterns::Integer(0),
                        "How often a step may be re-solved on a mesh adapted "
                        "to its own solution. 0 freezes the initial mesh.");
      prm.declare_entry("Uniform surface",
                        "false",
                        Patterns::Bool(),
                        "Refine the whole top surface to the finest cell "
                        "(grading with depth only) instead of following the "
                        "contact edges: the reference for checking the "
                        "adaptive mesh, at a much higher cost.");
      prm.leave_subsection();
    }

    void
    Mesh::parse(ParameterHandler &prm)
    {
      prm.enter_subsection("Mesh");
      finest_cell           = prm.get_double("Finest surface cell");
      grading               = prm.get_double("Mesh grading");
      edge_gap_low          = prm.get_double("Edge gap lower");
      edge_gap_high         = prm.get_double("Edge gap upper");
      edge_margin           = prm.get_double("Edge margin");
      max_adaptation_cycles = prm.get_integer("Adaptation cycles per step");
      uniform_surface       = prm.get_bool("Uniform surface");
      prm.leave_subsection();
      require(finest_cell > 0,
              entry("Mesh", "Finest surface cell", finest_cell) +
                " must be positive");
      require(grading > 0 && grading <= 2,
              entry("Mesh", "Mesh grading", grading) + " must be in (0, 2]");
      require(edge_gap_high > edge_gap_low,
              entry("Mesh", "Edge gap upper", edge_gap_high) +
                " must exceed Edge gap lower");
    }
  } // namespace Parameters
} // namespace viscoslide

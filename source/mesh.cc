#include <deal.II/base/mpi.h>

#include <deal.II/grid/grid_generator.h>

#include <viscoslide/mesh.h>

#include <algorithm>
#include <cmath>

namespace viscoslide
{
  namespace
  {
    unsigned int
    n_coarse_cells(const double length, const double W, const double H)
    {
      return std::max(1., std::round(length / std::min(W, H)));
    }
  } // namespace


  void
  make_block(parallel::distributed::Triangulation<2> &triangulation,
             const Parameters::AllParameters         &prm)
  {
    const double W = prm.geometry.domain_width, H = prm.geometry.height();
    GridGenerator::subdivided_hyper_rectangle(triangulation,
                                              {n_coarse_cells(W, W, H),
                                               n_coarse_cells(H, W, H)},
                                              Point<2>(-W / 2, -H),
                                              Point<2>(W / 2, 0),
                                              true);
  }


  bool
  flag_cells_near_edges(parallel::distributed::Triangulation<2> &triangulation,
                        const std::vector<std::pair<double, double>> &edges,
                        const Parameters::AllParameters              &prm)
  {
    const double W = prm.geometry.domain_width, H = prm.geometry.height();
    const double coarse_width = W / n_coarse_cells(W, W, H);
    const std::vector<std::pair<double, double>> whole_surface{{-W / 2, W / 2}};
    const int                                    max_level = static_cast<int>(
      std::ceil(std::log2(coarse_width / prm.mesh.finest_cell) - 1e-9));
    // The refinement level a cell at distance d from the edges needs.
    const auto level_at = [&](const double d) {
      const double h = std::max(prm.mesh.finest_cell, prm.mesh.grading * d);
      return std::clamp(static_cast<int>(
                          std::ceil(std::log2(coarse_width / h) - 1e-9)),
                        0,
                        max_level);
    };

    bool must_change = false;
    for (const auto &cell : triangulation.active_cell_iterators())
      if (cell->is_locally_owned())
        {
          // The distance to the nearest edge, and to the nearest edge
          // widened by the margin along the surface.
          const auto   box = cell->bounding_box();
          const double dy  = std::max(0., -box.upper_bound(1));
          double       d = std::numeric_limits<double>::max(), d_wide = d;
          for (const auto &[a, b] :
               prm.mesh.uniform_surface ? whole_surface : edges)
            {
              const double dx =
                std::max({0., a - box.upper_bound(0), box.lower_bound(0) - b});
              d = std::min(d, std::hypot(dx, dy));
              d_wide =
                std::min(d_wide,
                         std::hypot(std::max(0., dx - prm.mesh.edge_margin),
                                    dy));
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
} // namespace viscoslide

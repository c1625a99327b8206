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

    for (const auto &cell : triangulation.active_cell_iterators())
      if (cell->is_locally_owned())
        {
          const auto box = cell->bounding_box();
          double     d   = std::numeric_limits<double>::max();
          for (const auto &[a, b] :
               prm.mesh.uniform_surface ? whole_surface : edges)
            {
              const double dx =
                std::max({0., a - box.upper_bound(0), box.lower_bound(0) - b});
              const double dy = std::max(0., -box.upper_bound(1));
              d               = std::min(d, std::hypot(dx, dy));
            }
          const double h_desired =
            std::max(prm.mesh.finest_cell, prm.mesh.grading * d);
          const int level =
            std::clamp(static_cast<int>(
                         std::ceil(std::log2(coarse_width / h_desired) - 1e-9)),
                       0,
                       max_level);
          if (cell->level() < level)
            cell->set_refine_flag();
          else if (cell->level() > level + 1)
            cell->set_coarsen_flag();
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

// SPDX-License-Identifier: LGPL-2.1-or-later
#include <viscoslide/boundary_element/graded_grid.h>
#include <viscoslide/boundary_element/grid.h>
#include <viscoslide/boundary_element/window_preconditioner.h>

#include <algorithm>
#include <cmath>
#include <limits>

namespace viscoslide
{
  namespace
  {
    // A motion d of a grid whose boundaries are `from` in a multiple of
    // the spacing of doubles beyond the window's ends, so that a cell moved
    // rigidly keeps its width to the last bit: rounded at each boundary, a
    // fine cell 1e6 eps from the origin changed its width by 1e-7 of
    // itself, a residual that the motions' columns (differences over the
    // finest cell) divide by it.
    double
    exact_motion(const std::vector<double> &from, const double d)
    {
      const double extent =
        std::max(std::abs(from.front()), std::abs(from.back()));
      const double unit = std::ldexp(1.,
                                     std::ilogb(extent) + 2 -
                                       std::numeric_limits<double>::digits);
      return std::round(d / unit) * unit;
    }

    // The boundaries `from`, made for edges `from_edges`, moved with the
    // edges by d_trail and d_lead (edge_shift, grid.h).
    std::vector<double>
    moved_boundaries(const std::vector<double>       &from,
                     const std::pair<double, double> &from_edges,
                     const double                     d_trail,
                     const double                     d_lead)
    {
      const auto          shift = edge_shift(from_edges, d_trail, d_lead);
      std::vector<double> moved(from);
      for (double &b : moved)
        b += shift(b);
      return moved;
    }
  } // namespace


  GradedGrid::GradedGrid(const Parameters::AllParameters &prm,
                         const Scales                    &scales,
                         const ViscoelasticSolid         &material,
                         const Indenter                  &indenter,
                         const double                     dx,
                         ConditionalOStream              &out)
    : SurfaceGrid<2>(dx)
    , prm(prm)
    , scales(scales)
    , material(material)
    , indenter(indenter)
    , out(out)
    , depth(prm.geometry.height() * scales.eps)
    , window(
        std::make_unique<WindowPreconditioner>(*this, scales.sigma_max, true))
  {
  }


  GradedGrid::~GradedGrid() = default;


  void
  GradedGrid::set_speed(const double V)
  {
    speed = V;
    compliance->set_speed(V);
  }


  void
  GradedGrid::apply(const Vector<double> &q, Vector<double> &u) const
  {
    compliance->apply(q, u);
  }


  FullMatrix<double>
  GradedGrid::block(const unsigned int first, const unsigned int m) const
  {
    return compliance->block(first, m);
  }


  void
  GradedGrid::creep_slope(const Vector<double> &q, Vector<double> &slope) const
  {
    compliance->creep_slope(q, slope);
  }


  NewtonPreconditioner &
  GradedGrid::preconditioner()
  {
    return *window;
  }


  std::shared_ptr<const SurfaceGrid<2>::Placement>
  GradedGrid::placement() const
  {
    return std::make_shared<Cells>(cells);
  }


  void
  GradedGrid::regrid(const Placement &p, SurfaceState &state)
  {
    const auto &c = dynamic_cast<const Cells &>(p);
    make(c.boundaries, c.edges, state);
  }


  void
  GradedGrid::place(const Placement      &p,
                    const Vector<double> &gaps,
                    SurfaceState         &state)
  {
    const auto &c = dynamic_cast<const Cells &>(p);
    set_cells(c.boundaries, c.edges, gaps, state);
  }


  void
  GradedGrid::place_about(const double  trail,
                          const double  lead,
                          SurfaceState &state)
  {
    make_about(trail, lead, state);
  }


  void
  GradedGrid::make(const std::vector<double>           &new_boundaries,
                   const std::pair<double, double>     &edges,
                   SurfaceState                        &state,
                   const std::function<double(double)> &shift)
  {
    // The state carried over as its gaps; the first grid from u = 0.
    const auto           &x       = points.x;
    const Vector<double> &old_gap = state.gap; // read before set_cells
    const unsigned int    n       = new_boundaries.size() - 1;
    Vector<double>        gap(n);
    for (unsigned int j = 0; j < n; ++j)
      {
        // Linear between the old points, beyond them the nearer end's.
        const double centre = 0.5 * (new_boundaries[j] + new_boundaries[j + 1]);
        const double from   = shift ? centre - shift(centre) : centre;
        const auto   k = std::upper_bound(x.begin(), x.end(), from) - x.begin();
        if (x.empty())
          gap[j] = scales.eps + indenter.profile(centre) - state.delta;
        else if (k == 0)
          gap[j] = old_gap[0];
        else if (k == long(x.size()))
          gap[j] = old_gap[x.size() - 1];
        else
          {
            const double t = (from - x[k - 1]) / (x[k] - x[k - 1]);
            gap[j]         = (1 - t) * old_gap[k - 1] + t * old_gap[k];
          }
      }
    set_cells(new_boundaries, edges, gap, state);
    pins = {};
    ++n_generation;
    out << "Graded boundary-element grid: " << n << " cells, " << dx
        << " eps at the contact edges x = " << edges.first / scales.eps << ", "
        << edges.second / scales.eps << " eps, window "
        << cells.boundaries.front() / scales.eps << " to "
        << cells.boundaries.back() / scales.eps << " eps" << std::endl;
  }


  void
  GradedGrid::set_cells(const std::vector<double>       &new_boundaries,
                        const std::pair<double, double> &edges,
                        const Vector<double>            &gap,
                        SurfaceState                    &state)
  {
    // A grid moved with its edges, or made anew with as many cells, keeps
    // the window preconditioner's factors of the grid before: they stay a
    // preconditioner (grid.apply() is the present compliance; the factors
    // are renewed when the stiff points leave their window or GMRES needs
    // too many iterations with them). With the edges as unknowns the grid
    // moves at every Newton step, and a factorization at each (the
    // compliance formed, n^3, and factorized) was half the time of a
    // curve. Another number of cells needs new factors.
    if (new_boundaries.size() != cells.boundaries.size())
      window->reset();
    cells.boundaries     = new_boundaries;
    cells.edges          = edges;
    const auto        &b = cells.boundaries;
    const unsigned int n = b.size() - 1;
    compliance           = std::make_unique<GradedCompliance>(material,
                                                    prm.material.poisson_ratio,
                                                    b,
                                                    depth);
    compliance->set_speed(speed);
    points.x.resize(n);
    points.y.assign(n, 0.);
    points.h.resize(n);
    points.slope.resize(n);
    points.area.resize(n);
    state.gap = gap;
    for (unsigned int j = 0; j < n; ++j)
      {
        const double x  = 0.5 * (b[j] + b[j + 1]);
        points.x[j]     = x;
        points.area[j]  = b[j + 1] - b[j];
        points.h[j]     = indenter.profile(x);
        points.slope[j] = indenter.slope(x);
      }
    // The boundaries at the two edges (graded_boundaries places them).
    for (unsigned int e = 0; e < 2; ++e)
      {
        const double at = e == 0 ? edges.first : edges.second;
        focus[e]        = std::lower_bound(b.begin(), b.end(), at) - b.begin();
      }
  }


  void
  GradedGrid::make_about(const double                         trail,
                         const double                         lead,
                         SurfaceState                        &state,
                         const std::function<double(double)> &shift)
  {
    const double margin =
      std::max(margin_factor * (lead - trail), 50 * scales.eps);
    make(graded_boundaries(
           trail, lead, dx, prm.boundary_element.grading_ratio, margin),
         {trail, lead},
         state,
         shift);
  }


  bool
  GradedGrid::follow(const SurfaceQuantities &q,
                     const Vector<double>    &traction,
                     const bool               always,
                     SurfaceState            &state)
  {
    const unsigned int n     = size();
    const double       ratio = prm.boundary_element.grading_ratio;
    // Where the cells are at most 1.5 times the finest.
    const double tolerance = 0.5 * dx / (ratio - 1);
    const bool   loaded_ends =
      std::max(std::abs(traction[0]), std::abs(traction[n - 1])) >
      1e-4 * scales.sigma_max;
    if (loaded_ends)
      margin_factor *= 2;
    if (!always && !loaded_ends &&
        std::abs(q.x_trail - cells.edges.first) <= tolerance &&
        std::abs(q.x_lead - cells.edges.second) <= tolerance)
      return false;
    make_about(q.x_trail, q.x_lead, state);
    return true;
  }


  void
  GradedGrid::predict(const std::pair<double, double> &edges,
                      const std::pair<double, double> &edges_before,
                      const double                     ratio,
                      SurfaceState                    &state)
  {
    // Each edge's adhesive zone moved with its edge, so that it arrives
    // whole where it is predicted (the secant of u at fixed x would smear
    // it over cells far coarser than it).
    if (!(std::abs(ratio) <= 2) || edges.second <= edges.first)
      return;
    const double trail =
                   edges.first + ratio * (edges.first - edges_before.first),
                 lead =
                   edges.second + ratio * (edges.second - edges_before.second);
    if (!(lead > trail))
      return;
    const auto shift =
      edge_shift(edges, trail - edges.first, lead - edges.second);
    make_about(trail, lead, state, shift);
  }


  bool
  GradedGrid::prepare_motions(const SurfaceQuantities &q, SurfaceState &state)
  {
    // Each edge's gap is pinned where the contact gap is crossed now, so
    // that the pins hold at the start and the zone keeps the cells it has.
    // Only an edge that strayed from its focus beyond the cells at most
    // 1.5 times the finest (where follow() refits too) gets a grid made
    // about it: a remade grid carries the zone's gaps by interpolation,
    // whose error in a zone of a few cells is a residual of a sizeable
    // fraction of eps at Tabor parameters of 1000.
    if (!(q.x_lead > q.x_trail))
      return false; // no contact
    const double tolerance =
      0.5 * dx / (prm.boundary_element.grading_ratio - 1);
    if (std::abs(q.x_trail - cells.edges.first) > tolerance ||
        std::abs(q.x_lead - cells.edges.second) > tolerance)
      make_about(q.x_trail, q.x_lead, state);
    const auto &x = points.x;
    for (unsigned int e = 0; e < 2; ++e)
      {
        const double at = e == 0 ? q.x_trail : q.x_lead;
        const auto   k  = std::upper_bound(x.begin(), x.end(), at) - x.begin();
        if (k == 0 || k == long(x.size()))
          return false;
        const double t = (at - x[k - 1]) / (x[k] - x[k - 1]);
        pins[e]        = {{k - 1, 1 - t}, {k, t}};
      }
    return true;
  }


  void
  GradedGrid::move(const Placement           &from,
                   const std::vector<double> &d,
                   const Vector<double>      &gaps,
                   SurfaceState              &state)
  {
    const auto  &c     = dynamic_cast<const Cells &>(from);
    const double trail = exact_motion(c.boundaries, d[0]),
                 lead  = exact_motion(c.boundaries, d[1]);
    set_cells(moved_boundaries(c.boundaries, c.edges, trail, lead),
              {c.edges.first + trail, c.edges.second + lead},
              gaps,
              state);
  }


  std::unique_ptr<SurfaceGrid<2>>
  GradedGrid::moved(const Placement           &from,
                    const std::vector<double> &d,
                    const Vector<double>      &gaps,
                    SurfaceState              &state) const
  {
    auto grid =
      std::make_unique<GradedGrid>(prm, scales, material, indenter, dx, out);
    grid->speed = speed;
    grid->move(from, d, gaps, state);
    return grid;
  }


  std::vector<std::pair<unsigned int, double>>
  GradedGrid::pin(const unsigned int k) const
  {
    if (!pins[k].empty())
      return pins[k];
    if (focus[0] < 1 || focus[1] >= size() || focus[1] <= focus[0])
      return {};
    return {{focus[k] - 1, 0.5}, {focus[k], 0.5}};
  }


  // The ends are their own neighbours (no traction reaches them), and the
  // distance to the next point is its own.
  unsigned int
  GradedGrid::next(const unsigned int j) const
  {
    return std::min(j + 1, size() - 1);
  }


  unsigned int
  GradedGrid::previous(const unsigned int j) const
  {
    return j > 0 ? j - 1 : 0u;
  }


  double
  GradedGrid::distance_to_next(const unsigned int j) const
  {
    return points.x[next(j)] - points.x[j];
  }


  double
  GradedGrid::distance_across(const unsigned int j) const
  {
    return points.x[next(j)] - points.x[previous(j)];
  }
} // namespace viscoslide

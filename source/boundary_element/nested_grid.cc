// SPDX-License-Identifier: LGPL-2.1-or-later
#include <viscoslide/boundary_element/nested_grid.h>
#include <viscoslide/boundary_element/uniform_grid.h>
#include <viscoslide/case_setup/common.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <fstream>
#include <numeric>
#include <sstream>
#include <stdexcept>

namespace viscoslide
{
  NestedGrid::NestedGrid(const Parameters::AllParameters &prm,
                         const Scales                    &scales,
                         const ViscoelasticSolid         &material,
                         const Indenter                  &indenter,
                         const double                     dx,
                         ConditionalOStream              &out)
    : SurfaceGrid<3>(dx)
    , prm(prm)
    , scales(scales)
    , material(material)
    , indenter(indenter)
    , out(out)
    , refining(!(prm.sliding.speed > 0))
  {
  }


  NestedGrid::~NestedGrid() = default;


  void
  NestedGrid::set_speed(const double V)
  {
    speed = V;
    window->set_speed(V);
    multigrid->set_speed(V);
    compliance->set_speed(V);
  }


  // The window of the isolated grid: Domain width along x, Domain length
  // across, counts a multiple of 16 for the multigrid's levels. Before
  // sliding, the quasi-static approach runs on the coarse cells alone
  // (its contact has no creep to resolve, and its steps would each remake
  // the band); the band follows from the first speed on.
  void
  NestedGrid::fit_to_speed(const double V_hat, SurfaceState &state)
  {
    refining = refining || V_hat > 0;
    if (size() > 0)
      return;
    shape[1] = 16 * fft_size(prm.geometry.domain_width * scales.eps / dx / 16);
    shape[0] = 16 * fft_size(prm.geometry.length() * scales.eps / dx / 16);
    // The coarse window's operators, the same for every band.
    const double nu = prm.material.poisson_ratio;
    window = std::make_unique<IsolatedCompliance>(material, nu, shape, dx);
    multigrid =
      std::make_unique<SurfaceMultigrid<3>>(Parameters::Substrate::half_plane,
                                            0.,
                                            material,
                                            nu,
                                            shape,
                                            dx,
                                            scales.sigma_max);
    window->set_speed(speed);
    multigrid->set_speed(speed);
    make(std::vector<bool>(shape[0] * shape[1], false), state);
  }


  void
  NestedGrid::make(const std::vector<bool> &band, SurfaceState &state)
  {
    require_fits(band);
    std::unique_ptr<NestedLayout> old = std::move(layout);
    layout                            = std::make_unique<NestedLayout>(shape,
                                            dx,
                                            prm.boundary_element.refinement,
                                            band);
    compliance = std::make_unique<NestedCompliance>(material,
                                                    prm.material.poisson_ratio,
                                                    *layout,
                                                    *window);
    compliance->set_speed(speed);
    nested_preconditioner =
      std::make_unique<NestedPreconditioner>(*layout, *multigrid);
    // The displacements carried over (they are smooth where the gaps are
    // not: under the contact's edge).
    const Vector<double> old_u = state.displacement(points.h, scales.eps);
    const unsigned int   n     = layout->size();
    const double         h     = layout->h;
    Points              &p     = points;
    p                          = Points();
    for (unsigned int j = 0; j < n; ++j)
      {
        const int lx = layout->lattice_x(j), ly = layout->lattice_y(j);
        p.x.push_back(lx * h);
        p.y.push_back(ly * h);
        p.area.push_back(layout->area(j));
        const double r = radius(lx, ly);
        p.h.push_back(indenter.profile(r));
        p.slope.push_back(r > 0 ? indenter.slope(r) * p.x[j] / r : 0.);
      }
    state.set_displacement(old ? carried(*old, old_u) : Vector<double>(n),
                           p.h,
                           scales.eps);
    ++n_generation;
    std::ostringstream s;
    s << "Boundary-element grid: " << n << " points, " << shape[1] << " x "
      << shape[0] << " cells of " << dx / scales.eps << " eps, "
      << std::count(band.begin(), band.end(), true) << " of them divided "
      << layout->r << " x " << layout->r;
    out << s.str() << std::endl;
  }


  void
  NestedGrid::require_fits(const std::vector<bool> &band) const
  {
    const unsigned int r = prm.boundary_element.refinement;
    const double       points =
      band.size() + std::count(band.begin(), band.end(), true) * (r * r - 1.);
    const double gigabytes = plane_grid_bytes_per_point * points / 1e9;
    const double limit     = CaseSetup::internal::plane_grid_memory_limit_gb();
    if (gigabytes <= limit)
      return;
    std::ostringstream s;
    s << "the nested boundary-element grid about the contact's edge at V_hat "
      << speed * scales.tau_ref / scales.eps << " needs " << points
      << " points, about " << gigabytes << " GB, more than the " << limit
      << " GB a grid may take on this machine: lower 'Boundary "
         "element/Refinement' or 'Boundary "
         "element/Band width', or raise 'Boundary element/Grid spacing'";
    throw std::runtime_error(s.str());
  }


  double
  NestedGrid::value_at(const NestedLayout   &old,
                       const Vector<double> &u,
                       const int             x,
                       const int             y) const
  {
    const int r = old.r, n_x = old.n[1], n_y = old.n[0];
    // The cell holding the point, and the point's place in it.
    const auto cell_of = [&](const int lattice, const int n) {
      return std::clamp((lattice + (n / 2) * r + r / 2) / r, 0, n - 1);
    };
    const int ix = cell_of(x, n_x), iy = cell_of(y, n_y);
    if (old.band[iy * n_x + ix])
      {
        const int k = x - (ix - n_x / 2) * r + r / 2,
                  s = y - (iy - n_y / 2) * r + r / 2;
        return u[old.fine(iy * n_x + ix, s, k)];
      }
    // Bilinear between the centres of the four cells about the point.
    const double fx = double(x) / r + n_x / 2, fy = double(y) / r + n_y / 2;
    const int    x0 = std::clamp(int(std::floor(fx)), 0, n_x - 2),
              y0    = std::clamp(int(std::floor(fy)), 0, n_y - 2);
    const double a  = std::clamp(fx - x0, 0., 1.),
                 b  = std::clamp(fy - y0, 0., 1.);
    const auto at   = [&](const int i, const int j) {
      return u[old.centre(j * n_x + i)];
    };
    return (1 - a) * (1 - b) * at(x0, y0) + a * (1 - b) * at(x0 + 1, y0) +
           (1 - a) * b * at(x0, y0 + 1) + a * b * at(x0 + 1, y0 + 1);
  }


  Vector<double>
  NestedGrid::carried(const NestedLayout &old, const Vector<double> &u) const
  {
    Vector<double> here(layout->size());
    for (unsigned int j = 0; j < here.size(); ++j)
      here[j] = value_at(old, u, layout->lattice_x(j), layout->lattice_y(j));
    return here;
  }


  double
  NestedGrid::radius(const int x, const int y) const
  {
    return std::hypot(x * layout->h,
                      y * layout->h / std::sqrt(prm.geometry.elongation));
  }


  std::shared_ptr<const SurfaceGrid<3>::Placement>
  NestedGrid::coarse_placement() const
  {
    if (std::find(layout->band.begin(), layout->band.end(), true) ==
        layout->band.end())
      return nullptr;
    auto p   = std::make_shared<Band>();
    p->flags = std::vector<bool>(layout->band.size(), false);
    return p;
  }


  bool
  NestedGrid::carry(const Placement &p, SurfaceState &state) const
  {
    const NestedLayout old(shape,
                           dx,
                           prm.boundary_element.refinement,
                           dynamic_cast<const Band &>(p).flags);
    if (old.size() != state.gap.size())
      return false;
    std::vector<double> h(old.size());
    for (unsigned int j = 0; j < h.size(); ++j)
      h[j] = indenter.profile(radius(old.lattice_x(j), old.lattice_y(j)));
    state.set_displacement(carried(old, state.displacement(h, scales.eps)),
                           points.h,
                           scales.eps);
    return true;
  }


  std::vector<bool>
  NestedGrid::core_of(const Vector<double> &traction) const
  {
    const NestedLayout &l   = *layout;
    const int           n_x = shape[1], n_y = shape[0];
    // Each cell's mean traction.
    std::vector<double> mean(l.n_cells(), 0.);
    for (unsigned int j = 0; j < l.size(); ++j)
      mean[l.cell_of[j]] += traction[j] * l.area(j) / (dx * dx);
    const double      peak = *std::max_element(mean.begin(), mean.end());
    std::vector<bool> core(l.n_cells(), false);
    for (int iy = 0; iy + 1 < n_y; ++iy)
      for (int ix = 0; ix + 1 < n_x; ++ix)
        {
          const int  c    = iy * n_x + ix;
          const bool pull = mean[c] > 0;
          if (peak > 0 && mean[c] > 0.5 * peak)
            core[c] = true;
          for (const int d : {1, n_x})
            if ((mean[c + d] > 0) != pull)
              core[c] = core[c + d] = true;
        }
    return core;
  }


  std::vector<bool>
  NestedGrid::widened(const std::vector<bool> &core, const int spare) const
  {
    const int n_x = shape[1], n_y = shape[0];
    // By the band width and `spare` cells.
    const int w =
      int(std::ceil(prm.boundary_element.band_width * scales.eps / dx - 1e-9)) +
      spare;
    // No band cell within the compliance's margin of the window's border
    // (nested_compliance.h): a band that would reach there is refused,
    // the window being too small for the contact.
    const int         m = NestedCompliance::margin;
    std::vector<bool> band(core.size(), false);
    for (int iy = 0; iy < n_y; ++iy)
      for (int ix = 0; ix < n_x; ++ix)
        if (core[iy * n_x + ix])
          {
            if (std::min({ix, iy, n_x - 1 - ix, n_y - 1 - iy}) < m + w)
              throw std::runtime_error(
                "the band of the nested boundary-element grid about the "
                "contact's edge (the adhesive zone widened by 'Boundary "
                "element/Band width') reaches within " +
                std::to_string(m) +
                " cells of the window's border, where no band cell may be "
                "(the near field's margin): raise 'Geometry/Domain width' "
                "and 'Geometry/Domain length', or lower 'Boundary "
                "element/Band width'");
            for (int y = iy - w; y <= iy + w; ++y)
              for (int x = ix - w; x <= ix + w; ++x)
                band[y * n_x + x] = true;
          }
    return band;
  }


  bool
  NestedGrid::follow(const SurfaceQuantities &,
                     const Vector<double> &traction,
                     const bool            always,
                     SurfaceState         &state)
  {
    if (!refining)
      return false;
    // Kept while the band asked for lies within the refined cells; a new
    // one has a cell to spare on every side, so that a band that moves by
    // a cell between two solutions does not remake the grid each time.
    const std::vector<bool> core   = core_of(traction);
    const std::vector<bool> wanted = widened(core, 0);
    bool                    inside = true;
    for (unsigned int c = 0; c < wanted.size() && inside; ++c)
      inside = !wanted[c] || layout->band[c];
    if (inside && !always)
      return false;
    const std::vector<bool> spared = widened(core, 1);
    if (spared == layout->band)
      return false;
    make(spared, state);
    return true;
  }


  std::shared_ptr<const SurfaceGrid<3>::Placement>
  NestedGrid::placement() const
  {
    auto p   = std::make_shared<Band>();
    p->flags = layout->band;
    return p;
  }


  void
  NestedGrid::regrid(const Placement &p, SurfaceState &state)
  {
    make(dynamic_cast<const Band &>(p).flags, state);
  }


  void
  NestedGrid::write_map(const std::string    &path,
                        const std::string    &what,
                        const Vector<double> &gaps,
                        const Vector<double> &traction,
                        const Vector<double> &u,
                        const double          eps,
                        const double          sigma_max,
                        const double          R) const
  {
    const Points &p                 = points;
    const auto [extent_x, extent_y] = reach_within(gaps, 10 * eps);
    std::vector<unsigned int> shown;
    for (unsigned int j = 0; j < size(); ++j)
      if (std::abs(p.x[j]) <= 1.25 * extent_x + 4 * dx &&
          std::abs(p.y[j]) <= 1.25 * extent_y + 4 * dx)
        shown.push_back(j);
    // VTK poly data of the points, its arrays appended as raw binary in
    // single precision (the 7 digits a picture needs; six tenths of the
    // decimal text's size, and no time formatting it), each its length in
    // bytes then its values.
    std::string        arrays;
    std::ostringstream tags;
    const auto append = [&](const std::string &tag, const auto &values) {
      tags << tag << " format=\"appended\" offset=\"" << arrays.size()
           << "\"/>\n";
      const std::uint64_t bytes = values.size() * sizeof(values[0]);
      arrays.append(reinterpret_cast<const char *>(&bytes), sizeof(bytes));
      arrays.append(reinterpret_cast<const char *>(values.data()), bytes);
    };
    const auto field = [&](const char *name, const auto &value) {
      std::vector<float> values;
      for (const unsigned int j : shown)
        values.push_back(value(j));
      append(std::string("<DataArray type=\"Float32\" Name=\"") + name + "\"",
             values);
    };
    tags << "<PointData>\n";
    field("p_hat", [&](unsigned int j) { return -traction[j] / sigma_max; });
    field("gap_over_eps", [&](unsigned int j) { return gaps[j] / eps; });
    field("u_over_eps", [&](unsigned int j) { return u[j] / eps; });
    field("cell_over_eps",
          [&](unsigned int j) { return std::sqrt(p.area[j]) / eps; });
    tags << "</PointData>\n<Points>\n";
    std::vector<float> xyz;
    for (const unsigned int j : shown)
      xyz.insert(xyz.end(), {float(p.x[j] / R), float(p.y[j] / R), 0.f});
    append("<DataArray type=\"Float32\" NumberOfComponents=\"3\"", xyz);
    tags << "</Points>\n<Verts>\n";
    std::vector<std::int32_t> connectivity(shown.size()), offsets(shown.size());
    std::iota(connectivity.begin(), connectivity.end(), 0);
    std::iota(offsets.begin(), offsets.end(), 1);
    append("<DataArray type=\"Int32\" Name=\"connectivity\"", connectivity);
    append("<DataArray type=\"Int32\" Name=\"offsets\"", offsets);
    tags << "</Verts>\n";
    const std::uint16_t one = 1;
    const bool    little = *reinterpret_cast<const unsigned char *>(&one) == 1;
    std::ofstream out(path.substr(0, path.rfind('.')) + ".vtp",
                      std::ios::binary);
    out << "<?xml version=\"1.0\"?>\n<!-- " << what << " -->\n"
        << "<VTKFile type=\"PolyData\" version=\"1.0\" byte_order=\""
        << (little ? "LittleEndian" : "BigEndian")
        << "\" header_type=\"UInt64\">\n<PolyData>\n"
        << "<Piece NumberOfPoints=\"" << shown.size() << "\" NumberOfVerts=\""
        << shown.size() << "\">\n"
        << tags.str() << "</Piece>\n</PolyData>\n"
        << "<AppendedData encoding=\"raw\">\n_" << arrays
        << "\n</AppendedData>\n</VTKFile>\n";
    if (!out)
      throw std::runtime_error("could not write the map beside " + path);
  }


  double
  NestedGrid::distance_to_next(const unsigned int j) const
  {
    const unsigned int k = next(j);
    return k == j ? layout->h
                  : (layout->lattice_x(k) - layout->lattice_x(j)) * layout->h;
  }


  double
  NestedGrid::distance_across(const unsigned int j) const
  {
    return (layout->lattice_x(next(j)) - layout->lattice_x(previous(j))) *
           layout->h;
  }


  // The contact's area: each point's square of side sqrt(area), the gap
  // linear over it with the slopes between its neighbours, split into two
  // triangles (exact for a linear gap); the half-width across the track
  // from the crossings between neighbours along y.
  void
  NestedGrid::measure_plane(const Vector<double> &gaps,
                            const double          gc,
                            SurfaceQuantities    &q) const
  {
    const NestedLayout &l    = *layout;
    double              area = 0;
    for (unsigned int j = 0; j < l.size(); ++j)
      {
        const double a = std::sqrt(l.area(j));
        double       slope[2];
        for (unsigned int axis = 0; axis < 2; ++axis)
          {
            const unsigned int f = l.neighbour(j, axis, true),
                               b = l.neighbour(j, axis, false);
            const auto lattice   = [&](const unsigned int i) {
              return axis == 0 ? l.lattice_x(i) : l.lattice_y(i);
            };
            slope[axis] =
              f == b ? 0.
                     : (gaps[f] - gaps[b]) / ((lattice(f) - lattice(b)) * l.h);
          }
        const double gx = 0.5 * a * slope[0], gy = 0.5 * a * slope[1],
                     g = gaps[j];
        area += 0.5 * a * a *
                (fraction_below({{g - gx - gy, g + gx - gy, g + gx + gy}}, gc) +
                 fraction_below({{g - gx - gy, g - gx + gy, g + gx + gy}}, gc));
        const unsigned int up = l.neighbour(j, 1, true);
        if (up != j && (gaps[j] < gc) != (gaps[up] < gc))
          q.y_half = std::max(q.y_half,
                              std::abs(points.y[j] +
                                       (gc - gaps[j]) / (gaps[up] - gaps[j]) *
                                         (points.y[up] - points.y[j])));
      }
    q.contact_length = area;
  }
} // namespace viscoslide

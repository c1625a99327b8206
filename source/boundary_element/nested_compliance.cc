// SPDX-License-Identifier: LGPL-2.1-or-later
#include <viscoslide/boundary_element/nested_compliance.h>

#include <algorithm>
#include <stdexcept>

namespace viscoslide
{
  namespace
  {
    // Love's influence of a square of side `side` at the points (x, y)
    // dx of the lattice, |x|, |y| <= span.
    template <typename Table>
    Table
    love_table(const int span, const double dx, const double side)
    {
      Table t;
      t.span = span;
      for (int y = -span; y <= span; ++y)
        for (int x = -span; x <= span; ++x)
          t.value.push_back(love(x * dx, y * dx, side / 2));
      return t;
    }
  } // namespace


  NestedCompliance::NestedCompliance(const ViscoelasticSolid &material,
                                     const double             nu,
                                     const NestedLayout      &layout,
                                     const unsigned int       near,
                                     const unsigned int       order)
    : layout(layout)
    , near(near)
    , order(order)
    , creep(material, nu)
    , coarse(material, nu, layout.n, layout.H)
    , fine_decay(creep.retardations.size())
    , coarse_decay(creep.retardations.size())
  {
    const int    r = layout.r;
    const double H = layout.H, h = layout.h;
    coarse_at_coarse = love_table<Table>(near + order + 1, H, H);
    fine_at_fine     = love_table<Table>((near + 1) * r, h, h);
    coarse_at_fine   = love_table<Table>((near + 1) * r, h, H);
    // Lagrange's weights on the nodes -order..order at (k - c)/r.
    const int p = order;
    for (int k = 0; k < r; ++k)
      {
        const double        xi = double(k - int(layout.c)) / r;
        std::vector<double> w(2 * p + 1, 1.);
        for (int a = -p; a <= p; ++a)
          for (int b = -p; b <= p; ++b)
            if (b != a)
              w[a + p] *= (xi - b) / double(a - b);
        weight.push_back(w);
      }
    // The cells within `near` of a band cell; no band cell so close to
    // the window's border that its near cells or interpolation points
    // would leave it.
    const unsigned int n_x = layout.n[1], n_y = layout.n[0];
    near_band.assign(layout.n_cells(), 0);
    const unsigned int margin = near + order + 1;
    for (unsigned int cell = 0; cell < layout.n_cells(); ++cell)
      if (layout.band[cell])
        {
          const unsigned int ix = cell % n_x, iy = cell / n_x;
          if (ix < margin || iy < margin || ix + margin >= n_x ||
              iy + margin >= n_y)
            throw std::logic_error("a band cell of the nested grid lies "
                                   "within its margin of the window's "
                                   "border");
          for_near(cell, [&](const unsigned int j) { near_band[j] = 1; });
        }
  }


  template <typename F>
  void
  NestedCompliance::for_near(const unsigned int cell, const F &f) const
  {
    const int n_x = layout.n[1], n_y = layout.n[0], m = near;
    const int ix = cell % n_x, iy = cell / n_x;
    for (int y = std::max(iy - m, 0); y <= std::min(iy + m, n_y - 1); ++y)
      for (int x = std::max(ix - m, 0); x <= std::min(ix + m, n_x - 1); ++x)
        f(y * n_x + x);
  }


  void
  NestedCompliance::set_speed(const double speed)
  {
    V = speed;
    coarse.set_speed(V);
    for (unsigned int r = 0; r < creep.retardations.size(); ++r)
      {
        const double L  = V * creep.retardations[r].first;
        fine_decay[r]   = CellDecay(layout.h, L);
        coarse_decay[r] = CellDecay(layout.H, L);
      }
  }


  double
  NestedCompliance::smear_fine_row(const Vector<double> &q,
                                   const unsigned int    row,
                                   const unsigned int    s,
                                   const unsigned int    r,
                                   std::vector<double>  &q_eff) const
  {
    const NestedLayout       &l = layout;
    std::vector<double>       values, smeared;
    std::vector<unsigned int> index;
    std::vector<bool>         fine;
    for (unsigned int ix = 0; ix < l.n[1]; ++ix)
      {
        const unsigned int cell = row * l.n[1] + ix;
        for (unsigned int k = 0; k < (l.band[cell] ? l.r : 1); ++k)
          {
            index.push_back(l.band[cell] ? l.fine(cell, s, k) : l.first[cell]);
            values.push_back(q[index.back()]);
            fine.push_back(l.band[cell]);
          }
      }
    smeared.assign(values.size(), 0.);
    const auto decay = [&](const unsigned int j) -> const CellDecay & {
      return fine[j] ? fine_decay[r] : coarse_decay[r];
    };
    const double E0 = smear_row(values.data(),
                                values.size(),
                                decay,
                                creep.retardations[r].second,
                                smeared.data());
    // A coarse cell keeps the mean of its r strips.
    for (unsigned int j = 0; j < index.size(); ++j)
      q_eff[index[j]] += fine[j] ? smeared[j] : smeared[j] / l.r;
    return E0;
  }


  void
  NestedCompliance::effective_traction(
    const Vector<double>             &q,
    std::vector<double>              &q_eff,
    std::vector<std::vector<double>> &edge) const
  {
    const NestedLayout &l   = layout;
    const unsigned int  n_x = l.n[1], n_y = l.n[0];
    q_eff.assign(q.begin(), q.end());
    for (double &v : q_eff)
      v *= creep.inverse_glassy;
    edge.assign(creep.retardations.size(), {});
    for (unsigned int r = 0; r < creep.retardations.size(); ++r)
      {
        const double c = creep.retardations[r].second;
        if (coarse.has_wake(r))
          edge[r].assign(n_y, 0.);
        const auto cell = [&d = coarse_decay[r]](
                            unsigned int) -> const CellDecay & { return d; };
        for (unsigned int row = 0; row < n_y; ++row)
          {
            double E0 = 0;
            if (!l.row_has_band[row])
              {
                const unsigned int f = l.first[row * n_x];
                E0 = smear_row(q.begin() + f, n_x, cell, c, q_eff.data() + f);
              }
            else
              for (unsigned int s = 0; s < l.r; ++s)
                E0 += smear_fine_row(q, row, s, r, q_eff) / l.r;
            if (!edge[r].empty())
              edge[r][row] = c * E0;
          }
      }
  }


  std::vector<NestedCompliance::Moments>
  NestedCompliance::moments(const std::vector<double> &q_eff) const
  {
    const NestedLayout  &l = layout;
    std::vector<Moments> m(l.n_cells());
    const double         n = l.r * l.r;
    for (unsigned int cell = 0; cell < l.n_cells(); ++cell)
      if (l.band[cell])
        for (unsigned int s = 0; s < l.r; ++s)
          for (unsigned int k = 0; k < l.r; ++k)
            {
              const double v = q_eff[l.fine(cell, s, k)] / n;
              m[cell].mean += v;
              m[cell].dx += v * (double(k) - l.c) / l.r;
              m[cell].dy += v * (double(s) - l.c) / l.r;
            }
    return m;
  }


  double
  NestedCompliance::carried(const unsigned int          source,
                            const unsigned int          at,
                            const std::vector<double>  &q_eff,
                            const std::vector<Moments> &m) const
  {
    const int n_x  = layout.n[1];
    const int x    = int(at % n_x) - int(source % n_x),
              y    = int(at / n_x) - int(source / n_x);
    const Table &K = coarse_at_coarse;
    if (!layout.band[source])
      return K(x, y) * q_eff[layout.first[source]];
    const Moments &s = m[source];
    return s.mean * K(x, y) + 0.5 * s.dx * (K(x - 1, y) - K(x + 1, y)) +
           0.5 * s.dy * (K(x, y - 1) - K(x, y + 1));
  }


  double
  NestedCompliance::exact(const unsigned int         source,
                          const int                  x,
                          const int                  y,
                          const std::vector<double> &q_eff) const
  {
    const NestedLayout &l      = layout;
    const unsigned int  centre = l.centre(source);
    const int dx = x - l.lattice_x(centre), dy = y - l.lattice_y(centre);
    if (!l.band[source])
      return coarse_at_fine(dx, dy) * q_eff[l.first[source]];
    double        sum = 0;
    const int     c   = l.c;
    const double *v   = q_eff.data() + l.first[source];
    for (int s = 0; s < int(l.r); ++s)
      for (int k = 0; k < int(l.r); ++k)
        sum += fine_at_fine(dx - (k - c), dy - (s - c)) * *v++;
    return sum;
  }


  void
  NestedCompliance::convolve(const std::vector<double>              &q_eff,
                             const std::vector<std::vector<double>> &edge,
                             Vector<double>                         &u) const
  {
    const NestedLayout        &l   = layout;
    const unsigned int         n_x = l.n[1];
    const std::vector<Moments> m   = moments(q_eff);
    // The traction carried onto the coarse cells, and its response there.
    std::vector<double> carried_traction(l.n_cells(), 0.);
    for (unsigned int cell = 0; cell < l.n_cells(); ++cell)
      if (!l.band[cell])
        carried_traction[cell] += q_eff[l.first[cell]];
      else
        {
          carried_traction[cell] += m[cell].mean;
          carried_traction[cell + 1] += 0.5 * m[cell].dx;
          carried_traction[cell - 1] -= 0.5 * m[cell].dx;
          carried_traction[cell + n_x] += 0.5 * m[cell].dy;
          carried_traction[cell - n_x] -= 0.5 * m[cell].dy;
        }
    Vector<double> U;
    coarse.convolve(carried_traction, edge, U);

    u.reinit(l.size());
    const int p = order;
    for (unsigned int cell = 0; cell < l.n_cells(); ++cell)
      {
        const unsigned int centre = l.centre(cell);
        const int          x = l.lattice_x(centre), y = l.lattice_y(centre);
        if (!l.band[cell])
          {
            double v = U[cell];
            if (near_band[cell])
              for_near(cell, [&](const unsigned int j) {
                if (l.band[j])
                  v += exact(j, x, y, q_eff) - carried(j, cell, q_eff, m);
              });
            u[l.first[cell]] = v;
            continue;
          }
        // The far field at the coarse points about the cell.
        std::vector<double> far((2 * p + 1) * (2 * p + 1));
        for (int a = -p; a <= p; ++a)
          for (int b = -p; b <= p; ++b)
            {
              const unsigned int at = cell + a * int(n_x) + b;
              double             v  = U[at];
              for_near(cell, [&](const unsigned int j) {
                v -= carried(j, at, q_eff, m);
              });
              far[(a + p) * (2 * p + 1) + b + p] = v;
            }
        for (unsigned int s = 0; s < l.r; ++s)
          for (unsigned int k = 0; k < l.r; ++k)
            {
              double v = 0;
              for (int a = -p; a <= p; ++a)
                for (int b = -p; b <= p; ++b)
                  v += weight[s][a + p] * weight[k][b + p] *
                       far[(a + p) * (2 * p + 1) + b + p];
              const int xf = x + int(k) - int(l.c), yf = y + int(s) - int(l.c);
              for_near(cell, [&](const unsigned int j) {
                v += exact(j, xf, yf, q_eff);
              });
              u[l.fine(cell, s, k)] = v;
            }
      }
  }


  void
  NestedCompliance::apply(const Vector<double> &q, Vector<double> &u) const
  {
    std::vector<double>              q_eff;
    std::vector<std::vector<double>> edge;
    effective_traction(q, q_eff, edge);
    convolve(q_eff, edge, u);
  }


  void
  NestedCompliance::creep_slope(const Vector<double> &q,
                                Vector<double>       &slope) const
  {
    std::vector<double>              q_eff;
    std::vector<std::vector<double>> edge;
    effective_traction(q, q_eff, edge);
    for (unsigned int j = 0; j < q.size(); ++j)
      q_eff[j] -= q[j];
    Vector<double> u;
    convolve(q_eff, edge, u);
    const NestedLayout &l = layout;
    slope.reinit(q.size());
    for (unsigned int j = 0; j < q.size(); ++j)
      {
        const unsigned int next = l.neighbour(j, 0, true),
                           back = l.neighbour(j, 0, false);
        const int span          = l.lattice_x(next) - l.lattice_x(back);
        if (next != j && back != j)
          slope[j] = (u[next] - u[back]) / (span * l.h);
      }
  }
} // namespace viscoslide

// SPDX-License-Identifier: LGPL-2.1-or-later
#include <deal.II/lac/lapack_templates.h>

#include <viscoslide/boundary_element/nested_compliance.h>

#include <algorithm>
#include <stdexcept>

namespace viscoslide
{
  namespace
  {
    // Love's influence of a square of side `side` at the points (x, y) dx
    // of a lattice, |x|, |y| <= span.
    struct LoveTable
    {
      LoveTable(const int span, const double dx, const double side)
        : span(span)
      {
        for (int y = -span; y <= span; ++y)
          for (int x = -span; x <= span; ++x)
            value.push_back(love(x * dx, y * dx, side / 2));
      }
      double
      operator()(const int x, const int y) const
      {
        return value[(y + span) * (2 * span + 1) + x + span];
      }
      int                 span;
      std::vector<double> value;
    };

    // Lagrange's weights on the nodes -p..p at the offsets (k - c)/r of
    // the r points of a cell (c its middle), k < r.
    std::vector<std::vector<double>>
    lagrange_weights(const int r, const int p)
    {
      std::vector<std::vector<double>> weights;
      for (int k = 0; k < r; ++k)
        {
          const double        xi = double(k - (r - 1) / 2) / r;
          std::vector<double> w(2 * p + 1, 1.);
          for (int a = -p; a <= p; ++a)
            for (int b = -p; b <= p; ++b)
              if (b != a)
                w[a + p] *= (xi - b) / double(a - b);
          weights.push_back(w);
        }
      return weights;
    }
  } // namespace


  NestedCompliance::NestedCompliance(const ViscoelasticSolid  &material,
                                     const double              nu,
                                     const NestedLayout       &layout,
                                     const IsolatedCompliance &window,
                                     const unsigned int        near,
                                     const unsigned int        order)
    : layout(layout)
    , near(near)
    , order(order)
    , creep(material, nu)
    , coarse(window)
    , fine_decay(creep.retardations.size())
    , coarse_decay(creep.retardations.size())
  {
    make_near_field();
    make_strips();
    // The cells within `near` of a band cell; no band cell so close to
    // the window's border that its near cells or interpolation points
    // would leave it.
    const unsigned int n_x = layout.n[1], n_y = layout.n[0];
    near_band.assign(layout.n_cells(), false);
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
          for_near(cell, [&](const unsigned int j, unsigned int) {
            near_band[j] = true;
          });
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
        f(y * n_x + x, (y - iy + m) * (2 * m + 1) + x - ix + m);
  }


  void
  NestedCompliance::set_speed(const double speed)
  {
    V = speed;
    for (unsigned int r = 0; r < creep.retardations.size(); ++r)
      {
        const double L  = V * creep.retardations[r].first;
        fine_decay[r]   = CellDecay(layout.h, L);
        coarse_decay[r] = CellDecay(layout.H, L);
      }
  }


  void
  NestedCompliance::make_strips()
  {
    const NestedLayout &l = layout;
    strips.assign(l.n[0] * l.r, {});
    for (unsigned int row = 0; row < l.n[0]; ++row)
      if (l.row_has_band[row])
        for (unsigned int s = 0; s < l.r; ++s)
          {
            Strip &strip = strips[row * l.r + s];
            for (unsigned int ix = 0; ix < l.n[1]; ++ix)
              {
                const unsigned int cell = row * l.n[1] + ix;
                for (unsigned int k = 0; k < (l.band[cell] ? l.r : 1); ++k)
                  {
                    strip.index.push_back(l.band[cell] ? l.fine(cell, s, k)
                                                       : l.first[cell]);
                    strip.fine.push_back(l.band[cell]);
                  }
              }
          }
  }


  double
  NestedCompliance::smear_strip(const Vector<double> &q,
                                const Strip          &strip,
                                const unsigned int    r,
                                std::vector<double>  &q_eff) const
  {
    const unsigned int  n = strip.index.size();
    std::vector<double> values(n), smeared(n, 0.);
    for (unsigned int j = 0; j < n; ++j)
      values[j] = q[strip.index[j]];
    const auto decay = [&](const unsigned int j) -> const CellDecay & {
      return strip.fine[j] ? fine_decay[r] : coarse_decay[r];
    };
    const double E0 = smear_row(
      values.data(), n, decay, creep.retardations[r].second, smeared.data());
    // A coarse cell keeps the mean of its r strips.
    for (unsigned int j = 0; j < n; ++j)
      q_eff[strip.index[j]] +=
        strip.fine[j] ? smeared[j] : smeared[j] / layout.r;
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
                E0 += smear_strip(q, strips[row * l.r + s], r, q_eff) / l.r;
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
    const unsigned int nf = l.r * l.r;
    for (unsigned int cell = 0; cell < l.n_cells(); ++cell)
      if (!l.band[cell])
        {
          double v = U[cell];
          if (near_band[cell])
            for_near(cell, [&](const unsigned int j, const unsigned int D) {
              if (l.band[j])
                {
                  const double *a = &coarse_from_band[D * nf];
                  const double *q = &q_eff[l.first[j]];
                  for (unsigned int f = 0; f < nf; ++f)
                    v += a[f] * q[f];
                }
            });
          u[l.first[cell]] = v;
        }
    set_band_points(q_eff, U, u);
  }


  // For a batch of band cells the values about each gathered as one
  // column (the band's sources, the coarse cells' (zeros where the other
  // kind is), the coarse response about the cell) and at_band_point
  // applied to the batch as one matrix product (BLAS), faster than the
  // same sums cell by cell (doc/boundary_element.md).
  void
  NestedCompliance::set_band_points(const std::vector<double> &q_eff,
                                    const Vector<double>      &U,
                                    Vector<double>            &u) const
  {
    const NestedLayout &l   = layout;
    const int           n_x = l.n[1], p = order;
    const unsigned int  nf = l.r * l.r, nD = (2 * near + 1) * (2 * near + 1),
                       nP           = (2 * order + 1) * (2 * order + 1),
                       K            = nD * (nf + 1) + nP;
    constexpr unsigned int    batch = 128;
    std::vector<unsigned int> cells;
    std::vector<double>       columns(K * batch), response(nf * batch);
    const auto                flush = [&] {
      const types::blas_int m = nf, n = cells.size(), k = K;
      const double          one = 1., zero = 0.;
      gemm("N",
           "N",
           &m,
           &n,
           &k,
           &one,
           at_band_point.data(),
           &m,
           columns.data(),
           &k,
           &zero,
           response.data(),
           &m);
      for (unsigned int i = 0; i < cells.size(); ++i)
        std::copy_n(&response[i * nf], nf, &u[l.first[cells[i]]]);
      cells.clear();
    };
    for (unsigned int cell = 0; cell < l.n_cells(); ++cell)
      if (l.band[cell])
        {
          // Every offset of a band cell lies in the window (margin), so
          // each entry of the column is written once.
          double *const column  = &columns[cells.size() * K];
          double *const coarser = column + nD * nf;
          for_near(cell, [&](const unsigned int j, const unsigned int D) {
            if (l.band[j])
              std::copy_n(&q_eff[l.first[j]], nf, column + D * nf);
            else
              std::fill_n(column + D * nf, nf, 0.);
            coarser[D] = l.band[j] ? 0. : q_eff[l.first[j]];
          });
          double *P = coarser + nD;
          for (int a = -p; a <= p; ++a)
            for (int b = -p; b <= p; ++b)
              *P++ = U[cell + a * n_x + b];
          cells.push_back(cell);
          if (cells.size() == batch)
            flush();
        }
    if (!cells.empty())
      flush();
  }


  void
  NestedCompliance::make_near_field()
  {
    const int    r = layout.r, c = layout.c, m = near, p = order;
    const double H = layout.H, h = layout.h;
    const int    nf = r * r, nD = (2 * m + 1) * (2 * m + 1),
              nP = (2 * p + 1) * (2 * p + 1);
    const LoveTable coarse_at_coarse(m + p + 1, H, H),
      fine_at_fine((m + 1) * r, h, h), coarse_at_fine((m + 1) * r, h, H);
    const std::vector<std::vector<double>> lagrange = lagrange_weights(r, p);
    // What the coarse grid carried of a source cell at offset (X, Y) from
    // a coarse point: its mean's response, and its dipoles' per unit
    // moment.
    struct Carried
    {
      double mean, x, y;
    };
    const LoveTable &K       = coarse_at_coarse;
    const auto       carried = [&](const int X, const int Y) {
      return Carried{K(X, Y),
                     0.5 * (K(X - 1, Y) - K(X + 1, Y)),
                     0.5 * (K(X, Y - 1) - K(X, Y + 1))};
    };
    // at_band_point's three blocks (nested_compliance.h).
    at_band_point.assign(nf * (nD * (nf + 1) + nP), 0.);
    const auto fine_from_band =
      [&](const int t, const int D, const int f) -> double & {
      return at_band_point[(D * nf + f) * nf + t];
    };
    const auto fine_from_coarse = [&](const int t, const int D) -> double & {
      return at_band_point[(nD * nf + D) * nf + t];
    };
    const auto interpolation = [&](const int t, const int P) -> double & {
      return at_band_point[(nD * (nf + 1) + P) * nf + t];
    };
    coarse_from_band.assign(nD * nf, 0.);
    for (int t = 0; t < nf; ++t)
      for (int a = -p; a <= p; ++a)
        for (int b = -p; b <= p; ++b)
          interpolation(t, (a + p) * (2 * p + 1) + b + p) =
            lagrange[t / r][a + p] * lagrange[t % r][b + p];
    for (int Dy = -m; Dy <= m; ++Dy)
      for (int Dx = -m; Dx <= m; ++Dx)
        {
          const int D = (Dy + m) * (2 * m + 1) + Dx + m;
          // At a coarse point: the source's fine cells exactly, less
          // what was carried (P the point itself, at offset -D).
          const Carried at_centre = carried(-Dx, -Dy);
          for (int f = 0; f < nf; ++f)
            {
              const int    sf = f / r - c, kf = f % r - c;
              const double xi = double(kf) / r, eta = double(sf) / r;
              coarse_from_band[D * nf + f] =
                fine_at_fine(Dx * r + kf, Dy * r + sf) -
                (at_centre.mean + xi * at_centre.x + eta * at_centre.y) / nf;
            }
          for (int t = 0; t < nf; ++t)
            {
              const int st = t / r - c, kt = t % r - c;
              // What was carried, interpolated to t.
              Carried interpolated{0, 0, 0};
              for (int a = -p; a <= p; ++a)
                for (int b = -p; b <= p; ++b)
                  {
                    const double w =
                      interpolation(t, (a + p) * (2 * p + 1) + b + p);
                    const Carried k = carried(b - Dx, a - Dy);
                    interpolated.mean += w * k.mean;
                    interpolated.x += w * k.x;
                    interpolated.y += w * k.y;
                  }
              fine_from_coarse(t, D) =
                coarse_at_fine(Dx * r - kt, Dy * r - st) - interpolated.mean;
              for (int f = 0; f < nf; ++f)
                {
                  const int    sf = f / r - c, kf = f % r - c;
                  const double xi = double(kf) / r, eta = double(sf) / r;
                  fine_from_band(t, D, f) =
                    fine_at_fine(Dx * r + kf - kt, Dy * r + sf - st) -
                    (interpolated.mean + xi * interpolated.x +
                     eta * interpolated.y) /
                      nf;
                }
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
    // An elastic response, alpha G q for any alpha, does no work in a
    // steady state; the uniform grids take out the relaxed one (alpha =
    // 1/E0* = 1, compliance.h). Here the differences between neighbours
    // along x are not uniform where coarse and fine cells meet, and the
    // work of what is left of an elastic response cancels only to their
    // accuracy: at V_hat 1000, where q_eff is nearly q/Einf*, taking out
    // the relaxed response left 0.8 % of the dissipation as error. Taken
    // out instead is the elastic response nearest to it, alpha the
    // projection of q_eff on q (weighted by the cells' areas).
    const NestedLayout &l  = layout;
    double              qq = 0, qe = 0;
    for (unsigned int j = 0; j < q.size(); ++j)
      {
        qq += l.area(j) * q[j] * q[j];
        qe += l.area(j) * q[j] * q_eff[j];
      }
    const double alpha = qq > 0 ? qe / qq : 1.;
    for (unsigned int j = 0; j < q.size(); ++j)
      q_eff[j] -= alpha * q[j];
    Vector<double> u;
    convolve(q_eff, edge, u);
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

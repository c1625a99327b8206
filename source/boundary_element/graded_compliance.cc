// SPDX-License-Identifier: LGPL-2.1-or-later
#include <viscoslide/boundary_element/graded_compliance.h>

#include <cmath>

namespace viscoslide
{
  namespace
  {
    // The integral of ln|t| from b to a = b + w (a cell seen from a point
    // at a from its left end), ln|a| and ln|b| given, w the cell's width
    // (a - b far from the cell has lost the digits): P(a) - P(b) with
    // P(t) = t ln|t| - t. Far from the cell P(a) and P(b) are large and
    // nearly equal: a cell of 0.001 eps seen from 1e6 eps loses 7 of the
    // 16 digits to the difference, a rounding that the motions' columns
    // (differences over a grid moved by its finest cell) divide by their
    // step. There the difference in closed form, w (ln far - 1) - near
    // ln(1 - w/far), the logarithm by its series where w/far < 1e-5 (three
    // terms: 1e-16 of it), which most entries are.
    double
    log_one_minus(const double x)
    {
      return x < 1e-5 ? -x * (1 + x * (0.5 + x / 3)) : std::log1p(-x);
    }

    double
    cell_integral(const double a,
                  const double b,
                  const double w,
                  const double log_a,
                  const double log_b)
    {
      if (b > 0)
        return w * (log_a - 1) - b * log_one_minus(w / a);
      if (a < 0)
        return w * (log_b - 1) + a * log_one_minus(-w / b);
      return (a == 0. ? 0. : a * log_a - a) - (b == 0. ? 0. : b * log_b - b);
    }

    // e^z E1(z) for z > 0 (E1 the exponential integral): its series below
    // 1, the continued fraction above (Abramowitz and Stegun 5.1.11 and
    // 5.1.22), both to machine precision.
    double
    scaled_exponential_integral(const double z)
    {
      if (z <= 1.)
        {
          constexpr double euler = 0.57721566490153286;
          double           sum = 0., term = 1.;
          for (unsigned int k = 1; k < 40; ++k)
            {
              term *= -z / k;
              sum -= term / k;
            }
          return std::exp(z) * (-euler - std::log(z) + sum);
        }
      // Lentz's evaluation of 1/(z + 1 - 1/(z + 3 - 4/(z + 5 - ...))).
      const double tiny = 1e-300;
      double       b = z + 1., c = 1. / tiny, d = 1. / b, h = d;
      for (unsigned int i = 1; i < 1000; ++i)
        {
          const double a = -double(i) * i;
          b += 2.;
          d                  = 1. / (a * d + b);
          c                  = b + a / c;
          const double delta = c * d;
          h *= delta;
          if (std::abs(delta - 1.) < 1e-16)
            break;
        }
      return h;
    }
  } // namespace


  GradedCompliance::GradedCompliance(const ViscoelasticSolid   &material,
                                     const double               nu,
                                     const std::vector<double> &boundaries,
                                     const double               depth)
    : s(boundaries)
    , n(boundaries.size() - 1)
    , depth(depth)
    , x(n)
    , w(n)
    , creep(material, nu)
    , G(n, n)
    , decay(creep.retardations.size())
    , wake(creep.retardations.size())
  {
    for (unsigned int j = 0; j < n; ++j)
      {
        w[j] = s[j + 1] - s[j];
        x[j] = 0.5 * (s[j] + s[j + 1]);
      }
    // Column by column, as G is stored, each boundary's logarithm at every
    // point once.
    const double        log_depth = std::log(depth);
    std::vector<double> left(n), right(n);
    for (unsigned int i = 0; i < n; ++i)
      left[i] = std::log(std::abs(x[i] - s[0]));
    for (unsigned int j = 0; j < n; ++j)
      {
        for (unsigned int i = 0; i < n; ++i)
          {
            right[i] = std::log(std::abs(x[i] - s[j + 1]));
            G(i, j)  = 2. / M_PI *
                      (w[j] * log_depth - cell_integral(x[i] - s[j],
                                                        x[i] - s[j + 1],
                                                        w[j],
                                                        left[i],
                                                        right[i]));
          }
        std::swap(left, right);
      }
  }


  void
  GradedCompliance::set_speed(const double speed)
  {
    if (speed == V)
      return;
    V = speed;
    // Each retardation's decay over each cell, and the wake behind s_0:
    // its displacement at x_i per unit edge value, (2/pi) int_0^inf
    // ln(H/(d + t)) e^{-t/L} dt, d = x_i - s_0, for every retardation that
    // creeps (V > 0).
    for (unsigned int r = 0; r < creep.retardations.size(); ++r)
      {
        const auto [theta, c] = creep.retardations[r];
        const double L        = V * theta;
        decay[r].resize(n);
        for (unsigned int j = 0; j < n; ++j)
          decay[r][j] = CellDecay(w[j], L);
        wake[r].clear();
        if (!(L > 0))
          continue;
        wake[r].resize(n);
        for (unsigned int i = 0; i < n; ++i)
          {
            const double d = x[i] - s[0];
            wake[r][i] =
              c * 2. / M_PI * L *
              (std::log(depth / d) - scaled_exponential_integral(d / L));
          }
      }
    formed = false;
    C.reinit(0, 0);
  }


  void
  GradedCompliance::effective_traction(const double        *q,
                                       Vector<double>      &q_eff,
                                       std::vector<double> &edge) const
  {
    q_eff.reinit(n);
    for (unsigned int j = 0; j < n; ++j)
      q_eff[j] = creep.inverse_glassy * q[j];
    edge.resize(creep.retardations.size());
    for (unsigned int r = 0; r < creep.retardations.size(); ++r)
      {
        const auto cell =
          [&d = decay[r]](const unsigned int j) -> const CellDecay & {
          return d[j];
        };
        edge[r] =
          smear_row(q, n, cell, creep.retardations[r].second, q_eff.begin());
      }
  }


  void
  GradedCompliance::form_matrix() const
  {
    // C = G Q + sum_r wake_r (x) E0_r, Q the effective-traction map (its
    // column k the smeared unit traction of cell k), E0_r the row that
    // gives the edge value of retardation r.
    LAPACKFullMatrix<double>         Q(n, n);
    std::vector<std::vector<double>> edge_row(creep.retardations.size(),
                                              std::vector<double>(n));
    Vector<double>                   unit(n), column;
    std::vector<double>              edge;
    for (unsigned int k = 0; k < n; ++k)
      {
        unit[k] = 1.;
        effective_traction(unit.begin(), column, edge);
        unit[k] = 0.;
        for (unsigned int j = 0; j < n; ++j)
          Q(j, k) = column[j];
        for (unsigned int r = 0; r < edge.size(); ++r)
          edge_row[r][k] = edge[r];
      }
    C.reinit(n, n);
    G.mmult(C, Q);
    for (unsigned int r = 0; r < wake.size(); ++r)
      for (unsigned int i = 0; i < wake[r].size(); ++i)
        for (unsigned int k = 0; k < n; ++k)
          C(i, k) += wake[r][i] * edge_row[r][k];
    formed = true;
  }


  void
  GradedCompliance::apply(const Vector<double> &q, Vector<double> &u) const
  {
    u.reinit(n);
    if (formed)
      {
        C.vmult(u, q);
        return;
      }
    Vector<double>      q_eff;
    std::vector<double> edge;
    effective_traction(q.begin(), q_eff, edge);
    G.vmult(u, q_eff);
    for (unsigned int r = 0; r < wake.size(); ++r)
      for (unsigned int i = 0; i < wake[r].size(); ++i)
        u[i] += wake[r][i] * edge[r];
  }


  FullMatrix<double>
  GradedCompliance::block(const unsigned int first, const unsigned int m) const
  {
    if (!formed)
      form_matrix();
    FullMatrix<double> b(m, m);
    for (unsigned int i = 0; i < m; ++i)
      for (unsigned int j = 0; j < m; ++j)
        b(i, j) = C(first + i, first + j);
    return b;
  }


  void
  GradedCompliance::creep_slope(const Vector<double> &q,
                                Vector<double>       &slope) const
  {
    slope.reinit(n);
    if (V <= 0)
      return;
    // The response to q_eff - q/E0* (E0* = 1), its mean slope over each
    // cell in closed form, and its wakes'. The mean, not the slope at the
    // cell's centre: then sum_i A_i q_i slope_i is the exact dissipation of
    // the piecewise-constant traction. At the centres, the slope's
    // logarithmic peaks at the boundaries of neighbours of other widths
    // made it first order in the grading ratio (the energy balance +0.96 %
    // at V_hat 100 with ratio 1.05, +0.48 % with 1.025, while mu moved by
    // 0.06 %; doc/boundary_element.md).
    Vector<double>      creep_traction;
    std::vector<double> edge, mean_log(n + 1), left(n + 1), right(n + 1);
    effective_traction(q.begin(), creep_traction, edge);
    creep_traction -= q;
    // e^z E1(z) + ln z, whose derivative is e^z E1(z); -euler at z = 0.
    const auto wake_primitive = [](const double z) {
      constexpr double euler = 0.57721566490153286;
      return z > 0 ? scaled_exponential_integral(z) + std::log(z) : -euler;
    };
    // The mean of ln|x - s_k| over cell i, for every boundary k, from the
    // logarithms of the distances of the cell's ends (-inf at its own,
    // which cell_integral does not use).
    for (unsigned int k = 0; k <= n; ++k)
      left[k] = std::log(std::abs(s[0] - s[k]));
    for (unsigned int i = 0; i < n; ++i)
      {
        for (unsigned int k = 0; k <= n; ++k)
          {
            right[k]    = std::log(std::abs(s[i + 1] - s[k]));
            mean_log[k] = cell_integral(s[i + 1] - s[k],
                                        s[i] - s[k],
                                        w[i],
                                        right[k],
                                        left[k]) /
                          w[i];
          }
        std::swap(left, right);
        for (unsigned int j = 0; j < n; ++j)
          slope[i] -=
            2. / M_PI * creep_traction[j] * (mean_log[j] - mean_log[j + 1]);
        for (unsigned int r = 0; r < wake.size(); ++r)
          if (!wake[r].empty())
            {
              const auto [theta, c] = creep.retardations[r];
              const double L        = V * theta;
              slope[i] -= 2. / M_PI * c * edge[r] * L / w[i] *
                          (wake_primitive((s[i + 1] - s[0]) / L) -
                           wake_primitive((s[i] - s[0]) / L));
            }
      }
  }
} // namespace viscoslide

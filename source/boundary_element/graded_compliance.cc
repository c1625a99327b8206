#include <viscoslide/boundary_element/graded_compliance.h>

#include <cmath>

namespace viscoslide
{
  namespace
  {
    // t ln|t| - t, the integral of ln|t| (0 at t = 0).
    double
    primitive(const double t)
    {
      return t == 0. ? 0. : t * std::log(std::abs(t)) - t;
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
    , retardation(creep_retardations(material, nu))
    , G(n, n)
  {
    for (unsigned int j = 0; j < n; ++j)
      {
        w[j] = s[j + 1] - s[j];
        x[j] = 0.5 * (s[j] + s[j + 1]);
      }
    inverse_glassy = 1.;
    for (const auto &[theta, c] : retardation)
      inverse_glassy -= c;
    const double log_depth = std::log(depth);
    for (unsigned int i = 0; i < n; ++i)
      for (unsigned int j = 0; j < n; ++j)
        G(i, j) = 2. / M_PI *
                  (w[j] * log_depth - primitive(x[i] - s[j]) +
                   primitive(x[i] - s[j + 1]));
  }


  void
  GradedCompliance::effective_traction_map(
    FullMatrix<double>               &Q,
    std::vector<std::vector<double>> &edges) const
  {
    Q.reinit(n, n);
    for (unsigned int j = 0; j < n; ++j)
      Q(j, j) = inverse_glassy;
    edges.assign(retardation.size(), {});
    std::vector<double> e(n), m(n), R(n);
    for (unsigned int r = 0; r < retardation.size(); ++r)
      {
        const auto [theta, c] = retardation[r];
        const double L        = V * theta;
        for (unsigned int j = 0; j < n; ++j)
          {
            // 1 - e_j and m_j without cancellation for L >> w_j.
            const double one_minus_e = L > 0 ? -std::expm1(-w[j] / L) : 1.;
            e[j]                     = 1. - one_minus_e;
            m[j]                     = L > 0 ? L / w[j] * one_minus_e : 0.;
          }
        // R holds the row of E_j+1 (E as a combination of the q_k, k > j)
        // while row j of Q is made; then becomes E_j's.
        std::fill(R.begin(), R.end(), 0.);
        for (unsigned int j = n; j-- > 0;)
          {
            Q(j, j) += c * (1. - m[j]);
            if (m[j] > 0)
              for (unsigned int k = j + 1; k < n; ++k)
                Q(j, k) += c * m[j] * R[k];
            for (unsigned int k = j + 1; k < n; ++k)
              R[k] *= e[j];
            R[j] = 1. - e[j];
          }
        if (L > 0)
          edges[r] = R;
      }
  }


  void
  GradedCompliance::set_speed(const double speed)
  {
    if (speed == V)
      return;
    V = speed;
    effective_traction_map(Q, edge);
    // The wake behind s_0 of each retardation: its displacement at x_i
    // per unit edge value, (2/pi) int_0^inf ln(H/(d + t)) e^{-t/L} dt,
    // d = x_i - s_0.
    wake.assign(retardation.size(), {});
    for (unsigned int r = 0; r < retardation.size(); ++r)
      if (!edge[r].empty())
        {
          const auto [theta, c] = retardation[r];
          const double L        = V * theta;
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
  GradedCompliance::form_matrix() const
  {
    C.reinit(n, n);
    G.mmult(C, Q);
    for (unsigned int r = 0; r < retardation.size(); ++r)
      for (unsigned int i = 0; i < wake[r].size(); ++i)
        for (unsigned int k = 0; k < n; ++k)
          C(i, k) += wake[r][i] * edge[r][k];
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
    Vector<double> q_eff(n);
    Q.vmult(q_eff, q);
    G.vmult(u, q_eff);
    for (unsigned int r = 0; r < retardation.size(); ++r)
      if (!wake[r].empty())
        {
          double E0 = 0;
          for (unsigned int k = 0; k < n; ++k)
            E0 += edge[r][k] * q[k];
          for (unsigned int i = 0; i < n; ++i)
            u[i] += wake[r][i] * E0;
        }
  }


  FullMatrix<double>
  GradedCompliance::block(const unsigned int first, const unsigned int m) const
  {
    if (!formed)
      form_matrix();
    FullMatrix<double> b(m, m);
    b.fill(C, 0, 0, first, first);
    return b;
  }


  double
  GradedCompliance::dissipation_rate(const Vector<double> &q) const
  {
    if (V <= 0)
      return 0.;
    // q_eff - q/E0* = Q q - q (E0* = 1).
    Vector<double> creep(n);
    Q.vmult(creep, q);
    creep -= q;
    // Each wake's edge value E_0.
    std::vector<double> E0(retardation.size(), 0.);
    for (unsigned int r = 0; r < retardation.size(); ++r)
      for (unsigned int k = 0; k < edge[r].size(); ++k)
        E0[r] += edge[r][k] * q[k];
    double rate = 0;
    for (unsigned int i = 0; i < n; ++i)
      {
        double slope = 0; // du/dx at x_i
        for (unsigned int j = 0; j < n; ++j)
          slope -= 2. / M_PI * creep[j] *
                   std::log(std::abs((x[i] - s[j]) / (x[i] - s[j + 1])));
        for (unsigned int r = 0; r < retardation.size(); ++r)
          if (!edge[r].empty())
            {
              const auto [theta, c] = retardation[r];
              slope -= 2. / M_PI * c * E0[r] *
                       scaled_exponential_integral((x[i] - s[0]) / (V * theta));
            }
        rate -= V * q[i] * slope * w[i];
      }
    return rate;
  }
} // namespace viscoslide

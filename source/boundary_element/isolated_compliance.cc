// SPDX-License-Identifier: LGPL-2.1-or-later
#include <viscoslide/boundary_element/isolated_compliance.h>
#include <viscoslide/numerics/fft_plans.h>

#include <fftw3.h>

#include <algorithm>
#include <cmath>
#include <complex>
#include <stdexcept>

namespace viscoslide
{
  double
  love(const double x, const double y, const double h)
  {
    const auto r = [](const double a, const double b) {
      return std::sqrt(a * a + b * b);
    };
    const double xp = x + h, xm = x - h, yp = y + h, ym = y - h;
    const double s = xp * std::log((yp + r(yp, xp)) / (ym + r(ym, xp))) +
                     yp * std::log((xp + r(yp, xp)) / (xm + r(yp, xm))) +
                     xm * std::log((ym + r(ym, xm)) / (yp + r(yp, xm))) +
                     ym * std::log((xm + r(ym, xm)) / (xp + r(ym, xp)));
    return s / M_PI;
  }


  namespace
  {
    // The smeared traction beyond the window's trailing edge x_b, on the
    // row of cells |y'| <= h/2, is e^{-(x_b - x')/L} for x' < x_b; its
    // displacement at (x_b + X, y) on the half-space of unit modulus is
    //   K(X, y) = 1/pi int_X^inf e^{-(a - X)/L} f(a) da,
    //   f(a) = int_{-h/2}^{h/2} dy'/sqrt(a^2 + (y - y')^2)
    //        = asinh((y + h/2)/a) - asinh((y - h/2)/a).
    // Returns K at X = (j + 1/2) h for j < n_x: from the far end inwards,
    // each cell's interval by six-point Gauss-Legendre, and beyond the
    // window on intervals doubling in length until the exponential is
    // spent.
    std::vector<double>
    wake_tail(const unsigned int n_x,
              const double       h,
              const double       y,
              const double       L)
    {
      static constexpr double node[6]   = {-0.9324695142031521,
                                           -0.6612093864662645,
                                           -0.2386191860831969,
                                           0.2386191860831969,
                                           0.6612093864662645,
                                           0.9324695142031521};
      static constexpr double weight[6] = {0.1713244923791704,
                                           0.3607615730481386,
                                           0.4679139345726910,
                                           0.4679139345726910,
                                           0.3607615730481386,
                                           0.1713244923791704};
      const auto              f         = [&](const double a) {
        return std::asinh((y + h / 2) / a) - std::asinh((y - h / 2) / a);
      };
      // int_a^b e^{-(x - a)/L} f(x) dx
      const auto interval = [&](const double a, const double b) {
        double sum = 0;
        for (unsigned int k = 0; k < 6; ++k)
          {
            const double x = 0.5 * (a + b) + 0.5 * (b - a) * node[k];
            sum += weight[k] * std::exp(-(x - a) / L) * f(x);
          }
        return 0.5 * (b - a) * sum;
      };
      // Beyond the window, from its far end a = X_n.
      const double a_n = (n_x + 0.5) * h;
      double       J = 0, shift = 1, a = a_n, length = h;
      while (a - a_n < 40 * L)
        {
          J += shift * interval(a, a + length);
          shift *= std::exp(-length / L);
          a += length;
          length *= 2;
        }
      std::vector<double> K(n_x);
      const double        decay = std::exp(-h / L);
      for (int j = n_x - 1; j >= 0; --j)
        {
          J    = interval((j + 0.5) * h, (j + 1.5) * h) + decay * J;
          K[j] = J / M_PI;
        }
      return K;
    }
  } // namespace


  struct IsolatedCompliance::Convolution
  {
    explicit Convolution(const std::array<unsigned int, 2> &n)
      : rows(2 * n[0])
      , columns(2 * n[1])
      , modes(rows * (columns / 2 + 1))
      , real(fftw_alloc_real(rows * columns))
      , spectrum(fftw_alloc_complex(modes))
      , kernel(modes)
      , line(fftw_alloc_real(rows))
      , line_spectrum(fftw_alloc_complex(rows / 2 + 1))
    {
      forward      = make_fft_plan([&](const unsigned int flags) {
        return fftw_plan_dft_r2c_2d(rows, columns, real, spectrum, flags);
      });
      backward     = make_fft_plan([&](const unsigned int flags) {
        return fftw_plan_dft_c2r_2d(rows, columns, spectrum, real, flags);
      });
      line_forward = make_fft_plan([&](const unsigned int flags) {
        return fftw_plan_dft_r2c_1d(rows, line, line_spectrum, flags);
      });
    }
    ~Convolution()
    {
      fftw_destroy_plan(forward);
      fftw_destroy_plan(backward);
      fftw_destroy_plan(line_forward);
      fftw_free(real);
      fftw_free(spectrum);
      fftw_free(line);
      fftw_free(line_spectrum);
    }
    // The spectrum of `real`, divided by rows columns.
    std::vector<std::complex<double>>
    transform()
    {
      fftw_execute(forward);
      const double normalisation = 1. / (double(rows) * columns);
      std::vector<std::complex<double>> result(modes);
      for (unsigned int m = 0; m < modes; ++m)
        result[m] =
          normalisation * std::complex<double>(spectrum[m][0], spectrum[m][1]);
      return result;
    }
    const unsigned int                rows, columns, modes;
    double                           *real;
    fftw_complex                     *spectrum;
    fftw_plan                         forward, backward;
    std::vector<std::complex<double>> kernel; // with 1/(rows columns)
    // A column of sources (the wake beyond the window) and its transform.
    double       *line;
    fftw_complex *line_spectrum;
    fftw_plan     line_forward;
  };


  IsolatedCompliance::IsolatedCompliance(const ViscoelasticSolid &material,
                                         const double             nu,
                                         const std::array<unsigned int, 2> &n,
                                         const double                       dx)
    : n(n)
    , dx(dx)
    , creep(material, nu)
    , decay(creep.retardations.size())
    , wake(creep.retardations.size())
    , convolution(std::make_unique<Convolution>(n))
  {
    // Love's kernel at every offset of the window, arranged for the
    // circular convolution of the padded grid.
    Convolution &f = *convolution;
    for (unsigned int i = 0; i < f.rows; ++i)
      for (unsigned int j = 0; j < f.columns; ++j)
        {
          const double dy =
            (2 * i < f.rows ? double(i) : double(i) - f.rows) * dx;
          const double dxx =
            (2 * j < f.columns ? double(j) : double(j) - f.columns) * dx;
          f.real[i * f.columns + j] = love(dxx, dy, dx / 2);
        }
    f.kernel = f.transform();
  }


  IsolatedCompliance::~IsolatedCompliance() = default;


  void
  IsolatedCompliance::set_speed(const double speed)
  {
    V = speed;
    // The wake beyond the window's trailing edge, for every retardation
    // that creeps (V > 0): its influence on the window, a column source at
    // the edge (column 0 of the padded grid) acting on the columns j >= 0
    // of the window.
    Convolution &f   = *convolution;
    const int    n_y = n[0];
    for (unsigned int r = 0; r < creep.retardations.size(); ++r)
      {
        const double L = V * creep.retardations[r].first;
        decay[r]       = CellDecay(dx, L);
        wake[r].clear();
        if (!(L > 0))
          continue;
        std::fill(f.real, f.real + f.rows * f.columns, 0.);
        for (int m = 0; m < n_y; ++m)
          {
            const std::vector<double> K = wake_tail(n[1], dx, m * dx, L);
            for (const int row : {m, m > 0 ? int(f.rows) - m : -1})
              if (row >= 0)
                std::copy(K.begin(), K.end(), f.real + row * f.columns);
          }
        wake[r] = f.transform();
      }
  }


  void
  IsolatedCompliance::effective_traction(
    const Vector<double>             &q,
    std::vector<double>              &q_eff,
    std::vector<std::vector<double>> &edge) const
  {
    const unsigned int n_x = n[1], n_y = n[0];
    q_eff.assign(q.begin(), q.end());
    for (double &v : q_eff)
      v *= creep.inverse_glassy;
    edge.assign(creep.retardations.size(), {});
    for (unsigned int r = 0; r < creep.retardations.size(); ++r)
      {
        const double c = creep.retardations[r].second;
        if (!wake[r].empty())
          edge[r].assign(n_y, 0.);
        const auto cell = [&d = decay[r]](unsigned int) -> const CellDecay & {
          return d;
        };
        for (unsigned int row = 0; row < n_y; ++row)
          {
            const double E0 = smear_row(
              q.begin() + row * n_x, n_x, cell, c, q_eff.data() + row * n_x);
            if (!edge[r].empty())
              edge[r][row] = c * E0;
          }
      }
  }


  void
  IsolatedCompliance::convolve(const std::vector<double>              &q_eff,
                               const std::vector<std::vector<double>> &edge,
                               Vector<double>                         &u) const
  {
    const unsigned int n_x = n[1], n_y = n[0];
    Convolution       &f = *convolution;
    std::fill(f.real, f.real + f.rows * f.columns, 0.);
    for (unsigned int row = 0; row < n_y; ++row)
      std::copy(q_eff.begin() + row * n_x,
                q_eff.begin() + (row + 1) * n_x,
                f.real + row * f.columns);
    fftw_execute(f.forward);
    auto *spectrum = reinterpret_cast<std::complex<double> *>(f.spectrum);
    for (unsigned int m = 0; m < f.modes; ++m)
      {
        const double a = spectrum[m].real(), b = spectrum[m].imag(),
                     c = f.kernel[m].real(), d = f.kernel[m].imag();
        spectrum[m] = {a * c - b * d, a * d + b * c};
      }
    add_wake(edge);
    fftw_execute(f.backward);
    u.reinit(n_x * n_y, true);
    for (unsigned int row = 0; row < n_y; ++row)
      std::copy(f.real + row * f.columns,
                f.real + row * f.columns + n_x,
                u.begin() + row * n_x);
  }


  void
  IsolatedCompliance::apply(const Vector<double> &q, Vector<double> &u) const
  {
    std::vector<double>              q_eff;
    std::vector<std::vector<double>> edge;
    effective_traction(q, q_eff, edge);
    convolve(q_eff, edge, u);
  }


  void
  IsolatedCompliance::add_wake(
    const std::vector<std::vector<double>> &edge) const
  {
    Convolution &f       = *convolution;
    auto       *spectrum = reinterpret_cast<std::complex<double> *>(f.spectrum);
    const auto *line =
      reinterpret_cast<std::complex<double> *>(f.line_spectrum);
    const unsigned int n_k_x = f.columns / 2 + 1;
    for (unsigned int r = 0; r < edge.size(); ++r)
      if (!edge[r].empty())
        {
          // The column's transform is the same for every k_x.
          std::fill(f.line, f.line + f.rows, 0.);
          std::copy(edge[r].begin(), edge[r].end(), f.line);
          fftw_execute(f.line_forward);
          for (unsigned int k_y = 0; k_y < f.rows; ++k_y)
            {
              const std::complex<double> source =
                2 * k_y <= f.rows ? line[k_y] : std::conj(line[f.rows - k_y]);
              for (unsigned int k_x = 0; k_x < n_k_x; ++k_x)
                spectrum[k_y * n_k_x + k_x] +=
                  source * wake[r][k_y * n_k_x + k_x];
            }
        }
  }


  void
  IsolatedCompliance::creep_slope(const Vector<double> &q,
                                  Vector<double>       &slope) const
  {
    // u - C_0 q: the response to q_eff - q (E0* = 1), with the wake; by
    // central differences along each row.
    std::vector<double>              q_eff;
    std::vector<std::vector<double>> edge;
    effective_traction(q, q_eff, edge);
    for (unsigned int j = 0; j < q.size(); ++j)
      q_eff[j] -= q[j];
    Vector<double> u;
    convolve(q_eff, edge, u);
    const unsigned int n_x = n[1], n_y = n[0];
    slope.reinit(q.size());
    for (unsigned int row = 0; row < n_y; ++row)
      for (unsigned int i = 1; i + 1 < n_x; ++i)
        {
          const unsigned int j = row * n_x + i;
          slope[j]             = (u[j + 1] - u[j - 1]) / (2 * dx);
        }
  }
} // namespace viscoslide

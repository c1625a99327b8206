#include <viscoslide/boundary_element/isolated_compliance.h>

#include <fftw3.h>

#include <algorithm>
#include <cmath>
#include <complex>
#include <stdexcept>

namespace viscoslide
{
  namespace
  {
    // Love's displacement at (x, y) under a unit traction on the square
    // |x'|, |y'| <= h on the elastic half-space of unit modulus E*
    // (Johnson, eq. 3.25).
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

    // The creep of the arms as retardations (see the header): E*(s) = 1 +
    // sum_a E_a s tau_a/(1 + s tau_a) has one root in each interval of
    // the negative axis between its poles -1/tau_a (and between the
    // nearest one and 0).
    std::vector<std::pair<double, double>>
    creep_retardations(const ViscoelasticSolid &material, const double nu)
    {
      std::vector<std::pair<double, double>> arms; // (tau_a, E_a*)
      for (unsigned int a = 0; a < material.n_arms(); ++a)
        if (material.arm_modulus(a) > 0)
          arms.emplace_back(material.relaxation_time(a),
                            material.arm_modulus(a) / (1. - nu * nu));
      std::sort(arms.begin(), arms.end());
      const auto E = [&](const double s) {
        double e = 1.;
        for (const auto &[tau, Ea] : arms)
          e += Ea * s * tau / (1. + s * tau);
        return e;
      };
      const auto dE = [&](const double s) {
        double d = 0.;
        for (const auto &[tau, Ea] : arms)
          d += Ea * tau / ((1. + s * tau) * (1. + s * tau));
        return d;
      };
      std::vector<std::pair<double, double>> result;
      double right = 0.; // the interval's upper end
      for (auto arm = arms.rbegin(); arm != arms.rend(); ++arm)
        {
          // E goes from -infinity just above the pole to E(right) > 0.
          double lo = -1. / arm->first, hi = right;
          for (int k = 0; k < 200; ++k)
            {
              const double mid       = 0.5 * (lo + hi);
              (E(mid) < 0 ? lo : hi) = mid;
            }
          const double s     = 0.5 * (lo + hi);
          const double theta = -1. / s;
          result.emplace_back(theta, theta / dE(s));
          right = -1. / arm->first;
        }
      return result;
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
    {
      forward =
        fftw_plan_dft_r2c_2d(rows, columns, real, spectrum, FFTW_MEASURE);
      backward =
        fftw_plan_dft_c2r_2d(rows, columns, spectrum, real, FFTW_MEASURE);
    }
    ~Convolution()
    {
      fftw_destroy_plan(forward);
      fftw_destroy_plan(backward);
      fftw_free(real);
      fftw_free(spectrum);
    }
    const unsigned int                rows, columns, modes;
    double                           *real;
    fftw_complex                     *spectrum;
    fftw_plan                         forward, backward;
    std::vector<std::complex<double>> kernel; // with 1/(rows columns)
  };


  IsolatedCompliance::IsolatedCompliance(const ViscoelasticSolid &material,
                                         const double             nu,
                                         const std::array<unsigned int, 2> &n,
                                         const double                       dx)
    : n(n)
    , dx(dx)
    , retardation(creep_retardations(material, nu))
    , convolution(std::make_unique<Convolution>(n))
  {
    // 1/E*(s -> infinity) = 1 - sum_r c_r (1/E*(0) = 1 = E0*).
    inverse_glassy = 1.;
    for (const auto &[theta, c] : retardation)
      inverse_glassy -= c;
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
    fftw_execute(f.forward);
    const double normalisation = 1. / (double(f.rows) * f.columns);
    for (unsigned int m = 0; m < f.modes; ++m)
      f.kernel[m] = normalisation *
                    std::complex<double>(f.spectrum[m][0], f.spectrum[m][1]);
  }


  IsolatedCompliance::~IsolatedCompliance() = default;


  void
  IsolatedCompliance::set_speed(const double speed)
  {
    V = speed;
  }


  void
  IsolatedCompliance::effective_traction(const Vector<double> &q,
                                         std::vector<double>  &q_eff) const
  {
    const unsigned int n_x = n[1], n_y = n[0];
    q_eff.assign(q.begin(), q.end());
    for (double &v : q_eff)
      v *= inverse_glassy;
    for (const auto &[theta, c] : retardation)
      {
        // Each retardation smears q downstream over L = V theta, exactly
        // for q constant on each cell: the own cell's half and the
        // cells upstream (larger x), each weighted by its exponential.
        const double L     = V * theta;
        const double decay = L > 0 ? std::exp(-dx / L) : 0.;
        const double half  = L > 0 ? std::exp(-0.5 * dx / L) : 0.;
        for (unsigned int row = 0; row < n_y; ++row)
          {
            const double *p = q.begin() + row * n_x;
            double       *e = q_eff.data() + row * n_x;
            double        S = 0.;
            for (int i = n_x - 1; i >= 0; --i)
              {
                if (i + 1 < int(n_x))
                  S = decay * S + p[i + 1] * half * (1. - decay);
                e[i] += c * (p[i] * (1. - half) + S);
              }
          }
      }
  }


  void
  IsolatedCompliance::apply(const Vector<double> &q, Vector<double> &u) const
  {
    const unsigned int  n_x = n[1], n_y = n[0];
    std::vector<double> q_eff;
    effective_traction(q, q_eff);
    Convolution &f = *convolution;
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
    fftw_execute(f.backward);
    u.reinit(n_x * n_y, true);
    for (unsigned int row = 0; row < n_y; ++row)
      std::copy(f.real + row * f.columns,
                f.real + row * f.columns + n_x,
                u.begin() + row * n_x);
  }


  double
  IsolatedCompliance::dissipation_rate(const Vector<double> &q) const
  {
    Vector<double> u;
    apply(q, u);
    const unsigned int n_x = n[1], n_y = n[0];
    double             sum = 0;
    for (unsigned int row = 0; row < n_y; ++row)
      for (unsigned int i = 1; i + 1 < n_x; ++i)
        {
          const unsigned int j = row * n_x + i;
          sum += q[j] * (u[j + 1] - u[j - 1]) / (2 * dx);
        }
    // The traction q pulls (attraction > 0), the solid's surface moves by
    // u towards the indenter: the work rate on the solid is -V q du/dx.
    return -V * sum * dx * dx;
  }
} // namespace viscoslide

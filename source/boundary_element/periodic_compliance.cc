// SPDX-License-Identifier: LGPL-2.1-or-later
#include <viscoslide/boundary_element/periodic_compliance.h>
#include <viscoslide/numerics/fft_plans.h>

#include <fftw3.h>

#include <cmath>
#include <stdexcept>

namespace viscoslide
{
  template <int dim>
  struct PeriodicCompliance<dim>::Plans
  {
    // FFTW's shape: slowest first, x (the last of n) fastest.
    explicit Plans(const std::array<unsigned int, dim - 1> &n,
                   const unsigned int                       n_points,
                   const unsigned int                       n_modes)
      : real(fftw_alloc_real(n_points))
      , spectrum(fftw_alloc_complex(n_modes))
    {
      std::array<int, dim - 1> shape;
      for (unsigned int d = 0; d < dim - 1; ++d)
        shape[d] = n[d];
      forward  = make_fft_plan([&](const unsigned int flags) {
        return fftw_plan_dft_r2c(dim - 1, shape.data(), real, spectrum, flags);
      });
      backward = make_fft_plan([&](const unsigned int flags) {
        return fftw_plan_dft_c2r(dim - 1, shape.data(), spectrum, real, flags);
      });
    }
    ~Plans()
    {
      fftw_destroy_plan(forward);
      fftw_destroy_plan(backward);
      fftw_free(real);
      fftw_free(spectrum);
    }
    double       *real;
    fftw_complex *spectrum;
    fftw_plan     forward, backward;
  };


  namespace
  {
    template <std::size_t d>
    unsigned int
    product(const std::array<unsigned int, d> &n)
    {
      unsigned int p = 1;
      for (const unsigned int m : n)
        p *= m;
      return p;
    }

    // The number of complex modes FFTW's real-to-complex transform keeps:
    // n_x/2 + 1 of the fastest (x) direction, all of the others.
    template <std::size_t d>
    unsigned int
    mode_count(const std::array<unsigned int, d> &n)
    {
      return product(n) / n[d - 1] * (n[d - 1] / 2 + 1);
    }
  } // namespace


  template <int dim>
  PeriodicCompliance<dim>::PeriodicCompliance(
    const Parameters::Substrate              substrate,
    const double                             thickness,
    const ViscoelasticSolid                 &material,
    const double                             nu,
    const std::array<unsigned int, dim - 1> &n,
    const double                             dx)
    : substrate(substrate)
    , thickness(thickness)
    , material(material)
    , nu(nu)
    , n(n)
    , n_points(product(n))
    , n_modes(mode_count(n))
    , dx(dx)
    , symbol(n_modes)
    , plans(std::make_unique<Plans>(n, n_points, n_modes))
  {
    set_speed(0.);
  }


  template <int dim>
  PeriodicCompliance<dim>::~PeriodicCompliance() = default;


  template <int dim>
  double
  PeriodicCompliance<dim>::layer_factor(const double s, const double nu)
  {
    // [(3 - 4 nu) sinh 2s - 2s] / [(3 - 4 nu) cosh 2s + 2 s^2 + 5 - 12 nu
    // + 8 nu^2], multiplied through by 2 exp(-2s) so that it neither
    // overflows for thick layers nor loses the small-s limit.
    const double kappa     = 3. - 4. * nu;
    const double e2        = std::exp(-2. * s);
    const double numerator = -kappa * std::expm1(-4. * s) - 4. * s * e2;
    const double denominator =
      kappa * (1. + e2 * e2) +
      (4. * s * s + 2. * (5. - 12. * nu + 8. * nu * nu)) * e2;
    return numerator / denominator;
  }


  template <int dim>
  std::complex<double>
  PeriodicCompliance<dim>::modulus(const double omega) const
  {
    const std::complex<double> i(0., 1.);
    std::complex<double>       E = 1.;
    for (unsigned int a = 0; a < material.n_arms(); ++a)
      {
        const double wt = omega * material.relaxation_time(a);
        E += material.arm_modulus(a) / (1. - nu * nu) * i * wt / (1. + i * wt);
      }
    return E;
  }


  template <int dim>
  double
  PeriodicCompliance<dim>::elastic_compliance(const double k) const
  {
    if (substrate == Parameters::Substrate::half_plane)
      return k == 0 ? 0. : 2. / k;
    if (k == 0)
      return thickness * (1. - 2. * nu) / ((1. - nu) * (1. - nu));
    return 2. / k * layer_factor(k * thickness, nu);
  }


  template <int dim>
  std::pair<double, double>
  PeriodicCompliance<dim>::wave_vector(const unsigned int m) const
  {
    const unsigned int n_x = n[dim - 2], kept = n_x / 2 + 1;
    const double       k_x = 2. * M_PI * (m % kept) / (n_x * dx);
    if (dim == 2)
      return {k_x, k_x};
    // FFTW's order of the y modes: 0 .. n_y/2, then the negative ones.
    const unsigned int n_y = n[0], i = m / kept;
    const double       k_y =
      2. * M_PI * (2 * i <= n_y ? double(i) : double(i) - n_y) / (n_y * dx);
    return {k_x, std::sqrt(k_x * k_x + k_y * k_y)};
  }


  template <int dim>
  void
  PeriodicCompliance<dim>::set_speed(const double speed)
  {
    V = speed;
    for (unsigned int m = 0; m < n_modes; ++m)
      {
        const auto [k_x, k] = wave_vector(m);
        symbol[m] =
          elastic_compliance(k) / modulus(-k_x * V) / double(n_points);
      }
    stiffness.resize(n_modes);
    const double normalisation = 1. / (double(n_points) * double(n_points));
    for (unsigned int m = 0; m < n_modes; ++m)
      stiffness[m] = stiffness_symbol(m) * normalisation;
  }


  template <int dim>
  void
  PeriodicCompliance<dim>::multiply(
    const std::vector<std::complex<double>> &factors,
    const Vector<double>                    &in,
    Vector<double>                          &out) const
  {
    AssertDimension(in.size(), n_points);
    std::copy(in.begin(), in.end(), plans->real);
    fftw_execute(plans->forward);
    // fftw_complex is laid out as std::complex<double> (FFTW's manual).
    auto *spectrum = reinterpret_cast<std::complex<double> *>(plans->spectrum);
    for (unsigned int m = 0; m < n_modes; ++m)
      {
        // (c + id)(a + ib) without the library's checks for infinities
        const double a = spectrum[m].real(), b = spectrum[m].imag(),
                     c = factors[m].real(), d = factors[m].imag();
        spectrum[m] = {c * a - d * b, c * b + d * a};
      }
    fftw_execute(plans->backward);
    out.reinit(n_points, true);
    std::copy(plans->real, plans->real + n_points, out.begin());
  }


  template <int dim>
  void
  PeriodicCompliance<dim>::apply(const Vector<double> &q,
                                 Vector<double>       &u) const
  {
    multiply(symbol, q, u);
  }


  template <int dim>
  std::complex<double>
  PeriodicCompliance<dim>::stiffness_symbol(const unsigned int m) const
  {
    if (symbol[m] != 0.)
      return 1. / symbol[m];
    // The half-space's mean: the stiffness of the longest wave along y
    // (3D) or x (2D), the first mode of FFTW's order that has one.
    const unsigned int first = dim == 2 ? 1 : n[dim - 2] / 2 + 1;
    return 1. / symbol[std::min(first, n_modes - 1)];
  }


  template <int dim>
  void
  PeriodicCompliance<dim>::apply_stiffness(const Vector<double> &u,
                                           Vector<double>       &q) const
  {
    multiply(stiffness, u, q);
  }


  template <int dim>
  double
  PeriodicCompliance<dim>::stiffness_diagonal() const
  {
    // Modes 0 < k_x < Nyquist stand for themselves and their conjugates.
    const unsigned int n_x = n[dim - 2], kept = n_x / 2 + 1;
    double             sum = 0;
    for (unsigned int m = 0; m < n_modes; ++m)
      {
        const unsigned int i      = m % kept;
        const double       weight = (i == 0 || 2 * i == n_x) ? 1. : 2.;
        // symbol carries FFTW's 1/n; the stiffness of the mode is 1/(n C).
        sum += weight * (stiffness_symbol(m) / double(n_points)).real();
      }
    return sum / double(n_points);
  }


  template <int dim>
  Vector<double>
  PeriodicCompliance<dim>::impulse_response() const
  {
    Vector<double> unit(n_points), response(n_points);
    unit[0] = 1.;
    apply(unit, response);
    return response;
  }


  template <int dim>
  FullMatrix<double>
  PeriodicCompliance<dim>::block(const unsigned int first,
                                 const unsigned int m) const
  {
    (void)first; // circulant: the same block everywhere
    const Vector<double> column = impulse_response();
    FullMatrix<double>   c(m, m);
    for (unsigned int i = 0; i < m; ++i)
      for (unsigned int j = 0; j < m; ++j)
        c(i, j) = column[(i + n_points - j) % n_points];
    return c;
  }


  template <int dim>
  void
  PeriodicCompliance<dim>::creep_slope(const Vector<double> &q,
                                       Vector<double>       &slope) const
  {
    const unsigned int                n_x = n[dim - 2], kept = n_x / 2 + 1;
    std::vector<std::complex<double>> factors(n_modes);
    for (unsigned int m = 0; m < n_modes; ++m)
      if (m % kept != 0 && 2 * (m % kept) < n_x)
        {
          const auto [k_x, k] = wave_vector(m);
          factors[m]          = std::complex<double>(0., k_x) *
                       (symbol[m] - elastic_compliance(k) / double(n_points));
        }
    multiply(factors, q, slope);
  }


  template class PeriodicCompliance<2>;
  template class PeriodicCompliance<3>;
} // namespace viscoslide

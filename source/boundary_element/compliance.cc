#include <viscoslide/boundary_element/compliance.h>

#include <fftw3.h>

#include <cmath>

namespace viscoslide
{
  struct SurfaceCompliance::Plans
  {
    explicit Plans(const unsigned int n)
      : real(fftw_alloc_real(n))
      , spectrum(fftw_alloc_complex(n / 2 + 1))
      , forward(fftw_plan_dft_r2c_1d(n, real, spectrum, FFTW_ESTIMATE))
      , backward(fftw_plan_dft_c2r_1d(n, spectrum, real, FFTW_ESTIMATE))
    {
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


  SurfaceCompliance::SurfaceCompliance(const Parameters::Substrate substrate,
                                       const double                thickness,
                                       const ViscoelasticSolid    &material,
                                       const double                nu,
                                       const unsigned int          n,
                                       const double                dx)
    : substrate(substrate)
    , thickness(thickness)
    , material(material)
    , nu(nu)
    , n(n)
    , dx(dx)
    , symbol(n / 2 + 1)
    , plans(std::make_unique<Plans>(n))
  {
    set_speed(0.);
  }


  SurfaceCompliance::~SurfaceCompliance() = default;


  double
  SurfaceCompliance::layer_factor(const double s, const double nu)
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


  std::complex<double>
  SurfaceCompliance::modulus(const double omega) const
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


  double
  SurfaceCompliance::elastic_compliance(const unsigned int m) const
  {
    const double k = 2. * M_PI * m / (n * dx);
    if (substrate == Parameters::Substrate::half_plane)
      return m == 0 ? 0. : 2. / k;
    if (m == 0)
      return thickness * (1. - 2. * nu) / ((1. - nu) * (1. - nu));
    return 2. / k * layer_factor(k * thickness, nu);
  }


  void
  SurfaceCompliance::set_speed(const double speed)
  {
    V = speed;
    for (unsigned int m = 0; m <= n / 2; ++m)
      {
        const double k = 2. * M_PI * m / (n * dx);
        symbol[m]      = elastic_compliance(m) / modulus(-k * V) / double(n);
      }
  }


  void
  SurfaceCompliance::apply(const Vector<double> &q, Vector<double> &u) const
  {
    AssertDimension(q.size(), n);
    std::copy(q.begin(), q.end(), plans->real);
    fftw_execute(plans->forward);
    for (unsigned int m = 0; m <= n / 2; ++m)
      {
        const std::complex<double> z(plans->spectrum[m][0],
                                     plans->spectrum[m][1]);
        const std::complex<double> w = symbol[m] * z;
        plans->spectrum[m][0]        = w.real();
        plans->spectrum[m][1]        = w.imag();
      }
    fftw_execute(plans->backward);
    u.reinit(n, true);
    std::copy(plans->real, plans->real + n, u.begin());
  }


  Vector<double>
  SurfaceCompliance::impulse_response() const
  {
    Vector<double> unit(n), response(n);
    unit[0] = 1.;
    apply(unit, response);
    return response;
  }


  double
  SurfaceCompliance::dissipation_rate(const Vector<double> &q) const
  {
    std::copy(q.begin(), q.end(), plans->real);
    fftw_execute(plans->forward);
    // V L sum over k != 0 of k Im C(k) |q_k|^2, the modes +k and -k
    // counted together; the Nyquist mode carries no loss (the inverse
    // transform keeps only its real part).
    double sum = 0;
    for (unsigned int m = 1; 2 * m < n; ++m)
      {
        const double k  = 2. * M_PI * m / (n * dx);
        const double q2 = std::norm(
          std::complex<double>(plans->spectrum[m][0], plans->spectrum[m][1]));
        sum += k * (symbol[m] * double(n)).imag() * q2;
      }
    return 2. * V * dx * sum / double(n);
  }
} // namespace viscoslide

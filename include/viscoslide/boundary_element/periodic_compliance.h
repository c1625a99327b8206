// SPDX-License-Identifier: LGPL-2.1-or-later
// The viscoelastic surface compliance of the boundary-element solver: the
// vertical displacement of the top surface under a vertical traction that
// slides at speed V towards +x, for a periodic half-space or a periodic
// layer bonded to a rigid base, on a uniform grid of the surface: a line
// of points for dim = 2 (plane strain), a plane of points for dim = 3
// (doc/boundary_element.md).
//
// In the frame of the indenter a surface field exp(i k.x) is, for the
// material, a load of angular frequency omega = -k_x V, so that
//     u_k = K(|k|) q_k / E*(-k_x V),
// K = 2/|k| for the half-space, 2 Phi(|k| t)/|k| for the layer, and E*(w)
// the complex modulus E/(1 - nu^2) of the Prony series (doc/model.md):
// the same function of |k| in plane strain and in 3D. FFTW applies it;
// the k = 0 mode of the half-space, whose compliance is infinite, is the
// reference of u: the mean surface displacement over the period is zero.
//
// The points are numbered with x fastest: point j sits at
// x = (j mod n_x - n_x/2) dx and, in 3D, y = (j div n_x - n_y/2) dx.
#ifndef viscoslide_boundary_element_periodic_compliance_h
#define viscoslide_boundary_element_periodic_compliance_h

#include <deal.II/lac/full_matrix.h>
#include <deal.II/lac/vector.h>

#include <viscoslide/boundary_element/compliance.h>
#include <viscoslide/io/parameters.h>
#include <viscoslide/physics/material.h>

#include <array>
#include <complex>
#include <memory>
#include <vector>

namespace viscoslide
{
  using namespace dealii;

  template <int dim>
  class PeriodicCompliance : public Compliance
  {
  public:
    // n points per direction (n_x, and n_y in 3D) of spacing dx (internal
    // units) on one period; `material` gives the arms, nu the Poisson ratio
    // of every branch; `thickness` is the layer's.
    PeriodicCompliance(Parameters::Substrate                    substrate,
                       double                                   thickness,
                       const ViscoelasticSolid                 &material,
                       double                                   nu,
                       const std::array<unsigned int, dim - 1> &n,
                       double                                   dx);
    ~PeriodicCompliance();
    PeriodicCompliance(const PeriodicCompliance &) = delete;
    PeriodicCompliance &
    operator=(const PeriodicCompliance &) = delete;

    void
    set_speed(double V) override;

    double
    speed() const
    {
      return V;
    }

    void
    apply(const Vector<double> &q, Vector<double> &u) const override;

    // From the impulse response: C is circulant.
    FullMatrix<double>
    block(unsigned int first, unsigned int m) const;

    // q = K u with K the inverse of C, the surface stiffness; for the
    // half-space's k = 0 mode (no compliance) the stiffness of the
    // longest wave instead, so that K is regular. For the multigrid
    // preconditioner (multigrid_preconditioner.h).
    void
    apply_stiffness(const Vector<double> &u, Vector<double> &q) const;

    // The diagonal of K (the same at every point): the mean of its real
    // symbol over the modes.
    double
    stiffness_diagonal() const;

    // The displacement at every point under a unit force at point 0 (the
    // first column of the circulant matrix of C).
    Vector<double>
    impulse_response() const;

    // du_c/dx by the spectral derivative, i k_x (C - C_0) on each mode:
    // the loss part of C alone does work (the Nyquist modes of x carry
    // none: the inverse transform keeps only their real part).
    void
    creep_slope(const Vector<double> &q, Vector<double> &slope) const override;

    // Phi(s) of the bonded layer, s = |k| t: 1 for s -> infinity (the
    // half-plane), s (1 - 2 nu)/(2 (1 - nu)^2) for s -> 0 (the layer's
    // oedometric compliance t/M).
    static double
    layer_factor(double s, double nu);

    // The complex plane-strain modulus at angular frequency omega, in
    // units of E0*.
    std::complex<double>
    modulus(double omega) const;

  private:
    // out = F^-1 (factors F in) on the grid: the factors of each mode
    // carry FFTW's normalisation (symbol, stiffness).
    void
    multiply(const std::vector<std::complex<double>> &factors,
             const Vector<double>                    &in,
             Vector<double>                          &out) const;

    // K(|k|) at unit modulus; at k = 0 0 for the half-space (the reference
    // of u), the limit t(1 - 2 nu)/(1 - nu)^2 for the layer.
    double
    elastic_compliance(double k) const;

    // 1/symbol[m] (n times the stiffness of mode m), with the k = 0 mode
    // of the half-space replaced as apply_stiffness() says.
    std::complex<double>
    stiffness_symbol(unsigned int m) const;

    // The wave vector (k_x, |k|) of spectral mode m, numbered as FFTW's
    // real-to-complex transform stores them (k_x >= 0 fastest).
    std::pair<double, double>
    wave_vector(unsigned int m) const;

    const Parameters::Substrate             substrate;
    const double                            thickness;
    const ViscoelasticSolid                &material;
    const double                            nu;
    const std::array<unsigned int, dim - 1> n;
    const unsigned int                      n_points, n_modes;
    const double                            dx;
    double                                  V = 0;
    // C at each mode's wave vector, including FFTW's normalisation 1/n,
    // and K with it.
    std::vector<std::complex<double>> symbol, stiffness;
    // FFTW's plans and buffers, kept out of this header.
    struct Plans;
    std::unique_ptr<Plans> plans;
  };
} // namespace viscoslide

#endif

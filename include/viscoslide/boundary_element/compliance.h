// The viscoelastic surface compliance of the boundary-element solver: the
// vertical displacement of the top surface under a vertical traction that
// slides at speed V, for a periodic half-plane or a periodic layer bonded
// to a rigid base, on a uniform grid (doc/boundary_element.md).
//
// In the frame of the indenter a surface field exp(i k x) is, for the
// material, a load of angular frequency omega = -k V, so that
//     u_k = K(k) q_k / E*(-k V),
// K = 2/|k| for the half-plane, 2 Phi(|k| t)/|k| for the layer, and E*(w)
// the complex plane-strain modulus of the Prony series (doc/model.md).
// FFTW applies it; the k = 0 mode of the half-plane, whose compliance is
// infinite, is the reference of u: the mean surface displacement over the
// period is zero.
#ifndef viscoslide_boundary_element_compliance_h
#define viscoslide_boundary_element_compliance_h

#include <deal.II/lac/vector.h>

#include <viscoslide/material.h>
#include <viscoslide/parameters.h>

#include <complex>
#include <memory>
#include <vector>

namespace viscoslide
{
  using namespace dealii;

  class SurfaceCompliance
  {
  public:
    // n points of spacing dx (internal units) on one period; `material`
    // gives the arms, nu the Poisson ratio of every branch; `thickness` is
    // the layer's.
    SurfaceCompliance(Parameters::Substrate    substrate,
                      double                   thickness,
                      const ViscoelasticSolid &material,
                      double                   nu,
                      unsigned int             n,
                      double                   dx);
    ~SurfaceCompliance();
    SurfaceCompliance(const SurfaceCompliance &) = delete;
    SurfaceCompliance &
    operator=(const SurfaceCompliance &) = delete;

    // The sliding speed V (internal units); 0 is the relaxed solid.
    void
    set_speed(double V);

    double
    speed() const
    {
      return V;
    }

    // u = C q on the grid.
    void
    apply(const Vector<double> &q, Vector<double> &u) const;

    // The displacement at every point under a unit force at point 0 (the
    // first column of the circulant matrix of C).
    Vector<double>
    impulse_response() const;

    // Rate of work the traction q does on the solid, V times the integral
    // of -q du_y/dx over the period, from the loss part of C alone: in a
    // steady state all of it is dissipated.
    double
    dissipation_rate(const Vector<double> &q) const;

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
    // |k| K(k), the elastic part at unit modulus; at k = 0 (layer only)
    // the limit K(k) itself is used.
    double
    elastic_compliance(unsigned int m) const;

    const Parameters::Substrate substrate;
    const double                thickness;
    const ViscoelasticSolid    &material;
    const double                nu;
    const unsigned int          n;
    const double                dx;
    double                      V = 0;
    // C at the wave numbers k_m = 2 pi m/(n dx), m = 0 .. n/2, including
    // FFTW's normalisation 1/n.
    std::vector<std::complex<double>> symbol;
    // FFTW's plans and buffers, kept out of this header.
    struct Plans;
    std::unique_ptr<Plans> plans;
  };
} // namespace viscoslide

#endif

// SPDX-License-Identifier: LGPL-2.1-or-later
// The viscoelastic surface compliance of an isolated contact on a
// half-space, for the boundary elements in 3D: the window of n_y x n_x
// points of spacing dx about the contact is all of the surface that
// carries traction, and the solid around it is infinite (no periodic
// images, the far field at rest), as in the experiments.
//
// The surface displacement is the elastic response to the effective
// traction of the creep (creep.h), q constant on each square cell: u = G *
// q_eff, G Love's influence of a uniform unit traction on a square cell on
// the elastic half-space of unit modulus (Johnson, Contact Mechanics, eq.
// 3.25), applied as a linear (not circular) convolution by FFTs on a grid
// of twice the window in each direction (zero padding). The smeared
// traction beyond the window's trailing edge is the exponential
// e^{-(x_b - x)/L_r} times its value at the edge x_b, row by row: its
// displacement in the window is a column source at the edge with a kernel
// integrated once per speed (wake_tail), so that the wake is whole however
// far the creep carries it (V_hat 100: V tau_c = 1000 eps).
#ifndef viscoslide_boundary_element_isolated_compliance_h
#define viscoslide_boundary_element_isolated_compliance_h

#include <deal.II/lac/vector.h>

#include <viscoslide/boundary_element/compliance.h>
#include <viscoslide/boundary_element/creep.h>
#include <viscoslide/physics/material.h>

#include <array>
#include <complex>
#include <memory>
#include <vector>

namespace viscoslide
{
  using namespace dealii;

  // Love's displacement at (x, y) under a unit traction on the square
  // |x'|, |y'| <= a on the elastic half-space of unit modulus E*
  // (Johnson, Contact Mechanics, eq. 3.25).
  double
  love(double x, double y, double a);


  class IsolatedCompliance : public Compliance
  {
  public:
    // n = (n_y, n_x) points of spacing dx (internal units, E0* = 1).
    IsolatedCompliance(const ViscoelasticSolid           &material,
                       double                             nu,
                       const std::array<unsigned int, 2> &n,
                       double                             dx);
    ~IsolatedCompliance();
    IsolatedCompliance(const IsolatedCompliance &) = delete;
    IsolatedCompliance &
    operator=(const IsolatedCompliance &) = delete;

    void
    set_speed(double V) override;

    // u = C q on the window.
    void
    apply(const Vector<double> &q, Vector<double> &u) const override;

    // d/dx of the response beyond the relaxed one, by central differences
    // along x (0 at the window's ends, where no traction reaches).
    void
    creep_slope(const Vector<double> &q, Vector<double> &slope) const override;

    // u = G * q_eff plus the wakes of the edge values `edge` (per
    // retardation whose wake reaches beyond the window, per row; empty
    // where it does not): the elastic step, which the nested grid shares
    // (nested_compliance.h).
    void
    convolve(const std::vector<double>              &q_eff,
             const std::vector<std::vector<double>> &edge,
             Vector<double>                         &u) const;
    // Whether retardation r has a wake beyond the window at this speed.
    bool
    has_wake(const unsigned int r) const
    {
      return !wake[r].empty();
    }

  private:
    // q_eff of q on the window, and for each retardation whose wake
    // reaches beyond the window its smeared traction at the trailing
    // edge, per row.
    void
    effective_traction(const Vector<double>             &q,
                       std::vector<double>              &q_eff,
                       std::vector<std::vector<double>> &edge) const;
    // Adds the displacement of the wakes beyond the trailing edge (their
    // edge values times their exponential tails) to the transformed
    // displacement of the convolution.
    void
    add_wake(const std::vector<std::vector<double>> &edge) const;

    const std::array<unsigned int, 2> n;
    const double                      dx;
    double                            V = 0;
    const Creep                       creep;
    // Per retardation, its decay over a cell at the present speed and the
    // transformed influence of its wake beyond the window (empty at rest).
    std::vector<CellDecay>                         decay;
    std::vector<std::vector<std::complex<double>>> wake;
    // FFTW's plans, buffers and the transformed kernel, kept out of this
    // header.
    struct Convolution;
    std::unique_ptr<Convolution> convolution;
  };
} // namespace viscoslide

#endif

// SPDX-License-Identifier: LGPL-2.1-or-later
// The creep of the solid as the isolated contacts of the boundary elements
// use it (isolated_compliance.h in 3D, graded_compliance.h in plane
// strain): the creep function of the Prony series as a sum of
// retardations, and the traction smeared downstream over each retardation
// length, written once for both (doc/boundary_element.md, Creep).
//
// With s = i w,
//     1/E*(s) = 1/Einf* + sum_r c_r/(1 + s theta_r),
// the retardation times theta_r and weights c_r found from the arms'
// moduli (one for each arm, the roots of E*(s) between the arms' poles;
// E0* = 1). A material point under the contact at x was at x + V t a time
// t ago (sliding towards +x), so that the surface displacement is the
// elastic response to an effective traction,
//     q_eff(x) = q(x)/Einf* + sum_r c_r int_0^inf exp(-xi/L_r) q(x + xi)
//                dxi/L_r,     L_r = V theta_r.
// On a row of cells [s_j, s_j+1] of widths w_j, the traction q_j constant
// on each,
//     int_0^inf exp(-xi/L) q(x + xi) dxi/L
//       = q_j (1 - e^{-(s_j+1 - x)/L}) + e^{-(s_j+1 - x)/L} E_j+1,
// with E_j its value at s_j, E_j = q_j (1 - e_j) + e_j E_j+1, e_j =
// exp(-w_j/L), E_n = 0 ahead of the row; each cell keeps its mean,
// q_j (1 - m_j) + m_j E_j+1, m_j = (L/w_j)(1 - e_j): exact for q constant
// on each cell, also where L is below the cell (a value at the cell's
// centre would lose the creep there altogether). Behind the row's trailing
// end s_0 the smeared traction is E_0 exp(-(s_0 - x)/L): the wake, whose
// displacement each compliance adds whole however far the creep carries
// it.
#ifndef viscoslide_boundary_element_creep_h
#define viscoslide_boundary_element_creep_h

#include <viscoslide/physics/material.h>

#include <cmath>
#include <utility>
#include <vector>

namespace viscoslide
{
  // The creep function of the solid in units of 1/E0*: its retardations
  // (theta_r, c_r) and its glassy limit 1/Einf* = 1 - sum_r c_r (nu of
  // every branch). [creep.cc]
  struct Creep
  {
    Creep(const ViscoelasticSolid &material, double nu);

    std::vector<std::pair<double, double>> retardations;
    double                                 inverse_glassy;
  };


  // One retardation of length L over a cell of width w: e = exp(-w/L),
  // 1 - e and m = (L/w)(1 - e), without cancellation where L >> w (1 - e by
  // expm1: the difference 1 - exp(-w/L) loses log10(L/w) digits). L = 0
  // (the solid at rest) leaves the traction where it is: e = 0, m = 0.
  struct CellDecay
  {
    double e = 0, one_minus_e = 1, m = 0;

    CellDecay() = default;
    CellDecay(const double w, const double L)
      : one_minus_e(L > 0 ? -std::expm1(-w / L) : 1.)
      , m(L > 0 ? L / w * one_minus_e : 0.)
    {
      e = 1. - one_minus_e;
    }
  };


  // Adds c times the smeared traction of one retardation to q_eff on a row
  // of n cells, x increasing, decay(j) the CellDecay of cell j; returns
  // E_0, the smeared traction at the row's trailing end, which the wake
  // continues.
  template <typename Decay>
  double
  smear_row(const double      *q,
            const unsigned int n,
            const Decay       &decay,
            const double       c,
            double            *q_eff)
  {
    double E = 0.; // E_j+1
    for (unsigned int j = n; j-- > 0;)
      {
        const CellDecay &d = decay(j);
        q_eff[j] += c * ((1. - d.m) * q[j] + d.m * E);
        E = d.one_minus_e * q[j] + d.e * E;
      }
    return E;
  }
} // namespace viscoslide

#endif

// SPDX-License-Identifier: LGPL-2.1-or-later
// The viscoelastic surface compliance of an isolated contact on the
// plane-strain half-plane, on a graded grid (boundary_element/grid.h):
// cells [s_j, s_j+1] of any widths w_j, the traction q_j constant on each,
// the displacement u_i collocated at the cells' centres x_i.
//
// The surface displacement is the elastic response to the effective
// traction of the creep (creep.h). The elastic response of unit modulus to
// a traction on the line is
//     u(x) = (2/pi) int ln(H/|x - s|) q(s) ds,
// H the depth the displacement is measured from (Geometry/Domain
// height, as the finite elements' block): the plane-strain half-plane
// has no absolute displacement, and H shifts delta by a constant only.
// Cell by cell in closed form (t ln|t| - t): the dense matrix G. Behind
// the trailing edge s_0 the smeared traction of retardation r is E_0,r
// exp(-(s_0 - x)/L_r), the wake, whose displacement T_r is integrated in
// closed form (exponential integrals), so that it is whole however far
// the creep carries it. So C = G Q + sum_r c_r T_r (x) E0_r, Q the
// effective-traction map, E0_r the row that gives the edge value. n^2
// numbers: the graded grid keeps n in the thousands. C itself (n^3 flops)
// is formed when a block of it is first asked for; until then apply()
// smears the traction and applies G (n^2 flops), which is what a grid
// that moves with the contact edges, made anew at every step, needs.
#ifndef viscoslide_boundary_element_graded_compliance_h
#define viscoslide_boundary_element_graded_compliance_h

#include <deal.II/lac/full_matrix.h>
#include <deal.II/lac/lapack_full_matrix.h>
#include <deal.II/lac/vector.h>

#include <viscoslide/boundary_element/compliance.h>
#include <viscoslide/boundary_element/creep.h>
#include <viscoslide/physics/material.h>

#include <vector>

namespace viscoslide
{
  using namespace dealii;

  class GradedCompliance : public Compliance
  {
  public:
    // The cells between the boundaries s (internal units, E0* = 1);
    // `depth` is H above.
    GradedCompliance(const ViscoelasticSolid   &material,
                     double                     nu,
                     const std::vector<double> &boundaries,
                     double                     depth);

    void
    set_speed(double V) override;

    void
    apply(const Vector<double> &q, Vector<double> &u) const override;

    FullMatrix<double>
    block(unsigned int first, unsigned int m) const;

    // du_c/dx at the cells' centres, the derivative of the response to
    // q_eff - q/E0* in closed form, cell by cell.
    void
    creep_slope(const Vector<double> &q, Vector<double> &slope) const override;

  private:
    // q_eff of the traction q, and each retardation's edge value E_0.
    void
    effective_traction(const double        *q,
                       Vector<double>      &q_eff,
                       std::vector<double> &edge) const;
    void
    form_matrix() const;

    const std::vector<double> s;
    const unsigned int        n;
    const double              depth;
    std::vector<double>       x, w;
    const Creep               creep;
    double                    V = -1;
    // BLAS's matrix-vector products (deal.II's FullMatrix loops were a
    // fifth of a curve's time).
    LAPACKFullMatrix<double> G;
    // Per retardation at the present speed, the decay over each cell and
    // the wake's displacement c_r T_r at the cells (empty at rest).
    std::vector<std::vector<CellDecay>> decay;
    std::vector<std::vector<double>>    wake;
    // C, once formed.
    mutable LAPACKFullMatrix<double> C;
    mutable bool                     formed = false;
  };
} // namespace viscoslide

#endif

// The viscoelastic surface compliance of an isolated contact on the
// plane-strain half-plane, on a graded grid (boundary_element/grid.h):
// cells [s_j, s_j+1] of any widths w_j, the traction q_j constant on each,
// the displacement u_i collocated at the cells' centres x_i.
//
// As for the 3D isolated contact (isolated_compliance.h), a material point
// at x was at x + V t a time t ago (sliding towards +x), and the surface
// displacement is the elastic response to an effective traction,
//     q_eff(x) = q(x)/Einf* + sum_r c_r int_0^inf exp(-xi/L_r) q(x + xi)
//                dxi/L_r,     L_r = V theta_r,
// the retardations (theta_r, c_r) of the Prony series
// (creep_retardations, compliance.h). On cell j,
//     int_0^inf exp(-xi/L) q(x + xi) dxi/L
//       = q_j (1 - e^{-(s_j+1 - x)/L}) + e^{-(s_j+1 - x)/L} E_j+1,
// with E_j its value at s_j, E_j = q_j (1 - e_j) + e_j E_j+1, e_j =
// exp(-w_j/L), E_n = 0 ahead of the window; each cell keeps its mean,
// q_j (1 - m_j) + m_j E_j+1, m_j = (L/w_j)(1 - e_j). Behind the trailing
// edge s_0 the smeared traction is E_0 exp(-(s_0 - x)/L): the wake, whose
// displacement is integrated in closed form, so that it is whole however
// far the creep carries it.
//
// The elastic response of unit modulus to a traction on the line is
//     u(x) = (2/pi) int ln(H/|x - s|) q(s) ds,
// H the depth the displacement is measured from (Geometry/Domain
// height, as the finite elements' block): the plane-strain half-plane
// has no absolute displacement, and H shifts delta by a constant only.
// Cell by cell in closed form (t ln|t| - t), so that C is the dense
// matrix G Q + sum_r c_r T_r (x) E0_r, G the elastic influence, Q the
// effective-traction map (upper triangular), T_r the wake's displacement
// per unit edge value and E0_r the row that gives E_0 of arm r. n^2
// numbers: the graded grid keeps n in the thousands. C itself (n^3 flops)
// is formed when a block of it is first asked for; until then apply()
// uses the factors (n^2 flops), which is what a grid that moves with the
// contact edges, made anew at every step, needs.
#ifndef viscoslide_boundary_element_graded_compliance_h
#define viscoslide_boundary_element_graded_compliance_h

#include <deal.II/lac/full_matrix.h>
#include <deal.II/lac/vector.h>

#include <viscoslide/boundary_element/compliance.h>
#include <viscoslide/material.h>

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
    block(unsigned int first, unsigned int m) const override;

    // -V times the integral of q du/dx, du/dx the derivative of the
    // response to q_eff - q/E0* (in closed form, cell by cell): the
    // relaxed part of the response does no work in a steady state, and
    // leaving it out leaves out its discretisation error too.
    double
    dissipation_rate(const Vector<double> &q) const override;

  private:
    // Q and the rows E0_r at the present speed, for every retardation
    // whose length is not negligible against the cells.
    void
    effective_traction_map(FullMatrix<double>               &Q,
                           std::vector<std::vector<double>> &edge) const;

    const std::vector<double>              s;
    const unsigned int                     n;
    const double                           depth;
    std::vector<double>                    x, w;
    std::vector<std::pair<double, double>> retardation; // (theta_r, c_r)
    double                                 inverse_glassy;
    double                                 V = -1;
    FullMatrix<double>                     G;
    // The effective-traction map of the present speed, the rows E0_r and
    // the wakes' displacements c_r T_r at the cells.
    FullMatrix<double>               Q;
    std::vector<std::vector<double>> edge, wake;
    // C, once formed.
    mutable FullMatrix<double> C;
    mutable bool               formed = false;
    void
    form_matrix() const;
  };
} // namespace viscoslide

#endif

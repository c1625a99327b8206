// SPDX-License-Identifier: LGPL-2.1-or-later
// The viscoelastic surface compliance of the isolated 3D contact on the
// nested grid (nested_layout.h): the uniform window of
// isolated_compliance.h with its band cells divided r x r, the traction
// constant on each cell, coarse or fine. Two levels, as Brandt and
// Lubrecht's multilevel multi-integration does it:
//  * the creep smears the traction along x exactly as on a uniform grid
//    (creep.h), along each fine row through the band and its coarse
//    cells, which keep the mean of their r strips;
//  * the far field is the coarse window's convolution (FFTs) of the
//    traction carried onto the coarse cells with its first moments kept:
//    a band cell's mean on itself and its dipoles as +-D/2 on its
//    neighbours, so that what the far field lacks of a band cell falls
//    off as its quadrupole, (H/d)^2 times its force;
//  * within `near` coarse cells of a band cell (Chebyshev distance) the
//    carried traction's response is taken out again and the exact one of
//    every cell put in its place, Love's influence of each fine or coarse
//    square at the point; at a fine point the far field is interpolated
//    between the coarse points about its cell (Lagrange, 2 `order` + 1
//    points in each direction), where it is smooth because its nearest
//    sources are `near` - `order` cells away.
// The cost of a product is the coarse window's FFTs and a near sum per
// point of the band, which grows with the band's area, not the window's.
#ifndef viscoslide_boundary_element_nested_compliance_h
#define viscoslide_boundary_element_nested_compliance_h

#include <deal.II/lac/vector.h>

#include <viscoslide/boundary_element/compliance.h>
#include <viscoslide/boundary_element/creep.h>
#include <viscoslide/boundary_element/isolated_compliance.h>
#include <viscoslide/boundary_element/nested_layout.h>

#include <memory>
#include <vector>

namespace viscoslide
{
  class NestedCompliance : public Compliance
  {
  public:
    // The near field's reach and the interpolation's order of the grids
    // (tests/nested_compliance_check.cc measures them), and how far a band
    // cell must stay from the window's border.
    static constexpr unsigned int default_near = 2, default_order = 2,
                                  margin = default_near + default_order + 1;

    // `window` is the compliance of the layout's coarse cells, which its
    // owner keeps at the speed (set_speed sets only this one's creep).
    NestedCompliance(const ViscoelasticSolid  &material,
                     double                    nu,
                     const NestedLayout       &layout,
                     const IsolatedCompliance &window,
                     unsigned int              near  = default_near,
                     unsigned int              order = default_order);

    void
    set_speed(double V) override;
    // u = C q on the layout's points.
    void
    apply(const Vector<double> &q, Vector<double> &u) const override;
    // d/dx of the response beyond the relaxed one, by differences between
    // neighbours along x.
    void
    creep_slope(const Vector<double> &q, Vector<double> &slope) const override;

  private:
    // q_eff of q on the points, and the wakes' edge values per coarse row
    // (isolated_compliance.h).
    void
    effective_traction(const Vector<double>             &q,
                       std::vector<double>              &q_eff,
                       std::vector<std::vector<double>> &edge) const;
    // A fine row through a coarse row that holds band cells: its points
    // along x (a coarse cell's point for each coarse cell it crosses) and
    // whether each is fine; made once per layout.
    struct Strip
    {
      std::vector<unsigned int> index;
      std::vector<bool>         fine;
    };
    void
    make_strips();
    // Smears one strip for retardation r into q_eff; returns its value at
    // the trailing end (creep.h, smear_row).
    double
    smear_strip(const Vector<double> &q,
                const Strip          &strip,
                unsigned int          r,
                std::vector<double>  &q_eff) const;
    // u = C from q_eff and the edge values.
    void
    convolve(const std::vector<double>              &q_eff,
             const std::vector<std::vector<double>> &edge,
             Vector<double>                         &u) const;
    // u at the band's points: the coarse response U interpolated, and the
    // near field of the sources about each band cell.
    void
    set_band_points(const std::vector<double> &q_eff,
                    const Vector<double>      &U,
                    Vector<double>            &u) const;

    // A band cell's moments of q_eff: its mean and dipoles (units of H),
    // which the coarse grid carries.
    struct Moments
    {
      double mean = 0, dx = 0, dy = 0;
    };
    std::vector<Moments>
    moments(const std::vector<double> &q_eff) const;
    // The near field's coefficients (below), from Love's influences.
    void
    make_near_field();
    // Calls f(cell, D) for the cells within `near` of `cell`, D the
    // index of their offset.
    template <typename F>
    void
    for_near(unsigned int cell, const F &f) const;

    const NestedLayout       &layout;
    const unsigned int        near, order;
    const Creep               creep;
    const IsolatedCompliance &coarse;
    double                    V = 0;
    // Per retardation, its decay over a fine and over a coarse cell.
    std::vector<CellDecay> fine_decay, coarse_decay;
    // The near field of a point depends on offsets only: the same
    // coefficients for every cell, built once (make_near_field). With D
    // the offset of a source cell from the point's cell, n_D = (2 near +
    // 1)^2 of them (index (D_y + near)(2 near + 1) + D_x + near), t a fine
    // point of the point's cell, f one of the source's (n_f = r^2 each):
    //   u_t = sum_P interpolation[t][P] U_P
    //         + sum_D (band: sum_f fine_from_band[t][D n_f + f] v_f;
    //                  coarse: fine_from_coarse[t][D] v),
    //   u_coarse = U + sum_D (band: sum_f coarse_from_band[D n_f + f] v_f),
    // each the exact influence less what the coarse grid carried. The
    // three of u_t are one matrix, at_band_point (n_f rows, stored by
    // columns): the columns D n_f + f of the band's sources, then n_D n_f
    // + D of the coarse ones, then n_D (n_f + 1) + P of U.
    std::vector<double> at_band_point, coarse_from_band;
    // Per coarse row and fine row s in it, index row r + s; empty where
    // the coarse row holds no band cell.
    std::vector<Strip> strips;
    // Whether a coarse cell lies within `near` of a band cell.
    std::vector<bool> near_band;
  };
} // namespace viscoslide

#endif

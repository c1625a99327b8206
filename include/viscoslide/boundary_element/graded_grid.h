// SPDX-License-Identifier: LGPL-2.1-or-later
// The graded grid of the boundary elements (Boundary element/Grid =
// graded; plane strain on the half-plane): an isolated contact whose cells
// are Grid spacing wide at the two contact edges and grow by the Grading
// ratio away from them (graded_boundaries, grid.h), the compliance dense
// (graded_compliance.h). The grid follows the contact: after each
// equilibrium it is made anew about the edges found where they stray from
// its finest cells; a continuation step is predicted on a grid about the
// extrapolated edges; and its two edges are motions that Newton's method
// can take among its unknowns, the cells beyond each edge (and the gaps on
// them) translated with it, those between stretched. A state moves between
// grids as its gaps: they vary on the scale of eps near the edges, while u
// varies by thousands of eps over the contact at R_hat 1e6
// (doc/boundary_element.md, Graded grid) [graded_grid.cc].
#ifndef viscoslide_boundary_element_graded_grid_h
#define viscoslide_boundary_element_graded_grid_h

#include <deal.II/base/conditional_ostream.h>

#include <viscoslide/boundary_element/graded_compliance.h>
#include <viscoslide/boundary_element/surface_grid.h>
#include <viscoslide/io/parameters.h>
#include <viscoslide/physics/indenter.h>

#include <array>
#include <functional>
#include <memory>

namespace viscoslide
{
  class WindowPreconditioner;

  class GradedGrid : public SurfaceGrid<2>
  {
  public:
    GradedGrid(const Parameters::AllParameters &prm,
               const Scales                    &scales,
               const ViscoelasticSolid         &material,
               const Indenter                  &indenter,
               double                           dx,
               ConditionalOStream              &out);
    ~GradedGrid();

    void
    set_speed(double V) override;
    void
    apply(const Vector<double> &q, Vector<double> &u) const override;
    FullMatrix<double>
    block(unsigned int first, unsigned int m) const override;
    bool
    positive_compliance() const override
    {
      return true;
    }
    void
    creep_slope(const Vector<double> &q, Vector<double> &slope) const override;
    NewtonPreconditioner &
    preconditioner() override;

    bool
    follows_contact() const override
    {
      return true;
    }
    std::shared_ptr<const Placement>
    placement() const override;
    void
    regrid(const Placement &p, SurfaceState &state) override;
    void
    place(const Placement      &p,
          const Vector<double> &gaps,
          SurfaceState         &state) override;
    void
    place_about(double trail, double lead, SurfaceState &state) override;
    bool
    follow(const SurfaceQuantities &q,
           const Vector<double>    &traction,
           bool                     always,
           SurfaceState            &state) override;
    void
    predict(const std::pair<double, double> &edges,
            const std::pair<double, double> &edges_before,
            double                           ratio,
            SurfaceState                    &state) override;

    unsigned int
    n_motions() const override
    {
      return 2;
    }
    bool
    prepare_motions(const SurfaceQuantities &q, SurfaceState &state) override;
    void
    move(const Placement           &from,
         const std::vector<double> &d,
         const Vector<double>      &gaps,
         SurfaceState              &state) override;
    std::unique_ptr<SurfaceGrid<2>>
    moved(const Placement           &from,
          const std::vector<double> &d,
          const Vector<double>      &gaps,
          SurfaceState              &state) const override;
    std::vector<std::pair<unsigned int, double>>
    pin(unsigned int k) const override;

  private:
    // The cell boundaries and the contact edges they were made for.
    struct Cells : Placement
    {
      std::vector<double>       boundaries;
      std::pair<double, double> edges;
    };

    // The grid of cells between `boundaries`, made for contact edges at
    // `edges`, the state's gaps interpolated onto it (from x - shift(x) if
    // given); counts a generation.
    void
    make(const std::vector<double>           &boundaries,
         const std::pair<double, double>     &edges,
         SurfaceState                        &state,
         const std::function<double(double)> &shift = {});
    // make() about contact edges at trail and lead, the grid reaching
    // margin_factor times the contact's width (at least 50 eps) beyond
    // each.
    void
    make_about(double                               trail,
               double                               lead,
               SurfaceState                        &state,
               const std::function<double(double)> &shift = {});
    // The cells between `boundaries` for edges at `edges` with the gaps
    // `gap` (delta kept), the compliance made for them.
    void
    set_cells(const std::vector<double>       &boundaries,
              const std::pair<double, double> &edges,
              const Vector<double>            &gap,
              SurfaceState                    &state);

    unsigned int
    next(unsigned int j) const override;
    unsigned int
    previous(unsigned int j) const override;
    double
    distance_to_next(unsigned int j) const override;
    double
    distance_across(unsigned int j) const override;

    const Parameters::AllParameters &prm;
    const Scales                    &scales;
    const ViscoelasticSolid         &material;
    const Indenter                  &indenter;
    ConditionalOStream              &out;
    const double                     depth;
    Cells                            cells;
    // The boundaries at the two edges: the focus of each edge.
    std::array<unsigned int, 2> focus{};
    // Where each edge's gap is pinned (points and weights) when that is
    // not the focus: the crossing of the contact gap measured when the
    // motions were prepared, on the grid since (empty: the focus).
    std::array<std::vector<std::pair<unsigned int, double>>, 2> pins;
    double                                margin_factor = 0.5;
    std::unique_ptr<GradedCompliance>     compliance;
    std::unique_ptr<WindowPreconditioner> window;
  };
} // namespace viscoslide

#endif

// SPDX-License-Identifier: LGPL-2.1-or-later
// The nested grid of the boundary elements on the 3D half-space: the
// isolated window of isolated_grid.h, its cells along the contact edge
// divided r x r (nested_layout.h, nested_compliance.h), so that the
// adhesive zone, a ring a fraction of an eps wide at slow speeds, is
// resolved where it is and the window elsewhere keeps its coarse cells.
// The band is what the converged state asks for: the cells where the
// attraction exceeds half its peak or the traction changes sign
// (the contact's edge), widened by Band width; after each converged state
// whose band has left the refined cells a new grid is made about it and
// the state solved again (solver.h, solve), so that the band moves with
// the edge through the continuation; each continuation step is taken
// first on the undivided window (coarse_placement, carry; solver.h,
// predict_on_coarse). Its preconditioner is the coarse window's multigrid
// (nested_preconditioner.h) [nested_grid.cc].
#ifndef viscoslide_boundary_element_nested_grid_h
#define viscoslide_boundary_element_nested_grid_h

#include <deal.II/base/conditional_ostream.h>

#include <viscoslide/boundary_element/nested_compliance.h>
#include <viscoslide/boundary_element/nested_preconditioner.h>
#include <viscoslide/boundary_element/surface_grid.h>
#include <viscoslide/io/parameters.h>
#include <viscoslide/physics/indenter.h>

#include <memory>

namespace viscoslide
{
  class NestedGrid : public SurfaceGrid<3>
  {
  public:
    NestedGrid(const Parameters::AllParameters &prm,
               const Scales                    &scales,
               const ViscoelasticSolid         &material,
               const Indenter                  &indenter,
               double                           dx,
               ConditionalOStream              &out);
    ~NestedGrid();

    void
    set_speed(double V) override;
    void
    apply(const Vector<double> &q, Vector<double> &u) const override
    {
      compliance->apply(q, u);
    }
    void
    creep_slope(const Vector<double> &q, Vector<double> &slope) const override
    {
      compliance->creep_slope(q, slope);
    }
    NewtonPreconditioner &
    preconditioner() override
    {
      return *nested_preconditioner;
    }
    double
    rows() const override
    {
      return shape[0];
    }
    // The window (no band) at the first call; the band from the first
    // speed on.
    void
    fit_to_speed(double V_hat, SurfaceState &state) override;
    bool
    refines_about_contact() const override
    {
      return true;
    }
    void
    refine_at_rest() override
    {
      refining = true;
    }
    bool
    follow(const SurfaceQuantities &q,
           const Vector<double>    &traction,
           bool                     always,
           SurfaceState            &state) override;
    std::shared_ptr<const Placement>
    placement() const override;
    // VTK poly data (.vtp in place of the uniform grids' .vti): the points
    // about the contact, where the surfaces are within 10 eps, with a
    // margin of a quarter of its size; pressure in sigma_max, gap and
    // displacement in eps, the cell's side in eps, lengths in R.
    void
    write_map(const std::string    &path,
              const std::string    &what,
              const Vector<double> &gaps,
              const Vector<double> &traction,
              const Vector<double> &u,
              double                eps,
              double                sigma_max,
              double                R) const override;
    void
    regrid(const Placement &p, SurfaceState &state) override;
    std::shared_ptr<const Placement>
    coarse_placement() const override;
    bool
    carry(const Placement &p, SurfaceState &state) const override;

  private:
    // The band flags of a grid.
    struct Band : Placement
    {
      std::vector<bool> flags;
    };
    // The grid with band `band`, the state carried over.
    void
    make(const std::vector<bool> &band, SurfaceState &state);
    // Refuses a band whose grid will not fit in this machine's memory,
    // naming the entries that shrink it.
    void
    require_fits(const std::vector<bool> &band) const;
    // The cells the traction asks to be refined (the zone and the edge),
    // and those widened by the band width and `spare` cells more.
    std::vector<bool>
    core_of(const Vector<double> &traction) const;
    std::vector<bool>
    widened(const std::vector<bool> &core, int spare) const;
    // The state's displacement at lattice point (x, y) of the grid
    // before: exact on its points, bilinear between its cells' centres.
    double
    value_at(const NestedLayout   &old,
             const Vector<double> &u,
             int                   x,
             int                   y) const;
    // The displacements u on the points of `old`, at this grid's points.
    Vector<double>
    carried(const NestedLayout &old, const Vector<double> &u) const;
    // The distance from the axis of the body of revolution, stretched
    // across the track, of lattice point (x, y).
    double
    radius(int x, int y) const;

    unsigned int
    next(unsigned int j) const override
    {
      return layout->neighbour(j, 0, true);
    }
    unsigned int
    previous(unsigned int j) const override
    {
      return layout->neighbour(j, 0, false);
    }
    double
    distance_to_next(unsigned int j) const override;
    double
    distance_across(unsigned int j) const override;
    void
    measure_plane(const Vector<double> &gaps,
                  double                gc,
                  SurfaceQuantities    &q) const override;

    const Parameters::AllParameters &prm;
    const Scales                    &scales;
    const ViscoelasticSolid         &material;
    const Indenter                  &indenter;
    ConditionalOStream              &out;
    std::array<unsigned int, 2>      shape{};
    // The coarse window's compliance and multigrid, made once; the
    // layout and what depends on the band, made with each band.
    std::unique_ptr<IsolatedCompliance>   window;
    std::unique_ptr<SurfaceMultigrid<3>>  multigrid;
    std::unique_ptr<NestedLayout>         layout;
    std::unique_ptr<NestedCompliance>     compliance;
    std::unique_ptr<NestedPreconditioner> nested_preconditioner;
    // Whether the band follows the contact (from the first speed on, or
    // from the start where there is no sliding).
    bool refining;
  };
} // namespace viscoslide

#endif

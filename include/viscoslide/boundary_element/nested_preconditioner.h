// SPDX-License-Identifier: LGPL-2.1-or-later
// The preconditioner of Newton's system on the nested grid
// (nested_grid.h): the coarse window's multigrid (multigrid_preconditioner.h)
// on the residual averaged over each band cell's points, its correction
// copied to them, and on the band's points what the average leaves of
// the residual scaled by the point's own diagonal, 1 + c_h w (c_h the
// compliance of a fine cell at its centre): a two-level additive
// preconditioner; GMRES does the rest [nested_preconditioner.cc].
#ifndef viscoslide_boundary_element_nested_preconditioner_h
#define viscoslide_boundary_element_nested_preconditioner_h

#include <viscoslide/boundary_element/multigrid_preconditioner.h>
#include <viscoslide/boundary_element/nested_layout.h>


namespace viscoslide
{
  class NestedPreconditioner : public NewtonPreconditioner
  {
  public:
    // `coarse` is the multigrid of the layout's coarse cells, which its
    // owner keeps at the speed.
    NestedPreconditioner(const NestedLayout  &layout,
                         SurfaceMultigrid<3> &coarse);

    void
    update(const Vector<double> &tangent, double dashpot, bool force) override;
    void
    vmult(Vector<double> &dst, const Vector<double> &src) const override;

  private:
    // Each cell's mean of a vector on the points, with the approach.
    Vector<double>
    restrict_to_cells(const Vector<double> &v) const;

    const NestedLayout  &layout;
    SurfaceMultigrid<3> &coarse;
    Vector<double>       inverse_diagonal;
  };
} // namespace viscoslide

#endif

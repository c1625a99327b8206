// SPDX-License-Identifier: LGPL-2.1-or-later
#include <viscoslide/boundary_element/isolated_compliance.h>
#include <viscoslide/boundary_element/nested_preconditioner.h>

namespace viscoslide
{
  NestedPreconditioner::NestedPreconditioner(const NestedLayout  &layout,
                                             SurfaceMultigrid<3> &coarse)
    : layout(layout)
    , coarse(coarse)
  {
  }


  Vector<double>
  NestedPreconditioner::restrict_to_cells(const Vector<double> &v) const
  {
    const unsigned int n = layout.size(), cells = layout.n_cells();
    Vector<double>     mean(cells + (v.size() > n ? 1 : 0));
    for (unsigned int j = 0; j < n; ++j)
      {
        const unsigned int cell = layout.cell_of[j];
        mean[cell] += v[j] / (layout.first[cell + 1] - layout.first[cell]);
      }
    if (v.size() > n)
      mean[cells] = v[n];
    return mean;
  }


  void
  NestedPreconditioner::update(const Vector<double> &tangent,
                               const double          dashpot,
                               const bool            force)
  {
    coarse.update(restrict_to_cells(tangent), dashpot, force);
    const double c_h = love(0, 0, layout.h / 2);
    inverse_diagonal.reinit(layout.size());
    for (unsigned int j = 0; j < layout.size(); ++j)
      inverse_diagonal[j] =
        1. / (1. + c_h * std::max(tangent[j] + dashpot, 0.));
  }


  void
  NestedPreconditioner::vmult(Vector<double>       &dst,
                              const Vector<double> &src) const
  {
    const unsigned int   n = layout.size(), cells = layout.n_cells();
    const Vector<double> mean = restrict_to_cells(src);
    Vector<double>       correction(mean.size());
    coarse.vmult(correction, mean);
    dst.reinit(src.size());
    for (unsigned int j = 0; j < n; ++j)
      {
        const unsigned int cell = layout.cell_of[j];
        dst[j]                  = correction[cell];
        if (layout.band[cell])
          dst[j] += (src[j] - mean[cell]) * inverse_diagonal[j];
      }
    if (src.size() > n)
      dst[n] = correction[cells];
  }
} // namespace viscoslide

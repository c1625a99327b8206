// SPDX-License-Identifier: LGPL-2.1-or-later
#include <viscoslide/boundary_element/nested_layout.h>

#include <stdexcept>

namespace viscoslide
{
  NestedLayout::NestedLayout(const std::array<unsigned int, 2> &n,
                             const double                       H,
                             const unsigned int                 r,
                             const std::vector<bool>           &band)
    : n(n)
    , H(H)
    , r(r)
    , c((r - 1) / 2)
    , h(H / r)
    , band(band)
    , row_has_band(n[0], false)
  {
    if (r % 2 == 0 || band.size() != n_cells())
      throw std::logic_error("a nested grid needs an odd refinement and a "
                             "flag per cell");
    first.reserve(n_cells() + 1);
    first.push_back(0);
    for (unsigned int cell = 0; cell < n_cells(); ++cell)
      {
        const unsigned int m = band[cell] ? r * r : 1;
        first.push_back(first.back() + m);
        cell_of.insert(cell_of.end(), m, cell);
        if (band[cell])
          row_has_band[cell / n[1]] = true;
      }
  }


  int
  NestedLayout::lattice_x(const unsigned int point) const
  {
    const unsigned int cell   = cell_of[point];
    const int          centre = (int(cell % n[1]) - int(n[1] / 2)) * int(r);
    return band[cell] ? centre + int((point - first[cell]) % r) - int(c)
                      : centre;
  }


  int
  NestedLayout::lattice_y(const unsigned int point) const
  {
    const unsigned int cell   = cell_of[point];
    const int          centre = (int(cell / n[1]) - int(n[0] / 2)) * int(r);
    return band[cell] ? centre + int((point - first[cell]) / r) - int(c)
                      : centre;
  }


  unsigned int
  NestedLayout::neighbour(const unsigned int point,
                          const unsigned int axis,
                          const bool         forwards) const
  {
    const unsigned int cell = cell_of[point];
    // (row, column) within the cell; a coarse cell's point is its middle.
    const unsigned int local = point - first[cell];
    unsigned int s = band[cell] ? local / r : c, k = band[cell] ? local % r : c;
    unsigned int &along = axis == 0 ? k : s;
    if (band[cell] && (forwards ? along + 1 < r : along > 0))
      {
        along = forwards ? along + 1 : along - 1;
        return fine(cell, s, k);
      }
    const unsigned int ix = cell % n[1], iy = cell / n[1];
    const unsigned int i = axis == 0 ? ix : iy;
    if (forwards ? i + 1 >= n[axis == 0 ? 1 : 0] : i == 0)
      return point;
    const unsigned int next =
      cell + (forwards ? 1 : -1) * int(axis == 0 ? 1 : n[1]);
    if (!band[next])
      return first[next];
    along = forwards ? 0 : r - 1;
    return fine(next, s, k);
  }
} // namespace viscoslide

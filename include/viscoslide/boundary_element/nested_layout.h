// SPDX-License-Identifier: LGPL-2.1-or-later
// The points of the nested grid of the 3D boundary elements: a window of
// n_y x n_x uniform coarse cells of spacing H (uniform_grid.h), some of
// which, the band cells along the contact edge, are divided into r x r
// fine cells of spacing h = H/r. r is odd, so that a coarse cell's centre
// is the centre of its middle fine cell and every point lies on the fine
// lattice. The points are numbered cell by cell (x fastest over the
// cells): a coarse cell has one, at its centre; a band cell r^2, x fastest
// within it [nested_layout.cc].
#ifndef viscoslide_boundary_element_nested_layout_h
#define viscoslide_boundary_element_nested_layout_h

#include <array>
#include <vector>

namespace viscoslide
{
  struct NestedLayout
  {
    // n = (n_y, n_x) coarse cells, `band` one flag per cell (x fastest).
    NestedLayout(const std::array<unsigned int, 2> &n,
                 double                             H,
                 unsigned int                       r,
                 const std::vector<bool>           &band);

    unsigned int
    size() const
    {
      return first.back();
    }
    unsigned int
    n_cells() const
    {
      return n[0] * n[1];
    }
    // The point of fine cell (s, k) (row s, column k) of band cell `cell`.
    unsigned int
    fine(const unsigned int cell,
         const unsigned int s,
         const unsigned int k) const
    {
      return first[cell] + s * r + k;
    }
    // The point at the centre of a cell.
    unsigned int
    centre(const unsigned int cell) const
    {
      return band[cell] ? fine(cell, c, c) : first[cell];
    }
    // The point's position on the fine lattice, from the window's centre
    // (in fine cells): x = (lattice_x) h.
    int
    lattice_x(unsigned int point) const;
    int
    lattice_y(unsigned int point) const;
    double
    area(const unsigned int point) const
    {
      return band[cell_of[point]] ? h * h : H * H;
    }
    // The neighbour of a point along x (axis 0) or y (axis 1), forwards or
    // backwards, within the window (the last point's own index beyond it);
    // from a coarse cell into a band cell the fine point on the cell's
    // middle line nearest to it.
    unsigned int
    neighbour(unsigned int point, unsigned int axis, bool forwards) const;

    const std::array<unsigned int, 2> n;
    const double                      H;
    const unsigned int                r, c;
    const double                      h;
    const std::vector<bool>           band;
    // The first point of each cell, and the number of points at the end.
    std::vector<unsigned int> first;
    // Each point's cell, and whether a coarse row holds a band cell.
    std::vector<unsigned int> cell_of;
    std::vector<bool>         row_has_band;
  };
} // namespace viscoslide

#endif

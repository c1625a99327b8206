// SPDX-License-Identifier: LGPL-2.1-or-later
// The uniform grids of the boundary elements: n_x points along x (and n_y
// across the track in 3D) of spacing dx, centred on the indenter's apex,
// x fastest: point j at x = (j mod n_x - n_x/2) dx and, in 3D, y = (j div
// n_x - n_y/2) dx, each standing for the area dx^(dim-1). What the
// periodic grid (periodic_grid.h) and the isolated window of the 3D
// half-space (isolated_grid.h) share: the points and the indenter on them,
// a state carried over at equal x, the neighbours along x (periodic), the
// 3D contact area and map. The length of the grid along x is the one its
// kind needs at a speed (period_for()); it grows with it and shrinks
// four-fold [uniform_grid.cc].
#ifndef viscoslide_boundary_element_uniform_grid_h
#define viscoslide_boundary_element_uniform_grid_h

#include <deal.II/base/conditional_ostream.h>

#include <viscoslide/boundary_element/surface_grid.h>
#include <viscoslide/physics/indenter.h>

#include <array>

namespace viscoslide
{
  // The smallest n >= m of the form 2^a 3^b 5^c 7^d, even, for which
  // FFTW is fastest.
  unsigned int
  fft_size(double m);

  // The part of a triangle where a linear function of vertex values g is
  // below c.
  double
  fraction_below(std::array<double, 3> g, double c);


  template <int dim>
  class UniformGrid : public SurfaceGrid<dim>
  {
  public:
    void
    fit_to_speed(double V_hat, SurfaceState &state) override;
    double
    rows() const override
    {
      return dim == 2 ? 1. : shape[0];
    }
    void
    write_map(const std::string    &path,
              const std::string    &what,
              const Vector<double> &gaps,
              const Vector<double> &traction,
              const Vector<double> &u,
              double                eps,
              double                sigma_max,
              double                R) const override;

  protected:
    // `elongation` stretches the 3D body of revolution across the track;
    // `length` is the grid's extent across it (3D); eps the law's range,
    // which relates the state's gaps to its displacements.
    UniformGrid(const Indenter     &indenter,
                double              elongation,
                double              dx,
                double              length,
                double              eps,
                ConditionalOStream &out);

    // The length along x the grid needs up to speed V_hat (internal
    // units).
    virtual double
    period_for(double V_hat) const = 0;
    // The compliance and the preconditioner for `shape`, made anew; the
    // speed is set after.
    virtual void
    make_operators(const std::array<unsigned int, dim - 1> &shape) = 0;
    // The grid's line of description.
    virtual std::string
    describe() const = 0;

    // The grid of `new_shape`, the state carried over at equal x (beyond
    // the old grid, its nearer end).
    void
    remake(const std::array<unsigned int, dim - 1> &new_shape,
           SurfaceState                            &state);

    unsigned int
    next(unsigned int j) const override;
    unsigned int
    previous(unsigned int j) const override;
    double
    distance_to_next(unsigned int) const override
    {
      return this->dx;
    }
    double
    distance_across(unsigned int) const override
    {
      return 2 * this->dx;
    }
    void
    measure_plane(const Vector<double> &gaps,
                  double                gc,
                  SurfaceQuantities    &q) const override;

    const Indenter                   &indenter;
    const double                      elongation, length, eps;
    ConditionalOStream               &out;
    std::array<unsigned int, dim - 1> shape{};
  };
} // namespace viscoslide

#endif

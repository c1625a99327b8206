// SPDX-License-Identifier: LGPL-2.1-or-later
// The periodic grid of the boundary elements: uniform points over one
// period of a periodic surface, one indenter per period
// (doc/boundary_element.md, Equations): the plane-strain half-plane and
// layer, the 3D layer. The compliance is PeriodicCompliance, applied by
// FFTW; the period is the larger of the Domain width and Wake periods
// creep lengths of the fastest speed (or Boundary element/Period). The 2D
// half-plane has no depth, so that its approach runs on the block of
// Domain height on a rigid base and sliding on the half-plane
// (to_sliding_solid). The preconditioner: the dense window on a line of
// points, multigrid on a plane of them [periodic_grid.cc].
#ifndef viscoslide_boundary_element_periodic_grid_h
#define viscoslide_boundary_element_periodic_grid_h

#include <viscoslide/boundary_element/multigrid_preconditioner.h>
#include <viscoslide/boundary_element/periodic_compliance.h>
#include <viscoslide/boundary_element/uniform_grid.h>
#include <viscoslide/io/parameters.h>

#include <memory>

namespace viscoslide
{
  template <int dim>
  class PeriodicGrid : public UniformGrid<dim>
  {
  public:
    PeriodicGrid(const Parameters::AllParameters &prm,
                 const Scales                    &scales,
                 const ViscoelasticSolid         &material,
                 const Indenter                  &indenter,
                 double                           dx,
                 ConditionalOStream              &out);
    ~PeriodicGrid();

    void
    set_speed(double V) override;
    void
    apply(const Vector<double> &q, Vector<double> &u) const override;
    FullMatrix<double>
    block(unsigned int first, unsigned int m) const override;
    void
    creep_slope(const Vector<double> &q, Vector<double> &slope) const override;
    NewtonPreconditioner &
    preconditioner() override
    {
      return *newton_preconditioner;
    }
    bool
    to_sliding_solid(SurfaceState &state) override;

  private:
    double
    period_for(double V_hat) const override;
    void
    make_operators(const std::array<unsigned int, dim - 1> &shape) override;
    std::string
    describe() const override;

    const Parameters::AllParameters         &prm;
    const Scales                            &scales;
    const ViscoelasticSolid                 &material;
    Parameters::Substrate                    substrate;
    const double                             thickness;
    std::unique_ptr<PeriodicCompliance<dim>> compliance;
    std::unique_ptr<NewtonPreconditioner>    newton_preconditioner;
    // In 3D, the multigrid preconditioner, which follows the speed.
    SurfaceMultigrid<dim> *multigrid = nullptr;
  };
} // namespace viscoslide

#endif

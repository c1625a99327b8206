// SPDX-License-Identifier: LGPL-2.1-or-later
// The isolated window of the boundary elements on the 3D half-space:
// uniform points over Domain width x Domain length about the indenter,
// all of the surface that carries traction, the solid around it infinite
// and at rest far away, as in the experiments (isolated_compliance.h), so
// that no period is needed at any speed and delta is measured from the
// far field. Its preconditioner is multigrid on the periodic operator of
// the window (a preconditioner need not be exact) [isolated_grid.cc].
#ifndef viscoslide_boundary_element_isolated_grid_h
#define viscoslide_boundary_element_isolated_grid_h

#include <viscoslide/boundary_element/isolated_compliance.h>
#include <viscoslide/boundary_element/multigrid_preconditioner.h>
#include <viscoslide/boundary_element/uniform_grid.h>
#include <viscoslide/io/parameters.h>

#include <memory>

namespace viscoslide
{
  class IsolatedGrid : public UniformGrid<3>
  {
  public:
    IsolatedGrid(const Parameters::AllParameters &prm,
                 const Scales                    &scales,
                 const ViscoelasticSolid         &material,
                 const Indenter                  &indenter,
                 double                           dx,
                 ConditionalOStream              &out);
    ~IsolatedGrid();

    void
    set_speed(double V) override;
    void
    apply(const Vector<double> &q, Vector<double> &u) const override;
    void
    creep_slope(const Vector<double> &q, Vector<double> &slope) const override;
    NewtonPreconditioner &
    preconditioner() override
    {
      return *multigrid;
    }

  private:
    double
    period_for(double V_hat) const override;
    void
    make_operators(const std::array<unsigned int, 2> &shape) override;
    std::string
    describe() const override;

    const Parameters::AllParameters     &prm;
    const Scales                        &scales;
    const ViscoelasticSolid             &material;
    std::unique_ptr<IsolatedCompliance>  compliance;
    std::unique_ptr<SurfaceMultigrid<3>> multigrid;
  };
} // namespace viscoslide

#endif

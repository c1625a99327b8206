// SPDX-License-Identifier: LGPL-2.1-or-later
#include <viscoslide/boundary_element/isolated_grid.h>

#include <sstream>

namespace viscoslide
{
  IsolatedGrid::IsolatedGrid(const Parameters::AllParameters &prm,
                             const Scales                    &scales,
                             const ViscoelasticSolid         &material,
                             const Indenter                  &indenter,
                             const double                     dx,
                             ConditionalOStream              &out)
    : UniformGrid<3>(indenter,
                     prm.geometry.elongation,
                     dx,
                     prm.geometry.length() * scales.eps,
                     scales.eps,
                     out)
    , prm(prm)
    , scales(scales)
    , material(material)
  {
  }


  IsolatedGrid::~IsolatedGrid() = default;


  // The window is the Domain width along the track at every speed: the
  // wake beyond it is in the compliance.
  double
  IsolatedGrid::period_for(const double) const
  {
    return prm.geometry.domain_width * scales.eps;
  }


  void
  IsolatedGrid::make_operators(const std::array<unsigned int, 2> &shape)
  {
    compliance = std::make_unique<IsolatedCompliance>(
      material, prm.material.poisson_ratio, shape, dx);
    multigrid =
      std::make_unique<SurfaceMultigrid<3>>(Parameters::Substrate::half_plane,
                                            prm.geometry.height() * scales.eps,
                                            material,
                                            prm.material.poisson_ratio,
                                            shape,
                                            dx,
                                            scales.sigma_max);
  }


  void
  IsolatedGrid::set_speed(const double V)
  {
    speed = V;
    compliance->set_speed(V);
    multigrid->set_speed(V);
  }


  void
  IsolatedGrid::apply(const Vector<double> &q, Vector<double> &u) const
  {
    compliance->apply(q, u);
  }


  void
  IsolatedGrid::creep_slope(const Vector<double> &q,
                            Vector<double>       &slope) const
  {
    compliance->creep_slope(q, slope);
  }


  std::string
  IsolatedGrid::describe() const
  {
    std::ostringstream s;
    s << "Boundary-element grid: " << size() << " points (" << shape[1] << " x "
      << shape[0] << "), spacing " << dx << " eps, window " << shape[1] * dx
      << " x " << shape[0] * dx << " eps, " << multigrid->n_levels()
      << " multigrid levels";
    return s.str();
  }
} // namespace viscoslide

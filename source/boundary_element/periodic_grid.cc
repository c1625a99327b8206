// SPDX-License-Identifier: LGPL-2.1-or-later
#include <viscoslide/boundary_element/periodic_grid.h>
#include <viscoslide/boundary_element/window_preconditioner.h>

#include <algorithm>
#include <sstream>

namespace viscoslide
{
  template <int dim>
  PeriodicGrid<dim>::PeriodicGrid(const Parameters::AllParameters &prm,
                                  const Scales                    &scales,
                                  const ViscoelasticSolid         &material,
                                  const Indenter                  &indenter,
                                  const double                     dx,
                                  ConditionalOStream              &out)
    : UniformGrid<dim>(indenter,
                       prm.geometry.elongation,
                       dx,
                       prm.geometry.length() * scales.eps,
                       scales.eps,
                       out)
    , prm(prm)
    , scales(scales)
    , material(material)
    // The approach on a layer: the 2D half-plane's on the block of Domain
    // height (doc/boundary_element.md, Approach).
    , substrate(Parameters::Substrate::layer)
    , thickness(prm.geometry.height() * scales.eps)
  {
    if constexpr (dim == 2)
      newton_preconditioner =
        std::make_unique<WindowPreconditioner>(*this, scales.sigma_max, false);
  }


  template <int dim>
  PeriodicGrid<dim>::~PeriodicGrid() = default;


  template <int dim>
  double
  PeriodicGrid<dim>::period_for(const double V_hat) const
  {
    const double wake = V_hat * longest_creep_time(prm) * scales.eps;
    return prm.boundary_element.period > 0
             ? prm.boundary_element.period * scales.eps
             : std::max(prm.geometry.domain_width * scales.eps,
                        prm.boundary_element.wake_periods * wake);
  }


  template <int dim>
  void
  PeriodicGrid<dim>::make_operators(
    const std::array<unsigned int, dim - 1> &shape)
  {
    compliance =
      std::make_unique<PeriodicCompliance<dim>>(substrate,
                                                thickness,
                                                material,
                                                prm.material.poisson_ratio,
                                                shape,
                                                this->dx);
    if constexpr (dim == 3)
      {
        auto mg =
          std::make_unique<SurfaceMultigrid<dim>>(substrate,
                                                  thickness,
                                                  material,
                                                  prm.material.poisson_ratio,
                                                  shape,
                                                  this->dx,
                                                  scales.sigma_max);
        multigrid             = mg.get();
        newton_preconditioner = std::move(mg);
      }
  }


  template <int dim>
  void
  PeriodicGrid<dim>::set_speed(const double V)
  {
    this->speed = V;
    compliance->set_speed(V);
    if (multigrid)
      multigrid->set_speed(V);
  }


  template <int dim>
  void
  PeriodicGrid<dim>::apply(const Vector<double> &q, Vector<double> &u) const
  {
    compliance->apply(q, u);
  }


  template <int dim>
  FullMatrix<double>
  PeriodicGrid<dim>::block(const unsigned int first, const unsigned int m) const
  {
    return compliance->block(first, m);
  }


  template <int dim>
  void
  PeriodicGrid<dim>::creep_slope(const Vector<double> &q,
                                 Vector<double>       &slope) const
  {
    compliance->creep_slope(q, slope);
  }


  template <int dim>
  bool
  PeriodicGrid<dim>::to_sliding_solid(SurfaceState &state)
  {
    if (substrate == prm.geometry.substrate)
      return false;
    substrate = prm.geometry.substrate;
    this->remake(this->shape, state);
    return true;
  }


  template <int dim>
  std::string
  PeriodicGrid<dim>::describe() const
  {
    const unsigned int n_x = this->shape[dim - 2];
    std::ostringstream s;
    s << "Boundary-element grid: " << this->size() << " points";
    if (dim == 3)
      s << " (" << n_x << " x " << this->shape[0] << ")";
    s << ", spacing " << this->dx << " eps, period " << n_x * this->dx;
    if (dim == 3)
      s << " x " << this->shape[0] * this->dx;
    s << " eps";
    if (multigrid)
      s << ", " << multigrid->n_levels() << " multigrid levels";
    return s.str();
  }


  template class PeriodicGrid<2>;
  template class PeriodicGrid<3>;
} // namespace viscoslide

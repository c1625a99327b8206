// SPDX-License-Identifier: LGPL-2.1-or-later
// What the boundary-element solver's grids need of a surface compliance:
// the vertical displacement of the top surface under a vertical traction
// that slides at speed V towards +x. One class per model of the solid:
// periodic (periodic_compliance.h, applied by FFTW), the isolated contact
// on the 3D half-space (isolated_compliance.h) and on the plane-strain
// half-plane on a graded grid (graded_compliance.h).
//
// The dissipation, one convention for all (doc/boundary_element.md,
// Dissipation): in a steady state the rate of work of the traction q
// (attraction > 0) on the solid is
//     D = -V integral q du_c/dx dA,   u_c = C q - C_0 q,
// u_c the response beyond the relaxed elastic one C_0 q, which does no
// work in a steady state (its integral vanishes for any q, and leaving it
// out leaves out its discretisation error too); each compliance gives
// du_c/dx at its points as its own discretisation has it (creep_slope),
// the grid sums (SurfaceGrid::dissipation_rate).
#ifndef viscoslide_boundary_element_compliance_h
#define viscoslide_boundary_element_compliance_h

#include <deal.II/lac/vector.h>

namespace viscoslide
{
  using namespace dealii;

  class Compliance
  {
  public:
    virtual ~Compliance() = default;

    // The sliding speed V (internal units); 0 is the relaxed solid.
    virtual void
    set_speed(double V) = 0;

    // u = C q on the grid.
    virtual void
    apply(const Vector<double> &q, Vector<double> &u) const = 0;

    // du_c/dx at the points (above).
    virtual void
    creep_slope(const Vector<double> &q, Vector<double> &slope) const = 0;
  };


} // namespace viscoslide

#endif

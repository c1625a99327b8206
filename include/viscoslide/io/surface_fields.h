// SPDX-License-Identifier: LGPL-2.1-or-later
// The surface fields of every solver (pressure and gap along the top
// surface) as VTU/PVTU or HDF5 through DataOutFaces (implemented in
// source/io/surface_fields.cc).
#ifndef viscoslide_surface_fields_h
#define viscoslide_surface_fields_h

#include <deal.II/dofs/dof_handler.h>

#include <deal.II/lac/trilinos_vector.h>

#include <viscoslide/io/output.h>
#include <viscoslide/io/parameters.h>
#include <viscoslide/physics/indenter.h>
#include <viscoslide/physics/interaction_law.h>

#include <string>

namespace viscoslide
{
  using namespace dealii;

  // p_hat and gap_over_eps on the locally owned top faces, from u_y (the
  // solution's component vertical<dim>) with the indenter at approach
  // delta and position s (in 3D stretched by `elongation` across the
  // track); step `counter` of the collection `name`.
  template <int dim>
  void
  write_surface_fields(OutputWriter                        &writer,
                       const std::string                   &name,
                       const DoFHandler<dim>               &dof_handler,
                       const TrilinosWrappers::MPI::Vector &solution,
                       const InteractionLaw                &law,
                       const Indenter                      &indenter,
                       const Scales                        &scales,
                       double                               delta,
                       double                               s,
                       unsigned int                         counter,
                       double                               time,
                       double                               elongation = 1.);
} // namespace viscoslide

#endif

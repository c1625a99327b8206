// SPDX-License-Identifier: LGPL-2.1-or-later
#include <viscoslide/case_setup.h>
#include <viscoslide/io/parameters.h>

namespace viscoslide
{
  namespace Parameters
  {
    void
    AllParameters::declare(ParameterHandler &prm)
    {
      Output::declare(prm);
      Material::declare(prm);
      Adhesion::declare(prm);
      IndenterProfile::declare(prm);
      Geometry::declare(prm);
      Loading::declare(prm);
      Mesh::declare(prm);
      Sliding::declare(prm);
      Solver::declare(prm);
      BoundaryElement::declare(prm);
      Sweep::declare(prm);
      Units::declare(prm);
    }

    void
    AllParameters::parse(ParameterHandler &prm)
    {
      output.parse(prm);
      material.parse(prm);
      adhesion.parse(prm);
      indenter.parse(prm);
      geometry.parse(prm);
      loading.parse(prm);
      mesh.parse(prm);
      sliding.parse(prm);
      solver.parse(prm);
      boundary_element.parse(prm);
      sweep.parse(prm);
      units.parse(prm);
      solver.verbose = output.verbosity == Verbosity::verbose;
      apply_units(*this);
      CaseSetup::choose_surface_grid(*this);
      CaseSetup::check_consistency(*this);
      // The memory is counted on the block that will be meshed.
      CaseSetup::fit_block_to_wake(*this);
      CaseSetup::fit_linear_solver_to_memory(*this);
      CaseSetup::check_mesh_can_hold_case(*this);
      CaseSetup::warn_about_accuracy(*this);
    }
  } // namespace Parameters
} // namespace viscoslide

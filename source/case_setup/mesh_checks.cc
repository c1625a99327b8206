// SPDX-License-Identifier: LGPL-2.1-or-later
// What the mesh can represent: the block's aspect ratio, the refinement's
// depth, the contact within the block.
#include <viscoslide/case_setup.h>
#include <viscoslide/case_setup/common.h>
#include <viscoslide/io/input.h>
#include <viscoslide/physics/indenter.h>

#include <algorithm>
#include <cmath>
#include <limits>

namespace viscoslide
{
  namespace CaseSetup
  {
    using namespace Parameters;
    using namespace internal;

    // Refuses, before a mesh is built, what the refinement cannot represent
    // and a block the contact does not fit in.
    void
    check_mesh_can_hold_case(const AllParameters &p)
    {
      // check_graded_grid judges a graded grid's case.
      if (graded_grid_only(p))
        return;
      const double      W = p.geometry.domain_width, H = p.geometry.height();
      const std::string block =
        "the block of " + num(W) + " x " + num(H) + " eps";
      require(std::max(W, H) / std::min(W, H) <= max_aspect_ratio,
              block + " ('Geometry/Domain width', '" +
                (p.geometry.substrate == Substrate::layer
                   ? "Geometry/Layer thickness"
                   : "Geometry/Domain height") +
                "') has an aspect ratio above 1e4; the mesh tiles it with "
                "squares of its smaller side");
      const double levels = std::log2(std::min(W, H) / p.mesh.finest_cell);
      require(levels <= max_refinement_levels,
              entry("Mesh", "Finest surface cell", p.mesh.finest_cell) +
                " is 2^" + num(std::ceil(levels)) +
                " times smaller than the coarse cells of " + block +
                "; at most 2^24 is allowed");
      require(p.mesh.finest_cell >= 1e-3,
              entry("Mesh", "Finest surface cell", p.mesh.finest_cell) +
                " is below 1e-3 eps, far finer than the interaction law "
                "needs (0.1 to 1 eps)");

      if (p.mesh.uniform_surface) // a periodic profile covers the surface
        return;
      // The indenter, pressed to its final depth, must not reach the
      // edges of the block within the range of the interaction.
      const auto profile =
        create_indenter(p.indenter, p.adhesion.R_over_eps, W);
      double       lowest = std::numeric_limits<double>::max();
      const double rim =
        std::min(profile->profile(-W / 2), profile->profile(W / 2));
      for (int i = 0; i <= 1000; ++i)
        lowest = std::min(lowest, profile->profile(-W / 2 + W * i / 1000.));
      const bool   force = p.loading.has_target_load();
      const double stiffest =
        std::max(1., 1. / p.material.E0_over_Einf); // plane-strain moduli
      double depth = std::max(p.loading.final_approach, 0.);
      if (force)
        depth =
          p.geometry.substrate == Substrate::half_plane
            ? std::pow(hertz_half_width(p.loading.target_load, stiffest, p),
                       2) /
                (p.geometry.dimension == 3 ? 1. : 2.) / p.adhesion.R_over_eps
            : 0.;
      require(
        rim - lowest >= depth + interaction_range,
        block + " is too narrow for the contact: its edges lie " +
          num(rim - lowest) +
          " eps above the lowest point of the indenter, which " +
          (force
             ? "'Loading/Target load' = " + num(p.loading.target_load) +
                 " presses about " + num(depth) + " eps deep (Hertz)"
             : entry("Loading", "Final approach", p.loading.final_approach) +
                 " presses in") +
          "; widen 'Geometry/Domain width'");
    }
  } // namespace CaseSetup
} // namespace viscoslide

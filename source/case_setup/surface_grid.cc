// SPDX-License-Identifier: LGPL-2.1-or-later
// The boundary elements' surface grid where the case leaves it to the
// program (doc/boundary_element.md, Nested grid).
#include <viscoslide/case_setup.h>
#include <viscoslide/case_setup/common.h>

#include <algorithm>
#include <cmath>
#include <iomanip>
#include <limits>
#include <sstream>

namespace viscoslide
{
  namespace CaseSetup
  {
    using namespace Parameters;
    using namespace internal;

    namespace
    {
      // The cells across the adhesive zone that the nested grid's band is
      // made to have: 7.2 (0.5-eps cells divided 5 x 5 at muT 3) bring the
      // sphere's curve within 0.4 % of the independent reference, 4.3 (3 x
      // 3) leave -0.86 % at V_hat 0.01, the undivided grid's 1.4 -7.1 %
      // (doc/boundary_element.md, Nested grid: scripts/bench_nested). The
      // uniform grid keeps the case where its own cells are as fine.
      constexpr double cells_across_zone = 7;
      constexpr long   finest_refinement = 15;
    } // namespace


    void
    choose_surface_grid(AllParameters &p)
    {
      auto        &b       = p.boundary_element;
      const double spacing = surface_grid_spacing(p);
      const double across =
        p.adhesion.adhesive() && p.adhesion.tabor_parameter > 0
          ? adhesive_zone(p) / spacing
          : std::numeric_limits<double>::infinity();
      const bool isolated = p.geometry.dimension == 3 &&
                            p.geometry.substrate == Substrate::half_plane &&
                            p.sliding.solver == SlidingSolver::boundary_element;
      if (b.grid == GridKind::automatic)
        {
          b.grid = isolated && across < cells_across_zone ? GridKind::nested
                                                          : GridKind::uniform;
          if (b.grid == GridKind::nested)
            {
              std::ostringstream note;
              note << std::setprecision(3)
                   << "Note: 'Boundary element/Grid' = automatic: the nested "
                   << "grid, since the uniform one's " << spacing
                   << "-eps cells would put " << across
                   << " across the adhesive zone at the contact's edge "
                   << "(about " << adhesive_zone(p)
                   << " eps); 'Boundary element/Grid' = uniform for "
                   << "the uniform grid";
              p.notes.push_back(note.str());
            }
        }
      if (b.grid == GridKind::nested && b.refinement == 0)
        {
          // The least odd refinement that gives the band its cells across
          // the zone.
          long r = static_cast<long>(std::ceil(cells_across_zone / across));
          r      = std::clamp(r + (r % 2 == 0 ? 1 : 0), 3L, finest_refinement);
          b.refinement = static_cast<unsigned int>(r);
          std::ostringstream note;
          note << std::setprecision(3)
               << "Note: 'Boundary element/Refinement' = 0: the nested "
               << "grid's band cells divided " << r << " x " << r;
          if (std::isfinite(across))
            note << ", " << r * across << " fine cells across the adhesive "
                 << "zone";
          p.notes.push_back(note.str());
        }
    }
  } // namespace CaseSetup
} // namespace viscoslide

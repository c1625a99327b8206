// SPDX-License-Identifier: LGPL-2.1-or-later
#include <viscoslide/boundary_element/grid.h>

#include <algorithm>
#include <cmath>
#include <limits>

namespace viscoslide
{
  namespace Parameters
  {
    void
    BoundaryElement::declare(ParameterHandler &prm)
    {
      prm.enter_subsection("Boundary element");
      prm.declare_entry(
        "Grid",
        "automatic",
        Patterns::Selection(choice_pattern<GridKind>()),
        "The surface grid of Sliding/Solver = boundary-element. uniform: "
        "points at Grid spacing over a period (Period); graded (plane "
        "strain on the half-plane under a Loading/Target load): an "
        "isolated contact whose cells are Grid spacing wide at the two "
        "contact edges and grow by Grading ratio away from them, over "
        "the contact and half its width beyond each edge, the wake behind "
        "it in the compliance; the grid follows the edges as they move. "
        "It reaches contacts 1e5 eps wide (R_hat 1e7) at a few thousand "
        "points (doc/boundary_element.md, Graded grid). nested (3D, "
        "half-space): the isolated window of Grid spacing whose cells "
        "along the contact edge are divided Refinement x Refinement, "
        "remade as the edge moves (doc/boundary_element.md, Nested "
        "grid). automatic: nested on the 3D half-space where the uniform "
        "grid would put fewer cells across the adhesive zone than the "
        "nested grid's band is made to (7), uniform elsewhere; the choice "
        "is said when the case starts.");
      prm.declare_entry("Grid spacing",
                        "0",
                        Patterns::Double(),
                        "Spacing (in eps) of the uniform surface grid, or "
                        "the graded grid's cells at the contact edges. 0: "
                        "half the Mesh/Finest surface cell, the node "
                        "spacing of the finite elements' quadratic surface "
                        "cells there.");
      prm.declare_entry("Grading ratio",
                        "1.05",
                        Patterns::Double(),
                        "Width ratio of neighbouring cells of Grid = "
                        "graded (> 1, at most 1.5).");
      prm.declare_entry(
        "Period",
        "0",
        Patterns::Double(),
        "Length (in eps) of the periodic cell of the boundary-element "
        "solver: one indenter per period. 0: automatic, the larger of "
        "Geometry/Domain width and Wake periods x V tau_c at each speed "
        "(tau_c the longest retardation time), so that the wake has "
        "relaxed before it reaches the next indenter.");
      prm.declare_entry("Wake periods",
                        "20",
                        Patterns::Double(),
                        "See Period.");
      prm.declare_entry("Refinement",
                        "0",
                        Patterns::Integer(),
                        "Grid = nested: each cell of the band along the "
                        "contact edge divided into Refinement x Refinement "
                        "cells (odd, 3 to 15). 0: automatic, the least "
                        "that puts 7 cells across the adhesive zone (at "
                        "most 15).");
      prm.declare_entry("Band width",
                        "0.5",
                        Patterns::Double(),
                        "Grid = nested: how far (in eps) the refined band "
                        "reaches beyond the cells of the adhesive zone "
                        "(the attraction above half its peak) and "
                        "of the contact's edge.");
      prm.leave_subsection();
    }

    void
    BoundaryElement::parse(ParameterHandler &prm)
    {
      prm.enter_subsection("Boundary element");
      grid = parse_choice<GridKind>(prm.get("Grid"), "'Boundary element/Grid'");
      grid_spacing  = prm.get_double("Grid spacing");
      grading_ratio = prm.get_double("Grading ratio");
      period        = prm.get_double("Period");
      wake_periods  = prm.get_double("Wake periods");
      const long r  = prm.get_integer("Refinement");
      band_width    = prm.get_double("Band width");
      prm.leave_subsection();
      require(r == 0 || (r >= 3 && r <= 15 && r % 2 == 1),
              entry("Boundary element", "Refinement", r) +
                " must be odd, from 3 to 15 (or 0: automatic)");
      refinement = r;
      require(band_width >= 0 && std::isfinite(band_width),
              entry("Boundary element", "Band width", band_width) +
                " must not be negative");
      require(grid_spacing >= 0 && std::isfinite(grid_spacing),
              entry("Boundary element", "Grid spacing", grid_spacing) +
                " must not be negative");
      require(grading_ratio > 1 && grading_ratio <= 1.5,
              entry("Boundary element", "Grading ratio", grading_ratio) +
                " must be above 1 and at most 1.5");
      require(period >= 0 && std::isfinite(period),
              entry("Boundary element", "Period", period) +
                " must not be negative");
      require(wake_periods > 0 && std::isfinite(wake_periods),
              entry("Boundary element", "Wake periods", wake_periods) +
                " must be positive");
    }
  } // namespace Parameters


  namespace
  {
    // Boundaries from `edge` towards `end` (either side), the first cell
    // `finest`, then growing by `ratio` up to `coarsest`; the last cell
    // ends at `end`, merged with the one before if it would be under half
    // of it. Excludes `edge` itself.
    std::vector<double>
    march(const double edge,
          const double end,
          const double finest,
          const double ratio,
          const double coarsest)
    {
      const double        direction = end > edge ? 1. : -1.;
      const double        length    = std::abs(end - edge);
      std::vector<double> s;
      double              at = 0, width = finest;
      while (at + 1.5 * width < length)
        {
          at += width;
          s.push_back(edge + direction * at);
          width = std::min(width * ratio, coarsest);
        }
      s.push_back(end);
      return s;
    }
  } // namespace


  std::vector<double>
  graded_boundaries(const double trail,
                    const double lead,
                    const double finest,
                    const double ratio,
                    const double margin)
  {
    const double        coarsest = std::max(finest, (lead - trail) / 200);
    const double        middle   = 0.5 * (trail + lead);
    std::vector<double> s =
      march(trail, trail - margin, finest, ratio, coarsest);
    std::reverse(s.begin(), s.end());
    s.push_back(trail);
    if (lead - trail > 2 * finest)
      {
        // From each edge to the middle; the two halves meet there.
        const std::vector<double> left =
          march(trail, middle, finest, ratio, coarsest);
        std::vector<double> right =
          march(lead, middle, finest, ratio, coarsest);
        s.insert(s.end(), left.begin(), left.end());
        right.pop_back(); // the middle, already there
        std::reverse(right.begin(), right.end());
        s.insert(s.end(), right.begin(), right.end());
        s.push_back(lead);
      }
    else if (lead > trail)
      s.push_back(lead);
    const std::vector<double> beyond =
      march(lead, lead + margin, finest, ratio, coarsest);
    s.insert(s.end(), beyond.begin(), beyond.end());
    return s;
  }


  std::function<double(double)>
  edge_shift(const std::pair<double, double> &edges,
             const double                     d_trail,
             const double                     d_lead)
  {
    const auto [trail, lead] = edges;
    const double from        = trail + (lead - trail) / 4,
                 to          = lead - (lead - trail) / 4;
    return [=](const double x) {
      return x <= from ? d_trail
             : x >= to
               ? d_lead
               : d_trail + (x - from) / (to - from) * (d_lead - d_trail);
    };
  }


  double
  cylinder_jkr_half_width(const double P, const double dgamma, const double R)
  {
    const auto load = [&](const double a) {
      return M_PI * a * a / (4 * R) - std::sqrt(2 * M_PI * dgamma * a);
    };
    double lo = std::pow(R * std::sqrt(2 * M_PI * dgamma) / M_PI, 2. / 3.);
    if (P < load(lo))
      return std::numeric_limits<double>::quiet_NaN();
    double hi = 2 * lo;
    while (load(hi) < P)
      hi *= 2;
    for (unsigned int k = 0; k < 200; ++k)
      {
        const double mid          = 0.5 * (lo + hi);
        (load(mid) < P ? lo : hi) = mid;
      }
    return 0.5 * (lo + hi);
  }


  double
  sphere_jkr_radius(const double P,
                    const double dgamma,
                    const double R,
                    const double E)
  {
    const double J    = 3 * M_PI * dgamma * R;
    const double root = 2 * J * P + J * J;
    if (root < 0)
      return std::numeric_limits<double>::quiet_NaN();
    return std::cbrt(3 * R / (4 * E) * (P + J + std::sqrt(root)));
  }
} // namespace viscoslide

// SPDX-License-Identifier: LGPL-2.1-or-later
// The memory a case needs against the machines': the 3D finite elements'
// linear solver chosen and refused by it, the boundary elements' plane
// and graded grids.
#include <viscoslide/boundary_element/grid.h>
#include <viscoslide/case_setup.h>
#include <viscoslide/case_setup/common.h>
#include <viscoslide/numerics/mesh.h>
#include <viscoslide/physics/scales.h>

#include <unistd.h>

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <iomanip>
#include <sstream>

namespace viscoslide
{
  namespace CaseSetup
  {
    using namespace Parameters;
    using namespace internal;

    namespace
    {
      // Peak memory per unknown of the 3D finite elements, in GB, summed over
      // two processes, measured on the sphere of tests/sphere_fem_hertz.prm
      // (scripts/bench_fem3d, doc/benchmark.md). The direct solver's
      // factors grow faster than the unknowns (as n^(4/3) for nested
      // dissection in 3D): 24.2, 24.5 and 38.2 kB per unknown at 128 004,
      // 266 304 and 501 390 unknowns, the fit through the first and the
      // last. The iterative solver's matrices, multigrid hierarchy and
      // Krylov vectors: 17.8 kB per unknown at 266 304. With its
      // displacement block factorized it takes the direct solver's figure:
      // 22.7 and 36.3 kB per unknown at 66 771 and 271 347 unknowns, where
      // it measured 23.2 and 26.4 (displacement control, no load) and the
      // direct solver 29.4 and 40.3.
      constexpr double direct_gb_per_unknown_at_1e5 = 26e-6;
      double
      direct_gb_per_unknown(const double unknowns)
      {
        return direct_gb_per_unknown_at_1e5 * std::cbrt(unknowns / 1e5);
      }
      constexpr double iterative_gb_per_unknown = 19e-6;

      // The most unknowns whose direct factorization fits in `gigabytes`:
      // n direct_gb_per_unknown(n) = gigabytes, solved for n.
      double
      most_unknowns_factorized(const double gigabytes)
      {
        return std::pow(gigabytes / direct_gb_per_unknown_at_1e5 *
                          std::cbrt(1e5),
                        0.75);
      }

      // Refused before anything is written, with the entries to change.
      void
      check_finite_elements_3d_fit(const AllParameters &p)
      {
        const FiniteElements3dSize size = finite_elements_3d_size(p);
        std::ostringstream         message;
        message << std::setprecision(3)
                << "the 3D finite elements about the relaxed contact of this "
                << "case (radius about " << size.radius << " eps) need "
                << (size.counted_all ? "about " : "more than ") << size.unknowns
                << " unknowns (" << size.cells << " cells) and, with "
                << linear_solver_name(size) << ", "
                << (size.counted_all ? "about " : "over ") << size.gigabytes
                << " GB; the machines of this run have " << size.available
                << " GB: raise 'Mesh/Finest surface cell' or 'Mesh/Mesh "
                   "grading'"
                << (size.direct ? ", or set 'Solver/Linear solver' = iterative"
                    : size.factorized
                      ? ", or set 'Solver/Displacement block' = multigrid" +
                          std::string(size.factorized_at_speed
                                        ? " (whose V-cycle may not converge "
                                          "at the fast speeds)"
                                        : "")
                      : "")
                << wake_advice(p) << " (doc/steady_state.md, Memory)";
        require(size.gigabytes <= 0.8 * size.available, message.str());
      }
    } // namespace


    namespace internal
    {
      // This machine's physical memory, in GB.
      double
      this_machine_memory_gb()
      {
        return double(sysconf(_SC_PHYS_PAGES)) *
               double(sysconf(_SC_PAGE_SIZE)) / 1e9;
      }

      double
      plane_grid_memory_limit_gb()
      {
        return 0.8 * this_machine_memory_gb();
      }

      // The memory of the machines this run has, in GB: this machine's times
      // the nodes the processes are spread over, read from the environment
      // of Open MPI's mpirun or of Slurm (so that no collective call is
      // needed here); one node where neither says.
      double
      machine_memory_gb()
      {
        const double one    = this_machine_memory_gb();
        const auto   number = [](const char *name) {
          const char *value = std::getenv(name);
          return value == nullptr ? 0 : std::atoi(value);
        };
        const int size  = number("OMPI_COMM_WORLD_SIZE"),
                  local = number("OMPI_COMM_WORLD_LOCAL_SIZE");
        if (size > 0 && local > 0)
          return one * std::ceil(double(size) / local);
        return one * std::max(1, number("SLURM_JOB_NUM_NODES"));
      }


      // The processes of this run on this node (Open MPI's mpirun says; one
      // where it does not): each holds the whole boundary-element problem.
      double
      processes_on_this_node()
      {
        const char *value = std::getenv("OMPI_COMM_WORLD_LOCAL_SIZE");
        return value == nullptr ? 1. : std::max(1, std::atoi(value));
      }

      // " in its N processes, ..." where there are several.
      std::string
      held_by_each(const double processes)
      {
        return processes > 1 ? " in its " + std::to_string(int(processes)) +
                                 " processes, each holding the whole grid"
                             : "";
      }


      FiniteElements3dSize
      finite_elements_3d_size(const AllParameters &p)
      {
        const Scales         s(p);
        const double         E = std::min(1., 1. / p.material.E0_over_Einf);
        FiniteElements3dSize size;
        double              &a = size.radius;
        if (p.loading.has_target_load())
          {
            a = sphere_jkr_radius(std::max(p.loading.target_load, 0.) * s.force,
                                  p.adhesion.adhesive() ? s.dgamma : 0.,
                                  s.R,
                                  E);
          }
        else
          a = std::sqrt(s.R * std::max(p.loading.final_approach, 0.) * s.eps);
        // The edge band reaches to the gap Edge gap upper (the rigid
        // profile's gap, which the surface's sinking only widens).
        const double outer =
          std::sqrt(a * a + 2 * s.R * p.mesh.edge_gap_high * s.eps);
        size.available = machine_memory_gb();
        // Per cell: the Q2 displacement (8 nodes' 3 components on a large
        // mesh) and 6 viscous-strain components per arm of degree k.
        const double k = p.sliding.viscous_strain_degree,
                     per_cell =
                       24 + 6. * make_solid(p, s).n_arms() * std::pow(k + 1, 3);
        // No need to count beyond what would not fit with either solver.
        const double most_cells =
          2 * size.available / iterative_gb_per_unknown / per_cell;
        size.cells       = estimated_cells_about_ring(p, a, outer, most_cells);
        size.counted_all = size.cells <= most_cells;
        size.unknowns    = size.cells * per_cell;
        size.direct      = p.solver.direct_for(size.unknowns);
        // The iterative solver factorizes A~ at its fastest speed if at any.
        const double fastest =
          *std::max_element(p.sliding.speeds.begin(), p.sliding.speeds.end());
        const double cells_per_speed =
          make_solid(p, s).longest_relaxation_time() / s.tau_ref /
          p.mesh.finest_cell;
        size.factorized =
          size.direct || p.solver.factorizes(fastest * cells_per_speed);
        size.factorized_at_speed =
          size.factorized && !size.direct && !p.solver.factorizes(0.);
        size.gigabytes = size.unknowns *
                         (size.factorized ? direct_gb_per_unknown(size.unknowns)
                                          : iterative_gb_per_unknown);
        return size;
      }

      std::string
      linear_solver_name(const FiniteElements3dSize &size)
      {
        return size.direct ? "the direct linear solver"
               : size.factorized
                 ? "the iterative linear solver with A~ factorized" +
                     std::string(size.factorized_at_speed ? " at speed" : "")
                 : "the iterative linear solver";
      }


      // The points the nested grid's band adds at least (r^2 - 1 per band
      // cell): a ring of cells about the JKR contact of the relaxed solid
      // at the Target load, as wide as the Band width on either side of
      // one cell with one cell to spare on each (nested_grid.cc); the band
      // the solution asks for is wider where the adhesive zone is (the
      // nested grid checks each band it makes).
      double
      nested_band_points(const AllParameters &p, const double spacing)
      {
        if (p.boundary_element.grid != GridKind::nested ||
            !p.loading.has_target_load())
          return 0;
        const Scales s(p);
        const double a =
          sphere_jkr_radius(p.loading.target_load * s.force, s.dgamma, s.R) /
          s.eps;
        if (!std::isfinite(a))
          return 0;
        const double across =
          3 + 2 * std::ceil(p.boundary_element.band_width / spacing);
        const unsigned int r = p.boundary_element.refinement;
        return 2 * M_PI * a / spacing * across * (r * r - 1.);
      }


      // A plane grid of the boundary elements must fit in memory at the
      // fastest speed (whose wake sets the period along x): refused before
      // anything is written, with the entries to change.
      void
      check_plane_grid_fits(const AllParameters &p,
                            const double         spacing,
                            const double         width)
      {
        // The isolated half-space's window is the Domain width square; a
        // periodic layer's period along x grows with the wake.
        const double length =
          p.geometry.substrate == Substrate::half_plane ? width
          : p.boundary_element.period > 0
            ? p.boundary_element.period
            : std::max(width,
                       p.boundary_element.wake_periods * fastest_wake(p));
        const double points =
          (length / spacing) * (p.geometry.length() / spacing) +
          nested_band_points(p, spacing);
        const double processes = processes_on_this_node();
        const double gigabytes =
          processes * plane_grid_bytes_per_point * points / 1e9;
        const double       max_grid_gigabytes = plane_grid_memory_limit_gb();
        std::ostringstream message;
        message << "the 3D boundary-element grid of " << points << " points ("
                << length << " x " << p.geometry.length() << " eps at "
                << "spacing " << spacing << " eps"
                << (p.boundary_element.grid == GridKind::nested
                      ? ", with its band about the contact's edge"
                      : "")
                << ") needs about " << gigabytes << " GB"
                << held_by_each(processes) << ", this machine has "
                << this_machine_memory_gb()
                << " GB: raise 'Boundary element/Grid spacing' or lower "
                << (p.geometry.substrate == Substrate::half_plane
                      ? "'Geometry/Domain width' or 'Geometry/Domain length'"
                      : "'Geometry/Domain width', 'Geometry/Domain length', "
                        "'Boundary element/Period' or 'Boundary "
                        "element/Wake periods'")
                << (p.boundary_element.grid == GridKind::nested
                      ? ", 'Boundary element/Refinement' or 'Boundary "
                        "element/Band width'"
                      : "");
        require(gigabytes <= max_grid_gigabytes, message.str());
      }


      // The graded grid of the boundary elements (plane strain, half-plane)
      // starts from the JKR contact at the Target load; its dense
      // compliance takes about 4 n^2 numbers, n the cells of the grid about
      // that contact: refused before anything is written if that will not
      // fit in memory.
      void
      check_graded_grid(const AllParameters &p, const double spacing)
      {
        const std::string what = "'Boundary element/Grid' = graded";
        require(p.geometry.dimension == 2,
                what + " is plane strain: set 'Geometry/Dimension' = 2");
        require(p.geometry.substrate == Substrate::half_plane,
                what + " needs 'Geometry/Substrate' = half-plane (its "
                       "compliance is the isolated half-plane's)");
        require(p.loading.has_target_load() && !p.loading.retract,
                what + " needs a 'Loading/Target load' and no retraction: "
                       "it starts from the JKR contact at that load");
        // Internal units (eps = E0* = 1), as the solver's.
        const Scales s(p);
        const double a =
          cylinder_jkr_half_width(p.loading.target_load * s.force,
                                  s.dgamma,
                                  s.R);
        require(std::isfinite(a),
                entry("Loading", "Target load", p.loading.target_load) +
                  " is below the JKR pull-off force of the relaxed contact, "
                  "from which " +
                  what + " starts");
        const double cells = graded_boundaries(-a,
                                               a,
                                               spacing,
                                               p.boundary_element.grading_ratio,
                                               std::max(a, 50.))
                               .size() -
                             1;
        const double processes = processes_on_this_node();
        const double gigabytes = processes * 4. * 8. * cells * cells / 1e9;
        const double available = this_machine_memory_gb();
        std::ostringstream message;
        message << what << " about the JKR contact (" << 2 * a
                << " eps wide) has about " << cells << " cells, whose dense "
                << "compliance needs about " << gigabytes << " GB"
                << held_by_each(processes) << "; this machine has " << available
                << " GB: raise 'Boundary element/Grid spacing' or 'Boundary "
                   "element/Grading ratio'";
        require(gigabytes <= 0.8 * available, message.str());
      }
    } // namespace internal


    void
    fit_linear_solver_to_memory(AllParameters &p)
    {
      if (p.geometry.dimension != 3 || boundary_elements_only(p))
        return;
      if (p.solver.linear_solver == LinearSolver::automatic)
        {
          // The direct solver only while its factors fit, at every solve
          // of the run (Solver::direct_for); say so where this case needs
          // the iterative one for it.
          const FiniteElements3dSize before = finite_elements_3d_size(p);
          const double most = most_unknowns_factorized(0.8 * before.available);
          p.solver.direct_solver_limit = static_cast<unsigned int>(
            std::min<double>(p.solver.direct_solver_limit, most));
          if (before.direct && !p.solver.direct_for(before.unknowns))
            {
              std::ostringstream note;
              note << std::setprecision(3)
                   << "Note: 'Solver/Linear solver' = automatic takes the "
                   << "iterative linear solver for this case: the direct "
                   << "one's factors would need about " << before.gigabytes
                   << " GB of the " << before.available
                   << " GB, and fit up to about " << most << " unknowns";
              p.notes.push_back(note.str());
            }
        }
      check_finite_elements_3d_fit(p);
    }
  } // namespace CaseSetup
} // namespace viscoslide

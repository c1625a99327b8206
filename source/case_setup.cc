// SPDX-License-Identifier: LGPL-2.1-or-later
#include <viscoslide/boundary_element/grid.h>
#include <viscoslide/case_setup.h>
#include <viscoslide/indenter.h>
#include <viscoslide/parameters.h>
#include <viscoslide/scales.h>

#include <unistd.h>

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <initializer_list>
#include <iomanip>
#include <limits>
#include <sstream>

namespace viscoslide
{
  namespace CaseSetup
  {

    using namespace Parameters;

    namespace
    {
      // The finest cell p4est can make from the coarse cells is 2^-30 of
      // theirs; the refinement stays well below that.
      constexpr double max_refinement_levels = 24;
      // make_block() tiles the block with squares of its smaller side.
      constexpr double max_aspect_ratio = 1e4;
      // Beyond this distance (in eps) the interaction laws are negligible.
      constexpr double interaction_range = 5;

      // The half-width of the elastic (Hertz) line contact of a cylinder of
      // radius R under F_hat, with plane-strain modulus E_star.
      double
      hertz_half_width(const double         F_hat,
                       const double         E_star,
                       const AllParameters &p)
      {
        // Plane strain: F = pi E* a^2/(4R); the sphere: F = 4 E* a^3/(3R).
        const Scales s(p);
        const double F = std::max(F_hat, 0.) * s.force;
        return p.geometry.dimension == 3
                 ? std::cbrt(3. * F * s.R / (4. * E_star))
                 : std::sqrt(4. * F * s.R / (M_PI * E_star));
      }

      // Whether every case runs one of `solvers`: the solver, and every one
      // a sweep lists.
      bool
      runs_only(const AllParameters                       &p,
                const std::initializer_list<SlidingSolver> solvers)
      {
        const auto listed = [&](const SlidingSolver s) {
          return std::find(solvers.begin(), solvers.end(), s) != solvers.end();
        };
        return listed(p.sliding.solver) && std::all_of(p.sweep.solvers.begin(),
                                                       p.sweep.solvers.end(),
                                                       listed);
      }

      bool
      boundary_elements_only(const AllParameters &p)
      {
        return runs_only(p, {SlidingSolver::boundary_element});
      }

      // Whether every case runs on the boundary elements' graded grid,
      // which builds neither a block nor a mesh.
      bool
      graded_grid_only(const AllParameters &p)
      {
        return p.boundary_element.grid == GridKind::graded &&
               boundary_elements_only(p);
      }

      // The wake V tau_c of the fastest listed speed, in eps (0 without
      // speeds).
      double
      fastest_wake(const AllParameters &p)
      {
        const auto &V = p.sliding.speeds;
        return V.empty() ? 0.
                         : *std::max_element(V.begin(), V.end()) *
                             longest_creep_time(p);
      }

      // The listed speeds (comma-separated; empty if none) at which the
      // relaxation length V tau is shorter than `length`; tau in units of
      // tau_ref, lengths in eps.
      std::string
      speeds_relaxing_within(const AllParameters &p,
                             const double         tau,
                             const double         length)
      {
        std::ostringstream speeds;
        for (const double V_hat : p.sliding.speeds)
          if (V_hat > 0 && V_hat * tau < length)
            speeds << (speeds.tellp() > 0 ? ", " : "") << V_hat;
        return speeds.str();
      }

      // The transient's step: an adhesive edge that snaps within one step
      // dissipates at the step's rate, not the material's. At V_hat 0.01
      // (R_hat 400, muT 6.08, 0.25-eps cells) steps of 1.25, 6 and 25
      // relaxation lengths V tau put mu +0.4 %, -1.1 % and -8.5 % from the
      // steady-state solver's (doc/steady_state.md, Cross-validation
      // table). tau is the slowest arm's, in units of tau_ref.
      void
      warn_coarse_sliding_step(AllParameters &p, const double tau)
      {
        if (p.sliding.solver != SlidingSolver::transient ||
            !p.adhesion.adhesive())
          return;
        const double      step   = p.sliding.increment * p.mesh.finest_cell;
        const std::string coarse = speeds_relaxing_within(p, tau, step / 2.);
        if (!coarse.empty())
          p.notes.push_back(
            "Warning: at V_hat = " + coarse +
            " the sliding step ('Sliding/Sliding increment' x 'Mesh/Finest "
            "surface cell' = " +
            num(step) +
            " eps) is longer than two relaxation lengths V tau of the "
            "slowest arm: an adhesive edge that snaps within one step "
            "dissipates at the step's rate, and the friction comes out a "
            "few percent off (-1 % at 6 V tau, -8 % at 25 V tau); a "
            "Sliding increment of about V tau / Finest surface cell "
            "resolves it");
      }

      // This machine's physical memory, in GB.
      double
      this_machine_memory_gb()
      {
        return double(sysconf(_SC_PHYS_PAGES)) *
               double(sysconf(_SC_PAGE_SIZE)) / 1e9;
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

      // The size of the 3D finite elements with the mesh about the largest
      // contact of the case, the relaxed one at the Target load (JKR's with
      // an adhesive law, Hertz's without; under displacement control Hertz's
      // at the Final approach): its cells counted before anything is built,
      // the unknowns per cell of the elements, and the memory per unknown
      // measured for each linear solver (scripts/bench_fem3d,
      // doc/benchmark.md).
      struct FiniteElements3dSize
      {
        double radius, cells, unknowns, gigabytes, available;
        bool   direct;
        bool   factorized; // the direct solver, or the iterative one with A~
                           // factorized
        bool factorized_at_speed; // ... only where V tau_k is long
        bool counted_all;         // false: the count stopped, there are more
      };

      FiniteElements3dSize
      finite_elements_3d_size(const AllParameters &p)
      {
        const Scales         s(p);
        const double         E = std::min(1., 1. / p.material.E0_over_Einf);
        FiniteElements3dSize size;
        double              &a = size.radius;
        if (p.loading.has_target_load())
          {
            const double F = std::max(p.loading.target_load, 0.) * s.force,
                         J = p.adhesion.adhesive() ? 3 * M_PI * s.dgamma * s.R
                                                   : 0.;
            a              = std::cbrt(3 * s.R / (4 * E) *
                          (F + J + std::sqrt(2 * J * F + J * J)));
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


      // Where the block is as long as the fastest speed's wake asks (it was
      // lengthened for it), the entries that shorten it.
      std::string
      wake_advice(const AllParameters &p)
      {
        if (p.sliding.speeds.empty() ||
            std::abs(p.geometry.domain_width -
                     p.geometry.wake_lengths * fastest_wake(p)) >
              1e-12 * p.geometry.domain_width)
          return "";
        std::ostringstream advice;
        advice << std::setprecision(3) << "; the block is "
               << p.geometry.domain_width
               << " eps long to hold the wake of the fastest speed: lower "
                  "the fastest 'Sliding/Sliding speed' or 'Geometry/Wake "
                  "lengths'";
        return advice.str();
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


    namespace
    {
      // The 3D finite elements' block lengthened along the track (x) to
      // Wake lengths wakes of the fastest speed, its depth and its extent
      // across the track kept: fields decay as 1/r in 3D, and four wakes
      // put the friction at V_hat 10 and 100 within 1.3 and 0.5 % of the
      // boundary elements' where the cube of 200 eps (2 and 0.2 wakes)
      // was 3 and 15 % off, its dissipation at V_hat 10 56 % high
      // (doc/steady_state.md, The block).
      void
      fit_3d_block_to_wake(AllParameters &p)
      {
        if (p.sliding.solver != SlidingSolver::steady_state ||
            p.sliding.speeds.empty() || p.mesh.uniform_surface)
          return;
        const double wake = fastest_wake(p), W0 = p.geometry.domain_width,
                     L = p.geometry.length(), H = p.geometry.height(),
                     width = p.geometry.wake_lengths * wake;
        if (W0 >= width)
          return;
        std::ostringstream note;
        const std::string  asked =
          entry("Geometry", "Wake lengths", p.geometry.wake_lengths);
        if (p.sliding.control == Control::force ||
            p.geometry.substrate == Substrate::layer)
          {
            p.geometry.domain_length = L;
            if (p.geometry.substrate == Substrate::half_plane)
              p.geometry.domain_height = H;
            p.geometry.domain_width = width;
            note << "the wake, V tau_c = " << wake
                 << " eps at the fastest speed, needs a longer block: " << W0
                 << " x " << L << " x " << H << " eps lengthened along the "
                 << "track to " << width << " (" << asked << ")";
          }
        else
          note << "Warning: the wake, V tau_c = " << wake
               << " eps at the fastest speed, does not fit the 3D block " << W0
               << " eps long, " << asked << " asks for " << width
               << " eps; with this control the block stays as given, and the "
               << "friction at the fastest speeds will be off (15 % high at "
               << "V_hat 100 on a block of 0.2 wakes)";
        p.notes.push_back(note.str());
      }
    } // namespace


    // Measured on Fig. 3 (muT 6.08, R_hat 1e4, F_hat 1) at V_hat 1000,
    // against the boundary elements: a block of 2 x 0.4 wake lengths gives
    // a friction 10 % low, 8 x 2 wake lengths 2 % low, 20 x 5 wake lengths
    // (the default) 0.5 % low (doc/model.md, Block and wake).
    void
    fit_block_to_wake(AllParameters &p)
    {
      if (p.geometry.dimension == 3)
        return fit_3d_block_to_wake(p);
      // A uniform surface would grow with the block; the graded grid has
      // none (its wake is in closed form, the Domain height only the
      // reference of delta).
      if (graded_grid_only(p) || p.sliding.solver == SlidingSolver::transient ||
          p.geometry.wake_lengths == 0 || p.sliding.speeds.empty() ||
          p.mesh.uniform_surface)
        return;
      const double V =
        *std::max_element(p.sliding.speeds.begin(), p.sliding.speeds.end());
      const double wake  = fastest_wake(p);
      const double width = p.geometry.wake_lengths * wake, depth = width / 4;
      const bool   layer = p.geometry.substrate == Substrate::layer;
      const bool   force = p.sliding.control == Control::force;
      const bool   fem   = p.sliding.solver == SlidingSolver::steady_state;
      const double W0 = p.geometry.domain_width, H0 = p.geometry.height();
      // A thin layer keeps to the aspect ratio the mesh can tile.
      if (fem && (force || layer))
        p.geometry.domain_width =
          std::max(W0, std::min(width, max_aspect_ratio * H0));
      if (force && !layer)
        p.geometry.domain_height = std::max(H0, depth);

      std::ostringstream note;
      if (p.geometry.domain_width != W0 || p.geometry.height() != H0)
        note << "the wake, V tau_c = " << wake << " eps at V_hat " << V
             << ", needs a larger block: " << W0 << " x " << H0
             << " eps widened to " << p.geometry.domain_width << " x "
             << p.geometry.height()
             << " ('Geometry/Wake lengths' = " << p.geometry.wake_lengths << ")"
             << (fem && p.geometry.domain_width < width
                   ? "; not to the " + num(width) +
                       " eps asked, the mesh tiles at most 1e4 layer "
                       "thicknesses: the friction at the fastest speeds may be "
                       "low"
                   : "");
      else if (fem && (W0 < width || (!layer && H0 < depth)))
        note << "Warning: the wake, V tau_c = " << wake << " eps at V_hat " << V
             << ", does not fit the block of " << W0 << " x " << H0
             << " eps ('Geometry/Wake lengths' = " << p.geometry.wake_lengths
             << " asks for " << width << " x " << depth
             << "); with this control the block stays as given, and the "
                "friction at the fastest speeds will be low";
      else
        return;
      p.notes.push_back(note.str());
    }



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


    // Legal but known to be inaccurate: said when the case starts.
    void
    warn_about_accuracy(AllParameters &p)
    {
      if (p.geometry.dimension == 3 && !boundary_elements_only(p))
        {
          const FiniteElements3dSize size = finite_elements_3d_size(p);
          std::ostringstream         note;
          note << std::setprecision(3)
               << "Note: the 3D finite elements about the relaxed contact "
               << "will have about " << size.unknowns << " unknowns and need "
               << "about " << size.gigabytes << " GB with "
               << linear_solver_name(size) << ", of " << size.available
               << " GB (an estimate before the mesh is built: "
               << "doc/steady_state.md, Memory)";
          p.notes.push_back(note.str());
          p.notes.push_back(
            "Warning: the 3D finite elements are verified on coarse meshes "
            "only (doc/steady_state.md, In three dimensions): on 4-eps "
            "cells their friction is within 3.4 % of the boundary "
            "elements' at V_hat 0.01 to 100 without adhesion, within 7.5 % "
            "at Tabor parameter 1 (V_hat 0.01 to 1000, low; the error "
            "halves with the cells at the contact's edge). Use "
            "'Sliding/Solver' = boundary-element for the friction, and "
            "refine 'Mesh/Finest surface cell' and 'Mesh/Mesh grading' to "
            "see whether a case is converged");
        }
      // The cohesive zone of a crack under the law's peak stress: about
      // (pi/8) E* dgamma / sigma_max^2, on the softer modulus.
      const Scales s(p);
      const double softest = std::min(1., 1. / p.material.E0_over_Einf);
      const double zone =
        M_PI / 8 * softest * s.dgamma / std::pow(s.sigma_max, 2);
      // The boundary elements resolve the zone with their grid spacing.
      const bool boundary_elements =
        p.sliding.solver == SlidingSolver::boundary_element;
      const double cell = !boundary_elements ? p.mesh.finest_cell
                          : p.boundary_element.grid_spacing > 0
                            ? p.boundary_element.grid_spacing
                            : p.mesh.finest_cell / 2;
      if (p.adhesion.adhesive() && p.adhesion.tabor_parameter > 0 &&
          cell > zone / 2)
        {
          std::ostringstream note;
          note << "Warning: "
               << (boundary_elements ? "'Boundary element/Grid spacing' = "
                                     : "'Mesh/Finest surface cell' = ")
               << cell << " eps is coarser than half the adhesive zone (about "
               << zone << " eps); expect the contact edges and the friction "
               << "to be off by several percent";
          if (p.geometry.dimension == 2 &&
              p.boundary_element.grid != GridKind::graded)
            note << " (plane strain on a half-plane: 'Sliding/Solver' = "
                    "boundary-element with 'Boundary element/Grid' = graded "
                    "resolves the zone at any R over eps, doc/"
                    "boundary_element.md)";
          p.notes.push_back(note.str());
        }
      // With the contact edges among Newton's unknowns the graded grid
      // computed whole curves at muT 100 and 300 (R_hat 1e7) in one to
      // three minutes; at 1000 the first step in speed failed, at 2260
      // (R_hat 2e6) the start stalled (doc/boundary_element.md, Graded
      // grid).
      if (boundary_elements && p.boundary_element.grid == GridKind::graded &&
          p.adhesion.tabor_parameter > 300)
        p.notes.push_back(
          "Warning: 'Adhesion/Tabor parameter' = " +
          num(p.adhesion.tabor_parameter) +
          " is beyond what the graded grid has been seen to reach (300): "
          "at 1000 and more its start or its first step in speed did not "
          "converge; expect it to take minutes or to stop with a message "
          "that Newton's method did not converge (doc/boundary_element.md, "
          "Graded grid)");
      // The finite elements resolve the arms' relaxation over a cell at
      // best: where even the slowest arm relaxes within the finest cell,
      // the dissipation at the contact edges lies below the mesh (R_hat
      // 400, muT 6.08, 2-eps cells: the transient's energy balance -14 %
      // at V tau = h / 20 and -2.4 % at h / 2, -0.2 % at 5 h).
      if (p.sliding.solver != SlidingSolver::boundary_element &&
          p.geometry.dimension == 2)
        {
          const double tau =
            make_solid(p, s).longest_relaxation_time() / s.tau_ref;
          warn_coarse_sliding_step(p, tau);
          const std::string slow =
            speeds_relaxing_within(p, tau, p.mesh.finest_cell);
          if (!slow.empty())
            p.notes.push_back(
              "Warning: at V_hat = " + slow +
              " the relaxation length V tau of the slowest arm is shorter "
              "than 'Mesh/Finest surface cell' = " +
              num(p.mesh.finest_cell) +
              " eps: the arms relax inside one cell and the dissipation at "
              "the contact edges is not resolved; expect the friction to be "
              "off by up to tens of percent (the energy balance printed "
              "with each row says how far), or refine the finest cell to "
              "about V tau");
        }
      // The fields' dissipation map: its shares (near the surface, under
      // the contact) change by up to 3 % from grading 0.25 to 0.125 and by
      // 0.1 % beyond (doc/steady_state.md, Fields).
      if (p.output.write_fields &&
          p.sliding.solver == SlidingSolver::steady_state &&
          p.mesh.grading > 0.125 && p.geometry.dimension == 2)
        {
          std::ostringstream note;
          note << "Warning: 'Mesh/Mesh grading' = " << p.mesh.grading
               << " with 'Output/Write fields': the written dissipation "
               << "field is resolved to a few percent away from the contact "
               << "edges (the table's values are not affected); 0.125 "
               << "resolves it to 0.1 % at two to three times the cost";
          p.notes.push_back(note.str());
        }
      if (p.sliding.solver == SlidingSolver::transient && p.sliding.speed > 0)
        p.notes.push_back(
          "Note: 'Sliding/Solver' = transient slides the indenter until the "
          "contact is steady, typically thousands of eps in steps of the "
          "finest cell: minutes per speed at R_hat 400, 20 minutes to hours "
          "at R_hat 1e4 (doc/benchmark.md). For the steady friction alone, "
          "'Sliding/Solver' = steady-state solves it directly (about a "
          "minute for a curve of 21 speeds at muT 1, 2-eps cells)");
      if (!p.loading.has_target_load() || p.mesh.uniform_surface)
        return;
      const double width =
        2 * hertz_half_width(p.loading.target_load, softest, p);
      if (width > p.geometry.domain_width / 4)
        {
          std::ostringstream note;
          note << "Warning: the contact at 'Loading/Target load' = "
               << p.loading.target_load << " is about " << width
               << " eps wide (Hertz, relaxed modulus), more than a quarter of "
               << "'Geometry/Domain width' = " << p.geometry.domain_width
               << "; the block's edges will shift the results";
          p.notes.push_back(note.str());
        }
    }

    // A plane grid of the boundary elements must fit in memory at the
    // fastest speed (whose wake sets the period along x): refused before
    // anything is written, with the entries to change. The solver checks
    // each grid again against the memory it finds.
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
          : std::max(width, p.boundary_element.wake_periods * fastest_wake(p));
      const double points =
        (length / spacing) * (p.geometry.length() / spacing);
      // GMRES keeps up to 102 vectors of the grid, the rest about 40; four
      // fifths of this machine's memory may go to them.
      const double       gigabytes          = 150. * 8. * points / 1e9;
      const double       max_grid_gigabytes = 0.8 * this_machine_memory_gb();
      std::ostringstream message;
      message << "the 3D boundary-element grid of " << points << " points ("
              << length << " x " << p.geometry.length() << " eps at "
              << "spacing " << spacing << " eps) needs about " << gigabytes
              << " GB, this machine has " << max_grid_gigabytes / 0.8
              << " GB: raise 'Boundary element/Grid spacing' "
                 "or lower 'Geometry/Domain width', 'Geometry/Domain "
                 "length', 'Boundary element/Period' or 'Boundary "
                 "element/Wake periods'";
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
        cylinder_jkr_half_width(p.loading.target_load * s.force, s.dgamma, s.R);
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
      const double       gigabytes = 4. * 8. * cells * cells / 1e9;
      const double       available = this_machine_memory_gb();
      std::ostringstream message;
      message << what << " about the JKR contact (" << 2 * a
              << " eps wide) has about " << cells << " cells, whose dense "
              << "compliance needs about " << gigabytes
              << " GB; this machine has " << available
              << " GB: raise 'Boundary element/Grid spacing' or 'Boundary "
                 "element/Grading ratio'";
      require(gigabytes <= 0.8 * available, message.str());
    }


    void
    check_consistency(const AllParameters &p)
    {
      // Builds the profile once, so that an unreadable table or a bad
      // expression is reported with the other input errors, before a run.
      create_indenter(p.indenter,
                      p.adhesion.R_over_eps,
                      p.geometry.domain_width);
      require(p.mesh.finest_cell < p.geometry.height() / 4,
              entry("Mesh", "Finest surface cell", p.mesh.finest_cell) +
                " must be well below the substrate height " +
                std::to_string(p.geometry.height()));
      require(p.geometry.domain_width >= 2 * p.geometry.height() ||
                p.geometry.substrate == Substrate::half_plane,
              entry("Geometry", "Domain width", p.geometry.domain_width) +
                " must be at least twice the Layer thickness");
      require(!p.loading.has_target_load() || p.loading.approach_speed == 0,
              "'Loading/Target load' needs a quasi-static approach "
              "('Loading/Approach speed' = 0): the load is found on the "
              "relaxed loading curve");
      require(p.sliding.solver == SlidingSolver::transient ||
                !p.loading.retract || p.sliding.speed == 0,
              "'Loading/Retract' = true needs 'Sliding/Solver' = transient: "
              "the steady-state solver has no time to retract in");
      // A program's segments: each at least one sliding step long, and
      // the indenter kept within the block.
      double s = 0.;
      for (unsigned int k = 0; k < p.sliding.program.size(); ++k)
        {
          const auto       &segment = p.sliding.program[k];
          const std::string where   = segment.name(k);
          const double      step    = p.sliding.increment * p.mesh.finest_cell;
          require(segment.rest() || segment.length >= step,
                  where + " slides " + num(segment.length) +
                    " eps, less than one sliding step ('Sliding/Sliding "
                    "increment' x 'Mesh/Finest surface cell' = " +
                    num(step) + " eps)");
          s += segment.displacement();
          require(std::abs(s) < p.geometry.domain_width / 2,
                  where + " takes the indenter " + num(s) +
                    " eps from the block's centre, beyond its lateral "
                    "boundary ('Geometry/Domain width' = " +
                    num(p.geometry.domain_width) +
                    "): widen the block or shorten the program");
        }
      require(p.sliding.speeds.size() == 1 ||
                std::find(p.sweep.solvers.begin(),
                          p.sweep.solvers.end(),
                          SlidingSolver::transient) == p.sweep.solvers.end(),
              "'Sweep/Solvers' with 'transient' needs a single 'Sliding/"
              "Sliding speed' (the transient solver runs each listed speed "
              "as a case of its own; the steady solvers follow the list)");
      require(p.geometry.dimension == 2 ||
                runs_only(p,
                          {SlidingSolver::boundary_element,
                           SlidingSolver::steady_state}),
              "'Geometry/Dimension' = 3 needs 'Sliding/Solver' = "
              "boundary-element or steady-state (and no other in "
              "'Sweep/Solvers'): the transient solver is plane strain");
      require(p.geometry.dimension == 2 ||
                p.geometry.substrate == Substrate::layer ||
                !boundary_elements_only(p) ||
                p.geometry.domain_height == Geometry::default_domain_height,
              "'Geometry/Domain height' is the depth of the 3D finite "
              "elements' block; the boundary elements' half-space is "
              "infinite: remove it");
      if (p.sliding.solver == SlidingSolver::boundary_element)
        {
          require(p.sliding.control != Control::spring,
                  "'Sliding/Control' = spring is not available with "
                  "'Sliding/Solver' = boundary-element: use force or "
                  "displacement");
          require(p.sliding.control == Control::force ||
                    p.geometry.substrate == Substrate::layer ||
                    p.sliding.speed == 0 || p.geometry.dimension == 3,
                  "'Sliding/Solver' = boundary-element on a half-plane "
                  "needs 'Sliding/Control' = force: the periodic "
                  "half-plane has no depth to measure delta from");
          require(p.loading.approach_speed == 0,
                  "'Sliding/Solver' = boundary-element approaches "
                  "quasi-statically: set 'Loading/Approach speed' = 0");
          const double h = p.boundary_element.grid_spacing > 0
                             ? p.boundary_element.grid_spacing
                             : p.mesh.finest_cell / 2;
          if (p.boundary_element.grid == GridKind::graded)
            {
              check_graded_grid(p, h);
              return;
            }
          const double L = p.boundary_element.period > 0
                             ? p.boundary_element.period
                             : p.geometry.domain_width;
          require(L / h >= 64 && L / h <= 1e8,
                  entry("Boundary element", "Grid spacing", h) +
                    " and the period " + std::to_string(L) + " eps give " +
                    std::to_string(L / h) +
                    " grid points; between 64 and 1e8 are allowed");
          if (p.geometry.dimension == 3)
            check_plane_grid_fits(p, h, L);
        }
    }
  } // namespace CaseSetup
} // namespace viscoslide

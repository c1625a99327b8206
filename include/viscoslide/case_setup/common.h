// SPDX-License-Identifier: LGPL-2.1-or-later
// What the checks of a case's parameters (case_setup.h) share: the limits
// of the mesh, which solvers a case runs, the contact's size and the wake
// of the fastest speed, the memory of the machines and of the 3D finite
// elements. [source/case_setup/common.cc, memory.cc]
#ifndef viscoslide_case_setup_common_h
#define viscoslide_case_setup_common_h

#include <viscoslide/io/parameters.h>

#include <initializer_list>
#include <string>

namespace viscoslide
{
  namespace CaseSetup
  {
    namespace internal
    {
      using namespace Parameters;

      // The finest cell p4est can make from the coarse cells is 2^-30 of
      // theirs; the refinement stays well below that.
      constexpr double max_refinement_levels = 24;
      // make_block() tiles the block with squares of its smaller side.
      constexpr double max_aspect_ratio = 1e4;
      // Beyond this distance (in eps) the interaction laws are negligible.
      constexpr double interaction_range = 5;

      // The half-width of the elastic (Hertz) contact of the indenter under
      // F_hat (a line contact in 2D, the sphere's radius in 3D), with
      // plane-strain modulus E_star.
      double
      hertz_half_width(double F_hat, double E_star, const AllParameters &p);

      // The cohesive zone of a crack under the law's peak stress, about
      // (pi/8) E* dgamma / sigma_max^2 on the softer modulus, in eps.
      double
      adhesive_zone(const AllParameters &p);
      // The boundary elements' Grid spacing, in eps: the entry, or half
      // the Finest surface cell where it is 0.
      double
      surface_grid_spacing(const AllParameters &p);

      // Whether every case runs one of `solvers`: the solver, and every one
      // a sweep lists.
      bool
      runs_only(const AllParameters                 &p,
                std::initializer_list<SlidingSolver> solvers);
      bool
      boundary_elements_only(const AllParameters &p);
      // Whether every case runs on the boundary elements' graded grid,
      // which builds neither a block nor a mesh.
      bool
      graded_grid_only(const AllParameters &p);

      // The wake V tau_c of the fastest listed speed, in eps (0 without
      // speeds).
      double
      fastest_wake(const AllParameters &p);
      // The listed speeds (comma-separated; empty if none) at which the
      // relaxation length V tau is shorter than `length`; tau in units of
      // tau_ref, lengths in eps.
      std::string
      speeds_relaxing_within(const AllParameters &p, double tau, double length);
      // Where the block is as long as the fastest speed's wake asks (it
      // was lengthened for it), the entries that shorten it.
      std::string
      wake_advice(const AllParameters &p);

      // This machine's physical memory, and that of the machines this run
      // has, in GB. [memory.cc]
      double
      this_machine_memory_gb();
      double
      machine_memory_gb();
      // The memory a 3D grid of the boundary elements may take, in GB:
      // four fifths of this machine's (checked before the run and by the
      // nested grid at each band it makes). [memory.cc]
      double
      plane_grid_memory_limit_gb();

      // The size of the 3D finite elements with the mesh about the largest
      // contact of the case, the relaxed one at the Target load (JKR's
      // with an adhesive law, Hertz's without; under displacement control
      // Hertz's at the Final approach): its cells counted before anything
      // is built, the unknowns per cell of the elements, and the memory
      // per unknown measured for each linear solver (scripts/bench_fem3d,
      // doc/benchmark.md). [memory.cc]
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
      finite_elements_3d_size(const AllParameters &p);
      std::string
      linear_solver_name(const FiniteElements3dSize &size);

      // A plane grid of the boundary elements must fit in memory at the
      // fastest speed; the graded grid's dense compliance too, and it
      // needs the case it was made for. [memory.cc]
      void
      check_plane_grid_fits(const AllParameters &p,
                            double               spacing,
                            double               width);
      void
      check_graded_grid(const AllParameters &p, double spacing);
    } // namespace internal
  }   // namespace CaseSetup
} // namespace viscoslide

#endif

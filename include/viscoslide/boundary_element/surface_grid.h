// SPDX-License-Identifier: LGPL-2.1-or-later
// The surface grid of the boundary-element solver: what the nonlinear
// solver (solver.h) sees of a discretisation of the top surface. One class
// per grid: the periodic grid of uniform points (periodic_grid.h: the 2D
// half-plane and layers, the 3D layer), the isolated window of uniform
// points on the 3D half-space (isolated_grid.h), the graded 2D grid that
// follows the contact edges (graded_grid.h). A grid owns everything that
// depends on where its points are: the indenter's height there, the
// compliance applied to a traction, the preconditioner of Newton's system,
// the dissipation, the contact measures, and how a state moves to a new
// grid. Newton's method, the continuation and the start are the solver's
// and are written once for every grid (doc/boundary_element.md, Grids).
#ifndef viscoslide_boundary_element_surface_grid_h
#define viscoslide_boundary_element_surface_grid_h

#include <deal.II/lac/full_matrix.h>
#include <deal.II/lac/vector.h>

#include <viscoslide/boundary_element/compliance.h>
#include <viscoslide/io/postprocessing.h>

#include <memory>
#include <ostream>
#include <string>
#include <utility>
#include <vector>

namespace viscoslide
{
  using namespace dealii;

  // The unknowns of the steady state on a grid: the gap g_j at the grid's
  // points and the approach delta. The surface's vertical displacement
  // (towards the indenter > 0) follows as u_j = eps + h_j - delta - g_j.
  // The gaps are kept rather than u: at R_hat 1e6 and more u, h and delta
  // are 1e4 eps, and a gap formed from them carries their rounding, 1e-12
  // eps, which the repulsive wall's stiffness and the coarse cells'
  // compliance turn into a residual of 1e-3 eps (doc/boundary_element.md).
  struct SurfaceState
  {
    Vector<double> gap;
    double         delta = 0;

    // u at points whose indenter heights are h.
    Vector<double>
    displacement(const std::vector<double> &h, const double eps) const
    {
      Vector<double> u(gap.size());
      for (unsigned int j = 0; j < gap.size(); ++j)
        u[j] = eps + h[j] - delta - gap[j];
      return u;
    }

    // The gaps of displacements u at points whose heights are h.
    void
    set_displacement(const Vector<double>      &u,
                     const std::vector<double> &h,
                     const double               eps)
    {
      gap.reinit(u.size());
      for (unsigned int j = 0; j < u.size(); ++j)
        gap[j] = eps + h[j] - delta - u[j];
    }

    // The approach moved to d with the displacements kept.
    void
    set_approach(const double d)
    {
      gap.add(delta - d);
      delta = d;
    }
  };


  // The preconditioner of Newton's system on a grid,
  //     J = I + C diag(w),  w = dq/dg + dashpot,
  // bordered under force control by the load row sum_j dq/dg_j (du_j +
  // d delta) A_j / sigma_max (solver.h).
  class NewtonPreconditioner
  {
  public:
    virtual ~NewtonPreconditioner() = default;

    // At every Jacobian: the traction law's tangent at the points, the
    // dashpot of the relaxation (per unit area), whether the load row is
    // there.
    virtual void
    update(const Vector<double> &tangent, double dashpot, bool force) = 0;

    // dst ~ J^-1 src, both of the grid's size plus one (the approach).
    virtual void
    vmult(Vector<double> &dst, const Vector<double> &src) const = 0;

    // After each GMRES on it: its iterations and whether it converged.
    virtual void
    solved(unsigned int /*iterations*/, bool /*converged*/)
    {
    }

    // The next update() makes it anew (the Jacobian moved far from it).
    virtual void
    reset()
    {
    }

    // Whether GMRES on it takes only a few iterations (a factorization of
    // the window): then Newton's linear solves are solved closely, whose
    // quadratic convergence saves Newton steps, each of which costs a
    // Jacobian; otherwise an inexact Newton step (newton.h, set_forcing)
    // saves iterations (measured on the graded cylinder and on the sphere,
    // doc/boundary_element.md, Newton's method).
    virtual bool
    nearly_exact() const
    {
      return false;
    }
  };


  template <int dim>
  class SurfaceGrid
  {
  public:
    // The points' coordinates, the area each stands for, the indenter's
    // height and its slope along x there (internal units).
    struct Points
    {
      std::vector<double> x, y, area, h, slope;
    };

    // Where a grid that moves has its points (graded_grid.h); opaque to
    // the solver, which keeps one to return to.
    struct Placement
    {
      virtual ~Placement() = default;
    };

    virtual ~SurfaceGrid() = default;

    unsigned int
    size() const
    {
      return points.x.size();
    }
    const Points &
    at() const
    {
      return points;
    }
    // Counts the grids made, so that a secant predictor spans one grid.
    unsigned int
    generation() const
    {
      return n_generation;
    }
    // The finest spacing (eps at the contact edges of the graded grid) and
    // its area dx^(dim - 1): the scales of the residual's load row.
    double
    spacing() const
    {
      return dx;
    }
    double
    cell_area() const
    {
      return dA;
    }

    // --- The solid: the compliance of this grid.

    // The sliding speed V (internal units); 0 is the relaxed solid.
    virtual void
    set_speed(double V) = 0;
    // u = C q.
    virtual void
    apply(const Vector<double> &q, Vector<double> &u) const = 0;
    // The block C[first + i][first + j], i, j < m, where the grid offers
    // one (the 2D grids: the JKR start, the window preconditioner).
    virtual FullMatrix<double>
    block(unsigned int first, unsigned int m) const;
    // Whether every entry of C is positive, so that C |v| bounds the
    // magnitudes of the terms of C v (the residual's rounding error).
    virtual bool
    positive_compliance() const
    {
      return false;
    }
    // du_c/dx of the compliance at the points (compliance.h).
    virtual void
    creep_slope(const Vector<double> &q, Vector<double> &slope) const = 0;
    // The rate of work of the traction q on the solid in a steady state,
    // -V sum_j A_j q_j du_c/dx_j: its dissipation (compliance.h states the
    // convention).
    double
    dissipation_rate(const Vector<double> &q) const;
    // The preconditioner of Newton's system on this grid.
    virtual NewtonPreconditioner &
    preconditioner() = 0;
    // The squared l2 norm of a displacement misfit is divided by this:
    // taken per row of points along x in 3D, as a line of them is
    // measured in 2D.
    virtual double
    rows() const
    {
      return 1.;
    }

    // --- Fitting the grid to the case.

    // Before the steady states up to speed V_hat (the approach: 0): the
    // grid a speed needs (a period that holds the wake), made or remade,
    // the state carried over.
    virtual void
    fit_to_speed(double /*V_hat*/, SurfaceState & /*state*/)
    {
    }
    // After the approach: the grid's solid for sliding, where the
    // approach was computed on another (the 2D half-plane's, on a block);
    // returns whether it changed, so that the state is solved again.
    virtual bool
    to_sliding_solid(SurfaceState & /*state*/)
    {
      return false;
    }

    // A grid that refines about the contact only from the first speed on
    // (the nested grid's band; the approach runs on its coarse cells), and
    // refining from now on, at rest.
    virtual bool
    refines_about_contact() const
    {
      return false;
    }
    virtual void
    refine_at_rest()
    {
    }

    // --- A grid that follows the contact (its points placed about the
    // contact edges); a fixed grid ignores all of this.

    virtual bool
    follows_contact() const
    {
      return false;
    }
    // Where the points are now, to return to with regrid().
    virtual std::shared_ptr<const Placement>
    placement() const
    {
      return nullptr;
    }
    // A new grid at `p`, the state carried over.
    virtual void
    regrid(const Placement & /*p*/, SurfaceState & /*state*/)
    {
    }
    // A grid that refines cells of a coarse one (the nested grid's band):
    // the coarse grid's placement, on which a continuation step is first
    // taken (solver.h, predict_on_coarse); null for any other grid or
    // while nothing is refined.
    virtual std::shared_ptr<const Placement>
    coarse_placement() const
    {
      return nullptr;
    }
    // A state of the grid at `p` carried onto this one (this grid left as
    // it is); false where it cannot be.
    virtual bool
    carry(const Placement & /*p*/, SurfaceState & /*state*/) const
    {
      return false;
    }
    // The grid at `p`, the state given by its gaps on the points (delta
    // kept).
    virtual void
    place(const Placement & /*p*/,
          const Vector<double> & /*gaps*/,
          SurfaceState & /*state*/)
    {
    }
    // A grid about a contact from x = trail to lead (the start from a JKR
    // contact), the state carried over.
    virtual void
    place_about(double /*trail*/, double /*lead*/, SurfaceState & /*state*/)
    {
    }
    // Whether the contact edges of `q` lie where the grid is finest and
    // no traction reaches its ends; if not, or `always`, a new grid about
    // them, the state carried over. Returns whether it made one.
    virtual bool
    follow(const SurfaceQuantities & /*q*/,
           const Vector<double> & /*traction*/,
           bool /*always*/,
           SurfaceState & /*state*/)
    {
      return false;
    }
    // The predictor of a continuation step: a grid about the edges
    // extrapolated from `edges` and `edges_before` (the step's length
    // `ratio` times the last one's), the state moved with them.
    virtual void
    predict(const std::pair<double, double> & /*edges*/,
            const std::pair<double, double> & /*edges_before*/,
            double /*ratio*/,
            SurfaceState & /*state*/)
    {
    }

    // --- The grid's own unknowns: its motions (the graded grid's two
    // contact edges), which Newton's method takes with the displacements
    // (solver.h, solve_moving_grid).

    virtual unsigned int
    n_motions() const
    {
      return 0;
    }
    // Ready for Newton's method with the motions: a grid recentred on the
    // edges of `q` where they are off its own. False where there is
    // nothing to follow.
    virtual bool
    prepare_motions(const SurfaceQuantities & /*q*/, SurfaceState & /*state*/)
    {
      return false;
    }
    // The grid of `from` moved by `d` (one value per motion), each cell's
    // gap kept (`gaps`): the state's u follows.
    virtual void
    move(const Placement & /*from*/,
         const std::vector<double> & /*d*/,
         const Vector<double> & /*gaps*/,
         SurfaceState & /*state*/)
    {
    }
    // The same as a new grid, this one left as it is (the residual's
    // derivatives along the motions).
    virtual std::unique_ptr<SurfaceGrid<dim>>
    moved(const Placement & /*from*/,
          const std::vector<double> & /*d*/,
          const Vector<double> & /*gaps*/,
          SurfaceState & /*state*/) const
    {
      return nullptr;
    }
    // Motion k's equation: sum_i w_i g_i = the contact gap, the points i
    // and weights w_i, which hold its edge where the grid is finest.
    virtual std::vector<std::pair<unsigned int, double>>
    pin(unsigned int /*k*/) const
    {
      return {};
    }
    // After a converged Newton's method with the motions.
    void
    count_generation()
    {
      ++n_generation;
    }

    // --- Measures and output.

    // F_n, the x force, eq. 2 on the contact set, the contact's measure
    // and extent, from the gaps, tractions and displacements at the
    // points; gc the contact gap.
    SurfaceQuantities
    measure(const Vector<double> &gaps,
            const Vector<double> &traction,
            const Vector<double> &u,
            double                gc) const;
    // A map of the surface beside a profile (3D: VTK image data).
    virtual void
    write_map(const std::string & /*path*/,
              const std::string & /*what*/,
              const Vector<double> & /*gaps*/,
              const Vector<double> & /*traction*/,
              const Vector<double> & /*u*/,
              double /*eps*/,
              double /*sigma_max*/,
              double /*R*/) const
    {
    }

  protected:
    SurfaceGrid(double dx)
      : dx(dx)
      , dA(std::pow(dx, dim - 1))
    {
    }

    // The largest |x| and |y| of the points where the gap is below `gap`:
    // the reach of a map about the contact (write_map).
    std::pair<double, double>
    reach_within(const Vector<double> &gaps, double gap) const;

    // The neighbours of point j along x and the distances to them, for
    // measure().
    virtual unsigned int
    next(unsigned int j) const = 0;
    virtual unsigned int
    previous(unsigned int j) const = 0;
    virtual double
    distance_to_next(unsigned int j) const = 0;
    virtual double
    distance_across(unsigned int j) const = 0;
    // In 3D the contact's area and half-width across the track, which a
    // uniform grid measures ([uniform_grid.cc]).
    virtual void
    measure_plane(const Vector<double> & /*gaps*/,
                  double /*gc*/,
                  SurfaceQuantities & /*q*/) const
    {
    }

    const double dx, dA;
    Points       points;
    unsigned int n_generation = 0;
    // The speed of the compliance (set_speed).
    double speed = 0;
  };
} // namespace viscoslide

#endif

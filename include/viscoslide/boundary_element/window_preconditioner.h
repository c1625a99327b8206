// SPDX-License-Identifier: LGPL-2.1-or-later
// The preconditioner of Newton's system on a line of points (the 2D
// grids): the Jacobian on the window of points near the contact, with the
// load equation bordered, factorized in single or double precision
// (doc/boundary_element.md, Newton's method and its linear solves).
#ifndef viscoslide_boundary_element_window_preconditioner_h
#define viscoslide_boundary_element_window_preconditioner_h

#include <deal.II/lac/lapack_full_matrix.h>
#include <deal.II/lac/vector.h>

#include <viscoslide/boundary_element/surface_grid.h>

#include <memory>

namespace viscoslide
{
  using namespace dealii;

  // The Jacobian of Newton's system restricted to the points near the
  // contact, where the traction law's tangent is large (|q'| > 1e-3
  // max|q'|, with a margin of an eighth of their width), factorized, and
  // kept while those points stay inside it and GMRES converges cheaply
  // with it. Outside the window the tangent is nearly zero, so that the
  // rest of the system is the identity plus the coupling through C, which
  // one more application of C accounts for (block elimination).
  //
  // GMRES on a factorization gets slower as the iterate moves away from
  // where it was made: it is renewed once the last GMRES cost more than the
  // average per solve since it was made, factorization included (the
  // renewal that minimises that average), or did not converge. The costs
  // are counted work, not wall times, so that Newton's path is the same on
  // every machine and under any load [window_preconditioner.cc].
  class WindowPreconditioner : public NewtonPreconditioner
  {
  public:
    // The grid whose block() and apply() it uses; the load row in units of
    // sigma_max. Single precision serves as a preconditioner and halves
    // the time of the factorization and of the solves (which read the
    // whole factor from memory); double precision where the displacements
    // are so much larger than eps that single precision does not resolve
    // the gaps (the graded grid at R_hat 1e6, where GMRES stalled with it).
    WindowPreconditioner(const SurfaceGrid<2> &grid,
                         double                sigma_max,
                         bool                  double_precision);
    ~WindowPreconditioner();

    void
    update(const Vector<double> &tangent, double dashpot, bool force) override;
    void
    vmult(Vector<double> &dst, const Vector<double> &src) const override;
    void
    solved(unsigned int iterations, bool converged) override;
    void
    reset() override;
    bool
    nearly_exact() const override
    {
      return true;
    }

  private:
    class Factorization;

    const SurfaceGrid<2>          &grid;
    const double                   sigma_max;
    const bool                     double_precision;
    std::unique_ptr<Factorization> factorization;
    unsigned int                   solves_since_factorization = 0;
    double work_since_factorization = 0., last_gmres_work = 0.;
    bool   last_gmres_converged = true;
  };
} // namespace viscoslide

#endif

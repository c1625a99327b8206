// SPDX-License-Identifier: LGPL-2.1-or-later
// The preconditioner of the boundary-element solver's GMRES on a plane of
// points (3D), where a dense Jacobian of the contact window (the 2D
// solver's WindowPreconditioner) would not fit: geometric multigrid on
// the surface grid.
//
// Newton's system is J du = r with J = I + C W, C the compliance and W the
// diagonal of the traction law's tangent dq/dg (plus a dashpot). With K
// the stiffness C^-1, J = C (K + W), so J^-1 = (K + W)^-1 K. K is a
// pseudo-differential operator of order one (its symbol E* |k| / 2), W a
// local reaction that is huge inside the contact and nil outside it: the
// sum is what geometric multigrid does well. For K the preconditioner
// takes the relaxed elastic operator of the periodic window, scaled by
// |E*| at the frequency of the contact (set_speed), not the viscoelastic
// one, whose strongly non-symmetric symbol near the friction peak the
// smoother cannot reduce. One V-cycle (damped Jacobi smoothing, full
// weighting, linear interpolation, K rediscretised on each coarser grid
// with W restricted onto it, a dense solve on the coarsest) approximates
// (K + W)^-1; GMRES is left the viscous part, which is smooth, and its
// iterations stay bounded as the grid is refined. Under force control the
// load row is eliminated with the preconditioner's own solution for the
// approach column (block elimination).
#ifndef viscoslide_boundary_element_multigrid_preconditioner_h
#define viscoslide_boundary_element_multigrid_preconditioner_h

#include <deal.II/lac/lapack_full_matrix.h>
#include <deal.II/lac/vector.h>

#include <viscoslide/boundary_element/periodic_compliance.h>
#include <viscoslide/boundary_element/surface_grid.h>

#include <array>
#include <memory>
#include <vector>

namespace viscoslide
{
  using namespace dealii;

  template <int dim>
  class SurfaceMultigrid : public NewtonPreconditioner
  {
  public:
    // The levels for the grid of `shape` points (x fastest) of spacing dx:
    // halved while every count is even and at least 8, or the coarsest
    // has no more than 1024 points. The load row of force control is sum_j
    // tangent_j (du_j + d delta) dx^(dim-1) / force_scale.
    SurfaceMultigrid(Parameters::Substrate                    substrate,
                     double                                   thickness,
                     const ViscoelasticSolid                 &material,
                     double                                   nu,
                     const std::array<unsigned int, dim - 1> &shape,
                     double                                   dx,
                     double                                   force_scale);

    void
    set_speed(double V);

    // The Jacobian's diagonal W, the tangent plus the dashpot, and under
    // force control the load row.
    void
    update(const Vector<double> &tangent, double dashpot, bool force) override;

    void
    vmult(Vector<double> &dst, const Vector<double> &src) const override;

    unsigned int
    n_levels() const
    {
      return levels.size();
    }

  private:
    struct Level
    {
      std::array<unsigned int, dim - 1>        shape;
      std::unique_ptr<PeriodicCompliance<dim>> compliance;
      // W, and Jacobi's damping over the diagonal of K + W.
      Vector<double> weight, inverse_diagonal;
    };

    // x ~ (K + W)^-1 b on level l.
    void
    v_cycle(unsigned int l, const Vector<double> &b, Vector<double> &x) const;
    void
    smooth(const Level          &level,
           const Vector<double> &b,
           Vector<double>       &x,
           unsigned int          sweeps) const;
    // (K + W) x on level l.
    void
    apply(const Level &level, const Vector<double> &x, Vector<double> &y) const;
    // The average over each coarse point's 2^(dim-1) fine points, and its
    // transpose up to that factor (constant prolongation).
    Vector<double>
    restrict_to(unsigned int coarse, const Vector<double> &fine) const;
    void
    add_prolongation(unsigned int          coarse,
                     const Vector<double> &coarse_values,
                     Vector<double>       &fine) const;
    void
    factorize_coarsest();

    std::vector<Level> levels;
    // The modulus scaling the relaxed elastic operator (set_speed), and
    // the window's length along x; the load row's cell area and scale.
    double       scale = 1., window = 0.;
    const double dA, force_scale;
    // The coarsest operator, factorized; empty where too large, then
    // smoothing alone stands in for it.
    LAPACKFullMatrix<double> coarsest;
    bool                     coarsest_factorized = false;

    // Block elimination of the load row: the tangent, the preconditioned
    // approach column z = (K + W)^-1 tangent, and the row's corner.
    bool           force = false;
    Vector<double> load_row, approach_column;
    double         corner = 0.;
  };
} // namespace viscoslide

#endif

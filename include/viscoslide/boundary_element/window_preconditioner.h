// The preconditioner of the boundary-element solver's GMRES (solver.h):
// the Jacobian on the window of grid points near the contact, with the
// load equation bordered, factorized in single precision.
#ifndef viscoslide_boundary_element_window_preconditioner_h
#define viscoslide_boundary_element_window_preconditioner_h

#include <deal.II/lac/lapack_full_matrix.h>
#include <deal.II/lac/vector.h>

#include <viscoslide/boundary_element/solver.h>

#include <numeric>

namespace viscoslide
{
  // The Jacobian of Newton's system restricted to the points near the
  // contact, where the traction law's tangent is large, factorized once
  // and used for as long as GMRES converges quickly with it. Outside the
  // window the tangent is nearly zero, so that the rest of the system is
  // the identity plus the coupling through C, which one more application
  // of C accounts for (block elimination).
  // (Defined for every dim, used on the line of points of dim = 2.)
  template <int dim>
  class BoundaryElementSolver<dim>::WindowPreconditioner
  {
  public:
    WindowPreconditioner(const SurfaceCompliance<dim> &compliance,
                         const Vector<double>         &tangent,
                         const double                  dashpot,
                         const unsigned int            first,
                         const unsigned int            m,
                         const bool                    force,
                         const double                  force_scale)
      : compliance(compliance)
      , first(first)
      , m(m)
      , force(force)
      , weight(m)
      , load_weight(m)
      , lu(m + 1, m + 1)
    {
      const Vector<double> column = compliance.impulse_response();
      const unsigned int   n      = column.size();
      for (unsigned int j = 0; j < m; ++j)
        {
          weight[j]      = tangent[first + j] + dashpot;
          load_weight[j] = tangent[first + j];
        }
      for (unsigned int i = 0; i < m; ++i)
        {
          double border = 0;
          for (unsigned int j = 0; j < m; ++j)
            {
              const double c = column[(i + n - j) % n];
              lu(i, j)       = (i == j ? 1. : 0.) + c * weight[j];
              border += c * load_weight[j];
            }
          lu(i, m) = force ? border : 0.;
          lu(m, i) = force ? load_weight[i] / force_scale : 0.;
        }
      // Without a stiff point (no contact) the load row is empty: the
      // identity there keeps the factorization regular.
      const double corner =
        std::accumulate(load_weight.begin(), load_weight.end(), 0.);
      lu(m, m) = force && corner != 0. ? corner / force_scale : 1.;
      lu.compute_lu_factorization();
    }

    void
    vmult(Vector<double> &dst, const Vector<double> &src) const
    {
      const unsigned int n = src.size() - 1;
      Vector<float>      window(m + 1);
      for (unsigned int j = 0; j < m; ++j)
        window[j] = src[first + j];
      window[m] = src[n];
      lu.solve(window);
      Vector<double> w(n), Cw;
      for (unsigned int j = 0; j < m; ++j)
        w[first + j] = weight[j] * window[j] + load_weight[j] * window[m];
      compliance.apply(w, Cw);
      for (unsigned int j = 0; j < n; ++j)
        dst[j] = src[j] - Cw[j];
      for (unsigned int j = 0; j < m; ++j)
        dst[first + j] = window[j];
      dst[n] = window[m];
    }

    // Whether the window [begin, begin + size) lies within this one.
    bool
    covers(const unsigned int begin, const unsigned int size) const
    {
      return begin >= first && begin + size <= first + m;
    }

    unsigned int
    size() const
    {
      return m;
    }

  private:
    const SurfaceCompliance<dim> &compliance;
    const unsigned int            first, m;
    const bool                    force;
    Vector<double>                weight, load_weight;
    // Single precision: as a preconditioner it need not be exact, and both
    // the factorization and the solves (which read the whole factor from
    // memory) take half the time.
    LAPACKFullMatrix<float> lu;
  };
} // namespace viscoslide

#endif

// The preconditioner of the boundary-element solver's GMRES (solver.h):
// the Jacobian on the window of grid points near the contact, with the
// load equation bordered, factorized in single or double precision.
#ifndef viscoslide_boundary_element_window_preconditioner_h
#define viscoslide_boundary_element_window_preconditioner_h

#include <deal.II/lac/lapack_full_matrix.h>
#include <deal.II/lac/vector.h>

#include <viscoslide/boundary_element/solver.h>

#include <memory>

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
    // The window [first, first + m) of the points whose areas are `area`;
    // the load row in units of sigma_max. Single precision serves as a
    // preconditioner and halves the time of the factorization and of the
    // solves (which read the whole factor from memory); double precision
    // where the displacements are so much larger than eps that single
    // precision does not resolve the gaps (the graded grid at R_hat 1e6,
    // where GMRES stalled with it).
    WindowPreconditioner(const Compliance          &compliance,
                         const Vector<double>      &tangent,
                         const double               dashpot,
                         const unsigned int         first,
                         const unsigned int         m,
                         const bool                 force,
                         const std::vector<double> &area,
                         const double               sigma_max,
                         const bool                 double_precision)
      : compliance(compliance)
      , first(first)
      , m(m)
      , force(force)
      , weight(m)
      , load_weight(m)
    {
      for (unsigned int j = 0; j < m; ++j)
        {
          weight[j]      = tangent[first + j] + dashpot;
          load_weight[j] = tangent[first + j];
        }
      if (double_precision)
        factorize(precise, area, sigma_max);
      else
        factorize(single, area, sigma_max);
    }

    void
    vmult(Vector<double> &dst, const Vector<double> &src) const
    {
      if (precise)
        solve(*precise, dst, src);
      else
        solve(*single, dst, src);
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
    template <typename Number>
    void
    factorize(std::unique_ptr<LAPACKFullMatrix<Number>> &lu,
              const std::vector<double>                 &area,
              const double                               sigma_max)
    {
      const FullMatrix<double> c = compliance.block(first, m);
      lu            = std::make_unique<LAPACKFullMatrix<Number>>(m + 1, m + 1);
      double corner = 0;
      for (unsigned int i = 0; i < m; ++i)
        {
          double border = 0;
          for (unsigned int j = 0; j < m; ++j)
            {
              (*lu)(i, j) = (i == j ? 1. : 0.) + c(i, j) * weight[j];
              border += c(i, j) * load_weight[j];
            }
          const double load = load_weight[i] / (sigma_max / area[first + i]);
          (*lu)(i, m)       = force ? border : 0.;
          (*lu)(m, i)       = force ? load : 0.;
          corner += load;
        }
      // Without a stiff point (no contact) the load row is empty: the
      // identity there keeps the factorization regular.
      (*lu)(m, m) = force && corner != 0. ? corner : 1.;
      lu->compute_lu_factorization();
    }

    template <typename Number>
    void
    solve(const LAPACKFullMatrix<Number> &lu,
          Vector<double>                 &dst,
          const Vector<double>           &src) const
    {
      const unsigned int n = src.size() - 1;
      Vector<Number>     window(m + 1);
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

    const Compliance                         &compliance;
    const unsigned int                        first, m;
    const bool                                force;
    Vector<double>                            weight, load_weight;
    std::unique_ptr<LAPACKFullMatrix<float>>  single;
    std::unique_ptr<LAPACKFullMatrix<double>> precise;
  };
} // namespace viscoslide

#endif

// SPDX-License-Identifier: LGPL-2.1-or-later
#include <viscoslide/boundary_element/window_preconditioner.h>

#include <algorithm>
#include <cmath>

namespace viscoslide
{
  namespace
  {
    // The cost of the preconditioner's renewal and of GMRES, counted from
    // the sizes instead of timed, so that the path of Newton's method (and
    // with it the equilibrium reached past a jump of a contact edge) is the
    // same on every machine and under any load. The unit is one point of
    // one FFT, n log2 n per transform; the weights were fitted to wall
    // times on the main example and on Fig. 3 (within 15 % and 8 %): the
    // window matrix is filled in m^2 and factorized in single precision in
    // m^3, and each GMRES iteration applies the compliance twice, solves
    // with the factors and orthogonalizes against up to 100 vectors.
    double
    factorization_work(const unsigned int m)
    {
      const double w = m;
      return 0.0055 * w * w * w + 4. * w * w;
    }

    double
    gmres_work(const unsigned int n,
               const unsigned int m,
               const unsigned int iterations)
    {
      const double points = n, w = m, k = iterations;
      return k * (points * std::log2(points) + 0.1 * w * w +
                  0.3 * points * std::min(k, 100.));
    }
  } // namespace


  // The window [first, first + m) of the grid's points, factorized.
  class WindowPreconditioner::Factorization
  {
  public:
    Factorization(const SurfaceGrid<2> &grid,
                  const Vector<double> &tangent,
                  const double          dashpot,
                  const unsigned int    first,
                  const unsigned int    m,
                  const bool            force,
                  const double          sigma_max,
                  const bool            double_precision)
      : grid(grid)
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
        factorize(precise, sigma_max);
      else
        factorize(single, sigma_max);
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
              const double                               sigma_max)
    {
      const FullMatrix<double>   c    = grid.block(first, m);
      const std::vector<double> &area = grid.at().area;
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
      grid.apply(w, Cw);
      for (unsigned int j = 0; j < n; ++j)
        dst[j] = src[j] - Cw[j];
      for (unsigned int j = 0; j < m; ++j)
        dst[first + j] = window[j];
      dst[n] = window[m];
    }

    const SurfaceGrid<2>                     &grid;
    const unsigned int                        first, m;
    const bool                                force;
    Vector<double>                            weight, load_weight;
    std::unique_ptr<LAPACKFullMatrix<float>>  single;
    std::unique_ptr<LAPACKFullMatrix<double>> precise;
  };


  WindowPreconditioner::WindowPreconditioner(const SurfaceGrid<2> &grid,
                                             const double          sigma_max,
                                             const bool double_precision)
    : grid(grid)
    , sigma_max(sigma_max)
    , double_precision(double_precision)
  {
  }


  WindowPreconditioner::~WindowPreconditioner() = default;


  void
  WindowPreconditioner::update(const Vector<double> &tangent,
                               const double          dashpot,
                               const bool            force)
  {
    // The points where the traction law is stiff, and a window about them
    // with a margin of an eighth of their width, so that the factorization
    // serves while the contact edges move within it.
    const unsigned int n     = tangent.size();
    const double       stiff = 1e-3 * tangent.linfty_norm();
    long               first = -1, last = -1;
    for (unsigned int j = 0; j < n; ++j)
      if (std::abs(tangent[j]) > stiff)
        {
          if (first < 0)
            first = j;
          last = j;
        }
    const bool   no_contact = first < 0;
    const long   margin     = std::max(4l, (last - first) / 8);
    unsigned int begin = 0, m = 0;
    if (!no_contact)
      {
        begin = std::max(0l, first - margin);
        m     = std::min<long>(last + margin + 1, n) - begin;
      }
    if (factorization && last_gmres_converged &&
        last_gmres_work * solves_since_factorization <=
          work_since_factorization &&
        factorization->covers(no_contact ? 0 : first,
                              no_contact ? 0 : last + 1 - first))
      return;
    factorization = std::make_unique<Factorization>(
      grid, tangent, dashpot, begin, m, force, sigma_max, double_precision);
    work_since_factorization   = factorization_work(m);
    solves_since_factorization = 1;
    last_gmres_work            = 0.;
    last_gmres_converged       = true;
  }


  void
  WindowPreconditioner::vmult(Vector<double>       &dst,
                              const Vector<double> &src) const
  {
    factorization->vmult(dst, src);
  }


  void
  WindowPreconditioner::solved(const unsigned int iterations,
                               const bool         converged)
  {
    last_gmres_converged = converged;
    last_gmres_work =
      gmres_work(grid.size(), factorization->size(), iterations);
    work_since_factorization += last_gmres_work;
    ++solves_since_factorization;
  }


  void
  WindowPreconditioner::reset()
  {
    factorization.reset();
  }
} // namespace viscoslide

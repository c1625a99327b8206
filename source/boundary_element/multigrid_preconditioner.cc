// SPDX-License-Identifier: LGPL-2.1-or-later
#include <viscoslide/boundary_element/multigrid_preconditioner.h>

#include <algorithm>
#include <cmath>

namespace viscoslide
{
  namespace
  {
    // The smoother's damping and sweeps, and the coarsest grid's size.
    constexpr double       jacobi_damping     = 0.7;
    constexpr unsigned int sweeps             = 1;
    constexpr unsigned int coarsest_sweeps    = 30;
    constexpr unsigned int max_dense_points   = 1024;
    constexpr unsigned int min_points_per_dim = 8;

    // A grid as rows x columns, x (columns) fastest; one row in 2D.
    template <std::size_t d>
    std::pair<unsigned int, unsigned int>
    rows_columns(const std::array<unsigned int, d> &shape)
    {
      return {d == 1 ? 1u : shape[0], shape[d - 1]};
    }

    // Full weighting along one axis of a periodic grid: the coarse point J
    // sits on the fine point 2J and gets (f(2J-1) + 2 f(2J) + f(2J+1))/4.
    // The grid is rows x columns (x fastest); along x (`along_rows`) or
    // along y.
    Vector<double>
    restrict_axis(const Vector<double> &fine,
                  const unsigned int    rows,
                  const unsigned int    columns,
                  const bool            along_rows)
    {
      const unsigned int R = along_rows ? rows : rows / 2,
                         C = along_rows ? columns / 2 : columns;
      Vector<double> coarse(R * C);
      for (unsigned int I = 0; I < R; ++I)
        for (unsigned int J = 0; J < C; ++J)
          {
            double value;
            if (along_rows)
              {
                const unsigned int row = I * columns, c = 2 * J;
                value = fine[row + (c + columns - 1) % columns] +
                        2 * fine[row + c] + fine[row + (c + 1) % columns];
              }
            else
              {
                const unsigned int r = 2 * I;
                value = fine[((r + rows - 1) % rows) * columns + J] +
                        2 * fine[r * columns + J] +
                        fine[((r + 1) % rows) * columns + J];
              }
            coarse[I * C + J] = 0.25 * value;
          }
      return coarse;
    }
  } // namespace


  template <int dim>
  SurfaceMultigrid<dim>::SurfaceMultigrid(
    const Parameters::Substrate              substrate,
    const double                             thickness,
    const ViscoelasticSolid                 &material,
    const double                             nu,
    const std::array<unsigned int, dim - 1> &shape,
    const double                             dx,
    const double                             force_scale)
    : dA(std::pow(dx, dim - 1))
    , force_scale(force_scale)
  {
    std::array<unsigned int, dim - 1> s = shape;
    double                            h = dx;
    window                              = shape[dim - 2] * dx;
    for (;;)
      {
        Level level;
        level.shape      = s;
        level.compliance = std::make_unique<PeriodicCompliance<dim>>(
          substrate, thickness, material, nu, s, h);
        levels.push_back(std::move(level));
        unsigned int points = 1;
        bool         halve  = true;
        for (const unsigned int m : s)
          {
            points *= m;
            halve = halve && m % 2 == 0 && m / 2 >= min_points_per_dim;
          }
        if (!halve || points <= max_dense_points / 2)
          break;
        for (unsigned int &m : s)
          m /= 2;
        h *= 2;
      }
  }


  template <int dim>
  void
  SurfaceMultigrid<dim>::set_speed(const double V)
  {
    // Not the viscoelastic operator itself: at speeds near the peak its
    // symbol is far from symmetric, which damped Jacobi smoothing does not
    // reduce (about 120 GMRES iterations per Newton step at V_hat 10), but
    // the relaxed elastic one scaled by |E*| at the frequency with which
    // the material crosses a quarter of the window, about the contact's
    // size (19 iterations there; the same at rest). The viscous part is
    // smooth and left to GMRES. The levels' compliances stay relaxed, as
    // they were made.
    const auto  &top   = *levels[0].compliance;
    const double omega = 2 * M_PI * V / (0.25 * window);
    scale              = std::abs(top.modulus(omega));
  }


  template <int dim>
  Vector<double>
  SurfaceMultigrid<dim>::restrict_to(const unsigned int    coarse,
                                     const Vector<double> &fine) const
  {
    const auto [rows, columns]   = rows_columns(levels[coarse - 1].shape);
    const Vector<double> along_x = restrict_axis(fine, rows, columns, true);
    return rows == 1 ? along_x
                     : restrict_axis(along_x, rows, columns / 2, false);
  }


  template <int dim>
  void
  SurfaceMultigrid<dim>::add_prolongation(const unsigned int    coarse,
                                          const Vector<double> &c,
                                          Vector<double>       &fine) const
  {
    // Linear interpolation, the transpose of full weighting up to its
    // factor 2^(dim-1): fine 2J gets c(J), fine 2J+1 the mean of c(J) and
    // c(J+1), in each direction.
    const auto [rows, columns] = rows_columns(levels[coarse - 1].shape);
    const unsigned int R = rows == 1 ? 1 : rows / 2, C = columns / 2;
    auto               value = [&](const unsigned int I, const unsigned int J) {
      return c[(I % R) * C + (J % C)];
    };
    for (unsigned int i = 0; i < rows; ++i)
      for (unsigned int j = 0; j < columns; ++j)
        {
          const unsigned int I = i / 2, J = j / 2;
          const bool         odd_i = rows > 1 && i % 2 == 1, odd_j = j % 2 == 1;
          double             v;
          if (!odd_i && !odd_j)
            v = value(I, J);
          else if (!odd_i)
            v = 0.5 * (value(I, J) + value(I, J + 1));
          else if (!odd_j)
            v = 0.5 * (value(I, J) + value(I + 1, J));
          else
            v = 0.25 * (value(I, J) + value(I, J + 1) + value(I + 1, J) +
                        value(I + 1, J + 1));
          fine[i * columns + j] += v;
        }
  }


  template <int dim>
  void
  SurfaceMultigrid<dim>::update(const Vector<double> &tangent,
                                const double          dashpot,
                                const bool            force_control)
  {
    const Vector<double> &load_weight = tangent;
    levels[0].weight                  = tangent;
    levels[0].weight.add(dashpot);
    for (unsigned int l = 1; l < levels.size(); ++l)
      levels[l].weight = restrict_to(l, levels[l - 1].weight);
    for (Level &level : levels)
      {
        // Jacobi's diagonal; where the law's tangent is negative (the
        // attractive tail) no smaller than half of K's, so that the
        // smoother stays bounded.
        const double kappa = scale * level.compliance->stiffness_diagonal();
        level.inverse_diagonal.reinit(level.weight.size());
        for (unsigned int j = 0; j < level.weight.size(); ++j)
          level.inverse_diagonal[j] =
            jacobi_damping / (kappa + std::max(level.weight[j], -0.5 * kappa));
      }
    factorize_coarsest();

    force = force_control;
    if (!force)
      return;
    load_row = load_weight;
    load_row *= dA / force_scale;
    approach_column.reinit(load_weight.size());
    v_cycle(0, load_weight, approach_column);
    double rho = 0.;
    for (unsigned int j = 0; j < load_weight.size(); ++j)
      rho += load_row[j];
    corner = rho - load_row * approach_column;
  }


  template <int dim>
  void
  SurfaceMultigrid<dim>::factorize_coarsest()
  {
    const Level       &level = levels.back();
    const unsigned int n     = level.weight.size();
    coarsest_factorized      = n <= max_dense_points;
    if (!coarsest_factorized)
      return;
    coarsest.reinit(n, n);
    Vector<double> unit(n), column;
    for (unsigned int j = 0; j < n; ++j)
      {
        unit    = 0.;
        unit[j] = 1.;
        level.compliance->apply_stiffness(unit, column);
        for (unsigned int i = 0; i < n; ++i)
          coarsest(i, j) = scale * column[i];
        coarsest(j, j) += level.weight[j];
      }
    coarsest.compute_lu_factorization();
  }


  template <int dim>
  void
  SurfaceMultigrid<dim>::apply(const Level          &level,
                               const Vector<double> &x,
                               Vector<double>       &y) const
  {
    level.compliance->apply_stiffness(x, y);
    for (unsigned int j = 0; j < x.size(); ++j)
      y[j] = scale * y[j] + level.weight[j] * x[j];
  }


  template <int dim>
  void
  SurfaceMultigrid<dim>::smooth(const Level          &level,
                                const Vector<double> &b,
                                Vector<double>       &x,
                                const unsigned int    n_sweeps) const
  {
    Vector<double> Ax;
    for (unsigned int s = 0; s < n_sweeps; ++s)
      {
        apply(level, x, Ax);
        for (unsigned int j = 0; j < x.size(); ++j)
          x[j] += (b[j] - Ax[j]) * level.inverse_diagonal[j];
      }
  }


  template <int dim>
  void
  SurfaceMultigrid<dim>::v_cycle(const unsigned int    l,
                                 const Vector<double> &b,
                                 Vector<double>       &x) const
  {
    const Level &level = levels[l];
    x.reinit(b.size());
    if (l + 1 == levels.size())
      {
        if (coarsest_factorized)
          {
            x = b;
            coarsest.solve(x);
          }
        else
          smooth(level, b, x, coarsest_sweeps);
        return;
      }
    // The first sweep from x = 0 needs no product.
    for (unsigned int j = 0; j < x.size(); ++j)
      x[j] = b[j] * level.inverse_diagonal[j];
    smooth(level, b, x, sweeps - 1);
    Vector<double> Ax;
    apply(level, x, Ax);
    Ax.sadd(-1., 1., b);
    Vector<double> correction;
    v_cycle(l + 1, restrict_to(l + 1, Ax), correction);
    add_prolongation(l + 1, correction, x);
    smooth(level, b, x, sweeps);
  }


  template <int dim>
  void
  SurfaceMultigrid<dim>::vmult(Vector<double>       &dst,
                               const Vector<double> &src) const
  {
    const unsigned int n = src.size() - 1;
    Vector<double>     s(n), Ks, z;
    std::copy(src.begin(), src.begin() + n, s.begin());
    // (K + W)^-1 K s ~ (I + C W)^-1 s
    levels[0].compliance->apply_stiffness(s, Ks);
    Ks *= scale;
    v_cycle(0, Ks, z);
    double d = src[n];
    if (force && corner != 0.)
      {
        d = (src[n] - load_row * z) / corner;
        z.add(-d, approach_column);
      }
    std::copy(z.begin(), z.end(), dst.begin());
    dst[n] = d;
  }


  template class SurfaceMultigrid<2>;
  template class SurfaceMultigrid<3>;
} // namespace viscoslide

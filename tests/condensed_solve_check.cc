// SPDX-License-Identifier: LGPL-2.1-or-later
// The condensed direct solver (linear_solver.h) on a matrix whose answer
// is checked by its residual: the advection-diffusion operator of an
// N x N grid (unsymmetric, like the steady-state Jacobian), factorized
// once with its Schur complement on the top row T; then matrices changed
// on T x T only, with and without a border on T, solved through that one
// factorization. Prints, per solve, the relative residual
// |J x + b t - r| / |r| and |b.x + d t - m| / |m|. Then a nonlinear law on
// T given as a WindowModel, with and without a border: the relative
// residual of the nonlinear system after one solve, and the dense Newton
// iterations it took.
#include <deal.II/base/index_set.h>
#include <deal.II/base/mpi.h>
#include <deal.II/base/timer.h>

#include <deal.II/lac/dynamic_sparsity_pattern.h>
#include <deal.II/lac/trilinos_sparse_matrix.h>
#include <deal.II/lac/trilinos_vector.h>

#include <viscoslide/numerics/linear_solver.h>

#include <cmath>
#include <iostream>

using namespace dealii;

namespace
{
  constexpr unsigned int N = 40;

  unsigned int
  node(const unsigned int i, const unsigned int j)
  {
    return j * N + i;
  }

  // Deterministic values in [-1, 1], the same on every process.
  double
  noise(const unsigned int a, const unsigned int b, const unsigned int round)
  {
    return std::sin(12.9898 * a + 78.233 * b + 37.719 * round);
  }
} // namespace

int
main(int argc, char **argv)
{
  Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  const MPI_Comm                   comm = MPI_COMM_WORLD;
  const unsigned int               n    = N * N;
  const unsigned int procs              = Utilities::MPI::n_mpi_processes(comm);
  const unsigned int me = Utilities::MPI::this_mpi_process(comm);
  IndexSet           owned(n);
  owned.add_range(me * n / procs, (me + 1) * n / procs);

  DynamicSparsityPattern pattern(n, n, owned);
  for (const auto row : owned)
    {
      const unsigned int i = row % N, j = row / N;
      pattern.add(row, row);
      if (i > 0)
        pattern.add(row, node(i - 1, j));
      if (i + 1 < N)
        pattern.add(row, node(i + 1, j));
      if (j > 0)
        pattern.add(row, node(i, j - 1));
      if (j + 1 < N)
        pattern.add(row, node(i, j + 1));
    }
  TrilinosWrappers::SparseMatrix A, J;
  A.reinit(owned, owned, pattern, comm);
  J.reinit(owned, owned, pattern, comm);
  // -Laplace + advection to the left, with a diagonal shift.
  for (const auto row : owned)
    {
      const unsigned int i = row % N, j = row / N;
      A.set(row, row, 4.5);
      if (i > 0)
        A.set(row, node(i - 1, j), -1.4);
      if (i + 1 < N)
        A.set(row, node(i + 1, j), -0.6);
      if (j > 0)
        A.set(row, node(i, j - 1), -1.);
      if (j + 1 < N)
        A.set(row, node(i, j + 1), -1.);
    }
  A.compress(VectorOperation::insert);

  IndexSet T(n);
  for (unsigned int i = 0; i < N; ++i)
    if (owned.is_element(node(i, N - 1)))
      T.add_index(node(i, N - 1));

  TimerOutput                     quiet(comm,
                    std::cout,
                    TimerOutput::never,
                    TimerOutput::wall_times);
  viscoslide::ReusedFactorization solver(quiet, comm);
  solver.reinit(T, [&] { return T; });

  TrilinosWrappers::MPI::Vector r(owned, comm), b(owned, comm), x(owned, comm),
    y(owned, comm);
  for (const auto row : owned)
    r(row) = noise(row, 1, 0);
  for (const auto row : T)
    b(row) = noise(row, 2, 0);
  r.compress(VectorOperation::insert);
  b.compress(VectorOperation::insert);
  const double d = 3., m = 0.7;

  for (unsigned int round = 0; round < 3; ++round)
    {
      // Round 0 factorizes A itself; later rounds change the surface block
      // (a stiff surface law: diagonal and neighbours).
      J.copy_from(A);
      if (round > 0)
        for (const auto row : T)
          {
            const unsigned int i = row % N;
            J.add(row, row, 50. * (1. + noise(row, 3, round)));
            if (i > 0)
              J.add(row, node(i - 1, N - 1), 10. * noise(row, 4, round));
            if (i + 1 < N)
              J.add(row, node(i + 1, N - 1), 10. * noise(row, 5, round));
          }
      J.compress(VectorOperation::add);
      solver.matrix_changed(1.);

      solver.solve(J, r, x);
      J.vmult(y, x);
      y -= r;
      const double plain = y.l2_norm() / r.l2_norm();
      if (me == 0)
        std::cout << "plain_" << round << ' ' << plain << '\n';

      const double t = solver.solve_bordered(J, b, d, r, m, x);
      J.vmult(y, x);
      y.add(t, b);
      y -= r;
      const double bordered =
        std::max(y.l2_norm() / r.l2_norm(), std::abs((b * x) + d * t - m) / m);
      if (me == 0)
        std::cout << "bordered_" << round << ' ' << bordered << '\n';
    }
  if (me == 0)
    std::cout << "factorizations " << solver.factorizations << '\n';

  // A nonlinear surface law on T, F_T = -alpha (x_T + t)^3, and under the
  // border G = sum alpha (x_i + t)^3 + d t - m: the model's Newton
  // iterations on T solve the nonlinear system in one call.
  const double alpha = 5.;
  const auto   cube  = [alpha](const double v) { return alpha * v * v * v; };
  const auto   slope = [alpha](const double v) { return 3. * alpha * v * v; };
  viscoslide::ReusedFactorization nonlinear(quiet, comm);
  const double                    r_norm = r.l2_norm();
  for (const bool bordered : {false, true})
    {
      nonlinear.reinit(
        T,
        [&] { return T; },
        [&](const std::vector<int> &list) {
          viscoslide::WindowModel model;
          model.tolerance = 1e-10 * r_norm;
          if (me == 0)
            model.terms = [&, k = list.size()](const Vector<double> &x_T,
                                               const double          t) {
              viscoslide::WindowTerms W;
              W.rhs.reinit(k);
              W.border.reinit(k);
              for (unsigned int i = 0; i < k; ++i)
                {
                  W.rhs(i)    = -cube(x_T(i) + t);
                  W.border(i) = slope(x_T(i) + t);
                  W.tangent.push_back({i, i, W.border(i)});
                  W.force += cube(x_T(i) + t);
                  W.stiffness += slope(x_T(i) + t);
                }
              W.force += d * t;
              W.stiffness += d;
              return W;
            };
          return model;
        });
      nonlinear.matrix_changed(1.);
      double t = 0.;
      if (bordered)
        t = nonlinear.solve_bordered(A, b, d, r, m, x);
      else
        nonlinear.solve(A, r, x);
      // The residual of the nonlinear system at (x, t).
      TrilinosWrappers::MPI::Vector residual(owned, comm);
      A.vmult(residual, x);
      residual -= r;
      double G = 0.;
      for (const auto row : T)
        {
          residual(row) += cube(x(row) + t);
          G += cube(x(row) + t);
        }
      residual.compress(VectorOperation::add);
      G = Utilities::MPI::sum(G, comm) + d * t - m;
      const double relative =
        std::max(residual.l2_norm() / r_norm, bordered ? std::abs(G) / m : 0.);
      if (me == 0)
        std::cout << (bordered ? "nonlinear_bordered " : "nonlinear_plain ")
                  << relative << '\n';
    }
  if (me == 0)
    std::cout << "window_iterations " << nonlinear.window_iterations << '\n';
}

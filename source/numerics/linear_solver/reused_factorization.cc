// SPDX-License-Identifier: LGPL-2.1-or-later
// The factorization reused across Newton steps: the bulk factorized once,
// the surface window solved by its Schur complement.
#include <deal.II/base/mpi.h>
#include <deal.II/base/timer.h>

#include <deal.II/lac/lapack_full_matrix.h>
#include <deal.II/lac/vector.h>

#include <viscoslide/numerics/linear_solver.h>
#include <viscoslide/numerics/mpi_gather.h>

#include <algorithm>

namespace viscoslide
{
  using Vector = TrilinosWrappers::MPI::Vector;

  namespace
  {
    struct WindowSolution
    {
      dealii::Vector<double> x;
      double                 t          = 0.;
      unsigned int           iterations = 0;
    };

    // The top-left k x k block of `from` into `to`, column by column, as
    // both are stored.
    void
    copy_top_left(const LAPACKFullMatrix<double> &from,
                  const unsigned int              k,
                  LAPACKFullMatrix<double>       &to)
    {
      for (unsigned int j = 0; j < k; ++j)
        for (unsigned int i = 0; i < k; ++i)
          to(i, j) = from(i, j);
    }


    // The Jacobian of the reduced system of T: the bulk's reduced operator
    // and the surface tangent, bordered under force control by b_T and
    // dG/d delta = d.
    LAPACKFullMatrix<double>
    window_jacobian(const LAPACKFullMatrix<double> &bulk,
                    const WindowTerms              &W,
                    const bool                      bordered,
                    const double                    d)
    {
      const unsigned int       k = bulk.m(), n = bordered ? k + 1 : k;
      LAPACKFullMatrix<double> J(n, n);
      copy_top_left(bulk, k, J);
      for (const auto &e : W.tangent)
        J(e.row, e.column) += e.value;
      if (bordered)
        {
          for (unsigned int i = 0; i < k; ++i)
            J(k, i) = J(i, k) = W.border(i);
          J(k, k) = d;
        }
      return J;
    }


    // Newton's method on the reduced system of T (ReusedFactorization):
    // K = S + D is its matrix at x_T = 0, y and m the reduced right-hand
    // side and the border's, start_norm the whole system's residual norm.
    // Full steps only, as long as each reduces the residual norm: a step
    // that needs cutting ends the iterations before it, or, if it is the
    // first, is returned whole. Then the caller's Newton method sees the
    // steps it would have taken without the model, less the full steps it
    // would have needed to get there, and its line search and its
    // judgement of a crawl (a contact edge that must jump) stay its own.
    WindowSolution
    newton_on_window(const LAPACKFullMatrix<double> &K,
                     const std::vector<double>      &y,
                     const bool                      bordered,
                     const double                    d,
                     const double                    m,
                     const double                    start_norm,
                     const WindowModel              &model)
    {
      const unsigned int k = y.size(), n = bordered ? k + 1 : k;
      WindowSolution     s;
      s.x.reinit(k);
      const WindowTerms at_start = model.terms(s.x, 0.);
      // The bulk's reduced operator: S less the surface tangent it holds.
      LAPACKFullMatrix<double> bulk(k, k);
      copy_top_left(K, k, bulk);
      for (const auto &e : at_start.tangent)
        bulk(e.row, e.column) -= e.value;

      // The reduced residual (and G's row) at x_T, for W = the terms there.
      dealii::Vector<double> c(n), bx(k);
      const auto             residual = [&](const WindowTerms            &W,
                                const dealii::Vector<double> &x) {
        bulk.vmult(bx, x);
        for (unsigned int i = 0; i < k; ++i)
          c(i) = y[i] - bx(i) + W.rhs(i) - at_start.rhs(i);
        if (bordered)
          c(k) = m - (W.force - at_start.force);
        return c.l2_norm();
      };

      // The first step is judged against the whole residual, which the
      // reduction hides (the bulk's part of a speed step, say): after it
      // the rows outside T hold (up to the surface terms there), and the
      // reduced residual is the whole one.
      WindowTerms W    = at_start;
      double      norm = std::max(residual(W, s.x), start_norm);
      while (s.iterations < 50 && norm > 1e-2 * model.tolerance)
        {
          LAPACKFullMatrix<double> J = window_jacobian(
            bulk, W, bordered, d + W.stiffness - at_start.stiffness);
          dealii::Vector<double> step(c);
          J.compute_lu_factorization();
          J.solve(step);

          dealii::Vector<double> x(s.x);
          for (unsigned int i = 0; i < k; ++i)
            x(i) += step(i);
          const double t        = s.t + (bordered ? step(k) : 0.);
          WindowTerms  trial    = model.terms(x, t);
          const double r        = residual(trial, x);
          const bool   descends = r < (1. - 1e-4) * norm; // false if NaN
          if (!descends && s.iterations > 0)
            break;
          s.x  = x;
          s.t  = t;
          W    = std::move(trial);
          norm = r;
          ++s.iterations;
          if (!descends)
            break;
        }
      return s;
    }
  } // namespace



  ReusedFactorization::ReusedFactorization(TimerOutput   &timer,
                                           const MPI_Comm comm)
    : timer(timer)
    , comm(comm)
    , direct(comm)
  {
  }


  void
  ReusedFactorization::reinit(const IndexSet           &surface_unknowns,
                              std::function<IndexSet()> window,
                              WindowModelBuilder        model)
  {
    build_model = std::move(model);
    system_bulk = -1.;
    direct.clear();
    factorized    = false;
    surface       = surface_unknowns;
    surface_size  = Utilities::MPI::sum(surface.n_elements(), comm);
    choose_window = std::move(window);
    window_list.clear();
  }


  void
  ReusedFactorization::matrix_changed(const double bulk)
  {
    assembled_bulk = bulk;
  }


  void
  ReusedFactorization::load_bulk(const TrilinosWrappers::SparseMatrix &bulk,
                                 TrilinosWrappers::SparseMatrix       &system,
                                 const double                          bulk_id)
  {
    if (system_bulk == bulk_id)
      restore_surface_rows(bulk, system);
    else
      system.copy_from(bulk);
    system_bulk = bulk_id;
    matrix_changed(bulk_id);
  }


  void
  ReusedFactorization::restore_surface_rows(
    const TrilinosWrappers::SparseMatrix &bulk,
    TrilinosWrappers::SparseMatrix       &system) const
  {
    const Epetra_CrsMatrix &from = bulk.trilinos_matrix();
    const Epetra_CrsMatrix &to   = system.trilinos_matrix();
    for (const auto row : surface)
      {
        int     n, m;
        double *source, *target;
        int    *columns;
        from.ExtractMyRowView(from.LRID(static_cast<long long int>(row)),
                              n,
                              source,
                              columns);
        // Epetra hands out the row's values for writing even on a const
        // matrix; the pattern, and so the matrix's state, stays.
        to.ExtractMyRowView(to.LRID(static_cast<long long int>(row)),
                            m,
                            target,
                            columns);
        AssertThrow(n == m,
                    ExcMessage("The bulk and system matrices differ in their "
                               "pattern"));
        std::copy(source, source + n, target);
      }
  }


  void
  ReusedFactorization::factorize_if_needed(
    const TrilinosWrappers::SparseMatrix &matrix)
  {
    // A window of the whole surface (the relaxation's) is given up once a
    // smaller one serves: its dense system would slow every later solve.
    const auto window_shrinks = [this] {
      return window_list.size() == surface_size &&
             Utilities::MPI::sum(choose_window().n_elements(), comm) <
               surface_size;
    };
    if (!factorized || factorized_bulk != assembled_bulk || window_shrinks())
      factorize(matrix);
  }


  // With the window of the present iterate; a new window needs a new
  // analysis.
  void
  ReusedFactorization::factorize(const TrilinosWrappers::SparseMatrix &matrix)
  {
    std::vector<int> owned;
    for (const auto i : choose_window())
      owned.push_back(static_cast<int>(i));
    std::vector<int> window = gather_concatenated(comm, owned, -1);
    std::sort(window.begin(), window.end());
    if (window != window_list)
      direct.clear();
    window_list = std::move(window);
    if (!direct.analysed())
      {
        TimerOutput::Scope t(timer, "linear: analyse");
        direct.analyse(matrix, window_list);
      }
    TimerOutput::Scope t(timer, "linear: factorize");
    direct.factorize(matrix);
    factorized_block = surface_block(matrix, true);
    factorized       = true;
    factorized_bulk  = assembled_bulk;
    ++factorizations;
  }


  int
  ReusedFactorization::position(const long long int i) const
  {
    const auto p = std::lower_bound(window_list.begin(), window_list.end(), i);
    return (p != window_list.end() && *p == i) ? p - window_list.begin() : -1;
  }


  // The entries of the owned surface rows, in the order of the matrix's
  // rows; with `record`, where they go and the rows' diagonals.
  std::vector<double>
  ReusedFactorization::surface_block(
    const TrilinosWrappers::SparseMatrix &matrix,
    const bool                            record)
  {
    const Epetra_CrsMatrix &A = matrix.trilinos_matrix();
    std::vector<double>     block;
    if (record)
      {
        entries.clear();
        diagonal.clear();
      }
    for (const auto row : surface)
      {
        int     n;
        double *v;
        int    *c;
        A.ExtractMyRowView(A.LRID(static_cast<long long int>(row)), n, v, c);
        block.insert(block.end(), v, v + n);
        if (!record)
          continue;
        double diagonal_entry = 0.;
        for (int j = 0; j < n; ++j)
          {
            const long long int column = A.ColMap().GID64(c[j]);
            entries.push_back({position(row),
                               position(column),
                               static_cast<unsigned int>(diagonal.size())});
            if (column == static_cast<long long int>(row))
              diagonal_entry = std::abs(v[j]);
          }
        diagonal.push_back(diagonal_entry);
      }
    return block;
  }


  // D = J_TT - A_TT as (row, column, value) and b_T as (row, value), the
  // owned parts of every process on the host. A change of the matrix
  // outside T x T above 1e-3 of its row's diagonal (a node that entered
  // the traction law's stiff range) asks for a new window.
  ReusedFactorization::SurfaceTerms
  ReusedFactorization::gather_surface_terms(
    const TrilinosWrappers::SparseMatrix &matrix,
    const Vector                         *b)
  {
    const std::vector<double> block = surface_block(matrix, false);
    AssertThrow(block.size() == factorized_block.size(),
                ExcMessage("The matrix changed its pattern without reinit()"));
    std::vector<double> change, border;
    int                 outside = 0;
    for (unsigned int e = 0; e < block.size(); ++e)
      if (const double c = block[e] - factorized_block[e]; c != 0.)
        {
          const Entry &entry = entries[e];
          if (entry.row >= 0 && entry.column >= 0)
            change.insert(change.end(),
                          {double(entry.row), double(entry.column), c});
          else if (std::abs(c) > 1e-3 * diagonal[entry.surface_row])
            outside = 1;
        }
    if (b)
      for (const auto i : surface)
        if (const int p = position(i); p >= 0)
          border.insert(border.end(), {double(p), (*b)[i]});
    return {gather_concatenated(comm, change, 0),
            gather_concatenated(comm, border, 0),
            Utilities::MPI::max(outside, comm) != 0};
  }


  void
  ReusedFactorization::solve(const TrilinosWrappers::SparseMatrix &matrix,
                             const Vector                         &rhs,
                             Vector                               &x)
  {
    solve_condensed(matrix, nullptr, 0., rhs, 0., x);
  }


  double
  ReusedFactorization::solve_bordered(
    const TrilinosWrappers::SparseMatrix &matrix,
    const Vector                         &b,
    const double                          d,
    const Vector                         &r,
    const double                          m,
    Vector                               &x)
  {
    return solve_condensed(matrix, &b, d, r, m, x);
  }


  // The dense system on the window: the Schur complement S with the change
  // of the present matrix from the factorized one, and with the border of
  // force control (corner d) if asked.
  LAPACKFullMatrix<double>
  ReusedFactorization::window_matrix(const SurfaceTerms &terms,
                                     const bool          bordered,
                                     const double        d) const
  {
    const unsigned int       k = window_list.size();
    LAPACKFullMatrix<double> K(bordered ? k + 1 : k, bordered ? k + 1 : k);
    // S comes by rows and K is stored by columns: copied in tiles that
    // stay in the cache on both sides.
    const auto        &S    = direct.schur_complement();
    const unsigned int tile = 64;
    for (unsigned int i0 = 0; i0 < k; i0 += tile)
      for (unsigned int j0 = 0; j0 < k; j0 += tile)
        for (unsigned int j = j0; j < std::min(j0 + tile, k); ++j)
          for (unsigned int i = i0; i < std::min(i0 + tile, k); ++i)
            K(i, j) = S[i * k + j];
    const auto &change = terms.change;
    for (unsigned int e = 0; e < change.size(); e += 3)
      K(change[e], change[e + 1]) += change[e + 2];
    if (bordered)
      {
        const auto &border = terms.border;
        for (unsigned int e = 0; e < border.size(); e += 2)
          K(k, border[e]) = K(border[e], k) = border[e + 1];
        K(k, k) = d;
      }
    return K;
  }


  // Whether the part of b outside T holds more than 1e-3 of its l1 norm:
  // left out, it leaves Newton's method under force control converging
  // linearly (measured: a factor of 0.7 per iteration on a 3D adhesive
  // sphere, stalling).
  bool
  ReusedFactorization::border_outside_window(const Vector &b) const
  {
    double outside = 0., all = 0.;
    for (const auto i : surface)
      {
        all += std::abs(b[i]);
        if (position(i) < 0)
          outside += std::abs(b[i]);
      }
    return Utilities::MPI::sum(outside, comm) >
           1e-3 * Utilities::MPI::sum(all, comm);
  }


  // The bordered system by superposition on the window's linear system
  // (without the window's model, which is not linear): K z = r, K w = b,
  // t = (m - b.z) / (d - b.w), x = z - t w.
  double
  ReusedFactorization::solve_by_superposition(const SurfaceTerms &terms,
                                              const Vector       &b,
                                              const double        d,
                                              const Vector       &r,
                                              const double        m,
                                              Vector             &x)
  {
    TimerOutput::Scope       t(timer, "linear: surface solve");
    const unsigned int       k = window_list.size();
    LAPACKFullMatrix<double> K;
    int                      singular = 0;
    if (Utilities::MPI::this_mpi_process(comm) == 0)
      try
        {
          K = window_matrix(terms, false, 0.);
          K.compute_lu_factorization();
        }
      catch (const std::exception &)
        {
          singular = 1;
        }
    AssertThrow(Utilities::MPI::max(singular, comm) == 0,
                ExcMessage("The Newton matrix is singular on the surface"));
    const auto solve = [&](const Vector &v, Vector &z) {
      const std::vector<double> reduced = direct.reduce(v);
      std::vector<double>       x_T(k);
      if (Utilities::MPI::this_mpi_process(comm) == 0)
        {
          dealii::Vector<double> y(reduced.begin(), reduced.end());
          K.solve(y);
          std::copy(y.begin(), y.end(), x_T.begin());
        }
      direct.expand(x_T, z);
    };
    Vector w(b);
    solve(r, x);
    solve(b, w);
    surface_solves += 2;
    const double t_value = (m - b * x) / (d - b * w);
    x.add(-t_value, w);
    return t_value;
  }


  // The exact solution through the factorization of A: on the host the
  // dense system on T,
  //   [S + D   b_T] [x_T]   [r_T - A_TI A_II^-1 r_I]
  //   [b_T^T   d  ] [t  ] = [m                     ],
  // D = J_TT - A_TT; then x from x_T by the back-substitution.
  double
  ReusedFactorization::solve_condensed(
    const TrilinosWrappers::SparseMatrix &matrix,
    const Vector                         *b,
    const double                          d,
    const Vector                         &r,
    const double                          m,
    Vector                               &x)
  {
    factorize_if_needed(matrix);
    SurfaceTerms terms = gather_surface_terms(matrix, b);
    if (terms.outside_window)
      {
        factorize(matrix);
        terms = gather_surface_terms(matrix, b);
      }
    if (b && border_outside_window(*b))
      return solve_by_superposition(terms, *b, d, r, m, x);
    const WindowModel model =
      build_model ? build_model(window_list) : WindowModel();
    const double              start_norm = std::hypot(r.l2_norm(), b ? m : 0.);
    TimerOutput::Scope        t(timer, "linear: surface solve");
    const std::vector<double> reduced = direct.reduce(r);
    const unsigned int        k       = window_list.size();
    std::vector<double>       x_T(k);
    double                    t_value  = 0.;
    int                       singular = 0;
    if (Utilities::MPI::this_mpi_process(comm) == 0)
      {
        LAPACKFullMatrix<double> K = window_matrix(terms, b != nullptr, d);
        dealii::Vector<double>   y(K.m());
        std::copy(reduced.begin(), reduced.end(), y.begin());
        if (b)
          y(k) = m;
        try
          {
            if (model.terms)
              {
                const WindowSolution s = newton_on_window(
                  K, reduced, b != nullptr, d, m, start_norm, model);
                std::copy(s.x.begin(), s.x.end(), x_T.begin());
                t_value = s.t;
                window_iterations += s.iterations;
              }
            else
              {
                K.compute_lu_factorization();
                K.solve(y);
                std::copy(y.begin(), y.begin() + k, x_T.begin());
                if (b)
                  t_value = y(k);
              }
          }
        catch (const std::exception &)
          {
            singular = 1;
          }
      }
    // Every process learns it, or the others would wait in expand().
    AssertThrow(Utilities::MPI::max(singular, comm) == 0,
                ExcMessage("The Newton matrix is singular on the surface"));
    direct.expand(x_T, x);
    ++surface_solves;
    return Utilities::MPI::broadcast(comm, t_value, 0);
  }
} // namespace viscoslide

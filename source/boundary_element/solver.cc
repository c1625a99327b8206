// BoundaryElementSolver: the grid, Newton's method with its preconditioned
// GMRES, the continuation in approach, speed and load, and the run.
#include <deal.II/base/utilities.h>
#include <deal.II/lac/solver_control.h>
#include <deal.II/lac/solver_gmres.h>

#include <viscoslide/boundary_element/solver.h>
#include <viscoslide/boundary_element/window_preconditioner.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <numeric>

namespace viscoslide
{
  namespace
  {
    // The smallest n >= m of the form 2^a 3^b 5^c 7^d, even, for which
    // FFTW is fastest.
    unsigned int
    fft_size(const double m)
    {
      for (unsigned int n = std::max(2u, 2 * (unsigned int)(std::ceil(m / 2)));;
           n += 2)
        {
          unsigned int r = n;
          for (const unsigned int p : {2u, 3u, 5u, 7u})
            while (r % p == 0)
              r /= p;
          if (r == 1)
            return n;
        }
    }
  } // namespace


  template <int dim>
  BoundaryElementSolver<dim>::BoundaryElementSolver(CaseParts &parts)
    : prm(parts.prm)
    , comm(parts.comm)
    , pcout(std::cout,
            Utilities::MPI::this_mpi_process(comm) == 0 &&
              prm.output.verbosity != Parameters::Verbosity::quiet)
    , timer(comm, pcout, TimerOutput::never, TimerOutput::wall_times)
    , scales(parts.scales)
    , material(parts.material)
    , law(*parts.law)
    , law_range(parts.scales.eps)
    , indenter(*parts.indenter)
    , writer(parts.writer)
    , steady_state_table(parts.steady_state_table)
    , progress(parts.progress)
    , dx((prm.boundary_element.grid_spacing > 0
            ? prm.boundary_element.grid_spacing
            : prm.mesh.finest_cell / 2) *
         scales.eps)
    , dA(std::pow(dx, dim - 1))
    , graded(dim == 2 &&
             prm.boundary_element.grid == Parameters::GridKind::graded)
    , substrate(Parameters::Substrate::layer)
    , thickness(prm.geometry.height() * scales.eps)
  {
  }


  template <int dim>
  BoundaryElementSolver<dim>::~BoundaryElementSolver() = default;


  template <int dim>
  void
  BoundaryElementSolver<dim>::make_grid(
    const std::array<unsigned int, dim - 1> &new_shape)
  {
    const Vector<double>                    old_u     = u;
    const std::array<unsigned int, dim - 1> old_shape = shape;
    shape                                             = new_shape;
    const unsigned int n_x = shape[dim - 2], n_y = dim == 2 ? 1 : shape[0];
    const unsigned int n = n_x * n_y;
    if (isolated_half_space())
      compliance =
        std::make_unique<IsolatedCompliance>(material,
                                             prm.material.poisson_ratio,
                                             std::array<unsigned int, 2>{
                                               {shape[0], shape[dim - 2]}},
                                             dx);
    else
      compliance = std::make_unique<SurfaceCompliance<dim>>(
        substrate, thickness, material, prm.material.poisson_ratio, shape, dx);
    // The preconditioner's operator is periodic on the window in any case.
    if constexpr (dim == 3)
      multigrid = std::make_unique<SurfaceMultigrid<dim>>(
        substrate, thickness, material, prm.material.poisson_ratio, shape, dx);
    set_compliance_speed(V_hat * scales.eps / scales.tau_ref);
    x.resize(n);
    y.resize(n);
    h.resize(n);
    slope.resize(n);
    u.reinit(n);
    const unsigned int old_x = old_shape[dim - 2],
                       old_y = dim == 2 ? 1 : old_shape[0];
    for (unsigned int j = 0; j < n; ++j)
      {
        const long i_x = j % n_x, i_y = j / n_x;
        x[j] = (double(i_x) - n_x / 2) * dx;
        y[j] = dim == 2 ? 0. : (double(i_y) - n_y / 2) * dx;
        // In 3D the body of revolution of the profile, stretched across
        // the track by the elongation.
        const double r =
          dim == 2
            ? x[j]
            : std::hypot(x[j], y[j] / std::sqrt(prm.geometry.elongation));
        h[j]     = indenter.profile(r);
        slope[j] = dim == 2 ? indenter.slope(x[j])
                            : (r > 0 ? indenter.slope(r) * x[j] / r : 0.);
        // The same point on the old grid; beyond it, its nearer end.
        if (old_u.size() > 0)
          {
            const long o_x = std::clamp<long>(i_x - n_x / 2 + old_x / 2,
                                              0,
                                              long(old_x) - 1),
                       o_y = std::clamp<long>(i_y - n_y / 2 + old_y / 2,
                                              0,
                                              long(old_y) - 1);
            u[j]           = old_u[o_y * old_x + o_x];
          }
      }
    area.assign(n, dA);
    ++grid_generation;
    preconditioner.reset();
    pcout << "Boundary-element grid: " << n << " points";
    if (dim == 3)
      pcout << " (" << n_x << " x " << n_y << ")";
    pcout << ", spacing " << dx << " eps, "
          << (isolated_half_space() ? "window " : "period ") << n_x * dx;
    if (dim == 3)
      pcout << " x " << n_y * dx;
    pcout << " eps";
    if (multigrid)
      pcout << ", " << multigrid->n_levels() << " multigrid levels";
    pcout << std::endl;
  }


  template <int dim>
  void
  BoundaryElementSolver<dim>::fit_period(const double V)
  {
    if (graded)
      return; // the graded grid follows the contact, not the period
    // The isolated half-space of 3D needs no period: its window is the
    // Domain width along the track and the Domain length across it at
    // every speed.
    const double wake = V * longest_creep_time(prm) * scales.eps;
    const double period =
      isolated_half_space() ? prm.geometry.domain_width * scales.eps
      : prm.boundary_element.period > 0
        ? prm.boundary_element.period * scales.eps
        : std::max(prm.geometry.domain_width * scales.eps,
                   prm.boundary_element.wake_periods * wake);
    // In 3D, x and y coarsen together in the multigrid: both counts a
    // multiple of 2^levels, so that the coarsest grid is small.
    const unsigned int                multiple = dim == 2 ? 1 : 16;
    std::array<unsigned int, dim - 1> new_shape;
    new_shape[dim - 2] = multiple * fft_size(period / dx / multiple);
    if constexpr (dim == 3)
      new_shape[0] =
        multiple * fft_size(prm.geometry.length() * scales.eps / dx / multiple);
    const unsigned int n_x = new_shape[dim - 2], old_x = shape[dim - 2];
    if (u.size() == 0 || n_x > old_x || 4 * n_x < old_x)
      make_grid(new_shape);
  }


  template <int dim>
  bool
  BoundaryElementSolver<dim>::isolated_half_space() const
  {
    return dim == 3 && substrate == Parameters::Substrate::half_plane;
  }


  template <int dim>
  void
  BoundaryElementSolver<dim>::make_graded_grid(
    const std::vector<double>           &new_boundaries,
    const std::pair<double, double>     &edges,
    const std::function<double(double)> &shift)
  {
    // The state carried over as its gaps: they vary on the scale of eps
    // near the edges, while u varies by thousands of eps over the contact
    // at R_hat 1e6, where interpolated displacements would put points deep
    // into the repulsive wall.
    std::vector<double> old_gap(x.size());
    for (unsigned int j = 0; j < x.size(); ++j)
      old_gap[j] = scales.eps + h[j] - delta - u[j];
    const unsigned int n = new_boundaries.size() - 1;
    Vector<double>     gap(n);
    for (unsigned int j = 0; j < n; ++j)
      {
        // The first grid: u = 0. Else linear between the old points, beyond
        // them the nearer end's.
        const double centre = 0.5 * (new_boundaries[j] + new_boundaries[j + 1]);
        const double from   = shift ? centre - shift(centre) : centre;
        const auto   k = std::upper_bound(x.begin(), x.end(), from) - x.begin();
        if (x.empty())
          gap[j] = scales.eps + indenter.profile(centre) - delta;
        else if (k == 0)
          gap[j] = old_gap[0];
        else if (k == long(x.size()))
          gap[j] = old_gap[x.size() - 1];
        else
          {
            const double t = (from - x[k - 1]) / (x[k] - x[k - 1]);
            gap[j]         = (1 - t) * old_gap[k - 1] + t * old_gap[k];
          }
      }
    set_graded_cells(new_boundaries, edges, gap);
    ++grid_generation;
    pcout << "Graded boundary-element grid: " << n << " cells, " << dx
          << " eps at the contact edges x = " << edges.first / scales.eps
          << ", " << edges.second / scales.eps << " eps, window "
          << boundaries.front() / scales.eps << " to "
          << boundaries.back() / scales.eps << " eps" << std::endl;
  }


  template <int dim>
  void
  BoundaryElementSolver<dim>::set_graded_cells(
    const std::vector<double>       &new_boundaries,
    const std::pair<double, double> &edges,
    const Vector<double>            &gap,
    std::unique_ptr<Compliance>      kept)
  {
    boundaries           = new_boundaries;
    grid_edges           = edges;
    const unsigned int n = boundaries.size() - 1;
    shape[dim - 2]       = n;
    if (kept)
      compliance = std::move(kept);
    else
      {
        // The window preconditioner refers to the compliance it was made
        // with.
        preconditioner.reset();
        compliance = std::make_unique<GradedCompliance>(
          material, prm.material.poisson_ratio, boundaries, thickness);
        set_compliance_speed(V_hat * scales.eps / scales.tau_ref);
      }
    x.resize(n);
    y.assign(n, 0.);
    h.resize(n);
    slope.resize(n);
    area.resize(n);
    u.reinit(n);
    for (unsigned int j = 0; j < n; ++j)
      {
        x[j]     = 0.5 * (boundaries[j] + boundaries[j + 1]);
        area[j]  = boundaries[j + 1] - boundaries[j];
        h[j]     = indenter.profile(x[j]);
        slope[j] = indenter.slope(x[j]);
        u[j]     = scales.eps + h[j] - delta - gap[j];
      }
    // The boundaries at the two edges (graded_boundaries places them).
    for (unsigned int e = 0; e < 2; ++e)
      {
        const double at = e == 0 ? edges.first : edges.second;
        focus[e] = std::lower_bound(boundaries.begin(), boundaries.end(), at) -
                   boundaries.begin();
      }
  }


  template <int dim>
  void
  BoundaryElementSolver<dim>::predict_graded_grid(
    const std::pair<double, double> &edges,
    const std::pair<double, double> &edges_before,
    const double                     ratio)
  {
    if (!(std::abs(ratio) <= 2) || edges.second <= edges.first)
      return;
    const double trail =
                   edges.first + ratio * (edges.first - edges_before.first),
                 lead =
                   edges.second + ratio * (edges.second - edges_before.second);
    if (!(lead > trail))
      return;
    // Each edge's zone moved with its edge.
    const auto shift =
      edge_shift(edges, trail - edges.first, lead - edges.second);
    make_graded_grid_about(trail, lead, shift);
  }


  template <int dim>
  void
  BoundaryElementSolver<dim>::make_graded_grid_about(
    const double                         trail,
    const double                         lead,
    const std::function<double(double)> &shift)
  {
    const double margin =
      std::max(margin_factor * (lead - trail), 50 * scales.eps);
    make_graded_grid(graded_boundaries(trail,
                                       lead,
                                       dx,
                                       prm.boundary_element.grading_ratio,
                                       margin),
                     {trail, lead},
                     shift);
  }


  template <int dim>
  bool
  BoundaryElementSolver<dim>::refit_graded_grid(const bool always)
  {
    const unsigned int n     = u.size();
    const double       ratio = prm.boundary_element.grading_ratio;
    // Where the cells are at most 1.5 times the finest.
    const double tolerance = 0.5 * dx / (ratio - 1);
    const double trail = last_quantities.x_trail, lead = last_quantities.x_lead;
    const bool   loaded_ends =
      std::max(std::abs(traction[0]), std::abs(traction[n - 1])) >
      1e-4 * scales.sigma_max;
    if (loaded_ends)
      margin_factor *= 2;
    if (!always && !loaded_ends &&
        std::abs(trail - grid_edges.first) <= tolerance &&
        std::abs(lead - grid_edges.second) <= tolerance)
      return false;
    make_graded_grid_about(trail, lead);
    return true;
  }


  template <int dim>
  void
  BoundaryElementSolver<dim>::start_from_jkr_contact()
  {
    // The JKR contact in plane strain (cylinder_jkr_half_width, grid.h) of
    // the relaxed solid (E0* = 1) gives the contact's width 2a.
    const double P = prm.loading.target_load * scales.force;
    const double a = cylinder_jkr_half_width(P, scales.dgamma, scales.R);
    if (!std::isfinite(a))
      throw Parameters::ExcInvalidInput(
        "'Loading/Target load' = " + CsvTable::format(prm.loading.target_load) +
        " is below the JKR pull-off force of the relaxed contact: "
        "'Boundary element/Grid' = graded starts from the JKR contact");
    make_graded_grid_about(-a, a);
    // On the grid, the traction of the cells |x_j| < a that holds their
    // gap at eps (u_j = h_j - delta) under the load P, delta unknown: the
    // discrete JKR contact, its adhesive edges from the width alone. The
    // displacements are thousands of eps at R_hat 1e6, so that the state
    // must come from the grid's own compliance to be within a fraction of
    // eps of an equilibrium.
    // Those cells are the contiguous [first, first + m) of the sorted x.
    const unsigned int first =
      std::lower_bound(x.begin(), x.end(), -a) - x.begin();
    const unsigned int m =
      std::lower_bound(x.begin(), x.end(), a) - x.begin() - first;
    const FullMatrix<double> c = compliance->block(first, m);
    LAPACKFullMatrix<double> system(m + 1, m + 1);
    Vector<double>           rhs(m + 1);
    for (unsigned int i = 0; i < m; ++i)
      {
        for (unsigned int j = 0; j < m; ++j)
          system(i, j) = c(i, j);
        system(i, m) = 1.;
        system(m, i) = -area[first + i] / scales.sigma_max;
        rhs[i]       = h[first + i];
      }
    rhs[m] = P / scales.sigma_max;
    system.compute_lu_factorization();
    system.solve(rhs);
    Vector<double> q(x.size());
    for (unsigned int i = 0; i < m; ++i)
      q[first + i] = rhs[i];
    delta = rhs[m];
    compliance->apply(q, u);
    // Newton's method from this contact converges for Tabor parameters up
    // to about 10, and crawls beyond (the adhesive zone must form at each
    // edge, a short-range jump). A larger one is reached by continuation
    // in the law's range: the same law with range l > eps and the same
    // dgamma, so that the contact is nearly the same (JKR's depends on
    // dgamma alone) while the zone is l^(3/2) times wider; l then shrinks
    // to eps in steps of 0.7, each equilibrium the start of the next.
    double range =
      scales.eps *
      std::max(1., prm.adhesion.tabor_parameter / start_tabor_parameter);
    set_law_range(range);
    // The contact at the law's equilibrium gap, the range.
    delta -= range - scales.eps;
    // Inside, the gap at which the law gives that traction (at most its
    // peak), so that the residual u - C q(g) starts small.
    const auto start_gap = gap_for_traction(traction_law(), range);
    for (unsigned int j = first; j < first + m; ++j)
      u[j] = scales.eps + h[j] - delta - start_gap(q[j]);
    control.hold_force(P);
    pcout << "Start: the JKR contact of the relaxed solid at F_hat = "
          << prm.loading.target_load << ", L_hat = " << 2 * a / scales.R;
    if (range > scales.eps)
      pcout << ", the law's range from " << range / scales.eps << " eps";
    pcout << std::endl;
    const auto fail = [this](const double at) {
      return std::runtime_error(
        "the boundary-element solver found no equilibrium from the JKR "
        "contact at the Target load (Newton's method and the relaxation "
        "did not converge on the graded grid at the law's range " +
        CsvTable::format(at / scales.eps) + " eps)");
    };
    if (solve() < 0)
      throw fail(range);
    // Each step shrinks the range by `factor`; a step that fails is taken
    // again shorter, and only a step of a few percent is given the
    // relaxation, which crawls.
    double factor = 0.7;
    while (range > scales.eps)
      {
        const Vector<double> u_at = u, gaps_at = gaps, traction_at = traction;
        const double         delta_at                 = delta;
        const std::vector<double>       boundaries_at = boundaries;
        const std::pair<double, double> edges_at      = grid_edges;
        const double next = std::max(scales.eps, factor * range);
        // The contact's gap shrinks with the range: delta follows, so that
        // the next law finds the contact at its own equilibrium gap; where
        // the surfaces are nearer than the old law's peak, the gap is where
        // the new law gives the old traction (the wall's stiffness grows as
        // 1/range^2: at the old gaps the pressure under the contact would
        // jump).
        const double peak = gap_for_traction(traction_law(), range)(1e300);
        set_law_range(next);
        const auto next_gap = gap_for_traction(traction_law(), next);
        delta += range - next;
        for (unsigned int j = 0; j < u.size(); ++j)
          if (gaps_at[j] < peak)
            u[j] = scales.eps + h[j] - delta - next_gap(traction_at[j]);
        const bool last_resort = factor > 0.95;
        if (solve(last_resort) >= 0)
          {
            range  = next;
            factor = std::max(0.7, factor * factor);
            pcout << "  the law's range " << range / scales.eps << " eps, "
                  << u.size() << " cells, L_hat = "
                  << last_quantities.contact_length / scales.contact
                  << std::endl;
            continue;
          }
        if (last_resort)
          throw fail(next);
        set_law_range(range);
        delta = delta_at;
        set_graded_cells(boundaries_at, edges_at, gaps_at);
        u = u_at;
        assemble(false); // the gaps and tractions the next step starts from
        factor = std::sqrt(factor);
      }
  }


  template <int dim>
  std::function<double(double)>
  BoundaryElementSolver<dim>::gap_for_traction(const InteractionLaw &law,
                                               const double range) const
  {
    // The law rises from its repulsive wall through 0 at the range to its
    // peak: found once, then each traction's gap by bisection below it.
    double peak = range;
    for (double g = range; g < 3 * range; g += 1e-3 * range)
      if (law.traction(g) > law.traction(peak))
        peak = g;
    return [&law, range, peak](const double q) {
      double lo = 0.2 * range, hi = peak;
      for (unsigned int k = 0; k < 100; ++k)
        {
          const double mid                  = 0.5 * (lo + hi);
          (law.traction(mid) < q ? lo : hi) = mid;
        }
      return 0.5 * (lo + hi);
    };
  }


  template <int dim>
  void
  BoundaryElementSolver<dim>::set_law_range(const double range)
  {
    law_range = range;
    ranged_law.reset();
    if (range != scales.eps)
      ranged_law =
        create_interaction_law(prm.adhesion.law, scales.dgamma, range);
    preconditioner.reset();
  }


  template <int dim>
  void
  BoundaryElementSolver<dim>::set_compliance_speed(const double V)
  {
    compliance->set_speed(V);
    if (multigrid)
      multigrid->set_speed(V);
  }


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


  template <int dim>
  void
  BoundaryElementSolver<dim>::assemble(const bool with_matrix)
  {
    TimerOutput::Scope t(timer, "boundary element: residual");
    const unsigned int n = u.size();
    gaps.reinit(n);
    traction.reinit(n);
    tangent.reinit(n);
    Vector<double> w(n), Cw;
    double         Fn = 0;
    for (unsigned int j = 0; j < n; ++j)
      {
        gaps[j]     = scales.eps + h[j] - delta - u[j];
        traction[j] = traction_law().traction(gaps[j]);
        tangent[j]  = traction_law().derivative(gaps[j]);
        w[j] = traction[j] - (dashpot > 0 ? dashpot * (u[j] - anchor[j]) : 0.);
        Fn -= traction[j] * area[j];
      }
    compliance->apply(w, Cw);
    residual.reinit(n + 1);
    for (unsigned int j = 0; j < n; ++j)
      residual[j] = u[j] - Cw[j];
    residual[n] = control.force_controlled
                    ? control.mismatch(Fn, delta) / scales.sigma_max
                    : 0.;
    if (with_matrix && graded)
      {
        // The residual's rounding error: at R_hat 1e6 and more u is 1e4
        // eps, its gap's last digits times the repulsive wall's stiffness
        // a traction that the coarse cells' compliance turns into 1e-6 eps
        // and more, above the tolerance. The graded compliance is
        // positive, so that C|v| sums the magnitudes of the terms of C v;
        // their rounding errors, of either sign, add up as a random walk
        // (1/sqrt(n) of that sum).
        Vector<double> magnitude(n), C_magnitude;
        for (unsigned int j = 0; j < n; ++j)
          magnitude[j] =
            std::abs(traction[j]) +
            std::abs(tangent[j]) *
              (std::abs(u[j]) + std::abs(h[j]) + std::abs(delta) + scales.eps);
        compliance->apply(magnitude, C_magnitude);
        double sum = 0;
        for (unsigned int j = 0; j < n; ++j)
          sum += std::pow(std::numeric_limits<double>::epsilon() *
                            (std::abs(u[j]) + C_magnitude[j]),
                          2);
        round_off = std::sqrt(sum / n) / scales.eps;
      }
    if (with_matrix)
      update_preconditioner();
  }


  template <int dim>
  void
  BoundaryElementSolver<dim>::update_preconditioner()
  {
    const unsigned int n = u.size();
    if constexpr (dim == 3)
      {
        TimerOutput::Scope t(timer, "boundary element: multigrid");
        Vector<double>     weight(tangent);
        weight.add(dashpot);
        multigrid->update(
          weight, tangent, control.force_controlled, dA, scales.sigma_max);
      }
    else
      {
        // The points where the traction law is stiff, and a window about
        // them with a margin of an eighth of their width, so that the
        // factorization serves while the contact edges move within it.
        const double stiff = 1e-3 * tangent.linfty_norm();
        long         first = -1, last = -1;
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
        if (!preconditioner || !last_gmres_converged ||
            last_gmres_work * solves_since_factorization >
              work_since_factorization ||
            !preconditioner->covers(no_contact ? 0 : first,
                                    no_contact ? 0 : last + 1 - first))
          {
            TimerOutput::Scope t(timer, "boundary element: factorization");
            preconditioner =
              std::make_unique<WindowPreconditioner>(*compliance,
                                                     tangent,
                                                     dashpot,
                                                     begin,
                                                     m,
                                                     control.force_controlled,
                                                     area,
                                                     scales.sigma_max,
                                                     graded);
            work_since_factorization   = factorization_work(m);
            solves_since_factorization = 1;
            last_gmres_work            = 0.;
            last_gmres_converged       = true;
          }
      }
  }


  template <int dim>
  double
  BoundaryElementSolver<dim>::residual_norm() const
  {
    // The l2 norm of the displacement misfit: a smooth merit function for
    // the line search (the largest misfit alone stalled it at the contact
    // edges). With it the load equation relative to the total absolute
    // traction, as the finite-element solvers measure their residual.
    const unsigned int n        = u.size();
    double             misfit   = 0;
    double             absolute = 0;
    for (unsigned int j = 0; j < n; ++j)
      {
        misfit += residual[j] * residual[j];
        absolute += std::abs(traction[j]) * area[j];
      }
    const double load =
      residual[n] * scales.sigma_max / (absolute + scales.sigma_max * dA);
    // In 3D per row of points, as a line of them is measured in 2D.
    if (dim == 3)
      misfit /= shape[0];
    return std::sqrt(misfit / (scales.eps * scales.eps) + load * load);
  }


  template <int dim>
  void
  BoundaryElementSolver<dim>::compute_update()
  {
    Vector<double> rhs(residual);
    rhs *= -1.;
    solve_linearized(rhs, update);
  }


  template <int dim>
  void
  BoundaryElementSolver<dim>::solve_linearized(const Vector<double> &rhs,
                                               Vector<double>       &solution)
  {
    TimerOutput::Scope t(timer, "boundary element: GMRES");
    const unsigned int n = u.size();
    // The Jacobian: du + C[(q' + c) du + q' d delta], and the load row.
    struct Jacobian
    {
      const BoundaryElementSolver &s;
      void
      vmult(Vector<double> &dst, const Vector<double> &src) const
      {
        const unsigned int n = s.u.size();
        Vector<double>     w(n), Cw;
        double             load = 0;
        for (unsigned int j = 0; j < n; ++j)
          {
            const double du = src[j];
            const double dd = s.control.force_controlled ? src[n] : 0.;
            w[j]            = s.tangent[j] * (du + dd) + s.dashpot * du;
            load += s.tangent[j] * (du + dd) * s.area[j];
          }
        s.compliance->apply(w, Cw);
        for (unsigned int j = 0; j < n; ++j)
          dst[j] = src[j] + Cw[j];
        dst[n] =
          s.control.force_controlled ? load / s.scales.sigma_max : src[n];
      }
    } jacobian{*this};
    solution.reinit(n + 1);
    SolverControl solver_control(1000, 1e-8 * rhs.l2_norm(), false, false);
    SolverGMRES<Vector<double>> gmres(
      solver_control, SolverGMRES<Vector<double>>::AdditionalData(100));
    try
      {
        if constexpr (dim == 3)
          gmres.solve(jacobian, solution, rhs, *multigrid);
        else
          gmres.solve(jacobian, solution, rhs, *preconditioner);
        last_gmres_converged = true;
      }
    catch (SolverControl::NoConvergence &)
      {
        // Newton's method judges the update by the residual it gives; the
        // next Jacobian gets a new factorization.
        last_gmres_converged = false;
      }
    gmres_iterations += solver_control.last_step();
    ++gmres_solves;
    if constexpr (dim == 2)
      {
        last_gmres_work =
          gmres_work(n, preconditioner->size(), solver_control.last_step());
        work_since_factorization += last_gmres_work;
        ++solves_since_factorization;
      }
  }


  template <int dim>
  NewtonProblem
  BoundaryElementSolver<dim>::newton_problem()
  {
    NewtonProblem p;
    p.assemble      = [this](const bool with_matrix) { assemble(with_matrix); };
    p.residual_norm = [this] { return residual_norm(); };
    p.tolerance     = [this] {
      return std::max(100. * prm.solver.newton_tolerance, round_off);
    };
    p.compute_update   = [this] { compute_update(); };
    p.update_norm      = [this] { return update.l2_norm(); };
    p.update_max_norm  = [this] { return update.linfty_norm(); };
    p.remember_iterate = [this] {
      u0     = u;
      delta0 = delta;
    };
    p.step = [this](const double alpha) {
      const unsigned int n = u.size();
      for (unsigned int j = 0; j < n; ++j)
        u[j] = u0[j] + alpha * update[j];
      delta = delta0 + (control.force_controlled ? alpha * update[n] : 0.);
    };
    p.set_dashpot = [this](const double c) {
      dashpot = c;
      if (c > 0)
        anchor = u;
    };
    return p;
  }


  template <int dim>
  int
  BoundaryElementSolver<dim>::solve(const bool relax)
  {
    int its = solve_on_grid(relax);
    if (!graded || its < 0)
      return its;
    // A graded grid follows the contact edges: solved again on a grid
    // about the edges found, until they are where the grid is finest. If
    // that fails, the state before, on its own grid.
    const std::vector<double> old_boundaries = boundaries;
    const Vector<double>      old_u          = u;
    const double              old_delta      = delta;
    const auto                old_edges      = grid_edges;
    for (unsigned int k = 0; k < 8 && refit_graded_grid(false); ++k)
      {
        const int more = solve_on_grid(relax);
        if (more < 0)
          {
            make_graded_grid(old_boundaries, old_edges);
            u     = old_u;
            delta = old_delta;
            update_quantities();
            return -1;
          }
        its += more;
      }
    last_newton_iterations = its;
    return its;
  }


  template <int dim>
  int
  BoundaryElementSolver<dim>::solve_on_grid(const bool relax)
  {
    const Vector<double> u_start          = u;
    const double         delta_start      = delta;
    const NewtonProblem  problem          = newton_problem();
    auto                 relax_from_start = [&] {
      u     = u_start;
      delta = delta_start;
      preconditioner.reset();
      const int steps = relax_surface(problem, scales, prm.solver, pcout);
      dashpot = 0;
      return steps;
    };
    // Without contact the surface jumps in. Newton's method from the flat
    // surface lands on whichever equilibrium its steps reach; the
    // pseudo-transient relaxation follows the jump as an overdamped motion
    // would, to the first equilibrium on its way, as the finite-element
    // approach does.
    assemble(false);
    const bool in_contact = *std::min_element(gaps.begin(), gaps.end()) <
                            prm.adhesion.contact_gap * law_range;
    int its = in_contact ? newton(problem,
                                  prm.solver.max_newton_iterations,
                                  prm.solver.line_search,
                                  prm.solver.verbose,
                                  pcout)
                         : -1;
    // On a graded grid an edge's zone that must move by more than its
    // width moves as one unknown (solve_following_edges).
    if constexpr (dim == 2)
      if (its < 0 && in_contact && graded)
        {
          u     = u_start;
          delta = delta_start;
          preconditioner.reset();
          its = solve_following_edges();
          if (its >= 0)
            return its;
        }
    // Past a jump of a contact edge the equilibrium is not near: relax
    // towards it (newton.h).
    if (its < 0 && relax)
      its = relax_from_start();
    if (its < 0)
      {
        u     = u_start;
        delta = delta_start;
        preconditioner.reset();
        return -1;
      }
    last_newton_iterations = its;
    update_quantities();
    return its;
  }


  template <int dim>
  bool
  BoundaryElementSolver<dim>::follow(const double from,
                                     const double to,
                                     const double step,
                                     const double min_step,
                                     const std::function<void(double)> &set,
                                     const std::function<void()> &on_converged,
                                     const std::function<bool()> &done)
  {
    double         at = from, size = step;
    double         at_before = 0, delta_before = 0;
    Vector<double> u_before;
    unsigned int   generation_before = 0;
    // The graded grid's contact edges at the step before, for their secant.
    std::pair<double, double> edges_before;
    bool                      have_edges_before = false;
    while (at != to)
      {
        const bool           last = std::abs(to - at) <= size * (1 + 1e-9);
        const double         next = last ? to : at + (to > at ? size : -size);
        const Vector<double> u_at = u;
        const double         delta_at                 = delta;
        const unsigned int   generation_at            = grid_generation;
        const std::vector<double>       boundaries_at = boundaries;
        const std::pair<double, double> grid_edges_at = grid_edges;
        const std::pair<double, double> edges_at{last_quantities.x_trail,
                                                 last_quantities.x_lead};
        set(next);
        if (graded && have_edges_before)
          predict_graded_grid(edges_at,
                              edges_before,
                              (next - at) / (at - at_before));
        // Secant predictor from the step before, then no predicted gap
        // below the smaller of its present one and eps: a point that the
        // step before drew into contact would otherwise be extrapolated
        // deep into the repulsive wall (and without a step before, the
        // contact moved with delta), where the traction is huge and
        // Newton's method crawls back.
        const double ratio =
          generation_before == grid_generation && u_before.size() == u.size()
            ? (next - at) / (at - at_before)
            : 0.;
        const bool secant = ratio != 0. && std::abs(ratio) <= 2;
        if (secant && control.force_controlled)
          delta += ratio * (delta_at - delta_before);
        for (unsigned int j = 0;
             generation_at == grid_generation && j < u.size();
             ++j)
          {
            if (secant)
              u[j] += ratio * (u_at[j] - u_before[j]);
            const double g_at = scales.eps + h[j] - delta_at - u_at[j];
            u[j] =
              std::min(u[j],
                       scales.eps + h[j] - delta - std::min(g_at, scales.eps));
          }
        // On a graded grid a shorter step is cheaper than the relaxation,
        // which moves the edges by a fraction of eps per step.
        if (solve(!graded) >= 0)
          {
            at_before         = at;
            u_before          = u_at;
            delta_before      = delta_at;
            generation_before = generation_at;
            edges_before      = edges_at;
            have_edges_before = graded;
            at                = next;
            on_converged();
            if (done())
              return true;
            size = std::min(step, 2 * size);
            continue;
          }
        if (graded)
          make_graded_grid(boundaries_at, grid_edges_at);
        u     = u_at;
        delta = delta_at;
        set(at);
        size /= 2;
        if (size < min_step)
          return false;
      }
    return true;
  }


  template <int dim>
  bool
  BoundaryElementSolver<dim>::continue_to(
    const double                 target,
    const std::function<void()> &on_converged)
  {
    fit_period(std::max(V_hat, target));
    auto set_speed = [this, target](const double log_V) {
      V_hat =
        std::abs(log_V - std::log(target)) < 1e-12 ? target : std::exp(log_V);
      // The factorization of the speed before stays a good preconditioner
      // (it is renewed when GMRES needs too many iterations with it).
      set_compliance_speed(V_hat * scales.eps / scales.tau_ref);
    };
    if (V_hat == 0)
      {
        // From the relaxed state: directly, or else from the speed whose
        // relaxation length is a tenth of the grid spacing for the slowest
        // arm (a spectrum's may be decades slower than the time unit of
        // V_hat). A graded grid's contact is thousands of eps wide, and
        // the creep at its edges moves them by many cells in a direct
        // jump, where Newton's method fails and the relaxation takes
        // minutes: it starts slow.
        if (!graded)
          {
            set_speed(std::log(target));
            if (solve() >= 0)
              {
                on_converged();
                return true;
              }
          }
        const double start = std::min(target,
                                      0.1 * dx /
                                        (scales.eps / scales.tau_ref *
                                         material.longest_relaxation_time()));
        set_speed(std::log(start));
        if (solve() < 0)
          {
            V_hat = 0;
            set_compliance_speed(0);
            return false;
          }
        on_converged();
      }
    // A line per step short of the target: from a slow start the
    // continuation crosses decades before the first station.
    const auto report = [&] {
      if (V_hat != target)
        pcout << "  continuation: V_hat " << V_hat << " on the way to "
              << target << " (" << last_newton_iterations
              << " Newton iterations)" << std::endl;
      on_converged();
    };
    return follow(std::log(V_hat),
                  std::log(target),
                  std::log(prm.sliding.continuation_factor),
                  1e-3,
                  set_speed,
                  report);
  }


  template <int dim>
  bool
  BoundaryElementSolver<dim>::continue_to_load(
    const double                 target,
    const std::function<void()> &on_converged)
  {
    double &parameter = control.force_controlled ? control.target_force : delta;
    const double distance = std::abs(target - parameter);
    return follow(
      parameter,
      target,
      distance / 10,
      distance * 1e-4,
      [&parameter](const double v) { parameter = v; },
      on_converged);
  }


  // Unloading in steps of the Approach increment down to Retract to; the
  // minimum force on the way is the pull-off force under displacement
  // control. The jump out of contact is relaxed as the jump in is.
  template <int dim>
  void
  BoundaryElementSolver<dim>::retract(
    const std::function<void(const std::string &)> &add_row)
  {
    const auto report = [&] {
      add_row("retract");
      pcout << "Retract delta_hat = " << approach() / scales.eps
            << ": F_n_hat = " << last_quantities.normal_force / scales.force
            << ", " << contact_column(dim) << " = "
            << last_quantities.contact_length / scales.contact << std::endl;
    };
    move_indenter(prm.loading.retract_to, "retraction", report);
  }


  // delta to delta_hat = `to` in Approach increments, cut down to the
  // Minimum approach increment where a step fails.
  template <int dim>
  void
  BoundaryElementSolver<dim>::move_indenter(const double                 to,
                                            const std::string           &phase,
                                            const std::function<void()> &report,
                                            const std::function<bool()> &done)
  {
    if (!follow(
          delta,
          to * scales.eps,
          prm.loading.increment * scales.eps,
          prm.loading.minimum_increment * scales.eps,
          [this](const double d) { delta = d; },
          report,
          done))
      throw std::runtime_error(
        "the boundary-element solver failed in the " + phase +
        " at delta_hat = " + CsvTable::format(approach() / scales.eps) +
        " (Newton's method and the relaxation did not converge with "
        "the Minimum approach increment)");
  }


  // Under force control, the approach step that passed the Target load
  // (`reached`) solved again with F_n held at exactly that load.
  template <int dim>
  void
  BoundaryElementSolver<dim>::hold_target_load(
    const bool                                      reached,
    const std::function<void(const std::string &)> &add_row)
  {
    const double F = prm.loading.target_load * scales.force;
    if (!reached)
      throw Parameters::ExcInvalidInput(
        "'Loading/Target load' = " + CsvTable::format(prm.loading.target_load) +
        " was not reached by 'Loading/Final approach' = " +
        CsvTable::format(prm.loading.final_approach) + " (F_n_hat there: " +
        CsvTable::format(last_quantities.normal_force / scales.force) +
        "); raise the Final approach");
    control.hold_force(F);
    preconditioner.reset();
    if (solve() < 0)
      throw std::runtime_error("the boundary-element solver could not "
                               "hold the Target load after the approach");
    add_row("load");
    pcout << "Load F_hat = " << prm.loading.target_load
          << " reached at delta_hat = " << approach() / scales.eps << std::endl;
  }


  template <int dim>
  void
  BoundaryElementSolver<dim>::approach_phase()
  {
    TimerOutput::Scope t(timer, "boundary element: approach");
    // In 2D on the block of Domain height; in 3D on the substrate itself
    // (the isolated half-space's delta is measured from the far field).
    // The graded grid on the half-plane from the start.
    substrate         = dim == 3 || graded ? prm.geometry.substrate
                                           : Parameters::Substrate::layer;
    thickness         = prm.geometry.height() * scales.eps;
    const double F    = prm.loading.target_load * scales.force;
    bool         done = false;
    CsvTable     table(writer.path("approach.csv"),
                   {"step",
                        "phase",
                        "delta_hat",
                        "F_n_hat",
                        contact_column(dim),
                        "min_gap_over_eps",
                        "newton_iterations",
                        "n_dofs"},
                   version_string() +
                     "; forces per unit length in (pi dgamma^2 E0* R)^(1/3)",
                   comm,
                   scales.si_columns);
    unsigned int step    = 0;
    auto         add_row = [&](const std::string &phase) {
      const auto &q = last_quantities;
      table.add_row(
        {{"step", std::to_string(step++)},
         {"phase", phase},
         {"delta_hat", CsvTable::format(approach() / scales.eps)},
         {"F_n_hat", CsvTable::format(q.normal_force / scales.force)},
         {contact_column(dim),
          CsvTable::format(q.contact_length / scales.contact)},
         {"min_gap_over_eps", CsvTable::format(q.minimum_gap / scales.eps)},
         {"newton_iterations", std::to_string(last_newton_iterations)},
         {"n_dofs", std::to_string(n_unknowns())}});
    };
    if (graded)
      {
        start_from_jkr_contact();
        add_row("load");
        return;
      }
    fit_period(0.);
    control.hold_approach();
    delta = prm.loading.initial_approach * scales.eps;
    if (solve() < 0)
      throw std::runtime_error(
        "the boundary-element solver found no equilibrium at the initial "
        "approach delta_hat = " +
        CsvTable::format(prm.loading.initial_approach));
    add_row("start");
    ApproachProgress progress(prm.loading.final_approach,
                              prm.loading.increment,
                              prm.loading.target_load);
    auto             report = [&] {
      add_row("approach");
      pcout << "Approach delta_hat = " << approach() / scales.eps
            << ": F_n_hat = " << last_quantities.normal_force / scales.force
            << ", " << contact_column(dim) << " = "
            << last_quantities.contact_length / scales.contact << " ("
            << last_newton_iterations << " Newton iterations)  ["
            << progress.report(approach() / scales.eps,
                               last_quantities.normal_force / scales.force)
            << "]" << std::endl;
      done =
        prm.loading.has_target_load() &&
        last_quantities.minimum_gap < prm.adhesion.contact_gap * scales.eps &&
        last_quantities.normal_force >= F;
    };
    move_indenter(prm.loading.final_approach, "approach", report, [&done] {
      return done;
    });
    if (prm.loading.has_target_load())
      hold_target_load(done, add_row);
    if (prm.loading.retract)
      {
        control.hold_approach();
        retract(add_row);
      }
  }


  template <int dim>
  void
  BoundaryElementSolver<dim>::run()
  {
    approach_phase();
    if (prm.sliding.control == Parameters::Control::force)
      control.hold_force(last_quantities.normal_force);
    else
      control.hold_approach();
    if (dim == 2 && !graded &&
        prm.geometry.substrate == Parameters::Substrate::half_plane)
      {
        // From the block of the approach to the half-plane, at the load
        // of the approach.
        substrate = Parameters::Substrate::half_plane;
        make_grid(shape);
        if (solve() < 0)
          throw std::runtime_error(
            "the boundary-element solver could not carry the state of the "
            "approach over to the half-plane");
      }
    preconditioner.reset();
    if (prm.sliding.speed > 0)
      {
        pcout << "Steady sliding under "
              << Parameters::to_string(prm.sliding.control)
              << " control, boundary elements on " << u.size() << " points"
              << std::endl;
        run_stations(*this,
                     Parameters::SlidingSolver::boundary_element,
                     prm,
                     scales,
                     writer,
                     steady_state_table,
                     progress,
                     pcout,
                     comm);
      }
    else
      write_profile(writer.path("surface_profile_final.csv"));
    pcout << "GMRES: " << gmres_iterations << " iterations in " << gmres_solves
          << " solves ("
          << (gmres_solves > 0 ? double(gmres_iterations) / gmres_solves : 0.)
          << " per Newton step)" << std::endl;
    timer.print_wall_time_statistics(comm);
  }


  template class BoundaryElementSolver<2>;
  template class BoundaryElementSolver<3>;
} // namespace viscoslide

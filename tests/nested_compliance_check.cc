// SPDX-License-Identifier: LGPL-2.1-or-later
// The nested grid's compliance (nested_compliance.h) against the uniform
// window's (isolated_compliance.h) on the fine lattice, which holds the
// same piecewise-constant traction exactly: a coarse cell's value copied
// into its r x r fine cells. The traction is a contact's: a Hertzian
// pressure with an adhesive ring narrower than a coarse cell at its edge,
// the band the cells within 2 H of the ring. For each refinement and
// speed (the creep length from a tenth of a fine cell to far beyond the
// window) it prints the largest difference of the displacement at the
// points over the largest displacement, and the relative difference of
// the dissipation sum_j q_j A_j du_c/dx_j; tests/nested_compliance.check
// bounds them.
#include <viscoslide/boundary_element/isolated_compliance.h>
#include <viscoslide/boundary_element/nested_compliance.h>

#include <cmath>
#include <cstdio>
#include <cstdlib>

using namespace viscoslide;

namespace
{
  // The traction at (x, y): pressure -sqrt(1 - rho^2/a^2) inside, the
  // ring of attraction about rho = a.
  double
  traction(const double x, const double y)
  {
    const double a = 6., rho = std::hypot(x, y), w = 0.15;
    const double pressure = rho < a ? -std::sqrt(1 - rho * rho / (a * a)) : 0.;
    return pressure + 0.8 * std::exp(-std::pow((rho - a) / w, 2));
  }
} // namespace


int
main(int argc, char **argv)
{
  // The grid's near field and interpolation, or others to measure them.
  const unsigned int near =
    argc > 1 ? std::atoi(argv[1]) : NestedCompliance::default_near;
  const unsigned int order =
    argc > 2 ? std::atoi(argv[2]) : NestedCompliance::default_order;
  const ViscoelasticSolid           material(1. - 0.49 * 0.49,
                                   (1. - 0.49 * 0.49) / 0.1,
                                   0.49,
                                   1.);
  const std::array<unsigned int, 2> n{{48, 56}};
  const double                      H = 0.5;
  for (const unsigned int r : {3u, 5u})
    {
      std::vector<bool> band(n[0] * n[1]);
      for (unsigned int j = 0; j < band.size(); ++j)
        {
          const double x = (int(j % n[1]) - int(n[1] / 2)) * H,
                       y = (int(j / n[1]) - int(n[0] / 2)) * H;
          band[j]        = std::abs(std::hypot(x, y) - 6.) < 2 * H;
        }
      const NestedLayout layout(n, H, r, band);
      IsolatedCompliance window(material, 0.49, n, H);
      NestedCompliance   nested(material, 0.49, layout, window, near, order);
      const std::array<unsigned int, 2> nf{{n[0] * r, n[1] * r}};
      IsolatedCompliance                uniform(material, 0.49, nf, layout.h);

      Vector<double> q(layout.size()), qf(nf[0] * nf[1]);
      // The fine lattice's index of a point of the layout, and of fine
      // cell (s, k) of coarse cell `cell`.
      const auto at = [&](unsigned int cell, unsigned int s, unsigned int k) {
        return ((cell / n[1]) * r + s) * nf[1] + (cell % n[1]) * r + k;
      };
      std::vector<unsigned int> index(layout.size());
      for (unsigned int cell = 0; cell < layout.n_cells(); ++cell)
        for (unsigned int s = 0; s < r; ++s)
          for (unsigned int k = 0; k < r; ++k)
            {
              const unsigned int j =
                band[cell] ? layout.fine(cell, s, k) : layout.first[cell];
              if (!band[cell] && (s != layout.c || k != layout.c))
                {
                  qf[at(cell, s, k)] = q[j];
                  continue;
                }
              index[j]     = at(cell, s, k);
              q[j]         = traction(layout.lattice_x(j) * layout.h,
                              layout.lattice_y(j) * layout.h);
              qf[index[j]] = q[j];
            }
      // Coarse cells' copies, now that their values are set.
      for (unsigned int cell = 0; cell < layout.n_cells(); ++cell)
        if (!band[cell])
          for (unsigned int s = 0; s < r; ++s)
            for (unsigned int k = 0; k < r; ++k)
              qf[at(cell, s, k)] = q[layout.first[cell]];

      for (const double L : {0., 0.1 * layout.h, H, 10 * H, 1000.})
        {
          // The creep length of the slowest retardation is V theta; the
          // solid's retardation time is tau Einf/E0 = 10.
          const double V = L / 10.;
          window.set_speed(V);
          nested.set_speed(V);
          uniform.set_speed(V);
          Vector<double> u, uf, slope, slope_f;
          nested.apply(q, u);
          uniform.apply(qf, uf);
          double error = 0, scale = 0, band_error = 0;
          for (unsigned int j = 0; j < layout.size(); ++j)
            {
              error = std::max(error, std::abs(u[j] - uf[index[j]]));
              if (band[layout.cell_of[j]])
                band_error =
                  std::max(band_error, std::abs(u[j] - uf[index[j]]));
              scale = std::max(scale, std::abs(uf[index[j]]));
            }
          double D = 0, D_f = 0;
          if (V > 0)
            {
              nested.creep_slope(q, slope);
              uniform.creep_slope(qf, slope_f);
              for (unsigned int j = 0; j < layout.size(); ++j)
                D += q[j] * slope[j] * layout.area(j);
              for (unsigned int j = 0; j < qf.size(); ++j)
                D_f += qf[j] * slope_f[j] * layout.h * layout.h;
            }
          std::printf("r %u  L/h %-8g points %6u (uniform %6u)  "
                      "displacement %.2e (band %.2e)  dissipation %.2e\n",
                      r,
                      L / layout.h,
                      layout.size(),
                      qf.size(),
                      error / scale,
                      band_error / scale,
                      V > 0 ? std::abs(D - D_f) / std::abs(D_f) : 0.);
        }
    }
}

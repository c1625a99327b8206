// SPDX-License-Identifier: LGPL-2.1-or-later
// Newton's method (newton.h) on a scalar equation x = 1 whose residual
// norm carries a deterministic noise floor, as round-off gives a graded
// boundary-element grid's norm: |x - 1| + floor (1 + sin(1e9 x))/2. The
// update is exact, so every step lands within the floor and the line search
// can only see noise. Prints, per floor in tolerances, the iterations
// returned (-1: given up) and |x - 1|. tests/newton_round_off.check holds
// them to the contract: converged within ten tolerances, given up beyond.
#include <deal.II/base/conditional_ostream.h>

#include <viscoslide/numerics/newton.h>

#include <cmath>
#include <cstdio>
#include <iostream>

int
main()
{
  using namespace viscoslide;
  const double tolerance = 1e-8;
  for (const double floor : {3., 8., 30., 100.})
    {
      double        x = 3, x0 = 3, dx = 0;
      NewtonProblem p;
      p.assemble      = [](bool) {};
      p.residual_norm = [&] {
        return std::abs(x - 1) +
               floor * tolerance * 0.5 * (1 + std::sin(1e9 * x));
      };
      p.tolerance        = [&] { return tolerance; };
      p.compute_update   = [&] { dx = 1 - x; };
      p.update_norm      = [&] { return std::abs(dx); };
      p.update_max_norm  = [&] { return std::abs(dx); };
      p.remember_iterate = [&] { x0 = x; };
      p.step             = [&](const double alpha) { x = x0 + alpha * dx; };
      p.set_dashpot      = [](double) {};
      dealii::ConditionalOStream out(std::cout, false);
      const int                  its = newton(p, 50, true, false, out);
      std::printf("%g %d %.3e\n", floor, its, std::abs(x - 1));
    }
}

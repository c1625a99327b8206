// SPDX-License-Identifier: LGPL-2.1-or-later
// Prints, for each interaction law at dgamma = eps = 1: the equilibrium gap
// (p = 0 between wall and attraction), the work of separation from there
// (Simpson's rule to g = 2000), the peak attraction and the largest
// mismatch between derivative() and a central difference of traction().
// tests/interaction_laws.check compares them with their exact values.
#include <viscoslide/physics/interaction_law.h>

#include <cmath>
#include <cstdio>

int
main()
{
  using namespace viscoslide;
  for (const char *name : {"lennard-jones", "exponential", "dugdale"})
    {
      const auto law = create_interaction_law(name, 1., 1.);
      // equilibrium: the zero of p where the wall meets the attraction
      double lo = 0.6, hi = 1.3;
      for (int k = 0; k < 200; ++k)
        {
          const double mid                    = 0.5 * (lo + hi);
          (law->traction(mid) < 0. ? lo : hi) = mid;
        }
      const double g0 = 0.5 * (lo + hi);
      // Simpson on a graded grid: fine near the contact, coarse in the tail
      double work = 0., peak = 0.;
      for (double a = g0, h = 1e-4; a < 2000.;
           a += 2 * h, h    = std::min(1.01 * h, 0.5))
        {
             const double b = a + 2 * h;
             work +=
               h / 3. *
               (law->traction(a) + 4. * law->traction(a + h) + law->traction(b));
             peak = std::max(peak, law->traction(a + h));
        }
      double mismatch = 0.;
      for (double g = 0.55; g < 10.; g += 1e-3)
        {
          const double e  = 1e-7,
                       fd = (law->traction(g + e) - law->traction(g - e)) /
                            (2 * e);
          mismatch = std::max(mismatch,
                              std::abs(fd - law->derivative(g)) /
                                (1. + std::abs(law->derivative(g))));
        }
      std::printf(
        "%s %.10g %.10g %.10g %.3e\n", name, g0, work, peak, mismatch);
    }
}

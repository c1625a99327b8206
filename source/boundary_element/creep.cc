// SPDX-License-Identifier: LGPL-2.1-or-later
#include <viscoslide/boundary_element/creep.h>

#include <algorithm>

namespace viscoslide
{
  // E*(s) = 1 + sum_a E_a s tau_a/(1 + s tau_a) has one root in each
  // interval of the negative axis between its poles -1/tau_a (and between
  // the nearest one and 0); at each root s the retardation theta = -1/s,
  // whose weight is the residue of 1/E* there.
  Creep::Creep(const ViscoelasticSolid &material, const double nu)
  {
    std::vector<std::pair<double, double>> arms; // (tau_a, E_a*)
    for (unsigned int a = 0; a < material.n_arms(); ++a)
      if (material.arm_modulus(a) > 0)
        arms.emplace_back(material.relaxation_time(a),
                          material.arm_modulus(a) / (1. - nu * nu));
    std::sort(arms.begin(), arms.end());
    const auto E = [&](const double s) {
      double e = 1.;
      for (const auto &[tau, Ea] : arms)
        e += Ea * s * tau / (1. + s * tau);
      return e;
    };
    const auto dE = [&](const double s) {
      double d = 0.;
      for (const auto &[tau, Ea] : arms)
        d += Ea * tau / ((1. + s * tau) * (1. + s * tau));
      return d;
    };
    double right = 0.; // the interval's upper end
    for (auto arm = arms.rbegin(); arm != arms.rend(); ++arm)
      {
        // E goes from -infinity just above the pole to E(right) > 0.
        double lo = -1. / arm->first, hi = right;
        for (int k = 0; k < 200; ++k)
          {
            const double mid       = 0.5 * (lo + hi);
            (E(mid) < 0 ? lo : hi) = mid;
          }
        const double s     = 0.5 * (lo + hi);
        const double theta = -1. / s;
        retardations.emplace_back(theta, theta / dE(s));
        right = -1. / arm->first;
      }
    // 1/E*(s -> infinity) = 1 - sum_r c_r (1/E*(0) = 1 = E0*).
    inverse_glassy = 1.;
    for (const auto &[theta, c] : retardations)
      inverse_glassy -= c;
  }
} // namespace viscoslide

// SPDX-License-Identifier: LGPL-2.1-or-later
// The exact circle R - sqrt(R^2 - xi^2). Beyond |xi| = R the cylinder no
// longer faces the surface; there h = R, flat, a gap of R_hat >= 10
// interaction ranges at which every law's traction has vanished.
#include <viscoslide/physics/indenter.h>

#include <algorithm>
#include <cmath>

namespace viscoslide
{
  namespace
  {
    class Circle : public Indenter
    {
    public:
      explicit Circle(const double R)
        : R(R)
      {
      }

      double
      profile(const double xi) const override
      {
        return std::abs(xi) < R ? R - std::sqrt(R * R - xi * xi) : R;
      }

      double
      slope(const double xi) const override
      {
        // The slope diverges at |xi| = R, where the gap is already R; the
        // last percent of the quarter circle is cut to keep it finite.
        if (std::abs(xi) >= R)
          return 0.;
        const double x = std::clamp(xi, -0.99 * R, 0.99 * R);
        return x / std::sqrt(R * R - x * x);
      }

    private:
      double R;
    };
  } // namespace

  VISCOSLIDE_REGISTER(IndenterShape,
                      {"circle",
                       "the exact circle R - sqrt(R^2 - x^2).",
                       [](ParameterHandler &) {},
                       [](ParameterHandler &) -> IndenterMaker {
                         return [](const double R) {
                           return std::make_unique<Circle>(R);
                         };
                       }})
} // namespace viscoslide

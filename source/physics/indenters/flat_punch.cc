// SPDX-License-Identifier: LGPL-2.1-or-later
// A flat punch of half-width b whose corners are rounded by parabolas of
// radius r: h = 0 for |xi| <= b, (|xi| - b)^2/(2r) beyond, so that the
// pressure stays bounded and the contact edges move smoothly (Ciavarella,
// Hills and Monno 1998). r -> 0 is the sharp punch.
#include <viscoslide/physics/indenter.h>

#include <algorithm>
#include <cmath>

namespace viscoslide
{
  namespace
  {
    class FlatPunch : public Indenter
    {
    public:
      FlatPunch(const double half_width, const double corner_radius)
        : b(half_width)
        , r(corner_radius)
      {
      }

      double
      profile(const double xi) const override
      {
        const double d = std::max(0., std::abs(xi) - b);
        return d * d / (2. * r);
      }

      double
      slope(const double xi) const override
      {
        return std::copysign(std::max(0., std::abs(xi) - b) / r, xi);
      }

    private:
      double b, r;
    };

    void
    declare(ParameterHandler &prm)
    {
      prm.declare_entry("Punch half-width",
                        "100",
                        Patterns::Double(),
                        "Flat punch: half-width b of the flat part, in eps.");
      prm.declare_entry("Corner radius",
                        "1000",
                        Patterns::Double(),
                        "Flat punch: radius r of the parabolic corners "
                        "(h = (|x| - b)^2/(2r) beyond b), in eps; it keeps "
                        "the edge pressure finite. Resolve it: the corner "
                        "contact (a - b) should span several finest cells.");
    }

    IndenterMaker
    parse(ParameterHandler &prm)
    {
      using namespace Parameters;
      const double b = prm.get_double("Punch half-width");
      const double r = prm.get_double("Corner radius");
      require(b >= 0 && std::isfinite(b),
              entry("Indenter", "Punch half-width", b) +
                " must be zero or positive");
      require(r > 0 && std::isfinite(r),
              entry("Indenter", "Corner radius", r) + " must be positive");
      return [b, r](double) { return std::make_unique<FlatPunch>(b, r); };
    }
  } // namespace

  VISCOSLIDE_REGISTER(IndenterShape,
                      {"flat punch",
                       "flat over |x| <= Punch half-width, corners rounded "
                       "by parabolas of Corner radius.",
                       declare,
                       parse})
} // namespace viscoslide

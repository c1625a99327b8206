// SPDX-License-Identifier: LGPL-2.1-or-later
// h = |xi|^n/(n R^(n-1)); n = 2 is the parabola of radius R.
#include <viscoslide/physics/indenter.h>

#include <cmath>

namespace viscoslide
{
  namespace
  {
    class PowerLaw : public Indenter
    {
    public:
      PowerLaw(const double exponent, const double R)
        : n(exponent)
        , R(R)
      {
      }

      double
      profile(const double xi) const override
      {
        return R / n * std::pow(std::abs(xi) / R, n);
      }

      double
      slope(const double xi) const override
      {
        return std::copysign(std::pow(std::abs(xi) / R, n - 1.), xi);
      }

    private:
      double n, R;
    };

    void
    declare(ParameterHandler &prm)
    {
      prm.declare_entry("Exponent",
                        "2",
                        Patterns::Double(),
                        "Power law: n >= 1 (1: a wedge, 2: the parabola).");
    }

    IndenterMaker
    parse(ParameterHandler &prm)
    {
      using namespace Parameters;
      const double n = prm.get_double("Exponent");
      require(n >= 1 && std::isfinite(n),
              entry("Indenter", "Exponent", n) +
                " must be at least 1 (a finite slope at the apex)");
      return [n](const double R) { return std::make_unique<PowerLaw>(n, R); };
    }
  } // namespace

  VISCOSLIDE_REGISTER(IndenterShape,
                      {"power law",
                       "|x|^n/(n R^(n-1)) with n = Exponent (2: the "
                       "parabola).",
                       declare,
                       parse})
} // namespace viscoslide

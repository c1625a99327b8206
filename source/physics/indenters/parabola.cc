// SPDX-License-Identifier: LGPL-2.1-or-later
// The Hertzian cylinder h = xi^2/(2R), the paper's indenter.
#include <viscoslide/physics/indenter.h>

namespace viscoslide
{
  namespace
  {
    class Parabola : public Indenter
    {
    public:
      explicit Parabola(const double R)
        : R(R)
      {
      }

      double
      profile(const double xi) const override
      {
        return xi * xi / (2. * R);
      }

      double
      slope(const double xi) const override
      {
        return xi / R;
      }

    private:
      double R;
    };
  } // namespace

  VISCOSLIDE_REGISTER(IndenterShape,
                      {"parabola",
                       "x^2/(2R), the paper's cylinder.",
                       [](ParameterHandler &) {},
                       [](ParameterHandler &) -> IndenterMaker {
                         return [](const double R) {
                           return std::make_unique<Parabola>(R);
                         };
                       }})
} // namespace viscoslide

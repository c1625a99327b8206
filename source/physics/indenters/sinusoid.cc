// SPDX-License-Identifier: LGPL-2.1-or-later
// A periodic wavy indenter h = A (1 - cos(2 pi xi/lambda)), its apex
// curvature radius lambda^2/(4 pi^2 A).
#include <viscoslide/physics/indenter.h>

#include <cmath>

namespace viscoslide
{
  namespace
  {
    class Sinusoid : public Indenter
    {
    public:
      Sinusoid(const double amplitude, const double wavelength)
        : A(amplitude)
        , k(2. * M_PI / wavelength)
      {
      }

      double
      profile(const double xi) const override
      {
        return A * (1. - std::cos(k * xi));
      }

      double
      slope(const double xi) const override
      {
        return A * k * std::sin(k * xi);
      }

    private:
      double A, k;
    };

    void
    declare(ParameterHandler &prm)
    {
      prm.declare_entry("Amplitude",
                        "10",
                        Patterns::Double(),
                        "Sinusoid: amplitude A in eps (peak to valley 2A).");
      prm.declare_entry("Wavelength",
                        "2000",
                        Patterns::Double(),
                        "Sinusoid: wavelength in eps; the apex radius of "
                        "curvature is Wavelength^2/(4 pi^2 A).");
    }

    IndenterMaker
    parse(ParameterHandler &prm)
    {
      using namespace Parameters;
      const double A      = prm.get_double("Amplitude");
      const double lambda = prm.get_double("Wavelength");
      require(A > 0 && std::isfinite(A),
              entry("Indenter", "Amplitude", A) + " must be positive");
      require(lambda > 0 && std::isfinite(lambda),
              entry("Indenter", "Wavelength", lambda) + " must be positive");
      return
        [A, lambda](double) { return std::make_unique<Sinusoid>(A, lambda); };
    }
  } // namespace

  VISCOSLIDE_REGISTER(IndenterShape,
                      {"sinusoid",
                       "Amplitude (1 - cos(2 pi x/Wavelength)), periodic.",
                       declare,
                       parse})
} // namespace viscoslide

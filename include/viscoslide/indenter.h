// Rigid indenter profiles h(xi), xi = x - s measured from the apex (lengths
// in eps). Both solvers and the postprocessing see only this interface, so
// a new shape is one class here and one line in create_indenter().
#ifndef viscoslide_indenter_h
#define viscoslide_indenter_h

#include <deal.II/base/function_lib.h>
#include <deal.II/base/function_parser.h>

#include <viscoslide/parameters.h>

#include <memory>
#include <string>

namespace viscoslide
{
  class Indenter
  {
  public:
    virtual ~Indenter() = default;

    virtual double
    profile(double xi) const = 0;

    virtual double
    slope(double xi) const = 0;
  };

  // The Hertzian cylinder h = xi^2/(2R).
  class ParabolicIndenter : public Indenter
  {
  public:
    explicit ParabolicIndenter(const double R)
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

  // The exact circle R - sqrt(R^2 - xi^2). Beyond |xi| = R the cylinder no
  // longer faces the surface; there h = R, flat, a gap of R_hat >= 10
  // interaction ranges at which every law's traction has vanished.
  class CircularIndenter : public Indenter
  {
  public:
    explicit CircularIndenter(double R);
    double
    profile(double xi) const override;
    double
    slope(double xi) const override;

  private:
    double R;
  };

  // A flat punch of half-width b whose corners are rounded by parabolas of
  // radius r: h = 0 for |xi| <= b, (|xi| - b)^2/(2r) beyond, so that the
  // pressure stays bounded and the contact edges move smoothly
  // (Ciavarella, Hills and Monno 1998). r -> 0 is the sharp punch.
  class FlatPunchIndenter : public Indenter
  {
  public:
    FlatPunchIndenter(double half_width, double corner_radius);
    double
    profile(double xi) const override;
    double
    slope(double xi) const override;

  private:
    double b, r;
  };

  // h = |xi|^n/(n R^(n-1)); n = 2 is the parabola of radius R.
  class PowerLawIndenter : public Indenter
  {
  public:
    PowerLawIndenter(double exponent, double R);
    double
    profile(double xi) const override;
    double
    slope(double xi) const override;

  private:
    double n, R;
  };

  // A periodic wavy indenter h = A (1 - cos(2 pi xi/lambda)), its apex
  // curvature radius lambda^2/(4 pi^2 A).
  class SinusoidalIndenter : public Indenter
  {
  public:
    SinusoidalIndenter(double amplitude, double wavelength);
    double
    profile(double xi) const override;
    double
    slope(double xi) const override;

  private:
    double A, k;
  };

  // h(x) typed as a muParser expression in x (eps) with the constant R
  // (= R_hat); the slope by central differences (FunctionParser is an
  // AutoDerivativeFunction).
  class ExpressionIndenter : public Indenter
  {
  public:
    ExpressionIndenter(const std::string &expression, double R);
    double
    profile(double xi) const override;
    double
    slope(double xi) const override;

  private:
    FunctionParser<1> function;
  };

  // h(x) from a CSV table (columns x_over_eps, h_over_eps, x increasing),
  // linearly interpolated; beyond its ends the end values continue flat.
  class TabulatedIndenter : public Indenter
  {
  public:
    explicit TabulatedIndenter(const std::string &filename);
    double
    profile(double xi) const override;
    double
    slope(double xi) const override;

  private:
    std::unique_ptr<Functions::InterpolatedTensorProductGridData<1>> table;
    double x_first, x_last;
  };

  // The shape the parameters select; R is R_hat eps. A profile that cannot
  // be built (unreadable table, bad expression, non-finite values over
  // the domain) throws Parameters::ExcInvalidInput naming the entry.
  std::unique_ptr<Indenter>
  create_indenter(const Parameters::IndenterProfile &profile,
                  double                             R,
                  double                             domain_width);

  // The gap of doc/conventions.md, g = eps + h(x - s) - delta - u_y, for a
  // surface point at x displaced by u_y, with the indenter at approach
  // delta and lateral position s.
  inline double
  gap(const Indenter &indenter,
      const double    eps,
      const double    delta,
      const double    s,
      const double    x,
      const double    u_y)
  {
    return eps + indenter.profile(x - s) - delta - u_y;
  }
} // namespace viscoslide

#endif

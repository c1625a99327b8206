#include <deal.II/base/table.h>
#include <deal.II/base/utilities.h>

#include <viscoslide/indenter.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <sstream>

namespace viscoslide
{
  namespace
  {
    using Parameters::ExcInvalidInput;

    std::string
    entry(const std::string &name, const std::string &value)
    {
      return "'Indenter/" + name + "' = " + value;
    }
  } // namespace


  CircularIndenter::CircularIndenter(const double R)
    : R(R)
  {
  }

  double
  CircularIndenter::profile(const double xi) const
  {
    return std::abs(xi) < R ? R - std::sqrt(R * R - xi * xi) : R;
  }

  double
  CircularIndenter::slope(const double xi) const
  {
    // The slope diverges at |xi| = R, where the gap is already R; the
    // last percent of the quarter circle is cut to keep it finite.
    if (std::abs(xi) >= R)
      return 0.;
    const double x = std::clamp(xi, -0.99 * R, 0.99 * R);
    return x / std::sqrt(R * R - x * x);
  }


  FlatPunchIndenter::FlatPunchIndenter(const double half_width,
                                       const double corner_radius)
    : b(half_width)
    , r(corner_radius)
  {
  }

  double
  FlatPunchIndenter::profile(const double xi) const
  {
    const double d = std::max(0., std::abs(xi) - b);
    return d * d / (2. * r);
  }

  double
  FlatPunchIndenter::slope(const double xi) const
  {
    return std::copysign(std::max(0., std::abs(xi) - b) / r, xi);
  }


  PowerLawIndenter::PowerLawIndenter(const double exponent, const double R)
    : n(exponent)
    , R(R)
  {
  }

  double
  PowerLawIndenter::profile(const double xi) const
  {
    return R / n * std::pow(std::abs(xi) / R, n);
  }

  double
  PowerLawIndenter::slope(const double xi) const
  {
    return std::copysign(std::pow(std::abs(xi) / R, n - 1.), xi);
  }


  SinusoidalIndenter::SinusoidalIndenter(const double amplitude,
                                         const double wavelength)
    : A(amplitude)
    , k(2. * M_PI / wavelength)
  {
  }

  double
  SinusoidalIndenter::profile(const double xi) const
  {
    return A * (1. - std::cos(k * xi));
  }

  double
  SinusoidalIndenter::slope(const double xi) const
  {
    return A * k * std::sin(k * xi);
  }


  ExpressionIndenter::ExpressionIndenter(const std::string &expression,
                                         const double       R)
    // a difference step of 1e-6 eps: round-off stays below 1e-8 for
    // profiles of up to 1e2 R_hat
    : function(1, 0., 1e-6)
  {
    try
      {
        function.initialize("x", expression, {{"R", R}, {"pi", M_PI}});
        function.value(Point<1>(0.)); // muParser parses on first use
      }
    catch (ExceptionBase &e)
      {
        std::ostringstream message;
        e.print_info(message);
        throw ExcInvalidInput(
          entry("Expression", expression) +
          " is not a function of x: " + Utilities::trim(message.str()));
      }
  }

  double
  ExpressionIndenter::profile(const double xi) const
  {
    return function.value(Point<1>(xi));
  }

  double
  ExpressionIndenter::slope(const double xi) const
  {
    return function.gradient(Point<1>(xi))[0];
  }


  TabulatedIndenter::TabulatedIndenter(const std::string &filename)
  {
    const auto columns =
      Parameters::read_csv_columns(filename,
                                   {"x_over_eps", "h_over_eps"},
                                   entry("Profile file", filename));
    const std::vector<double> &x = columns[0], &h = columns[1];
    for (size_t i = 1; i < x.size(); ++i)
      if (!(x[i] > x[i - 1]))
        throw ExcInvalidInput(entry("Profile file", filename) +
                              ": x_over_eps must increase (data row " +
                              std::to_string(i + 1) + ")");
    if (x.size() < 2)
      throw ExcInvalidInput(entry("Profile file", filename) +
                            ": needs at least two rows of data");
    Table<1, double> values(h.size());
    for (size_t i = 0; i < h.size(); ++i)
      values[i] = h[i];
    x_first = x.front();
    x_last  = x.back();
    table   = std::make_unique<Functions::InterpolatedTensorProductGridData<1>>(
      std::array<std::vector<double>, 1>{{x}}, values);
  }

  double
  TabulatedIndenter::profile(const double xi) const
  {
    return table->value(Point<1>(xi));
  }

  double
  TabulatedIndenter::slope(const double xi) const
  {
    // the profile continues flat beyond the table: its slope there is
    // zero whatever deal.II's interpolant would extrapolate
    if (xi <= x_first || xi >= x_last)
      return 0.;
    return table->gradient(Point<1>(xi))[0];
  }


  std::unique_ptr<Indenter>
  create_indenter(const Parameters::IndenterProfile &p,
                  const double                       R,
                  const double                       domain_width)
  {
    std::unique_ptr<Indenter> indenter;
    if (p.shape == "parabola")
      indenter = std::make_unique<ParabolicIndenter>(R);
    else if (p.shape == "circle")
      indenter = std::make_unique<CircularIndenter>(R);
    else if (p.shape == "flat punch")
      indenter =
        std::make_unique<FlatPunchIndenter>(p.half_width, p.corner_radius);
    else if (p.shape == "power law")
      indenter = std::make_unique<PowerLawIndenter>(p.exponent, R);
    else if (p.shape == "sinusoid")
      indenter =
        std::make_unique<SinusoidalIndenter>(p.amplitude, p.wavelength);
    else if (p.shape == "expression")
      indenter = std::make_unique<ExpressionIndenter>(p.expression, R);
    else if (p.shape == "table")
      indenter = std::make_unique<TabulatedIndenter>(p.profile_file);
    else
      throw ExcInvalidInput(entry("Shape", p.shape) + " is not a shape");

    // A profile that is NaN or infinite somewhere the surface can meet it
    // (the indenter slides at most a domain width) would poison the
    // Newton residual many steps later; refuse it now.
    for (int i = -2000; i <= 2000; ++i)
      {
        const double xi = i * domain_width / 2000.;
        const double h = indenter->profile(xi), dh = indenter->slope(xi);
        if (!std::isfinite(h) || !std::isfinite(dh))
          {
            std::ostringstream s;
            s << "the profile of 'Indenter/Shape' = " << p.shape
              << " is not finite at x/eps = " << xi << " (h = " << h
              << ", h' = " << dh << ")";
            throw ExcInvalidInput(s.str());
          }
      }
    return indenter;
  }
} // namespace viscoslide

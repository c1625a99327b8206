// Prints, for each indenter shape at R_hat = 1e4 (lengths in eps):
//   slope NAME MISMATCH      largest |slope() - central difference of
//                            profile()| over |x| <= 1000, relative to the
//                            largest slope there
//   equal NAME REFERENCE D   largest |h - h_reference| over |x| <= 1000
//   refused CASE 0|1         whether a bad profile is refused at build time
// tests/indenter_shapes.check compares them with what they must be.
#include <viscoslide/indenter.h>

#include <cmath>
#include <cstdio>
#include <fstream>
#include <functional>

using namespace viscoslide;

namespace
{
  const double R = 1e4, W = 8000.;

  Parameters::IndenterProfile
  shape(const std::string &name)
  {
    Parameters::IndenterProfile p;
    p.shape         = name;
    p.half_width    = 100;
    p.corner_radius = 1000;
    p.exponent      = 2;
    p.amplitude     = 10;
    p.wavelength    = 2000;
    p.expression    = "x^2/(2*R)";
    p.profile_file  = "parabola.csv";
    return p;
  }

  double
  largest(const std::function<double(double)> &f)
  {
    double m = 0.;
    for (int i = -1000; i <= 1000; ++i)
      m = std::max(m, std::abs(f(i * 1.)));
    return m;
  }

  void
  slope_check(const std::string &name, const Indenter &indenter)
  {
    const double d        = 1e-3;
    const double mismatch = largest([&](const double x) {
      return indenter.slope(x) -
             (indenter.profile(x + d) - indenter.profile(x - d)) / (2 * d);
    });
    const double scale =
      largest([&](const double x) { return indenter.slope(x); });
    std::printf("slope %s %.3e\n", name.c_str(), mismatch / scale);
  }

  void
  equal_check(const std::string &name,
              const std::string &reference,
              const Indenter    &a,
              const Indenter    &b)
  {
    std::printf("equal %s %s %.3e\n",
                name.c_str(),
                reference.c_str(),
                largest(
                  [&](const double x) { return a.profile(x) - b.profile(x); }));
  }

  bool
  refused(Parameters::IndenterProfile p)
  {
    try
      {
        create_indenter(p, R, W);
      }
    catch (Parameters::ExcInvalidInput &e)
      {
        std::fprintf(stderr, "%s\n", e.what());
        return true;
      }
    return false;
  }
} // namespace


int
main()
{
  {
    // the parabola sampled every 2 eps: linear interpolation is exact to
    // h'' dx^2/8 = 5e-5 eps
    std::ofstream table("parabola.csv");
    table << "# a parabola of R_hat = 1e4\nx_over_eps,h_over_eps\n";
    for (int i = -2500; i <= 2500; ++i)
      table << 2. * i << "," << 4. * i * i / (2 * R) << "\n";
  }
  const ParabolicIndenter parabola(R);
  for (const char *name : {"parabola",
                           "circle",
                           "flat punch",
                           "power law",
                           "sinusoid",
                           "expression",
                           "table"})
    slope_check(name, *create_indenter(shape(name), R, W));
  auto quartic     = shape("power law");
  quartic.exponent = 4;
  slope_check("quartic", *create_indenter(quartic, R, W));

  for (const char *name : {"power law", "expression", "table", "circle"})
    equal_check(name,
                "parabola",
                *create_indenter(shape(name), R, W),
                parabola);
  // the punch without flat part is the parabola of its corner radius;
  // the sinusoid of apex radius R matches the parabola near its apex
  auto punch       = shape("flat punch");
  punch.half_width = 0;
  equal_check("flat punch b=0",
              "parabola(r)",
              *create_indenter(punch, R, W),
              ParabolicIndenter(punch.corner_radius));
  // (A = 1000 eps, so that k x <= 0.32 and the x^6 term stays below 0.4 %
  // of the x^4 one)
  auto wave       = shape("sinusoid");
  wave.amplitude  = 1000;
  wave.wavelength = 2 * M_PI * std::sqrt(R * wave.amplitude);
  equal_check("sinusoid", "parabola", *create_indenter(wave, R, W), parabola);

  auto bad       = shape("expression");
  bad.expression = "x^";
  std::printf("refused syntax %d\n", refused(bad));
  bad.expression = "sqrt(x)";
  std::printf("refused nan %d\n", refused(bad));
  bad              = shape("table");
  bad.profile_file = "no_such_file.csv";
  std::printf("refused missing %d\n", refused(bad));
  {
    std::ofstream("decreasing.csv") << "x_over_eps,h_over_eps\n1,0\n0,1\n";
    std::ofstream("header.csv") << "x,h\n0,0\n1,1\n";
  }
  bad.profile_file = "decreasing.csv";
  std::printf("refused decreasing %d\n", refused(bad));
  bad.profile_file = "header.csv";
  std::printf("refused header %d\n", refused(bad));
}

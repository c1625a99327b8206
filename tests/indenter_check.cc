// SPDX-License-Identifier: LGPL-2.1-or-later
// Prints, for each indenter shape at R_hat = 1e4 (lengths in eps):
//   slope NAME MISMATCH      largest |slope() - central difference of
//                            profile()| over |x| <= 1000, relative to the
//                            largest slope there
//   equal NAME REFERENCE D   largest |h - h_reference| over |x| <= 1000
//   refused CASE 0|1         whether a bad profile is refused at build time
// tests/indenter_shapes.check compares them with what they must be.
#include <viscoslide/physics/indenter.h>

#include <cmath>
#include <cstdio>
#include <fstream>
#include <functional>
#include <map>
#include <sstream>

using namespace viscoslide;

namespace
{
  const double R = 1e4, W = 8000.;

  // The 'Indenter' section of a parameter file with `name` and these
  // entries (the shapes' own entries at the values below unless changed),
  // parsed as the program parses it.
  Parameters::IndenterProfile
  shape(const std::string                        &name,
        const std::map<std::string, std::string> &changes = {})
  {
    std::map<std::string, std::string> entries = {{"Shape", name},
                                                  {"Punch half-width", "100"},
                                                  {"Corner radius", "1000"},
                                                  {"Exponent", "2"},
                                                  {"Amplitude", "10"},
                                                  {"Wavelength", "2000"},
                                                  {"Expression", "x^2/(2*R)"},
                                                  {"Profile file",
                                                   "parabola.csv"}};
    for (const auto &[entry, value] : changes)
      entries[entry] = value;
    ParameterHandler prm;
    Parameters::IndenterProfile::declare(prm);
    prm.enter_subsection("Indenter");
    for (const auto &[entry, value] : entries)
      prm.set(entry, value);
    prm.leave_subsection();
    Parameters::IndenterProfile p;
    p.parse(prm);
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

  // Whether building the shape with these entries is refused.
  bool
  refused(const std::string                        &name,
          const std::map<std::string, std::string> &changes)
  {
    try
      {
        create_indenter(shape(name, changes), R, W);
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
  const auto parabola = create_indenter(shape("parabola"), R, W);
  for (const char *name : {"parabola",
                           "circle",
                           "flat punch",
                           "power law",
                           "sinusoid",
                           "expression",
                           "table"})
    slope_check(name, *create_indenter(shape(name), R, W));
  slope_check("quartic",
              *create_indenter(shape("power law", {{"Exponent", "4"}}), R, W));

  for (const char *name : {"power law", "expression", "table", "circle"})
    equal_check(name,
                "parabola",
                *create_indenter(shape(name), R, W),
                *parabola);
  // the punch without flat part is the parabola of its corner radius;
  // the sinusoid of apex radius R matches the parabola near its apex
  equal_check("flat punch b=0",
              "parabola(r)",
              *create_indenter(shape("flat punch", {{"Punch half-width", "0"}}),
                               R,
                               W),
              *create_indenter(shape("parabola"), 1000, W));
  // (A = 1000 eps, so that k x <= 0.32 and the x^6 term stays below 0.4 %
  // of the x^4 one)
  const double       amplitude = 1000;
  std::ostringstream wavelength;
  wavelength.precision(17);
  wavelength << 2 * M_PI * std::sqrt(R * amplitude);
  equal_check("sinusoid",
              "parabola",
              *create_indenter(shape("sinusoid",
                                     {{"Amplitude", "1000"},
                                      {"Wavelength", wavelength.str()}}),
                               R,
                               W),
              *parabola);

  std::printf("refused syntax %d\n",
              refused("expression", {{"Expression", "x^"}}));
  std::printf("refused nan %d\n",
              refused("expression", {{"Expression", "sqrt(x)"}}));
  std::printf("refused missing %d\n",
              refused("table", {{"Profile file", "no_such_file.csv"}}));
  {
    std::ofstream("decreasing.csv") << "x_over_eps,h_over_eps\n1,0\n0,1\n";
    std::ofstream("header.csv") << "x,h\n0,0\n1,1\n";
  }
  std::printf("refused decreasing %d\n",
              refused("table", {{"Profile file", "decreasing.csv"}}));
  std::printf("refused header %d\n",
              refused("table", {{"Profile file", "header.csv"}}));
}

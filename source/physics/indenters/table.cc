// SPDX-License-Identifier: LGPL-2.1-or-later
// h(x) from a CSV table (columns x_over_eps, h_over_eps, x increasing),
// linearly interpolated; beyond its ends the end values continue flat.
#include <deal.II/base/function_lib.h>
#include <deal.II/base/table.h>

#include <viscoslide/physics/indenter.h>

#include <memory>

namespace viscoslide
{
  namespace
  {
    using Parameters::ExcInvalidInput;

    class TabulatedProfile : public Indenter
    {
    public:
      explicit TabulatedProfile(const std::string &filename)
      {
        const std::string what = "'Indenter/Profile file' = " + filename;
        const auto        columns =
          Parameters::read_csv_columns(filename,
                                       {"x_over_eps", "h_over_eps"},
                                       what);
        const std::vector<double> &x = columns[0], &h = columns[1];
        for (size_t i = 1; i < x.size(); ++i)
          if (!(x[i] > x[i - 1]))
            throw ExcInvalidInput(what +
                                  ": x_over_eps must increase (data row " +
                                  std::to_string(i + 1) + ")");
        if (x.size() < 2)
          throw ExcInvalidInput(what + ": needs at least two rows of data");
        Table<1, double> values(h.size());
        for (size_t i = 0; i < h.size(); ++i)
          values[i] = h[i];
        x_first = x.front();
        x_last  = x.back();
        table =
          std::make_unique<Functions::InterpolatedTensorProductGridData<1>>(
            std::array<std::vector<double>, 1>{{x}}, values);
      }

      double
      profile(const double xi) const override
      {
        return table->value(Point<1>(xi));
      }

      double
      slope(const double xi) const override
      {
        // the profile continues flat beyond the table: its slope there is
        // zero whatever deal.II's interpolant would extrapolate
        if (xi <= x_first || xi >= x_last)
          return 0.;
        return table->gradient(Point<1>(xi))[0];
      }

    private:
      std::unique_ptr<Functions::InterpolatedTensorProductGridData<1>> table;
      double x_first, x_last;
    };

    void
    declare(ParameterHandler &prm)
    {
      prm.declare_entry("Profile file",
                        "",
                        Patterns::Anything(),
                        "Table: a CSV file (path relative to the working "
                        "directory) with a header naming the columns "
                        "x_over_eps and h_over_eps, x increasing; '#' lines "
                        "are comments. h is interpolated linearly and "
                        "continues flat beyond the ends, so the table "
                        "should cover the contact and the sliding "
                        "distance. The file is read when the parameters "
                        "are, and a changed file is not detected by "
                        "--resume.");
    }

    IndenterMaker
    parse(ParameterHandler &prm)
    {
      const std::string file = prm.get("Profile file");
      Parameters::require(
        !file.empty(),
        "'Indenter/Shape' = table needs a 'Indenter/Profile file'");
      return
        [file](double) { return std::make_unique<TabulatedProfile>(file); };
    }
  } // namespace

  VISCOSLIDE_REGISTER(IndenterShape,
                      {"table", "the CSV Profile file.", declare, parse})
} // namespace viscoslide

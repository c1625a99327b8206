// SPDX-License-Identifier: LGPL-2.1-or-later
#include <viscoslide/physics/indenter.h>

#include <cmath>
#include <sstream>

namespace viscoslide
{
  namespace Parameters
  {
    void
    IndenterProfile::declare(ParameterHandler &prm)
    {
      using Shapes = Registry<IndenterShape>;
      prm.enter_subsection("Indenter");
      prm.declare_entry(
        "Shape",
        "parabola",
        Patterns::Selection(Shapes::pattern()),
        "The rigid profile h(x) above its lowest point, x from the apex and "
        "h in eps; the approach delta is measured from h = 0 (doc/model.md). " +
          Shapes::documentation() +
          " R is 'Adhesion/R over eps' for every shape, so the Tabor "
          "parameter, F_hat, V_hat and L_hat keep the paper's normalisation "
          "whatever the shape.");
      for (const auto &name : Shapes::names())
        Shapes::get(name, "Indenter/Shape").declare_parameters(prm);
      prm.leave_subsection();
    }

    void
    IndenterProfile::parse(ParameterHandler &prm)
    {
      prm.enter_subsection("Indenter");
      shape = prm.get("Shape");
      make  = Registry<IndenterShape>::get(shape, "Indenter/Shape")
               .parse_parameters(prm);
      prm.leave_subsection();
    }
  } // namespace Parameters


  std::unique_ptr<Indenter>
  create_indenter(const Parameters::IndenterProfile &p,
                  const double                       R,
                  const double                       domain_width)
  {
    std::unique_ptr<Indenter> indenter = p.make(R);
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
            throw Parameters::ExcInvalidInput(s.str());
          }
      }
    return indenter;
  }
} // namespace viscoslide

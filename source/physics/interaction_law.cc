// SPDX-License-Identifier: LGPL-2.1-or-later
#include <viscoslide/physics/interaction_law.h>

#include <cmath>

namespace viscoslide
{
  namespace Parameters
  {
    void
    Adhesion::declare(ParameterHandler &prm)
    {
      using Laws = Registry<InteractionLawType>;
      prm.enter_subsection("Adhesion");
      prm.declare_entry("Interaction law",
                        "lennard-jones",
                        Patterns::Selection(Laws::pattern()),
                        "Surface traction-gap law on the top boundary, each "
                        "with work of separation dgamma (doc/model.md). " +
                          Laws::documentation());
      prm.declare_entry("Tabor parameter",
                        default_tabor_parameter,
                        Patterns::Double(),
                        "muT = (R dgamma^2/(E0*^2 eps^3))^(1/3), computed with "
                        "the relaxed modulus. 1: long-range, 6.08: "
                        "short-range adhesion (the paper's two cases). With "
                        "'repulsive' it only sets the stiffness of the "
                        "repulsive wall.");
      prm.declare_entry("R over eps",
                        default_R_over_eps,
                        Patterns::Double(),
                        "Indenter radius R_hat = R/eps. The paper does not "
                        "state it; with 1e4, dgamma/(E0* eps) = 0.15 at "
                        "muT = 6.08. F_hat, delta_hat and p_hat do not "
                        "depend on it; V_hat, L_hat and mu scale with "
                        "sqrt(R_hat).");
      prm.declare_entry("Contact gap threshold",
                        "1.2",
                        Patterns::Double(),
                        "A surface point is in contact where the gap is "
                        "below this many eps (the paper uses 1.2, the "
                        "position of the Lennard-Jones peak traction).");
      prm.declare_entry("Face quadrature points",
                        "5",
                        Patterns::Integer(2, 12),
                        "Gauss points per top face for the adhesion "
                        "integral.");
      prm.leave_subsection();
    }

    void
    Adhesion::parse(ParameterHandler &prm)
    {
      prm.enter_subsection("Adhesion");
      law                    = prm.get("Interaction law");
      tabor_parameter        = prm.get_double("Tabor parameter");
      R_over_eps             = prm.get_double("R over eps");
      contact_gap            = prm.get_double("Contact gap threshold");
      face_quadrature_points = prm.get_integer("Face quadrature points");
      prm.leave_subsection();
      require(tabor_parameter > 0 && std::isfinite(tabor_parameter),
              entry("Adhesion", "Tabor parameter", tabor_parameter) +
                " must be positive");
      require(R_over_eps >= 10 && std::isfinite(R_over_eps),
              entry("Adhesion", "R over eps", R_over_eps) +
                " must be at least 10 (Derjaguin approximation)");
      require(contact_gap > 1,
              entry("Adhesion", "Contact gap threshold", contact_gap) +
                " must exceed 1 (the equilibrium gap)");
    }

    bool
    Adhesion::adhesive() const
    {
      return Registry<InteractionLawType>::get(law, "Adhesion/Interaction law")
        .adhesive;
    }
  } // namespace Parameters


  std::unique_ptr<InteractionLaw>
  create_interaction_law(const std::string &name,
                         const double       dgamma,
                         const double       eps)
  {
    return Registry<InteractionLawType>::get(name, "Adhesion/Interaction law")
      .create(dgamma, eps);
  }


  AttractionHomotopy::AttractionHomotopy(const std::string &name,
                                         const double       dgamma,
                                         const double       eps)
    : wall(create_interaction_law("repulsive", dgamma, eps))
    , law(create_interaction_law(name, dgamma, eps))
  {
  }


  void
  AttractionHomotopy::set_attraction(const double attraction)
  {
    s = attraction;
  }


  double
  AttractionHomotopy::traction(const double gap) const
  {
    const double p = wall->traction(gap);
    return p + s * (law->traction(gap) - p);
  }


  double
  AttractionHomotopy::derivative(const double gap) const
  {
    const double d = wall->derivative(gap);
    return d + s * (law->derivative(gap) - d);
  }
} // namespace viscoslide

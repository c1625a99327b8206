// SPDX-License-Identifier: LGPL-2.1-or-later
// Traction-gap laws of the top surface (Derjaguin approximation). The
// traction p(g) is positive when it attracts (pulls the surface up towards
// the indenter); the contact pressure of the paper is -p. The laws are
// plugins (source/physics/interaction_laws/, one file each) that register
// themselves by name; the 'Adhesion' section, declared here, chooses one
// and sets the scales every law shares.
#ifndef viscoslide_interaction_law_h
#define viscoslide_interaction_law_h

#include <viscoslide/io/input.h>
#include <viscoslide/io/registry.h>

#include <functional>
#include <memory>
#include <string>

namespace viscoslide
{
  class InteractionLaw
  {
  public:
    virtual ~InteractionLaw() = default;

    virtual double
    traction(double gap) const = 0;

    virtual double
    derivative(double gap) const = 0;
  };

  // One registered law: it is built from the work of adhesion dgamma and
  // the range eps.
  struct InteractionLawType
  {
    std::string name;
    // One or two sentences for the documentation of the entry.
    std::string description;
    std::function<std::unique_ptr<InteractionLaw>(double dgamma, double eps)>
      create;
    // false: a repulsive wall without attraction, whose stiffness alone the
    // Tabor parameter sets (no adhesive zone to resolve).
    bool adhesive;
  };

  namespace Parameters
  {
    struct Adhesion
    {
      // The declared defaults (units.cc refuses changed ones in SI).
      static constexpr const char *default_tabor_parameter = "6.08";
      static constexpr const char *default_R_over_eps      = "1e4";

      std::string  law; // a registered InteractionLawType
      double       tabor_parameter;
      double       R_over_eps;
      double       contact_gap;
      unsigned int face_quadrature_points;

      static void
      declare(ParameterHandler &prm);
      void
      parse(ParameterHandler &prm);

      // Whether the law attracts (InteractionLawType::adhesive).
      bool
      adhesive() const;
    };
  } // namespace Parameters

  // The law registered as `name`, for the work of adhesion dgamma and the
  // range eps.
  std::unique_ptr<InteractionLaw>
  create_interaction_law(const std::string &name, double dgamma, double eps);


  // A law whose attraction is switched on by a factor s in [0, 1]:
  // (1 - s) wall + s law, with the wall the law registered as "repulsive"
  // at the same dgamma and eps. An undeformed block cannot be brought into
  // adhesive contact by Newton's method (the surface has to jump); on the
  // wall (s = 0) there is no jump, and from that contact the adhesive one
  // follows continuously as s grows (at a fixed approach the contact only
  // widens).
  class AttractionHomotopy : public InteractionLaw
  {
  public:
    AttractionHomotopy(const std::string &name, double dgamma, double eps);

    void
    set_attraction(double s);

    double
    traction(double gap) const override;

    double
    derivative(double gap) const override;

  private:
    const std::unique_ptr<InteractionLaw> wall, law;
    double                                s = 1.;
  };
} // namespace viscoslide

#endif

// Traction-gap laws of the top surface (Derjaguin approximation). The
// traction p(g) is positive when it attracts (pulls the surface up towards
// the indenter); the contact pressure of the paper is -p.
#ifndef viscoslide_interaction_law_h
#define viscoslide_interaction_law_h

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


  // p(g) = 8 dgamma/(3 eps) [(eps/g)^3 - (eps/g)^9]. Below g = eps/2 the law
  // is continued linearly so that a wild Newton iterate cannot produce
  // Inf/NaN; converged states stay far from it.
  class LennardJones : public InteractionLaw
  {
  public:
    LennardJones(double dgamma, double eps, bool repulsive_only = false);

    double
    traction(double gap) const override;

    double
    derivative(double gap) const override;

  private:
    double
    raw_traction(double gap) const;
    double
    raw_derivative(double gap) const;

    double dgamma, eps;
    bool   repulsive_only;
    // Width of the C1 rounding of the repulsive-only branch below g = eps,
    // in units of eps (see traction()). Narrow: a band of 0.1 eps softened
    // the wall enough to widen the Hertz contact by 1 % (hertz test).
    static constexpr double rounding = 0.02;
  };

  // "lennard-jones" or "repulsive" (the repulsive branch alone, rounded to
  // C1 over [0.98 eps, eps]).
  std::unique_ptr<InteractionLaw>
  create_interaction_law(const std::string &name, double dgamma, double eps);
} // namespace viscoslide

#endif

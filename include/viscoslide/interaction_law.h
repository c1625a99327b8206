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

  // Xu-Needleman's normal law about the equilibrium gap eps: with d = g -
  // eps, p = dgamma d/delta^2 exp(-d/delta), whose work of separation from
  // d = 0 is exactly dgamma. delta = 9 sqrt(3)/(16 e) eps gives the peak
  // traction dgamma/(e delta) of the Lennard-Jones law, so that muT keeps
  // its meaning. Repulsion (d < 0) grows exponentially; continued linearly
  // below d = -eps/2 like the Lennard-Jones law.
  class Exponential : public InteractionLaw
  {
  public:
    Exponential(double dgamma, double eps);

    double
    traction(double gap) const override;

    double
    derivative(double gap) const override;

  private:
    double dgamma, eps, delta;
  };

  // Maugis-Dugdale: a constant attraction sigma0 (the Lennard-Jones peak
  // traction) from the contact up to the range h = dgamma/sigma0, on top of
  // the rounded repulsive branch of the Lennard-Jones law below eps. Newton
  // needs a continuous law: the attraction rises by a cubic step of width
  // 0.05 h centred on eps and falls by one of width 0.25 h centred on
  // eps + h, which keeps the work of separation from the contact at
  // dgamma. The fall is the wider: each surface point crosses it during an
  // approach or a retraction, and Newton's linearisation holds only over a
  // fraction of the step's width (with 0.05 h a step of 0.1 eps near the
  // jump-in had to be cut to 1/64).
  class Dugdale : public InteractionLaw
  {
  public:
    Dugdale(double dgamma, double eps);

    double
    traction(double gap) const override;

    double
    derivative(double gap) const override;

  private:
    LennardJones wall;
    double       eps, sigma0, h, w_rise, w_fall;
  };

  // "lennard-jones", "repulsive" (the repulsive branch alone, rounded to C1
  // over [0.98 eps, eps]), "exponential" or "dugdale".
  std::unique_ptr<InteractionLaw>
  create_interaction_law(const std::string &name, double dgamma, double eps);
} // namespace viscoslide

#endif

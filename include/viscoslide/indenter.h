// Rigid indenter profiles h(xi), xi = x - s measured from the apex.
#ifndef viscoslide_indenter_h
#define viscoslide_indenter_h

#include <memory>

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

  // The gap of physics.md, g = eps + h(x - s) - delta - u_y, for a surface
  // point at x displaced by u_y, with the indenter at approach delta and
  // lateral position s.
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

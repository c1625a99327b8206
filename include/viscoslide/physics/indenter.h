// SPDX-License-Identifier: LGPL-2.1-or-later
// Rigid indenter profiles h(xi), xi = x - s measured from the apex (lengths
// in eps). Every solver and the postprocessing see only the Indenter
// interface. The shapes are plugins (source/physics/indenters/, one file each):
// each registers itself by name with VISCOSLIDE_REGISTER(IndenterShape,
// ...), declares its own entries in the 'Indenter' section and reads them,
// so that a new shape is one new file.
#ifndef viscoslide_indenter_h
#define viscoslide_indenter_h

#include <deal.II/base/point.h>

#include <viscoslide/io/input.h>
#include <viscoslide/io/registry.h>

#include <cmath>
#include <functional>
#include <memory>
#include <string>

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

  // A shape whose entries have been read: it builds the indenter for the
  // radius R (R_hat eps, the 'Adhesion/R over eps' of every shape). A
  // profile that cannot be built (unreadable table, bad expression) throws
  // Parameters::ExcInvalidInput naming the entry.
  using IndenterMaker = std::function<std::unique_ptr<Indenter>(double R)>;

  // One registered shape.
  struct IndenterShape
  {
    std::string name;
    // One or two sentences for the documentation of 'Indenter/Shape'.
    std::string description;
    // Declares the shape's own entries, inside the 'Indenter' section.
    std::function<void(ParameterHandler &)> declare_parameters;
    // Reads and checks them, inside the 'Indenter' section.
    std::function<IndenterMaker(ParameterHandler &)> parse_parameters;
  };

  namespace Parameters
  {
    // The 'Indenter' section: the shape and, from its own entries, how to
    // build it.
    struct IndenterProfile
    {
      std::string   shape;
      IndenterMaker make;

      static void
      declare(ParameterHandler &prm);
      void
      parse(ParameterHandler &prm);
    };
  } // namespace Parameters

  // The shape the parameters select; R is R_hat eps. Refuses (with
  // Parameters::ExcInvalidInput) a profile that is not finite where the
  // surface of a block of domain_width can meet it.
  std::unique_ptr<Indenter>
  create_indenter(const Parameters::IndenterProfile &profile,
                  double                             R,
                  double                             domain_width);

  // Where a surface point at p lies on the profile with the apex at x = s:
  // xi = x - s in 2D; in 3D the radius of the body of revolution,
  // sqrt((x - s)^2 + y^2/elongation) (R_y/R_x = elongation, doc/sphere.md).
  template <int dim>
  inline double
  apex_distance(const dealii::Point<dim> &p,
                const double              s,
                const double              elongation)
  {
    if constexpr (dim == 2)
      return p[0] - s;
    else
      return std::hypot(p[0] - s, p[1] / std::sqrt(elongation));
  }

  // The gap of doc/conventions.md, g = eps + h(x - s) - delta - u_y, for a
  // surface point at x displaced by u_y, with the indenter at approach
  // delta and lateral position s.
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
  // The same gap at a surface point p displaced vertically by u: in 3D
  // the indenter as its body of revolution, stretched across the track by
  // `elongation` (apex_distance()).
  template <int dim>
  inline double
  gap(const Indenter           &indenter,
      const double              eps,
      const double              delta,
      const double              s,
      const dealii::Point<dim> &p,
      const double              u,
      const double              elongation)
  {
    return gap(indenter, eps, delta, 0., apex_distance(p, s, elongation), u);
  }
} // namespace viscoslide

#endif

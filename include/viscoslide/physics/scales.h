// SPDX-License-Identifier: LGPL-2.1-or-later
// The reduced units of a case. Internal units: eps = 1, E0* = E0/(1-nu^2)
// = 1 and the user's time constant tau_ref = 1. Everything that turns
// internal numbers into the paper's dimensionless groups lives here, so
// that no output invents its own normalisation (doc/conventions.md).
#ifndef viscoslide_scales_h
#define viscoslide_scales_h

#include <viscoslide/io/output.h>
#include <viscoslide/physics/material.h>

#include <vector>

namespace viscoslide
{
  namespace Parameters
  {
    struct AllParameters;
  }

  struct Scales
  {
    explicit Scales(const Parameters::AllParameters &p);

    double eps;       // interaction range (= 1)
    double R;         // indenter radius, R_hat eps
    double E0_star;   // plane-strain relaxed modulus (= 1)
    double Einf_star; // plane-strain instantaneous modulus
    double dgamma;    // work of adhesion, sqrt(muT^3/R_hat) E0* eps
    double sigma_max; // Lennard-Jones peak traction
    // The F_hat unit: in 2D (pi dgamma^2 E0* R)^(1/3) (per unit length),
    // in 3D 1.5 pi dgamma R (the JKR pull-off of the relaxed sphere).
    double force;
    // The unit of the contact's measure: in 2D R (L_hat = L/R), in 3D
    // pi R eps (A_hat = A/(pi R eps), delta/eps for Hertz).
    double contact;
    int    dimension; // of the problem, 2 or 3
    double tau_arm;   // relaxation time of the Maxwell arm
    double tau_ref;   // the time unit of V_hat and time_over_tau (= 1)
    // The SI columns every table adds in a case given in SI units (units.h;
    // none in a dimensionless case).
    std::vector<CsvTable::Derived> si_columns;
  };

  // The name of the contact's measure in the tables: L_hat = L/R in 2D,
  // A_hat = A/(pi R eps) in 3D (Scales::contact).
  inline const char *
  contact_column(const int dim)
  {
    return dim == 3 ? "A_hat" : "L_hat";
  }

  // The solid of the parameters in internal units: E0 = 1 - nu^2, so that
  // E0* = 1, and the arms' times in tau_ref.
  ViscoelasticSolid
  make_solid(const Parameters::AllParameters &p, const Scales &scales);

  // The creep (retardation) time of the slowest arm, in the time unit of
  // V_hat: V_hat times it is the wake length behind the contact in eps.
  double
  longest_creep_time(const Parameters::AllParameters &p);
} // namespace viscoslide

#endif

// SPDX-License-Identifier: LGPL-2.1-or-later
// The 'Units' section: a case given in SI units (moduli in Pa, times in s,
// lengths in m, speeds in m/s, loads in N/m in 2D and N in 3D) and the
// temperature at which the material is taken. The program works in the
// reduced units of doc/conventions.md; apply_units() converts the SI
// entries once, after every section is read, shifts the arms' times to the
// temperature, and says what it derived (muT, R_hat, V_hat, F_hat, a_T) in
// the case's notes. In SI every table gets SI columns beside its
// dimensionless ones (si_columns()). A dimensionless file is unchanged.
#ifndef viscoslide_units_h
#define viscoslide_units_h

#include <viscoslide/io/input.h>
#include <viscoslide/io/output.h>

#include <vector>

namespace viscoslide
{
  namespace Parameters
  {
    struct AllParameters;

    enum class UnitSystem
    {
      dimensionless,
      si
    };
    VISCOSLIDE_CHOICES(UnitSystem, "dimensionless", "SI")

    // How the relaxation times move with temperature (time-temperature
    // superposition): tau_k(T) = a_T tau_k(T_ref).
    enum class ShiftLaw
    {
      none,
      wlf,
      arrhenius
    };
    VISCOSLIDE_CHOICES(ShiftLaw, "none", "WLF", "Arrhenius")

    struct Units
    {
      UnitSystem system;
      // SI only: the material and the contact.
      double relaxed_modulus, instantaneous_modulus; // Pa
      double time_constant;                          // s
      double radius, work_of_adhesion, range;        // m, J/m^2, m
      // Both systems: the temperature and its shift of the arms' times.
      double   temperature, reference_temperature; // degrees C
      ShiftLaw shift_law;
      double   wlf_c1, wlf_c2;    // -, K
      double   activation_energy; // J/mol

      // Set by apply_units(): a_T, and in SI the SI value of the reduced
      // units of length (eps), time (tau), force, contact measure and
      // pressure (Scales::force, contact and sigma_max).
      double shift_factor = 1.;
      double length = 1., time = 1., force = 1., contact = 1., pressure = 1.;

      static void
      declare(ParameterHandler &prm);
      void
      parse(ParameterHandler &prm);

      // log10 a_T at `temperature` for the shift law (0 for none); throws
      // ExcInvalidInput where the law is undefined (WLF beyond its
      // asymptote T_ref - C2).
      double
      log_shift_factor(double temperature) const;

      // The SI columns of a table in SI units, from the dimensionless
      // columns they follow (none in dimensionless units).
      std::vector<CsvTable::Derived>
      si_columns(int dimension) const;
    };

    // Converts the SI entries of `p` (see Units), shifts the arms' times to
    // the temperature, and notes what it derived. Throws ExcInvalidInput
    // naming the entry on a missing or contradictory value.
    void
    apply_units(AllParameters &p);
  } // namespace Parameters
} // namespace viscoslide

#endif

// SPDX-License-Identifier: LGPL-2.1-or-later
// The control of the indenter's normal direction, shared by every solver.
// Displacement: delta is given. Force: delta is an unknown and the load
// equation F_n = target closes the system. Spring: force control whose
// target follows delta, F0 + k (delta0 - delta), between the two (a
// tribometer's loading spring).
#ifndef viscoslide_load_control_h
#define viscoslide_load_control_h

namespace viscoslide
{
  struct LoadControl
  {
    bool   force_controlled = false;
    double target_force     = 0.;
    // force per unit length per length of approach; 0: plain force control
    double spring_stiffness = 0.;
    // the approach at which the spring is relaxed
    double spring_delta = 0.;

    // Displacement control: delta is given.
    void
    hold_approach()
    {
      force_controlled = false;
      spring_stiffness = 0.;
    }

    // Force control at F_n = normal_force; with a spring the target is
    // normal_force + spring (delta_of_spring - delta).
    void
    hold_force(const double normal_force,
               const double spring          = 0.,
               const double delta_of_spring = 0.)
    {
      force_controlled = true;
      target_force     = normal_force;
      spring_stiffness = spring;
      spring_delta     = delta_of_spring;
    }

    // The load equation's residual G = F_n - target at the approach delta;
    // its derivative by delta is dF_n/ddelta + spring_stiffness.
    double
    mismatch(const double normal_force, const double delta) const
    {
      return normal_force - target_force -
             spring_stiffness * (spring_delta - delta);
    }

    // For a checkpoint.
    template <class Archive>
    void
    serialize(Archive &ar, const unsigned int)
    {
      ar &force_controlled &target_force &spring_stiffness &spring_delta;
    }
  };
} // namespace viscoslide

#endif

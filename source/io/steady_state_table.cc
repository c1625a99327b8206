// SPDX-License-Identifier: LGPL-2.1-or-later
#include <viscoslide/io/steady_state_table.h>

#include <cmath>
#include <iomanip>
#include <limits>
#include <sstream>

namespace viscoslide
{
  double
  energy_balance(const double tangential_force,
                 const double normal_force,
                 const double V,
                 const double dissipation_rate)
  {
    if (std::abs(dissipation_rate / V / normal_force) <= 1e-3)
      return std::numeric_limits<double>::quiet_NaN();
    return tangential_force * V / dissipation_rate - 1;
  }


  SteadyStateTable::SteadyStateTable(const Parameters::AllParameters &prm,
                                     const Scales                    &scales,
                                     const std::string               &filename,
                                     MPI_Comm                         comm)
    : prm(prm)
    , scales(scales)
    , filename(filename)
    , comm(comm)
  {
  }


  void
  SteadyStateTable::resume(const std::size_t keep_rows)
  {
    if (keep_rows > 0)
      table = std::make_unique<CsvTable>(filename,
                                         columns(prm.geometry.dimension),
                                         keep_rows,
                                         comm,
                                         scales.si_columns);
  }


  double
  SteadyStateTable::t_hat(const Parameters::AllParameters &prm)
  {
    return prm.geometry.substrate == Parameters::Substrate::layer
             ? prm.geometry.layer_thickness
             : std::numeric_limits<double>::infinity();
  }


  std::vector<std::string>
  SteadyStateTable::columns(const int dimension)
  {
    std::vector<std::string> c = {"control",
                                  "mu_T",
                                  "R_hat",
                                  "substrate",
                                  "t_hat",
                                  "V_hat",
                                  "delta_hat",
                                  "F_n_hat",
                                  "F_t_hat",
                                  "F_t_contact_set_hat",
                                  "mu",
                                  "mu_contact_set",
                                  "mu_energy",
                                  contact_column(dimension),
                                  "dissipation_rate_hat",
                                  "steady",
                                  "sliding_distance_over_eps",
                                  "time_constant",
                                  "solver"};
    if (dimension == 3)
      c.insert(c.end(), {"x_trail_over_R", "x_lead_over_R", "y_half_over_R"});
    return c;
  }


  void
  SteadyStateTable::add_row(const double                    V_hat,
                            const double                    delta,
                            const SurfaceQuantities        &q,
                            const double                    dissipation_rate,
                            const bool                      steady,
                            const double                    distance,
                            const Parameters::SlidingSolver solver,
                            ConditionalOStream             &out)
  {
    const double V  = V_hat * scales.eps / scales.tau_ref;
    const double Fn = q.normal_force, Ft = q.tangential_force;
    const double mu             = std::abs(Ft / Fn);
    const double mu_contact_set = std::abs(q.contact_set_tangential_force / Fn);
    const double mu_energy      = std::abs(dissipation_rate / V / Fn);
    using F                     = CsvTable;
    if (!table)
      table = std::make_unique<CsvTable>(filename,
                                         columns(scales.dimension),
                                         version_string(),
                                         comm,
                                         scales.si_columns);
    CsvTable::Row row = {
      {"control", Parameters::to_string(prm.sliding.control)},
      {"mu_T", F::format(prm.adhesion.tabor_parameter)},
      {"R_hat", F::format(prm.adhesion.R_over_eps)},
      {"substrate", Parameters::to_string(prm.geometry.substrate)},
      {"t_hat", F::format(t_hat(prm))},
      {"V_hat", F::format(V_hat)},
      {"delta_hat", F::format(delta / scales.eps)},
      {"F_n_hat", F::format(Fn / scales.force)},
      {"F_t_hat", F::format(Ft / scales.force)},
      {"F_t_contact_set_hat",
       F::format(q.contact_set_tangential_force / scales.force)},
      {"mu", F::format(mu)},
      {"mu_contact_set", F::format(mu_contact_set)},
      {"mu_energy", F::format(mu_energy)},
      {contact_column(scales.dimension),
       F::format(q.contact_length / scales.contact)},
      {"dissipation_rate_hat",
       F::format(dissipation_rate * scales.tau_ref /
                 (scales.force * scales.eps))},
      {"steady", steady ? "1" : "0"},
      {"sliding_distance_over_eps", F::format(distance)},
      {"time_constant", Parameters::to_string(prm.material.time_constant)},
      {"solver", Parameters::to_string(solver)}};
    if (scales.dimension == 3)
      row.insert(row.end(),
                 {{"x_trail_over_R", F::format(q.x_trail / scales.R)},
                  {"x_lead_over_R", F::format(q.x_lead / scales.R)},
                  {"y_half_over_R", F::format(q.y_half / scales.R)}});
    table->add_row(row);
    out << "mu = " << mu << ", mu_contact_set = " << mu_contact_set
        << ", mu_energy = " << mu_energy << ", "
        << contact_column(scales.dimension) << " = "
        << q.contact_length / scales.contact
        << ", F_n_hat = " << Fn / scales.force << std::endl;
    // Said at every row: a mesh can miss V tau, and the steady-state
    // solver has no other sign of it.
    if (const double balance = energy_balance(Ft, Fn, V, dissipation_rate);
        !std::isnan(balance))
      {
        std::ostringstream percent;
        percent << std::showpos << std::fixed << std::setprecision(2)
                << 100 * balance << " %";
        out << "energy balance: x force on the indenter against "
               "dissipation / V: "
            << percent.str()
            << (std::abs(balance) > 0.01
                  ? " (more than 1 %: not steady yet, or V tau and the "
                    "contact edges not resolved by the mesh)"
                  : "")
            << std::endl;
      }
  }
} // namespace viscoslide

// SPDX-License-Identifier: LGPL-2.1-or-later
#include <viscoslide/steady_sliding.h>

#include <cstdio>

namespace viscoslide
{
  namespace
  {
    // continuation.csv, new or reopened after the rows of a checkpoint.
    CsvTable
    open_continuation_table(const Parameters::AllParameters &prm,
                            const OutputWriter              &writer,
                            const StationCheckpoint         &start,
                            MPI_Comm                         comm)
    {
      const std::vector<std::string> columns = {"V_hat",
                                                "delta_hat",
                                                "F_n_hat",
                                                "F_t_hat",
                                                "mu",
                                                "mu_energy",
                                                contact_column(
                                                  prm.geometry.dimension),
                                                "newton_iterations",
                                                "n_dofs"};
      const std::string              path    = writer.path("continuation.csv");
      const auto si = prm.units.si_columns(prm.geometry.dimension);
      if (start.next_station > 0)
        return CsvTable(path, columns, start.continuation_rows, comm, si);
      return CsvTable(path,
                      columns,
                      version_string() + "; time unit: " +
                        Parameters::to_string(prm.material.time_constant) +
                        " time",
                      comm,
                      si);
    }

    // The last converged state, so that a failure reports it and not the
    // unconverged one.
    struct LastConverged
    {
      double            V_hat = 0., delta = 0., rate = 0.;
      SurfaceQuantities q{};

      // Takes the solver's state and adds its row to continuation.csv.
      void
      record(const SteadySliding &solver, const Scales &scales, CsvTable &table)
      {
        V_hat           = solver.speed();
        delta           = solver.approach();
        rate            = solver.dissipation_rate();
        q               = solver.quantities();
        const double V  = V_hat * scales.eps / scales.tau_ref;
        const double Fn = q.normal_force;
        using F         = CsvTable;
        table.add_row(
          {{"V_hat", F::format(V_hat)},
           {"delta_hat", F::format(delta / scales.eps)},
           {"F_n_hat", F::format(Fn / scales.force)},
           {"F_t_hat", F::format(q.tangential_force / scales.force)},
           {"mu", F::format(std::abs(q.tangential_force / Fn))},
           {"mu_energy", F::format(std::abs(rate / V / Fn))},
           {contact_column(scales.dimension),
            F::format(q.contact_length / scales.contact)},
           {"newton_iterations", std::to_string(solver.newton_iterations())},
           {"n_dofs", std::to_string(solver.n_unknowns())}});
      }
    };

    // The profiles and fields of station k of n: with a list, a profile per
    // station; the last one also under the name the single-speed run uses.
    void
    write_station(const SteadySliding             &solver,
                  const Parameters::AllParameters &prm,
                  OutputWriter                    &writer,
                  const unsigned int               k,
                  const unsigned int               n)
    {
      char suffix[16];
      std::snprintf(suffix, sizeof(suffix), "_%02u", k);
      if (n > 1)
        solver.write_profile(
          writer.path("surface_profile_steady" + std::string(suffix) + ".csv"));
      if (k + 1 == n)
        solver.write_profile(writer.path("surface_profile_steady.csv"));
      if (prm.output.write_fields)
        solver.write_fields(writer, k);
    }
  } // namespace


  void
  run_stations(SteadySliding                   &solver,
               const Parameters::SlidingSolver  kind,
               const Parameters::AllParameters &prm,
               const Scales                    &scales,
               OutputWriter                    &writer,
               SteadyStateTable                &steady_state_table,
               Progress                        *progress,
               ConditionalOStream              &out,
               MPI_Comm                         comm,
               const StationCheckpoint         &start,
               const std::function<void(const StationCheckpoint &)> &checkpoint)
  {
    CsvTable    table   = open_continuation_table(prm, writer, start, comm);
    const auto &speeds  = prm.sliding.speeds;
    const auto &loads   = prm.sliding.load_path;
    const auto  n_total = speeds.size() + loads.size();
    if (start.next_station > 0)
      {
        steady_state_table.resume(start.table_rows);
        if (progress != nullptr)
          progress->resume_case(double(start.next_station) / n_total);
      }
    LastConverged last;
    last.delta              = solver.approach();
    last.q                  = solver.quantities();
    const auto on_converged = [&] { last.record(solver, scales, table); };

    const bool        force     = solver.force_control();
    const double      unit      = force ? scales.force : scales.eps;
    const std::string load_name = force ? "F_hat " : "delta_hat ";
    std::string       failed;
    for (unsigned int k = start.next_station; k < n_total; ++k)
      {
        const bool   is_speed = k < speeds.size();
        const double value    = is_speed ? speeds[k] : loads[k - speeds.size()];
        const bool   converged =
          is_speed ? solver.continue_to(value, on_converged)
                     : solver.continue_to_load(value * unit, on_converged);
        steady_state_table.add_row(
          last.V_hat, last.delta, last.q, last.rate, converged, 0., kind, out);
        if (!converged)
          {
            failed += (failed.empty() ? "" : ", ") +
                      (is_speed ? std::string("V_hat ") : load_name) +
                      CsvTable::format(value);
            continue;
          }
        write_station(solver, prm, writer, k, n_total);
        if (checkpoint)
          checkpoint({k + 1, table.n_rows(), steady_state_table.n_rows()});
        if (progress != nullptr)
          out << "  " << (is_speed ? "V_hat " : load_name) << value << " ("
              << k + 1 << "/" << n_total << ")  ["
              << progress->report((k + 1.) / n_total) << "]" << std::endl;
      }
    if (!failed.empty())
      throw std::runtime_error(
        "The " + Parameters::to_string(kind) + " solver did not converge at " +
        failed +
        "; their rows in steady_state.csv hold the last converged state "
        "with steady = 0");
  }
} // namespace viscoslide

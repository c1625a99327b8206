// SPDX-License-Identifier: LGPL-2.1-or-later
#include <viscoslide/steady_sliding.h>

#include <cstdio>
#include <functional>
#include <type_traits>

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

    // A converged continuation step, as continuation.csv shows it; the last
    // one of a station is its row in steady_state.csv (that of a station
    // missed: the state it was left in). Plain numbers, so that the process
    // that took the station can send it.
    struct Step
    {
      double            V_hat = 0., delta = 0., rate = 0.;
      SurfaceQuantities q{};
      unsigned int      newton_iterations = 0;
      unsigned long     n_dofs            = 0;

      static Step
      of(const SteadySliding &solver)
      {
        return {solver.speed(),
                solver.approach(),
                solver.dissipation_rate(),
                solver.quantities(),
                solver.newton_iterations(),
                solver.n_unknowns()};
      }

      void
      add_to(CsvTable &table, const Scales &scales) const
      {
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
           {"newton_iterations", std::to_string(newton_iterations)},
           {"n_dofs", std::to_string(n_dofs)}});
      }
    };

    // A station as its process ran it: its converged steps, the state it
    // ended in, and the error that stopped it, if one did.
    struct Station
    {
      std::vector<Step> steps;
      Step              last;
      bool              converged = false;
      std::vector<char> error;
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

    // Station k from the solver's present state. Its steps go to `table`
    // as they converge, or, for a process whose stations another writes
    // (table = nullptr), into the station; if `catch_error`, the exception
    // that stopped it goes there too (the other process waits for its
    // outcome).
    Station
    run_station(SteadySliding                   &solver,
                const Parameters::AllParameters &prm,
                const Scales                    &scales,
                OutputWriter                    &writer,
                const unsigned int               k,
                Step                            &last,
                CsvTable                        *table,
                const bool                       catch_error)
    {
      const auto  &speeds  = prm.sliding.speeds;
      const auto   n_total = speeds.size() + prm.sliding.load_path.size();
      const double unit    = solver.force_control() ? scales.force : scales.eps;
      Station      station;
      const auto   on_converged = [&] {
        last = Step::of(solver);
        if (table != nullptr)
          last.add_to(*table, scales);
        else
          station.steps.push_back(last);
      };
      const auto run = [&] {
        station.converged =
          k < speeds.size()
            ? solver.continue_to(speeds[k], on_converged)
            : solver.continue_to_load(prm.sliding.load_path[k - speeds.size()] *
                                        unit,
                                      on_converged);
        if (station.converged)
          write_station(solver, prm, writer, k, n_total);
      };
      if (!catch_error)
        run();
      else
        try
          {
            run();
          }
        catch (const std::exception &e)
          {
            const std::string what = e.what();
            station.error.assign(what.begin(), what.end());
          }
      station.last = last;
      return station;
    }


    // Plain values sent from process 1 to process 0, and received there.
    template <typename T>
    void
    send(MPI_Comm comm, const std::vector<T> &values)
    {
      static_assert(std::is_trivially_copyable_v<T>);
      MPI_Send(values.data(), values.size() * sizeof(T), MPI_BYTE, 0, 0, comm);
    }

    template <typename T>
    std::vector<T>
    receive(MPI_Comm comm)
    {
      MPI_Status status;
      MPI_Probe(1, 0, comm, &status);
      int bytes = 0;
      MPI_Get_count(&status, MPI_BYTE, &bytes);
      std::vector<T> values(bytes / sizeof(T));
      MPI_Recv(values.data(), bytes, MPI_BYTE, 1, 0, comm, MPI_STATUS_IGNORE);
      return values;
    }

    void
    send(MPI_Comm comm, const Station &s)
    {
      send(comm, s.steps);
      send(comm, std::vector<Step>{s.last});
      send(comm, std::vector<char>{s.converged});
      send(comm, s.error);
    }

    Station
    receive_station(MPI_Comm comm)
    {
      // A braced list is evaluated in its order, that of the sends.
      return {receive<Step>(comm),
              receive<Step>(comm)[0],
              receive<char>(comm)[0] != 0,
              receive<char>(comm)};
    }


    // The last end's stations, taken downwards from the last (n - 1, n -
    // 2, ...), sent from process 1 and recorded upwards on process 0.
    void
    exchange_last_end(
      MPI_Comm                                                  comm,
      const unsigned int                                        end,
      const std::vector<Station>                               &from_last,
      const unsigned int                                        n,
      const std::function<void(unsigned int, const Station &)> &record)
    {
      if (end == 1)
        {
          send(comm, std::vector<unsigned int>{unsigned(from_last.size())});
          for (const Station &s : from_last)
            send(comm, s);
        }
      else if (end == 0)
        {
          const unsigned int   m = receive<unsigned int>(comm)[0];
          std::vector<Station> stations;
          for (unsigned int i = 0; i < m; ++i)
            stations.push_back(receive_station(comm));
          for (unsigned int i = m; i-- > 0;)
            record(n - 1 - i, stations[i]);
        }
    }


    // The stations [first, n) of a run, taken by one process in their
    // order, or by two from both ends: process 0 from the first up,
    // process 1 from the last down, meeting without overlap, each claiming
    // its next by an atomic count of the stations claimed, held by process
    // 0 (a shared-memory window on one node, so that a claim does not wait
    // for the other's computation).
    class StationClaims
    {
    public:
      StationClaims(MPI_Comm           comm,
                    const unsigned int first,
                    const unsigned int n,
                    const bool         two_ends)
        : end(two_ends ? std::min(Utilities::MPI::this_mpi_process(comm), 2u)
                       : 0)
        , first(first)
        , n(n)
      {
        if (!two_ends)
          return;
        const MPI_Aint bytes = end == 0 ? sizeof(long) : 0;
        MPI_Win_allocate(
          bytes, sizeof(long), MPI_INFO_NULL, comm, &count, &window);
        if (end == 0)
          *count = 0;
        MPI_Barrier(comm);
        MPI_Win_lock_all(0, window);
      }

      StationClaims(const StationClaims &) = delete;
      StationClaims &
      operator=(const StationClaims &) = delete;

      ~StationClaims()
      {
        if (window == MPI_WIN_NULL)
          return;
        MPI_Win_unlock_all(window);
        MPI_Win_free(&window);
      }

      // This process's next station, n where none is left for it.
      unsigned int
      next()
      {
        if (window == MPI_WIN_NULL)
          return first + mine++;
        if (end == 2)
          return n;
        const long one = 1;
        MPI_Fetch_and_op(&one, &claimed, MPI_LONG, 0, 0, MPI_SUM, window);
        MPI_Win_flush(0, window);
        if (claimed >= long(n - first))
          return n;
        return end == 0 ? first + mine++ : n - 1 - mine++;
      }

      // The stations claimed so far by both (this one's last claim).
      double
      fraction_claimed() const
      {
        return std::min(
          1.,
          (window == MPI_WIN_NULL ? first + mine : first + claimed + 1.) / n);
      }

      // Process 0 for the first end, 1 for the last, 2 for none.
      const unsigned int end;

    private:
      const unsigned int first, n;
      MPI_Win            window  = MPI_WIN_NULL;
      long              *count   = nullptr;
      long               claimed = 0;
      unsigned int       mine    = 0;
    };
  } // namespace


  bool
  stations_from_both_ends(const SteadySliding             &solver,
                          const Parameters::AllParameters &prm,
                          MPI_Comm                         comm)
  {
    return solver.from_both_ends() &&
           Utilities::MPI::n_mpi_processes(comm) > 1 &&
           prm.sliding.load_path.empty() && prm.sliding.speeds.size() > 1;
  }


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
    const auto  n_total = speeds.size() + prm.sliding.load_path.size();
    if (start.next_station > 0)
      {
        steady_state_table.resume(start.table_rows);
        if (progress != nullptr)
          progress->resume_case(double(start.next_station) / n_total);
      }
    Step last;
    last.delta = solver.approach();
    last.q     = solver.quantities();

    const bool        two_ends = stations_from_both_ends(solver, prm, comm);
    StationClaims     claims(comm, start.next_station, n_total, two_ends);
    const std::string load_name =
      solver.force_control() ? "F_hat " : "delta_hat ";
    std::string failed, error;
    // A station's rows and report: on every process (rank 0 writes them),
    // or, from both ends, on process 0.
    const auto record = [&](const unsigned int k, const Station &s) {
      for (const Step &step : s.steps)
        step.add_to(table, scales);
      const Step &row = s.last;
      steady_state_table.add_row(
        row.V_hat, row.delta, row.q, row.rate, s.converged, 0., kind, out);
      const bool   is_speed = k < speeds.size();
      const double value =
        is_speed ? speeds[k] : prm.sliding.load_path[k - speeds.size()];
      if (!s.error.empty())
        error = std::string(s.error.begin(), s.error.end());
      else if (!s.converged)
        failed += (failed.empty() ? "" : ", ") +
                  (is_speed ? std::string("V_hat ") : load_name) +
                  CsvTable::format(value);
      else if (checkpoint)
        checkpoint({k + 1, table.n_rows(), steady_state_table.n_rows()});
      if (progress != nullptr && s.converged)
        out << "  " << (is_speed ? "V_hat " : load_name) << value << " ("
            << k + 1 << "/" << n_total << ")  ["
            << progress->report(claims.fraction_claimed()) << "]" << std::endl;
    };
    // The last end's stations, sent to the first end when both are done.
    std::vector<Station> from_last;
    // A process stops claiming at an error (the other takes the rest).
    while (error.empty())
      {
        const unsigned int k = claims.next();
        if (k >= n_total)
          break;
        const Station s = run_station(solver,
                                      prm,
                                      scales,
                                      writer,
                                      k,
                                      last,
                                      claims.end == 0 ? &table : nullptr,
                                      two_ends);
        if (claims.end == 0)
          record(k, s);
        else
          {
            from_last.push_back(s);
            if (!s.error.empty())
              break;
          }
      }
    if (two_ends)
      {
        exchange_last_end(comm, claims.end, from_last, n_total, record);
        error  = Utilities::MPI::broadcast(comm, error, 0);
        failed = Utilities::MPI::broadcast(comm, failed, 0);
      }
    if (!error.empty())
      throw std::runtime_error(error);
    if (!failed.empty())
      throw std::runtime_error(
        "The " + Parameters::to_string(kind) + " solver did not converge at " +
        failed +
        "; their rows in steady_state.csv hold the last converged state "
        "with steady = 0");
  }
} // namespace viscoslide

// SPDX-License-Identifier: LGPL-2.1-or-later
// ContactProblem: the tables (approach.csv, history.csv), the per-step
// report, surface profiles and the volume and surface fields.
#include <deal.II/fe/fe_values.h>

#include <deal.II/numerics/data_out.h>

#include <viscoslide/contact_problem.h>
#include <viscoslide/io/field_recovery.h>
#include <viscoslide/io/surface_fields.h>

#include <array>
#include <iomanip>

namespace viscoslide
{
  namespace
  {
    const std::vector<std::string> approach_columns{"step",
                                                    "phase",
                                                    "time_over_tau",
                                                    "delta_hat",
                                                    "F_n_hat",
                                                    "F_t_hat",
                                                    "L_hat",
                                                    "min_gap_over_eps",
                                                    "newton_iterations",
                                                    "step_cuts",
                                                    "jump",
                                                    "n_dofs",
                                                    "n_cells"};
    const std::vector<std::string> history_columns{"time_over_tau",
                                                   "V_hat",
                                                   "s_over_eps",
                                                   "delta_hat",
                                                   "F_n_hat",
                                                   "F_t_hat",
                                                   "F_t_contact_set_hat",
                                                   "mu",
                                                   "mu_contact_set",
                                                   "L_hat",
                                                   "x_trail_over_R",
                                                   "x_lead_over_R",
                                                   "dissipation_rate_hat",
                                                   "mu_energy",
                                                   "newton_iterations",
                                                   "n_dofs"};
  } // namespace


  void
  ContactProblem::open_approach_table(const bool resume)
  {
    approach_table =
      open_table("approach.csv",
                 approach_columns,
                 resume,
                 approach_rows,
                 "; forces per unit length in (pi dgamma^2 E0* R)^(1/3)");
  }


  void
  ContactProblem::open_history_table(const bool resume)
  {
    history_table =
      open_table("history.csv", history_columns, resume, history_rows, "");
  }


  // A new table, or with `resume` the existing one continued after its
  // first keep_rows rows (those of the checkpoint).
  std::unique_ptr<CsvTable>
  ContactProblem::open_table(const std::string              &name,
                             const std::vector<std::string> &columns,
                             const bool                      resume,
                             const unsigned int              keep_rows,
                             const std::string              &units) const
  {
    if (resume)
      return std::make_unique<CsvTable>(writer.path(name),
                                        columns,
                                        keep_rows,
                                        mpi_communicator,
                                        scales.si_columns);
    return std::make_unique<CsvTable>(
      writer.path(name),
      columns,
      version_string() + "; time unit: " +
        Parameters::to_string(prm.material.time_constant) + " time" + units,
      mpi_communicator,
      scales.si_columns);
  }


  void
  ContactProblem::record_step(const Phase phase)
  {
    TimerOutput::Scope t(timer, "postprocessing");
    last_quantities       = postprocessor.integrate(dof_handler,
                                              solution,
                                              committed.delta,
                                              committed.s);
    last_dissipation_rate = total_dissipation_rate();
    if (phase == Phase::slide)
      {
        ++history_rows;
        add_history_row();
      }
    else
      {
        ++approach_rows;
        add_approach_row(phase);
      }
    print_step(phase);
    if (prm.output.profile_every > 0 &&
        step_number % prm.output.profile_every == 0)
      write_profile("surface_profile-" +
                    Utilities::int_to_string(step_number, 5) + ".csv");
    if (prm.output.write_fields && prm.output.fields_every > 0 &&
        step_number % prm.output.fields_every == 0)
      write_fields();
    ++step_number;
  }


  // A row of history.csv: the sliding step just committed.
  void
  ContactProblem::add_history_row()
  {
    const SurfaceQuantities &sq = last_quantities;
    using F                     = CsvTable;
    const auto   integer = [](const auto n) { return std::to_string(n); };
    const double V = std::abs(sliding_speed()) * scales.eps / scales.tau_ref;
    const double rate =
      last_dissipation_rate * scales.tau_ref / (scales.force * scales.eps);
    history_table->add_row(
      {{"time_over_tau", F::format(committed.time / scales.tau_ref)},
       {"V_hat", F::format(sliding_speed())},
       {"s_over_eps", F::format(committed.s / scales.eps)},
       {"delta_hat", F::format(committed.delta / scales.eps)},
       {"F_n_hat", F::format(sq.normal_force / scales.force)},
       {"F_t_hat", F::format(sq.tangential_force / scales.force)},
       {"F_t_contact_set_hat",
        F::format(sq.contact_set_tangential_force / scales.force)},
       {"mu", F::format(std::abs(sq.tangential_force / sq.normal_force))},
       {"mu_contact_set",
        F::format(std::abs(sq.contact_set_tangential_force / sq.normal_force))},
       {"L_hat", F::format(sq.contact_length / scales.R)},
       {"x_trail_over_R", F::format(sq.x_trail / scales.R)},
       {"x_lead_over_R", F::format(sq.x_lead / scales.R)},
       {"dissipation_rate_hat", F::format(rate)},
       {"mu_energy",
        F::format(std::abs(last_dissipation_rate / V / sq.normal_force))},
       {"newton_iterations", integer(last_newton_iterations)},
       {"n_dofs", integer(dof_handler.n_dofs())}});
  }


  // A row of approach.csv: the approach or hold step just committed.
  void
  ContactProblem::add_approach_row(const Phase phase)
  {
    const SurfaceQuantities &sq = last_quantities;
    using F                     = CsvTable;
    const auto integer = [](const auto n) { return std::to_string(n); };
    approach_table->add_row(
      {{"step", integer(step_number)},
       {"phase", name(phase)},
       {"time_over_tau", F::format(committed.time / scales.tau_ref)},
       {"delta_hat", F::format(committed.delta / scales.eps)},
       {"F_n_hat", F::format(sq.normal_force / scales.force)},
       {"F_t_hat", F::format(sq.tangential_force / scales.force)},
       {"L_hat", F::format(sq.contact_length / scales.R)},
       {"min_gap_over_eps", F::format(sq.minimum_gap / scales.eps)},
       {"newton_iterations", integer(last_newton_iterations)},
       {"step_cuts", integer(last_step_cuts)},
       {"jump", integer(last_step_relaxed ? 1 : 0)},
       {"n_dofs", integer(dof_handler.n_dofs())},
       {"n_cells", integer(triangulation.n_global_active_cells())}});
  }


  // The step's line on the screen, with how far its phase is.
  void
  ContactProblem::print_step(const Phase phase)
  {
    const SurfaceQuantities &sq = last_quantities;
    pcout << "  step " << std::setw(4) << step_number << "  " << std::setw(8)
          << name(phase) << "  delta_hat " << std::setw(9) << committed.delta
          << "  F_hat " << std::setw(12) << sq.normal_force / scales.force
          << "  L_hat " << std::setw(11) << sq.contact_length / scales.R
          << "  Newton " << last_newton_iterations << "  dofs "
          << dof_handler.n_dofs() << (last_step_relaxed ? "  (jump)" : "");
    // How far the sliding phase is: its distance, or the program's
    // segments.
    const auto  &program = prm.sliding.program;
    const double slid    = committed.s - slide_plan.s0;
    double       done    = 0.;
    if (phase == Phase::slide && program.empty())
      {
        pcout << "  s " << slid << "/" << slide_plan.distance << " eps";
        done = slid / slide_plan.distance;
      }
    else if (phase == Phase::slide && program_segment < program.size())
      {
        pcout << "  segment " << program_segment + 1 << "/" << program.size();
        done = program_fraction();
      }
    if (phase == Phase::approach)
      pcout << "  ["
            << approach_progress.report(committed.delta / scales.eps,
                                        sq.normal_force / scales.force)
            << "]";
    else if (progress != nullptr)
      pcout << "  [" << progress->report(done) << "]";
    pcout << std::endl;
  }


  void
  ContactProblem::write_profile(const std::string &filename)
  {
    write_profile_csv(writer.path(filename),
                      postprocessor.profile(
                        dof_handler, solution, committed.delta, committed.s),
                      scales,
                      "delta_hat = " + CsvTable::format(committed.delta) +
                        ", time_over_tau = " + CsvTable::format(committed.time),
                      mpi_communicator);
  }


  void
  ContactProblem::quadrature_fields(
    const FEValues<dim>                         &fe_values,
    const DoFHandler<dim>::active_cell_iterator &cell,
    std::vector<std::vector<double>>            &fields) const
  {
    const FEValuesExtractors::Vector     displacement(0);
    std::vector<SymmetricTensor<2, dim>> strain(quadrature.size());
    std::vector<types::global_dof_index> history_dofs(
      history_fe.n_dofs_per_cell());
    std::vector<double> values;
    fe_values[displacement].get_function_symmetric_gradients(solution, strain);
    read_cell_history(cell, values, history_dofs);
    const unsigned int n_q = quadrature.size();
    for (unsigned int q = 0; q < n_q; ++q)
      {
        ArmStress h;
        double    rate = 0.;
        for (unsigned int k = 0; k < material.n_arms(); ++k)
          {
            const ArmStress h_k = arm_stress_at(values, k, q);
            h += h_k;
            rate += material.dissipation_rate(k, h_k);
          }
        const auto sigma = material.stress(strain[q], h);
        fields[0][q]     = sigma[0][0];
        fields[1][q]     = sigma[1][1];
        fields[2][q]     = sigma[0][1];
        fields[3][q]     = material.stress_zz(strain[q], h);
        fields[4][q]     = rate;
        fields[5][q]     = values[dissipated_energy() * n_q + q];
      }
  }


  // Volume fields (displacement, the stress, the dissipation rate and the
  // accumulated dissipated energy from the quadrature points, recovered
  // onto a continuous field, MPI subdomain, refinement level) and surface
  // fields (pressure, gap).
  void
  ContactProblem::write_fields()
  {
    TimerOutput::Scope t(timer, "output");
    Vector<float>      subdomain(triangulation.n_active_cells()),
      level(triangulation.n_active_cells());
    for (const auto &cell : triangulation.active_cell_iterators())
      if (cell->is_locally_owned())
        {
          subdomain(cell->active_cell_index()) = cell->subdomain_id();
          level(cell->active_cell_index())     = cell->level();
        }

    DataOut<dim> data_out;
    data_out.attach_triangulation(triangulation);
    data_out.add_data_vector(
      dof_handler,
      solution,
      std::vector<std::string>(dim, "displacement"),
      std::vector<DataComponentInterpretation::DataComponentInterpretation>(
        dim, DataComponentInterpretation::component_is_part_of_vector));
    const FieldRecovery<dim> recovery(dof_handler);
    FEValues<dim>            fe_values(fe, quadrature, update_gradients);
    auto                     fields =
      recovery.recover(quadrature,
                       n_quadrature_fields,
                       [&](const auto                       &cell,
                           std::vector<std::vector<double>> &values) {
                         fe_values.reinit(cell);
                         quadrature_fields(fe_values, cell, values);
                       });
    // The paper's Fig. 5 shows the dissipated energy in units of dgamma/L
    // (L the present contact length); zero while there is no contact.
    fields.push_back(fields[n_quadrature_fields - 1]);
    fields.back() *= last_quantities.contact_length / scales.dgamma;
    const char *names[] = {"stress_xx",
                           "stress_yy",
                           "stress_xy",
                           "stress_zz",
                           "dissipation_rate",
                           "dissipated_energy",
                           "dissipated_energy_hat"};
    for (unsigned int f = 0; f < fields.size(); ++f)
      data_out.add_data_vector(recovery.dof_handler(), fields[f], names[f]);
    data_out.add_data_vector(subdomain, "subdomain");
    data_out.add_data_vector(level, "level");
    data_out.build_patches(2);
    writer.write(data_out, "solution", step_number, committed.time);

    write_surface_fields(writer,
                         "surface",
                         dof_handler,
                         solution,
                         law,
                         indenter,
                         scales,
                         committed.delta,
                         committed.s,
                         step_number,
                         committed.time);
  }
} // namespace viscoslide

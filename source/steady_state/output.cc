// SPDX-License-Identifier: LGPL-2.1-or-later
// SteadyStateSolver: the stations of a run with their rows, profiles and
// fields, and the dissipation.
#include <deal.II/fe/fe_values.h>

#include <deal.II/numerics/data_out.h>

#include <viscoslide/io/field_recovery.h>
#include <viscoslide/io/surface_fields.h>
#include <viscoslide/steady_state/solver.h>
#include <viscoslide/steady_state/viscous_strain.h>

#include <cstdio>

namespace viscoslide
{
  template <int dim>
  void
  SteadyStateSolver<dim>::quadrature_fields(
    const FEValues<dim>              &fe_values,
    std::vector<std::vector<double>> &fields) const
  {
    const FEValuesExtractors::Vector     displacement(0);
    const unsigned int                   n_q = quadrature.size();
    std::vector<SymmetricTensor<2, dim>> strain(n_q), projected_strain(n_q);
    std::vector<Vector<double>> values(n_q, Vector<double>(fe.n_components()));
    fe_values[displacement].get_function_symmetric_gradients(solution, strain);
    fe_values.get_function_values(solution, values);
    ViscousStrain::project(ViscousStrain::projection(fe_values, strain_basis),
                           strain,
                           projected_strain);
    for (unsigned int q = 0; q < n_q; ++q)
      if constexpr (dim == 2)
        {
          // Plane strain: the arms' out-of-plane stress counts too.
          ArmStress h;
          double    rate = 0.;
          for (unsigned int a = 0; a < material.n_arms(); ++a)
            {
              const auto h_a =
                material.arm_stress(a,
                                    projected_strain[q] -
                                      ViscousStrain::of_arm<dim>(values[q], a));
              h += h_a;
              rate += material.dissipation_rate(a, h_a);
            }
          const auto sigma = material.stress(strain[q], h);
          fields[0][q]     = rate;
          fields[1][q]     = sigma[0][0];
          fields[2][q]     = sigma[1][1];
          fields[3][q]     = sigma[0][1];
          fields[4][q]     = material.stress_zz(strain[q], h);
        }
      else
        {
          SymmetricTensor<2, dim> sigma =
            material.relaxed_stiffness_of<dim>() * strain[q];
          double rate = 0.;
          for (unsigned int a = 0; a < material.n_arms(); ++a)
            {
              const SymmetricTensor<2, dim> h_a =
                material.arm_stiffness_of<dim>(a) *
                (projected_strain[q] -
                 ViscousStrain::of_arm<dim>(values[q], a));
              sigma += h_a;
              rate += material.dissipation_rate(a, h_a);
            }
          fields[0][q] = rate;
          for (unsigned int c = 0; c < 6; ++c)
            fields[1 + c][q] = ViscousStrain::component(sigma, c);
        }
  }


  template <int dim>
  double
  SteadyStateSolver<dim>::dissipation_rate() const
  {
    FEValues<dim> fe_values(
      fe, quadrature, update_values | update_gradients | update_JxW_values);
    std::vector<std::vector<double>> fields(
      n_quadrature_fields, std::vector<double>(quadrature.size()));
    double rate = 0.;
    for (const auto &cell : dof_handler.active_cell_iterators())
      if (cell->is_locally_owned())
        {
          fe_values.reinit(cell);
          quadrature_fields(fe_values, fields);
          for (unsigned int q = 0; q < quadrature.size(); ++q)
            rate += fields[0][q] * fe_values.JxW(q);
        }
    return dealii::Utilities::MPI::sum(rate, mpi_communicator);
  }


  template <int dim>
  void
  SteadyStateSolver<dim>::write_profile(const std::string &path) const
  {
    write_profile_csv(path,
                      postprocessor.profile(dof_handler, solution, delta, s),
                      scales,
                      "steady state, V_hat = " + CsvTable::format(V_hat) +
                        ", delta_hat = " + CsvTable::format(delta),
                      mpi_communicator);
  }


  template <int dim>
  void
  SteadyStateSolver<dim>::write_fields(OutputWriter      &writer,
                                       const unsigned int counter) const
  {
    TimerOutput::Scope       t(timer, "output");
    std::vector<std::string> names(dim, "displacement");
    for (unsigned int a = 0; a < material.n_arms(); ++a)
      for (const std::string &c : ViscousStrain::component_names<dim>())
        names.push_back("viscous_strain_" +
                        (material.n_arms() > 1 ? std::to_string(a + 1) + "_"
                                               : std::string()) +
                        c);
    std::vector<DataComponentInterpretation::DataComponentInterpretation>
      interpretation(fe.n_components(),
                     DataComponentInterpretation::component_is_scalar);
    for (unsigned int d = 0; d < dim; ++d)
      interpretation[d] =
        DataComponentInterpretation::component_is_part_of_vector;
    DataOut<dim> data_out;
    data_out.attach_dof_handler(dof_handler);
    data_out.add_data_vector(solution,
                             names,
                             DataOut<dim>::type_dof_data,
                             interpretation);
    // The stress and the dissipation density of the equations (the arms
    // see Pi eps(u); eps(u) itself would add the arm stress of the strain
    // that the viscous strain's degree cannot hold, several times the
    // dissipation), recovered onto a continuous field.
    const FieldRecovery<dim> recovery(dof_handler);
    FEValues<dim>            fe_values(
      fe, quadrature, update_values | update_gradients | update_JxW_values);
    const auto recovered =
      recovery.recover(quadrature,
                       n_quadrature_fields,
                       [&](const auto                       &cell,
                           std::vector<std::vector<double>> &values) {
                         fe_values.reinit(cell);
                         quadrature_fields(fe_values, values);
                       });
    std::vector<std::string> names_of{"dissipation_rate"};
    for (const std::string &c :
         dim == 2 ? std::vector<std::string>{"xx", "yy", "xy", "zz"}
                  : ViscousStrain::component_names<dim>())
      names_of.push_back("stress_" + c);
    for (unsigned int k = 0; k < n_quadrature_fields; ++k)
      data_out.add_data_vector(recovery.dof_handler(),
                               recovered[k],
                               names_of[k]);
    data_out.build_patches(2);
    writer.write(data_out, "steady", counter, V_hat);
    write_surface_fields(writer,
                         "steady_surface",
                         dof_handler,
                         solution,
                         coupling.law(),
                         coupling.indenter(),
                         scales,
                         delta,
                         s,
                         counter,
                         V_hat,
                         prm.geometry.elongation);
  }


  template class SteadyStateSolver<2>;
  template class SteadyStateSolver<3>;
} // namespace viscoslide

// SteadyStateSolver: the stations of a run with their rows, profiles and
// fields, and the dissipation.
#include <deal.II/fe/fe_values.h>

#include <deal.II/numerics/data_out.h>
#include <deal.II/numerics/data_postprocessor.h>

#include <viscoslide/steady_state/solver.h>
#include <viscoslide/steady_state/viscous_strain.h>
#include <viscoslide/surface_fields.h>

#include <cstdio>

namespace viscoslide
{
  namespace
  {
    // Stress and dissipation density from u and eps_v, for DataOut. They
    // use eps(u), not its projection: exact for degree 2.
    class SteadyFields : public DataPostprocessor<2>
    {
    public:
      explicit SteadyFields(const ViscoelasticSolid &material)
        : material(material)
      {
      }

      void
      evaluate_vector_field(
        const DataPostprocessorInputs::Vector<2> &inputs,
        std::vector<Vector<double>>              &computed) const override
      {
        for (unsigned int q = 0; q < inputs.solution_values.size(); ++q)
          {
            const auto &v = inputs.solution_values[q];
            const auto &g = inputs.solution_gradients[q];
            const auto  strain =
              ViscousStrain::tensor(g[0][0],
                                    g[1][1],
                                    0.5 * (g[0][1] + g[1][0]));
            ArmStress h;
            double    rate = 0.;
            for (unsigned int k = 0; k < material.n_arms(); ++k)
              {
                const auto h_k =
                  material.arm_stress(k, strain - ViscousStrain::of_arm(v, k));
                h += h_k;
                rate += material.dissipation_rate(k, h_k);
              }
            const auto sigma = material.stress(strain, h);
            computed[q](0)   = sigma[0][0];
            computed[q](1)   = sigma[1][1];
            computed[q](2)   = sigma[0][1];
            computed[q](3)   = material.stress_zz(strain, h);
            computed[q](4)   = rate;
          }
      }

      std::vector<std::string>
      get_names() const override
      {
        return {"stress_xx",
                "stress_yy",
                "stress_xy",
                "stress_zz",
                "dissipation_rate"};
      }

      UpdateFlags
      get_needed_update_flags() const override
      {
        return update_values | update_gradients;
      }

    private:
      const ViscoelasticSolid &material;
    };
  } // namespace


  double
  SteadyStateSolver::dissipation_rate() const
  {
    FEValues<dim> fe_values(
      fe, quadrature, update_values | update_gradients | update_JxW_values);
    const FEValuesExtractors::Vector     displacement(0);
    std::vector<SymmetricTensor<2, dim>> strain(quadrature.size()),
      projected_strain(quadrature.size());
    std::vector<Vector<double>> values(quadrature.size(),
                                       Vector<double>(fe.n_components()));
    double                      rate = 0.;
    for (const auto &cell : dof_handler.active_cell_iterators())
      if (cell->is_locally_owned())
        {
          fe_values.reinit(cell);
          fe_values[displacement].get_function_symmetric_gradients(solution,
                                                                   strain);
          fe_values.get_function_values(solution, values);
          ViscousStrain::project(ViscousStrain::projection(fe_values,
                                                           strain_basis),
                                 strain,
                                 projected_strain);
          for (unsigned int q = 0; q < quadrature.size(); ++q)
            for (unsigned int a = 0; a < material.n_arms(); ++a)
              rate +=
                material.dissipation_rate(
                  a,
                  material.arm_stress(a,
                                      projected_strain[q] -
                                        ViscousStrain::of_arm(values[q], a))) *
                fe_values.JxW(q);
        }
    return dealii::Utilities::MPI::sum(rate, mpi_communicator);
  }


  void
  SteadyStateSolver::write_profile(const std::string &path) const
  {
    write_profile_csv(path,
                      postprocessor.profile(dof_handler, solution, delta, s),
                      scales,
                      "steady state, V_hat = " + CsvTable::format(V_hat) +
                        ", delta_hat = " + CsvTable::format(delta),
                      mpi_communicator);
  }


  void
  SteadyStateSolver::write_fields(OutputWriter      &writer,
                                  const unsigned int counter) const
  {
    TimerOutput::Scope       t(timer, "output");
    std::vector<std::string> names{"displacement", "displacement"};
    for (unsigned int a = 0; a < material.n_arms(); ++a)
      for (const std::string c : {"xx", "yy", "xy"})
        names.push_back("viscous_strain_" +
                        (material.n_arms() > 1 ? std::to_string(a + 1) + "_"
                                               : std::string()) +
                        c);
    std::vector<DataComponentInterpretation::DataComponentInterpretation>
      interpretation(fe.n_components(),
                     DataComponentInterpretation::component_is_scalar);
    interpretation[0] = interpretation[1] =
      DataComponentInterpretation::component_is_part_of_vector;
    const SteadyFields fields(material);
    DataOut<dim>       data_out;
    data_out.attach_dof_handler(dof_handler);
    data_out.add_data_vector(solution,
                             names,
                             DataOut<dim>::type_dof_data,
                             interpretation);
    data_out.add_data_vector(solution, fields);
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
                         V_hat);
  }
} // namespace viscoslide

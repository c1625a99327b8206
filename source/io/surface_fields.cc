// SPDX-License-Identifier: LGPL-2.1-or-later
#include <deal.II/numerics/data_out_faces.h>
#include <deal.II/numerics/data_postprocessor.h>

#include <viscoslide/io/surface_fields.h>
#include <viscoslide/numerics/mesh.h>

namespace viscoslide
{
  namespace
  {
    // Pressure and gap from u_y and x.
    template <int dim>
    class SurfaceFields : public DataPostprocessor<dim>
    {
    public:
      SurfaceFields(const InteractionLaw &law,
                    const Indenter       &indenter,
                    const Scales         &scales,
                    const double          delta,
                    const double          s,
                    const double          elongation)
        : law(law)
        , indenter(indenter)
        , scales(scales)
        , delta(delta)
        , s(s)
        , elongation(elongation)
      {
      }

      void
      evaluate_vector_field(
        const DataPostprocessorInputs::Vector<dim> &inputs,
        std::vector<Vector<double>>                &computed) const override
      {
        for (unsigned int q = 0; q < inputs.solution_values.size(); ++q)
          {
            const double g = gap(indenter,
                                 scales.eps,
                                 delta,
                                 s,
                                 inputs.evaluation_points[q],
                                 inputs.solution_values[q][vertical<dim>],
                                 elongation);
            computed[q](0) = -law.traction(g) / scales.sigma_max;
            computed[q](1) = g / scales.eps;
          }
      }

      std::vector<std::string>
      get_names() const override
      {
        return {"p_hat", "gap_over_eps"};
      }

      UpdateFlags
      get_needed_update_flags() const override
      {
        return update_values | update_quadrature_points;
      }

    private:
      const InteractionLaw &law;
      const Indenter       &indenter;
      const Scales         &scales;
      const double          delta, s, elongation;
    };

    // DataOutFaces over the locally owned faces of the top surface only.
    template <int dim>
    class TopSurfaceDataOut : public DataOutFaces<dim>
    {
    public:
      using FaceDescriptor = typename DataOutFaces<dim>::FaceDescriptor;

      TopSurfaceDataOut()
        : DataOutFaces<dim>(true)
      {
      }

      FaceDescriptor
      first_face() override
      {
        for (const auto &cell : this->triangulation->active_cell_iterators())
          if (cell->is_locally_owned())
            if (const auto f = top_face(cell);
                f != numbers::invalid_unsigned_int)
              return {cell, f};
        return {};
      }

      FaceDescriptor
      next_face(const FaceDescriptor &face) override
      {
        auto cell = face.first;
        for (++cell; cell != this->triangulation->end(); ++cell)
          if (cell->is_active() && cell->is_locally_owned())
            if (const auto f = top_face(cell);
                f != numbers::invalid_unsigned_int)
              return {cell, f};
        return {};
      }

    private:
      static unsigned int
      top_face(const typename Triangulation<dim>::cell_iterator &cell)
      {
        for (const unsigned int f : cell->face_indices())
          if (is_top_face(cell, f))
            return f;
        return numbers::invalid_unsigned_int;
      }
    };
  } // namespace


  template <int dim>
  void
  write_surface_fields(OutputWriter                        &writer,
                       const std::string                   &name,
                       const DoFHandler<dim>               &dof_handler,
                       const TrilinosWrappers::MPI::Vector &solution,
                       const InteractionLaw                &law,
                       const Indenter                      &indenter,
                       const Scales                        &scales,
                       const double                         delta,
                       const double                         s,
                       const unsigned int                   counter,
                       const double                         time,
                       const double                         elongation)
  {
    const SurfaceFields<dim> fields(
      law, indenter, scales, delta, s, elongation);
    TopSurfaceDataOut<dim> surface_out;
    surface_out.attach_dof_handler(dof_handler);
    surface_out.add_data_vector(solution, fields);
    surface_out.build_patches(2);
    writer.write(static_cast<const DataOutFaces<dim> &>(surface_out),
                 name,
                 counter,
                 time);
  }


  template void
  write_surface_fields(OutputWriter &,
                       const std::string &,
                       const DoFHandler<2> &,
                       const TrilinosWrappers::MPI::Vector &,
                       const InteractionLaw &,
                       const Indenter &,
                       const Scales &,
                       double,
                       double,
                       unsigned int,
                       double,
                       double);
  template void
  write_surface_fields(OutputWriter &,
                       const std::string &,
                       const DoFHandler<3> &,
                       const TrilinosWrappers::MPI::Vector &,
                       const InteractionLaw &,
                       const Indenter &,
                       const Scales &,
                       double,
                       double,
                       unsigned int,
                       double,
                       double);
} // namespace viscoslide

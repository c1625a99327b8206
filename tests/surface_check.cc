// SPDX-License-Identifier: LGPL-2.1-or-later
// The surface integrals of a 3D block (SurfacePostprocessor<3>) against
// sums over the same surface that know nothing of the mesh: a parabolic
// body of revolution, h = r^2/(2R) (R = 100 eps), pressed by delta into a
// block whose surface stays flat (u = 0), so that the gap at every point
// is known in closed form. The block is 80 x 80 x 40 eps, its top cells
// refined three times about the apex (hanging nodes included). Prints
//   area  A  A_reference     the contact set g < 1.5 eps: pi 2 R (1.5 - 1 +
//   delta) force F  F_reference     integral of -p over the top, the reference
//   a
//                            trapezoid sum on a 4000 x 4000 grid
//   extent x_trail x_lead y_half radius   the set's extent and its radius
// tests/surface_integrals_3d.check compares them.
#include <deal.II/base/mpi.h>

#include <deal.II/distributed/tria.h>

#include <deal.II/dofs/dof_handler.h>
#include <deal.II/dofs/dof_tools.h>

#include <deal.II/fe/fe_q.h>
#include <deal.II/fe/fe_system.h>

#include <deal.II/grid/grid_generator.h>

#include <deal.II/lac/trilinos_vector.h>

#include <viscoslide/io/postprocessing.h>
#include <viscoslide/numerics/mesh.h>
#include <viscoslide/physics/indenter.h>
#include <viscoslide/physics/interaction_law.h>

#include <cmath>
#include <cstdio>

using namespace dealii;
using namespace viscoslide;

namespace
{
  constexpr double R = 100., delta = 0.5, contact_gap = 1.5, half = 40.;

  class Paraboloid : public Indenter
  {
  public:
    double
    profile(const double r) const override
    {
      return r * r / (2. * R);
    }
    double
    slope(const double r) const override
    {
      return r / R;
    }
  };
} // namespace

int
main(int argc, char **argv)
{
  Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  const MPI_Comm                   comm = MPI_COMM_WORLD;

  parallel::distributed::Triangulation<3> triangulation(comm);
  GridGenerator::subdivided_hyper_rectangle(triangulation,
                                            {8, 8, 4},
                                            Point<3>(-half, -half, -half),
                                            Point<3>(half, half, 0.),
                                            true);
  for (unsigned int cycle = 0; cycle < 3; ++cycle)
    {
      for (const auto &cell : triangulation.active_cell_iterators())
        if (cell->is_locally_owned() && cell->center()[2] > -10. &&
            std::hypot(cell->center()[0], cell->center()[1]) < 30. - 5. * cycle)
          cell->set_refine_flag();
      triangulation.execute_coarsening_and_refinement();
    }

  const FESystem<3> fe(FE_Q<3>(2), 3);
  DoFHandler<3>     dofs(triangulation);
  dofs.distribute_dofs(fe);
  IndexSet relevant;
  DoFTools::extract_locally_relevant_dofs(dofs, relevant);
  TrilinosWrappers::MPI::Vector u(dofs.locally_owned_dofs(), relevant, comm);
  u = 0.;

  const auto       law = create_interaction_law("lennard-jones", 1., 1.);
  const Paraboloid paraboloid;
  const SurfacePostprocessor<3> surface(
    *law, paraboloid, 1., contact_gap, 4, top_boundary<3>);
  const SurfaceQuantities q = surface.integrate(dofs, u, delta, 0.);

  // The gap at (x, y) is 1 + r^2/(2R) - delta.
  const double radius = std::sqrt(2. * R * (contact_gap - 1. + delta));
  const int    n      = 4000;
  const double h      = 2. * half / n;
  double       force  = 0.;
  for (int i = 0; i <= n; ++i)
    for (int j = 0; j <= n; ++j)
      {
        const double x = -half + i * h, y = -half + j * h;
        const double w =
          (i == 0 || i == n ? 0.5 : 1.) * (j == 0 || j == n ? 0.5 : 1.) * h * h;
        force -= law->traction(1. + (x * x + y * y) / (2. * R) - delta) * w;
      }
  if (Utilities::MPI::this_mpi_process(comm) == 0)
    {
      std::printf("area %.10g %.10g\n",
                  q.contact_length,
                  M_PI * radius * radius);
      std::printf("force %.15g %.15g\n", q.normal_force, force);
      std::printf("extent %.10g %.10g %.10g %.10g\n",
                  q.x_trail,
                  q.x_lead,
                  q.y_half,
                  radius);
    }
}

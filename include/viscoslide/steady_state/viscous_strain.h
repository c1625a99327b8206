// SPDX-License-Identifier: LGPL-2.1-or-later
// The viscous strain of the steady-state solver: where its components sit
// in the FESystem, and the cell-wise projection of eps(u) onto its space
// (implemented in source/steady_state/viscous_strain.cc).
#ifndef viscoslide_steady_state_viscous_strain_h
#define viscoslide_steady_state_viscous_strain_h

#include <deal.II/base/symmetric_tensor.h>

#include <deal.II/fe/fe_values.h>

#include <deal.II/lac/full_matrix.h>
#include <deal.II/lac/vector.h>

#include <string>
#include <vector>

namespace viscoslide
{
  namespace ViscousStrain
  {
    using namespace dealii;

    // FESystem components: displacement, then the viscous strain of each
    // Maxwell arm, components_per_arm of them (2D: xx, yy, xy of arm k at
    // 2 + 3 k ... 4 + 3 k; 3D: xx, yy, zz, xy, xz, yz, SymmetricTensor's
    // unrolled order in both).
    template <int dim>
    constexpr unsigned int first_component = dim;
    template <int dim>
    constexpr unsigned int components_per_arm = dim *(dim + 1) / 2;

    // Strain component c of a symmetric tensor.
    template <int dim>
    inline double
    component(const SymmetricTensor<2, dim> &t, const unsigned int c)
    {
      return t[SymmetricTensor<2, dim>::unrolled_to_component_indices(c)];
    }

    // The tensor whose component c is 1 (off the diagonal: the symmetric
    // pair).
    template <int dim>
    SymmetricTensor<2, dim>
    unit(unsigned int c)
    {
      SymmetricTensor<2, dim> t;
      t[SymmetricTensor<2, dim>::unrolled_to_component_indices(c)] = 1.;
      return t;
    }

    // Viscous strain of one arm from the values of all components.
    template <int dim>
    SymmetricTensor<2, dim>
    of_arm(const Vector<double> &values, const unsigned int arm)
    {
      SymmetricTensor<2, dim> t;
      const unsigned int      first =
        first_component<dim> + components_per_arm<dim> * arm;
      for (unsigned int c = 0; c < components_per_arm<dim>; ++c)
        t[SymmetricTensor<2, dim>::unrolled_to_component_indices(c)] =
          values[first + c];
      return t;
    }

    // The names of the components, for output.
    template <int dim>
    std::vector<std::string>
    component_names()
    {
      if constexpr (dim == 2)
        return {"xx", "yy", "xy"};
      else
        return {"xx", "yy", "zz", "xy", "xz", "yz"};
    }

    // The L2 projection onto the viscous-strain space of a cell, acting on
    // values at the quadrature points: (Pi f)(q) = sum_q' P(q, q') f(q'),
    // basis = the local dofs of one strain component. The arm sees
    // Pi eps(u), the part of the strain that eps_v can represent: then
    // eps_v = Pi eps(u) is exactly the relaxed state, and a degree below 2
    // (which cannot hold the strain of Q2) adds no spurious arm stress.
    template <int dim>
    FullMatrix<double>
    projection(const FEValues<dim>             &fe_values,
               const std::vector<unsigned int> &basis);

    template <typename T>
    void
    project(const FullMatrix<double> &P,
            const std::vector<T>     &f,
            std::vector<T>           &pf)
    {
      for (unsigned int q = 0; q < P.m(); ++q)
        {
          pf[q] = T();
          for (unsigned int r = 0; r < P.n(); ++r)
            pf[q] += P(q, r) * f[r];
        }
    }
  } // namespace ViscousStrain
} // namespace viscoslide

#endif

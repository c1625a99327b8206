// SPDX-License-Identifier: LGPL-2.1-or-later
#include <viscoslide/steady_state/viscous_strain.h>

namespace viscoslide
{
  namespace ViscousStrain
  {
    template <int dim>
    FullMatrix<double>
    projection(const FEValues<dim>             &fe_values,
               const std::vector<unsigned int> &basis)
    {
      const unsigned int n_q = fe_values.n_quadrature_points, m = basis.size();
      FullMatrix<double> mass(m, m), P(n_q, n_q);
      for (unsigned int a = 0; a < m; ++a)
        for (unsigned int b = 0; b < m; ++b)
          for (unsigned int q = 0; q < n_q; ++q)
            mass(a, b) += fe_values.shape_value(basis[a], q) *
                          fe_values.shape_value(basis[b], q) * fe_values.JxW(q);
      mass.gauss_jordan();
      for (unsigned int q = 0; q < n_q; ++q)
        for (unsigned int r = 0; r < n_q; ++r)
          {
            double sum = 0.;
            for (unsigned int a = 0; a < m; ++a)
              for (unsigned int b = 0; b < m; ++b)
                sum += fe_values.shape_value(basis[a], q) * mass(a, b) *
                       fe_values.shape_value(basis[b], r);
            P(q, r) = sum * fe_values.JxW(r);
          }
      return P;
    }


    template FullMatrix<double>
    projection(const FEValues<2> &, const std::vector<unsigned int> &);
    template FullMatrix<double>
    projection(const FEValues<3> &, const std::vector<unsigned int> &);
  } // namespace ViscousStrain
} // namespace viscoslide

#include <viscoslide/steady_state/viscous_strain.h>

namespace viscoslide
{
  namespace ViscousStrain
  {
    SymmetricTensor<2, 2>
    unit(const unsigned int c)
    {
      SymmetricTensor<2, 2> t;
      if (c == 2)
        t[0][1] = 1.;
      else
        t[c][c] = 1.;
      return t;
    }


    SymmetricTensor<2, 2>
    tensor(const double xx, const double yy, const double xy)
    {
      SymmetricTensor<2, 2> t;
      t[0][0] = xx;
      t[1][1] = yy;
      t[0][1] = xy;
      return t;
    }


    SymmetricTensor<2, 2>
    of_arm(const Vector<double> &v, const unsigned int arm)
    {
      const unsigned int c = first_component + components_per_arm * arm;
      return tensor(v[c], v[c + 1], v[c + 2]);
    }


    FullMatrix<double>
    projection(const FEValues<2>               &fe_values,
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
  } // namespace ViscousStrain
} // namespace viscoslide

// The viscous strain of the steady-state solver: where its components sit
// in the FESystem, and the cell-wise projection of eps(u) onto its space
// (implemented in source/steady_state/viscous_strain.cc).
#ifndef viscoslide_steady_state_viscous_strain_h
#define viscoslide_steady_state_viscous_strain_h

#include <deal.II/base/symmetric_tensor.h>

#include <deal.II/fe/fe_values.h>

#include <deal.II/lac/full_matrix.h>
#include <deal.II/lac/vector.h>

#include <vector>

namespace viscoslide
{
  namespace ViscousStrain
  {
    using namespace dealii;

    // FESystem components: displacement, then the viscous strain of each
    // Maxwell arm (xx, yy, xy of arm k at 2 + 3 k ... 4 + 3 k).
    constexpr unsigned int first_component    = 2;
    constexpr unsigned int components_per_arm = 3;

    // Strain component c (xx, yy, xy) of a symmetric tensor.
    inline double
    component(const SymmetricTensor<2, 2> &t, const unsigned int c)
    {
      return c == 0 ? t[0][0] : (c == 1 ? t[1][1] : t[0][1]);
    }

    // The tensor whose component c is 1 (xy: the symmetric pair).
    SymmetricTensor<2, 2>
    unit(unsigned int c);

    SymmetricTensor<2, 2>
    tensor(double xx, double yy, double xy);

    // Viscous strain of one arm from the values of all components.
    SymmetricTensor<2, 2>
    of_arm(const Vector<double> &values, unsigned int arm);

    // The L2 projection onto the viscous-strain space of a cell, acting on
    // values at the quadrature points: (Pi f)(q) = sum_q' P(q, q') f(q'),
    // basis = the local dofs of one strain component. The arm sees
    // Pi eps(u), the part of the strain that eps_v can represent: then
    // eps_v = Pi eps(u) is exactly the relaxed state, and a degree below 2
    // (which cannot hold the strain of Q2) adds no spurious arm stress.
    FullMatrix<double>
    projection(const FEValues<2>               &fe_values,
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

#include <greentread/base/exceptions.h>
#include <greentread/fe/material.h>

#include <deal.II/base/tensor.h>

#include <Eigen/Dense>

#include <cmath>

namespace greentread
{
  namespace fe
  {
    using dealii::SymmetricTensor;

    namespace
    {
      /// Voigt index -> tensor index pair.
      constexpr unsigned int voigt[6][2] = {{0, 0}, {1, 1}, {2, 2}, {1, 2}, {0, 2}, {0, 1}};

      SymmetricTensor<4, 3>
      from_voigt(const Eigen::Matrix<double, 6, 6> &C)
      {
        SymmetricTensor<4, 3> c;
        for (unsigned int I = 0; I < 6; ++I)
          for (unsigned int J = 0; J < 6; ++J)
            c[voigt[I][0]][voigt[I][1]][voigt[J][0]][voigt[J][1]] = C(I, J);
        return c;
      }
    } // namespace



    SymmetricTensor<4, 3>
    Material::stiffness_at(const dealii::Point<3> &p) const
    {
      if (!cylindrical_axes)
        return stiffness;
      const double rho = std::hypot(p[0], p[1]);
      // On the axis the cylindrical axes are undefined (0 / 0).
      if (!(rho > 1e-12 * (std::abs(p[2]) + 1.)))
        throw InputError("the " + name +
                         " has cylindrical material axes, which are undefined "
                         "on the tyre axis, but a point of it lies there: the section must "
                         "stay at a radius > 0");
      // Columns: e_r, e_theta, e_z in global components.
      const double          c = p[0] / rho, s = p[1] / rho;
      const double          Q[3][3] = {{c, -s, 0.}, {s, c, 0.}, {0., 0., 1.}};
      SymmetricTensor<4, 3> global;
      for (unsigned int i = 0; i < 3; ++i)
        for (unsigned int j = i; j < 3; ++j)
          for (unsigned int k = 0; k < 3; ++k)
            for (unsigned int l = k; l < 3; ++l)
              {
                double sum = 0.;
                for (unsigned int a = 0; a < 3; ++a)
                  for (unsigned int b = 0; b < 3; ++b)
                    for (unsigned int e = 0; e < 3; ++e)
                      for (unsigned int d = 0; d < 3; ++d)
                        sum += Q[i][a] * Q[j][b] * Q[k][e] * Q[l][d] * stiffness[a][b][e][d];
                global[i][j][k][l] = sum;
              }
      return global;
    }



    SymmetricTensor<4, 3>
    isotropic_stiffness(const double E, const double nu)
    {
      const double          lambda = E * nu / ((1. + nu) * (1. - 2. * nu));
      const double          mu     = E / (2. * (1. + nu));
      SymmetricTensor<4, 3> c;
      for (unsigned int i = 0; i < 3; ++i)
        for (unsigned int j = i; j < 3; ++j)
          for (unsigned int k = 0; k < 3; ++k)
            for (unsigned int l = k; l < 3; ++l)
              c[i][j][k][l] =
                lambda * (i == j) * (k == l) + mu * ((i == k) * (j == l) + (i == l) * (j == k));
      return c;
    }



    SymmetricTensor<4, 3>
    orthotropic_stiffness(const double E1,
                          const double E2,
                          const double E3,
                          const double nu12,
                          const double nu13,
                          const double nu23,
                          const double G12,
                          const double G13,
                          const double G23)
    {
      Eigen::Matrix<double, 6, 6> S = Eigen::Matrix<double, 6, 6>::Zero();
      S(0, 0)                       = 1. / E1;
      S(1, 1)                       = 1. / E2;
      S(2, 2)                       = 1. / E3;
      S(0, 1) = S(1, 0) = -nu12 / E1;
      S(0, 2) = S(2, 0) = -nu13 / E1;
      S(1, 2) = S(2, 1) = -nu23 / E2;
      S(3, 3)           = 1. / G23;
      S(4, 4)           = 1. / G13;
      S(5, 5)           = 1. / G12;
      Eigen::SelfAdjointEigenSolver<Eigen::Matrix<double, 6, 6>> eigen(S);
      if (!(eigen.eigenvalues().minCoeff() > 0.))
        throw InputError("the orthotropic constants of the belt give a compliance that is not "
                         "positive definite (Poisson's ratios too large for the moduli): no "
                         "material has them");
      return from_voigt(S.inverse());
    }



    std::pair<double, double>
    rayleigh_coefficients(const double loss_factor, const double f1, const double f2)
    {
      const double w1 = 2. * M_PI * f1, w2 = 2. * M_PI * f2;
      return {loss_factor * w1 * w2 / (w1 + w2), loss_factor / (w1 + w2)};
    }
  } // namespace fe
} // namespace greentread

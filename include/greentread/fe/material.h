#pragma once

#include <deal.II/base/point.h>
#include <deal.II/base/symmetric_tensor.h>
#include <greentread/base/mesh_ids.h>
#include <greentread/fe/material_parameters.h>

#include <string>

/**
 * @file
 * The materials of the tyre (Table A.4): elastic constants, density and
 * viscous damping.
 */

namespace greentread
{
  namespace fe
  {
    /**
     * @brief One material: linear elastic (isotropic or orthotropic in
     * cylindrical axes about the z-axis), with a density and Rayleigh
     * damping \f$C = \alpha M + \beta K\f$.
     */
    struct Material
    {
      std::string name;
      /// Density [kg/m^3].
      double density = 0.;
      /// Stiffness in the material axes (radial, circumferential, axial for a
      /// cylindrical material; any axes for an isotropic one) [Pa].
      dealii::SymmetricTensor<4, 3> stiffness;
      /// Whether the axes of @p stiffness are the local cylindrical axes
      /// (e_r, e_theta, e_z) about the z-axis.
      bool cylindrical_axes = false;
      /// Rayleigh coefficients [1/s] and [s].
      double alpha = 0., beta = 0.;

      /// The stiffness in global Cartesian components at @p p.
      dealii::SymmetricTensor<4, 3>
      stiffness_at(const dealii::Point<3> &p) const;
    };

    /// An isotropic stiffness tensor from Young's modulus and Poisson's ratio.
    dealii::SymmetricTensor<4, 3>
    isotropic_stiffness(double E, double nu);

    /**
     * @brief An orthotropic stiffness tensor from engineering constants in
     * axes (1, 2, 3). Poisson's ratios \f$\nu_{ij}\f$ are the contraction in j
     * for a stress in i (\f$\nu_{ij}/E_i = \nu_{ji}/E_j\f$).
     * @throws InputError if the compliance is not positive definite.
     */
    dealii::SymmetricTensor<4, 3>
    orthotropic_stiffness(double E1,
                          double E2,
                          double E3,
                          double nu12,
                          double nu13,
                          double nu23,
                          double G12,
                          double G13,
                          double G23);

    /**
     * @brief Rayleigh coefficients that give a viscous damping ratio of
     * eta/2 (the loss factor eta of a hysteretic material) at the two
     * frequencies f1 and f2 [Hz]: alpha = eta w1 w2 / (w1 + w2), beta =
     * eta / (w1 + w2).
     */
    std::pair<double, double>
    rayleigh_coefficients(double loss_factor, double f1, double f2);
  } // namespace fe
} // namespace greentread

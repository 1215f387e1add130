#pragma once

#include <Eigen/Dense>

/**
 * @file
 * The modes of the ring at one circumferential wavenumber, as both routes
 * give them: the Bloch cells (bloch_modes.h) and the section's harmonics
 * (harmonic_modes.h). The modal synthesis (ring_modes.h) takes either.
 */

namespace greentread
{
  namespace synthesis
  {
    /**
     * @brief The modes of one circumferential wavenumber of the ring below a
     * cut-off: a Bloch wavenumber k of the ring of cells (bloch_modes()), or
     * a harmonic n of the axisymmetric ring's section (harmonic_modes(),
     * whose shapes are real).
     */
    struct WavenumberModes
    {
      unsigned int wavenumber = 0;
      /// Natural angular frequencies w_r [rad/s], ascending.
      Eigen::VectorXd omega;
      /// psi_r^H C_phi psi_r / (2 w_r): each mode's viscous damping ratio
      /// from the cell's damping C, its diagonal in the modal basis.
      Eigen::VectorXd damping_ratio;
      /// Psi^H C_phi Psi: the damping in the modal basis, whole (its
      /// diagonal is 2 xi_r w_r). A damping that is not proportional
      /// couples the modes through its off-diagonal terms.
      Eigen::MatrixXcd modal_damping;
      /// The mass-normalised shapes psi_r over [L, I], one column each.
      Eigen::MatrixXcd shapes;
      /// How the search went: sparse solves, Krylov dimension, and the
      /// largest relative residual |K psi - w^2 M psi| / |K psi| kept.
      unsigned int n_solves = 0, krylov_dimension = 0;
      double       max_residual = 0.;
    };
  } // namespace synthesis
} // namespace greentread

#pragma once

#include <greentread/fe/elastic_model.h>

#include <Eigen/Sparse>

#include <array>
#include <complex>
#include <vector>

/**
 * @file
 * The reference cell of the paper's periodic model (Section 4.2, Eqs. 42-45):
 * the cell's matrices in cylindrical components, so that every cell of the
 * ring has the same ones, with its DoFs split into the left face (theta = 0),
 * the interior and the right face (theta = 2 pi / N).
 */

namespace greentread
{
  namespace periodic
  {
    using Complex       = std::complex<double>;
    using SparseReal    = Eigen::SparseMatrix<double>;
    using SparseComplex = Eigen::SparseMatrix<Complex>;

    /// Where a DoF of the reference cell sits and which component it is.
    struct CellDof
    {
      double       radius;    ///< of its node [m]
      double       axial;     ///< z of its node [m]
      double       angle;     ///< theta of its node, 0 on the left face [rad]
      unsigned int component; ///< 0 radial, 1 circumferential, 2 axial
      bool         on_tread;  ///< its node is on the tread surface
    };

    /**
     * @brief One cell of a ring of N identical cells, in cylindrical
     * components (Eqs. 43-44), with the DoFs ordered [L, I, R]: the n_face
     * DoFs of the left face, the n_interior DoFs inside, and the n_face DoFs
     * of the right face, R[i] being L[i] rotated by the cell angle. Clamped
     * DoFs (the rim seat) are left out.
     */
    struct PeriodicCell
    {
      double       angle   = 0.; ///< 2 pi / N [rad]
      unsigned int n_cells = 0;  ///< N
      unsigned int n_face = 0, n_interior = 0;

      /// K + Kp, C and M over [L, I, R].
      SparseReal stiffness, damping, mass;
      /// The part of C proportional to the mass (sum of alpha M over the
      /// materials); C - mass_damping is proportional to the stiffness.
      SparseReal mass_damping;

      /// For each DoF of [L, I, R].
      std::vector<CellDof> dofs;

      /// The nodes of [L, I] whose DoFs are all clamped: radius, axial,
      /// angle (for plots of the whole ring).
      std::vector<std::array<double, 3>> held_nodes;

      unsigned int
      size() const
      {
        return 2 * n_face + n_interior;
      }

      /// D(w) = K + Kp + j w C - w^2 M of Eq. (45).
      SparseComplex
      dynamic_stiffness(double omega) const;
    };

    /**
     * @brief Build the reference cell from the assembled @p model of a cell
     * revolved by @p angle about the z-axis.
     *
     * @param[in] model         K, M, C assembled; Kp too if
     *                          @p with_prestress.
     * @param[in] angle         The cell angle 2 pi / N.
     * @param[in] n_cells       N.
     * @param[in] clamped       Boundary id whose DoFs are held (the rim seat).
     * @param[in] tread         Boundary id of the tread surface (marks
     *                          CellDof::on_tread).
     * @param[in] with_prestress Add Kp to K.
     * @throws InputError if a node of one periodic face has no partner on
     * the other (the faces do not match), naming the node.
     */
    PeriodicCell
    make_periodic_cell(const fe::ElasticModel    &model,
                       double                     angle,
                       unsigned int               n_cells,
                       dealii::types::boundary_id clamped,
                       dealii::types::boundary_id tread,
                       bool                       with_prestress);

    /**
     * @brief Mass redistribution at the contact surface (Khenous, Laborde
     * and Renard 2008): the velocity of each DoF on the tread surface is
     * taken as that of its partner, the DoF of the same component at the
     * nearest node off the surface that shares an element with it (for one
     * element through the tread, the node half-way down). With T that map
     * (identity elsewhere), M <- T^T M T; the damping's mass-proportional
     * part C_M moves with it, C <- C - C_M + T^T C_M T, and its
     * stiffness-proportional part stays, like K. A damping alpha M + beta K
     * so stays alpha M' + beta K, which the modes diagonalise.
     *
     * The surface DoFs then carry no mass: under kinematic contact they
     * follow the road through the stiffness and its damping beta K alone (a
     * Kelvin-Voigt solid, relaxing in the time beta), and the continuous
     * problem has a contact force that converges as the time step falls.
     * M stays symmetric positive semidefinite; the kinetic energy of an
     * axial translation is kept exactly, and that of any motion in which a
     * surface node moves as its partner.
     *
     * @returns the fraction of the cell's mass that was moved (the surface
     * DoFs' share of the axial translation's kinetic energy).
     * @throws NumericalError if a surface DoF shares no element with a DoF
     * off the surface, naming where it is.
     */
    double
    move_tread_mass_inward(PeriodicCell &cell);
  } // namespace periodic
} // namespace greentread

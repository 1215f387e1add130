#pragma once

#include <deal.II/base/point.h>
#include <deal.II/dofs/dof_handler.h>
#include <deal.II/fe/mapping.h>
#include <deal.II/lac/full_matrix.h>

#include <array>
#include <vector>

/**
 * @file
 * Cartesian and cylindrical components of nodal displacements (Eqs. 42-44):
 * in cylindrical components every cell of a ring has the same matrices.
 */

namespace greentread
{
  namespace fe
  {
    /// The three displacement DoFs (x, y, z) of one node and where it is.
    struct Node
    {
      std::array<dealii::types::global_dof_index, 3> dofs;
      dealii::Point<3>                               position;
    };

    /**
     * @brief The nodes of a vector-valued (x, y, z) Lagrange discretisation,
     * each with its three DoFs and its position under @p mapping.
     */
    std::vector<Node>
    nodes(const dealii::DoFHandler<3> &dofs, const dealii::Mapping<3> &mapping);

    /**
     * @brief The orthogonal transformation T of Eq. (42): for each node at
     * angle theta about the z-axis, (u_r, u_theta, u_z) = t (u_x, u_y, u_z)
     * with t = [[c, s, 0], [-s, c, 0], [0, 0, 1]]. Returns \f$T A T^T\f$
     * (Eqs. 43-44) of a dense matrix over the same DoFs.
     */
    dealii::FullMatrix<double>
    to_cylindrical(const dealii::FullMatrix<double> &A, const std::vector<Node> &nodes);
  } // namespace fe
} // namespace greentread

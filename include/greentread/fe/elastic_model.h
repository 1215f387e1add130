#pragma once

#include <greentread/fe/material.h>

#include <deal.II/base/symmetric_tensor.h>
#include <deal.II/dofs/dof_handler.h>
#include <deal.II/fe/fe_system.h>
#include <deal.II/fe/mapping_q.h>
#include <deal.II/lac/affine_constraints.h>
#include <deal.II/lac/sparse_matrix.h>
#include <deal.II/lac/sparsity_pattern.h>
#include <deal.II/lac/vector.h>

#include <filesystem>
#include <functional>
#include <map>

/**
 * @file
 * Linear elasticity on a hexahedral mesh with deal.II: the cell matrices K, M,
 * C of Eq. (1), the inflation's static solve and the geometric stiffness Kp
 * of the prestress (Eq. 41).
 */

namespace greentread
{
  namespace fe
  {
    /**
     * @brief Vector-valued elasticity with Lagrange elements of a chosen
     * degree, a mapping of the same degree, and one Material per material id.
     *
     * K, M, C and Kp are assembled without any boundary condition: the
     * periodic stage eliminates DoFs itself. Static solves take their
     * constraints as an argument.
     */
    class ElasticModel
    {
    public:
      /**
       * @param[in] triangulation  The mesh (it must outlive this object).
       * @param[in] materials      A material for every material id used.
       * @param[in] degree         Polynomial degree of the elements, 1 or 2.
       *                           Degree 2 is the default: trilinear
       *                           elements lock with nu = 0.49.
       */
      ElasticModel(const dealii::Triangulation<3>         &triangulation,
                   const std::map<unsigned int, Material> &materials,
                   unsigned int                            degree = 2);

      /// Assemble K, M and C (consistent mass, Rayleigh damping per material).
      void
      assemble();

      const dealii::SparseMatrix<double> &
      stiffness() const
      {
        return K;
      }
      const dealii::SparseMatrix<double> &
      mass() const
      {
        return M;
      }
      const dealii::SparseMatrix<double> &
      damping() const
      {
        return C;
      }
      /// The part of C proportional to the mass, sum over the materials of
      /// alpha M: it moves with the mass (periodic::move_tread_mass_inward).
      const dealii::SparseMatrix<double> &
      mass_damping() const
      {
        return C_mass;
      }
      /// Kp, after assemble_geometric_stiffness().
      const dealii::SparseMatrix<double> &
      geometric_stiffness() const
      {
        return Kp;
      }

      const dealii::DoFHandler<3> &
      dof_handler() const
      {
        return dofs;
      }
      const dealii::Mapping<3> &
      mapping() const
      {
        return map;
      }

      /// Consistent nodal forces of a pressure p on the faces of @p boundary:
      /// traction -p n, n the outward normal of the solid [N].
      dealii::Vector<double>
      pressure_load(dealii::types::boundary_id boundary, double pressure) const;

      /// Consistent nodal forces of a traction t(x) on the faces of @p boundary.
      dealii::Vector<double>
      traction_load(dealii::types::boundary_id                                           boundary,
                    const std::function<dealii::Tensor<1, 3>(const dealii::Point<3> &)> &t) const;

      /// Clamp (u = 0) every DoF on @p boundary.
      void
      add_clamp(dealii::types::boundary_id         boundary,
                dealii::AffineConstraints<double> &constraints) const;

      /**
       * @brief Rotational periodicity between the faces of @p first and
       * @p second, which is @p first rotated by @p angle about the z-axis:
       * \f$u(R x) = R\,u(x)\f$, the condition of an axisymmetric state
       * in Cartesian components.
       * @throws NumericalError if a face of @p first has no partner.
       */
      void
      add_rotational_periodicity(dealii::types::boundary_id         first,
                                 dealii::types::boundary_id         second,
                                 double                             angle,
                                 dealii::AffineConstraints<double> &constraints) const;

      /**
       * @brief Solve K u = f under @p constraints with a sparse direct solver
       * (UMFPACK).
       * @throws NumericalError if the system is singular or the relative
       * residual exceeds 1e-8 (ill-conditioned), naming what to check.
       */
      dealii::Vector<double>
      solve_static(const dealii::AffineConstraints<double> &constraints,
                   const dealii::Vector<double>            &load) const;

      /// The stress sigma = C : eps(u) at a point of a cell.
      dealii::SymmetricTensor<2, 3>
      stress(const dealii::Point<3>              &point,
             unsigned int                         material_id,
             const dealii::SymmetricTensor<2, 3> &strain) const;

      /**
       * @brief Kp of Eq. (41): \f$K^p_{ab} = \int \nabla N_a \cdot \sigma_0
       * \cdot \nabla N_b\,dV\f$ for each displacement component, the stress
       * \f$\sigma_0\f$ of the displacement @p u (the inflation).
       */
      void
      assemble_geometric_stiffness(const dealii::Vector<double> &u);

      /// The same for a prescribed prestress field.
      void
      assemble_geometric_stiffness(
        const std::function<dealii::SymmetricTensor<2, 3>(const dealii::Point<3> &)> &stress);

      /// Mass per material id [kg], by quadrature.
      std::map<unsigned int, double>
      masses() const;

      /// The largest von Mises stress of @p u at the quadrature points [Pa].
      double
      max_von_mises(const dealii::Vector<double> &u) const;

      /**
       * @brief Write @p u as a VTU file for ParaView: displacement, von
       * Mises stress and material id, on curved cells.
       */
      void
      write_vtu(const dealii::Vector<double> &u, const std::filesystem::path &file) const;

    private:
      const dealii::Triangulation<3>  &triangulation;
      std::map<unsigned int, Material> materials;
      dealii::FESystem<3>              fe;
      dealii::MappingQ<3>              map;
      dealii::DoFHandler<3>            dofs;
      dealii::SparsityPattern          pattern;
      dealii::SparseMatrix<double>     K, M, C, C_mass, Kp;

      const Material &
      material(unsigned int id) const;
    };

    /// Von Mises stress of a stress tensor.
    double
    von_mises(const dealii::SymmetricTensor<2, 3> &sigma);
  } // namespace fe
} // namespace greentread

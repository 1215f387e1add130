#pragma once

#include <deal.II/dofs/dof_handler.h>
#include <deal.II/lac/affine_constraints.h>
#include <deal.II/lac/sparse_matrix.h>

#include <vector>

namespace greentread
{
  namespace fe
  {
    /**
     * @brief The @p n eigenvalues of \f$K\phi = \lambda M \phi\f$ closest to
     * @p shift, with @p constraints applied (ARPACK in shift-invert mode,
     * the shifted matrix factorised by UMFPACK), in increasing order.
     *
     * Constrained DoFs are sent to an infinite eigenvalue. For a free
     * structure use a negative shift: K - shift M is then positive definite.
     *
     * @throws NumericalError if ARPACK does not converge or the shifted
     * matrix is singular (a shift on an eigenvalue).
     */
    std::vector<double>
    eigenvalues_near(const dealii::DoFHandler<3>             &dofs,
                     const dealii::SparseMatrix<double>      &K,
                     const dealii::SparseMatrix<double>      &M,
                     const dealii::AffineConstraints<double> &constraints,
                     unsigned int                             n,
                     double                                   shift);
  } // namespace fe
} // namespace greentread

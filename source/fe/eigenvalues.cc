#include <greentread/base/exceptions.h>
#include <greentread/fe/eigenvalues.h>

#include <deal.II/dofs/dof_tools.h>
#include <deal.II/lac/arpack_solver.h>
#include <deal.II/lac/dynamic_sparsity_pattern.h>
#include <deal.II/lac/solver_control.h>
#include <deal.II/lac/sparse_direct.h>
#include <deal.II/lac/vector.h>

#include <algorithm>

namespace greentread
{
  namespace fe
  {
    using namespace dealii;

    std::vector<double>
    eigenvalues_near(const DoFHandler<3>             &dofs,
                     const SparseMatrix<double>      &K,
                     const SparseMatrix<double>      &M,
                     const AffineConstraints<double> &constraints,
                     const unsigned int               n,
                     const double                     shift)
    {
      DynamicSparsityPattern dsp(dofs.n_dofs());
      DoFTools::make_sparsity_pattern(dofs, dsp);
      constraints.condense(dsp);
      SparsityPattern sp;
      sp.copy_from(dsp);
      SparseMatrix<double> A(sp), B(sp), shifted(sp);
      for (auto e = K.begin(); e != K.end(); ++e)
        A.add(e->row(), e->column(), e->value());
      for (auto e = M.begin(); e != M.end(); ++e)
        B.add(e->row(), e->column(), e->value());
      constraints.condense(A);
      constraints.condense(B);
      for (types::global_dof_index i = 0; i < dofs.n_dofs(); ++i)
        if (constraints.is_constrained(i))
          {
            A.set(i, i, 1.);
            B.set(i, i, 0.);
          }
      shifted.copy_from(A);
      shifted.add(-shift, B);
      SparseDirectUMFPACK inverse;
      try
        {
          inverse.initialize(shifted);
        }
      catch (const std::exception &)
        {
          throw NumericalError("eigenvalues: K - shift M is singular for shift " +
                               format_short(shift) + ": the shift sits on an eigenvalue");
        }

      std::vector<std::complex<double>> values(n);
      std::vector<Vector<double>>       vectors(n, Vector<double>(dofs.n_dofs()));
      SolverControl                     control(std::max<unsigned int>(dofs.n_dofs(), 1000), 1e-10);
      ArpackSolver::AdditionalData      data(std::min<unsigned int>(2 * n + 10, dofs.n_dofs() - 1),
                                             ArpackSolver::largest_magnitude, true);
      ArpackSolver                      solver(control, data);
      solver.set_shift(shift);
      try
        {
          solver.solve(A, B, inverse, values, vectors, n);
        }
      catch (const dealii::ExceptionBase &e)
        {
          std::ostringstream info;
          e.print_info(info);
          throw NumericalError("eigenvalues: ARPACK failed: " + info.str());
        }
      std::vector<double> result;
      for (const auto &v : values)
        result.push_back(v.real());
      std::sort(result.begin(), result.end());
      return result;
    }
  } // namespace fe
} // namespace greentread

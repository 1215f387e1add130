#include <greentread/periodic/green_solvers.h>

#include <algorithm>
#include <complex>
#include <vector>

// The Bloch-reduced cell D_phi (green_solvers.h): its pattern is built once,
// and each frequency and wavenumber only recombines the stored parts.

namespace greentread
{
  namespace periodic
  {
    BlochCell::BlochCell(const PeriodicCell &cell)
        : n_reduced(cell.n_face + cell.n_interior)
    {
      // Fold R onto L. Phase class 0: none; 1: e^{i phi} (column on R);
      // 2: e^{-i phi} (row on R).
      const auto fold = [&](const int i, bool &on_right) {
        on_right = i >= static_cast<int>(n_reduced);
        return on_right ? i - static_cast<int>(n_reduced) : i;
      };
      const SparseReal *matrices[3] = {&cell.stiffness, &cell.damping, &cell.mass};
      std::vector<Eigen::Triplet<Complex>> entries;
      for (const SparseReal *A : matrices)
        for (int c = 0; c < A->outerSize(); ++c)
          for (SparseReal::InnerIterator it(*A, c); it; ++it)
            {
              bool row_right, column_right;
              entries.emplace_back(fold(it.row(), row_right), fold(it.col(), column_right), 1.);
            }
      matrix.resize(n_reduced, n_reduced);
      matrix.setFromTriplets(entries.begin(), entries.end());
      matrix.makeCompressed();
      for (auto &per_matrix : parts)
        for (auto &per_class : per_matrix)
          per_class.assign(matrix.nonZeros(), 0.);
      for (unsigned int m = 0; m < 3; ++m)
        for (int c = 0; c < matrices[m]->outerSize(); ++c)
          for (SparseReal::InnerIterator it(*matrices[m], c); it; ++it)
            {
              bool      row_right, column_right;
              const int r = fold(it.row(), row_right), col = fold(it.col(), column_right);
              const int phase = row_right == column_right ? 0 : (column_right ? 1 : 2);
              parts[m][phase][position(r, col)] += it.value();
            }
    }



    void
    BlochCell::set_frequency(const double omega)
    {
      set_combination(1., Complex(0., omega), -omega * omega);
    }



    void
    BlochCell::set_combination(const Complex a, const Complex c, const Complex m)
    {
      for (unsigned int t = 0; t < 3; ++t)
        {
          at_frequency[t].resize(matrix.nonZeros());
          for (std::size_t e = 0; e < at_frequency[t].size(); ++e)
            at_frequency[t][e] = a * parts[0][t][e] + c * parts[1][t][e] + m * parts[2][t][e];
        }
    }



    const SparseComplex &
    BlochCell::assemble(const double phi)
    {
      const Complex phase = std::polar(1., phi);
      Complex      *out   = matrix.valuePtr();
      for (std::size_t e = 0; e < at_frequency[0].size(); ++e)
        out[e] =
          at_frequency[0][e] + phase * at_frequency[1][e] + std::conj(phase) * at_frequency[2][e];
      return matrix;
    }



    std::size_t
    BlochCell::position(const int row, const int column) const
    {
      const int *begin = matrix.innerIndexPtr() + matrix.outerIndexPtr()[column];
      const int *end   = matrix.innerIndexPtr() + matrix.outerIndexPtr()[column + 1];
      return std::lower_bound(begin, end, row) - matrix.innerIndexPtr();
    }
  } // namespace periodic
} // namespace greentread

#include <greentread/base/exceptions.h>
#include <greentread/synthesis/shared_pattern.h>

#include <algorithm>
#include <string>

namespace greentread
{
  namespace synthesis
  {
    namespace internal
    {
      SharedPattern::SharedPattern(const std::vector<const periodic::SparseComplex *> &matrices)
          : count(matrices.size())
      {
        if (matrices.empty())
          return;
        std::vector<Eigen::SparseMatrix<periodic::Complex, Eigen::RowMajor>> rows;
        for (const periodic::SparseComplex *A : matrices)
          rows.emplace_back(*A);
        const auto &first = rows.front();
        n                 = first.rows();
        start.assign(first.outerIndexPtr(), first.outerIndexPtr() + n + 1);
        column.assign(first.innerIndexPtr(), first.innerIndexPtr() + first.nonZeros());
        for (const auto &A : rows)
          if (A.rows() != n || A.nonZeros() != first.nonZeros() ||
              !std::equal(start.begin(), start.end(), A.outerIndexPtr()) ||
              !std::equal(column.begin(), column.end(), A.innerIndexPtr()))
            throw NumericalError("SharedPattern: the Bloch cell's matrices do not share their "
                                 "sparsity pattern");
        values.resize(2 * count * column.size());
        for (std::size_t e = 0; e < column.size(); ++e)
          for (std::size_t a = 0; a < count; ++a)
            {
              values[2 * (count * e + a)]     = rows[a].valuePtr()[e].real();
              values[2 * (count * e + a) + 1] = rows[a].valuePtr()[e].imag();
            }
      }



      void
      SharedPattern::apply(const Eigen::MatrixXcd                &X,
                           const std::vector<Eigen::MatrixXcd *> &out) const
      {
        if (out.empty() || out.size() > std::min<std::size_t>(count, 2) || X.rows() != n)
          throw NumericalError("SharedPattern::apply: " + std::to_string(out.size()) +
                               " products asked of " + std::to_string(count) +
                               " matrices (one or two at once), a block of " +
                               std::to_string(X.rows()) + " rows for " + std::to_string(n));
        if (out.size() == 1)
          multiply<1>(X, out);
        else
          multiply<2>(X, out);
      }



      template <std::size_t wanted>
      void
      SharedPattern::multiply(const Eigen::MatrixXcd                &X,
                              const std::vector<Eigen::MatrixXcd *> &out) const
      {
        const Eigen::Index b = X.cols();
        for (Eigen::MatrixXcd *o : out)
          o->resize(n, b);
        // Four columns of X per row: their real parts, then their imaginary.
        std::vector<double> x(8 * n);
        for (Eigen::Index first = 0; first < b; first += 4)
          {
            const Eigen::Index w = std::min<Eigen::Index>(4, b - first);
            std::fill(x.begin(), x.end(), 0.);
            for (Eigen::Index c = 0; c < w; ++c)
              for (Eigen::Index i = 0; i < n; ++i)
                {
                  x[8 * i + c]     = X(i, first + c).real();
                  x[8 * i + 4 + c] = X(i, first + c).imag();
                }
            for (Eigen::Index i = 0; i < n; ++i)
              {
                double re[wanted][4] = {}, im[wanted][4] = {};
                for (int e = start[i]; e < start[i + 1]; ++e)
                  {
                    const double *v  = values.data() + 2 * count * e;
                    const double *xr = x.data() + 8 * column[e], *xi = xr + 4;
                    for (std::size_t a = 0; a < wanted; ++a)
#pragma omp simd
                      for (int c = 0; c < 4; ++c)
                        {
                          re[a][c] += v[2 * a] * xr[c] - v[2 * a + 1] * xi[c];
                          im[a][c] += v[2 * a] * xi[c] + v[2 * a + 1] * xr[c];
                        }
                  }
                for (std::size_t a = 0; a < wanted; ++a)
                  for (Eigen::Index c = 0; c < w; ++c)
                    (*out[a])(i, first + c) = periodic::Complex(re[a][c], im[a][c]);
              }
          }
      }
    } // namespace internal
  }   // namespace synthesis
} // namespace greentread

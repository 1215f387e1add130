#pragma once

#include <greentread/periodic/green_solvers.h>

#include <Eigen/Dense>

#include <vector>

/**
 * @file
 * Products of the Bloch cell's sparse matrices with tall blocks, for the
 * mode search (synthesis/bloch_modes.h).
 */

namespace greentread
{
  namespace synthesis
  {
    namespace internal
    {
      /**
       * Products of sparse matrices that share the cell's pattern (K, M,
       * C) with tall blocks: one compressed-row copy holds the values of
       * all of them per entry, so that K X and M X come from one pass, and
       * X is read row-interleaved, four columns at a time, real and
       * imaginary parts apart, so that the products vectorise. Eigen's
       * column-major product went over the pattern once per column of X,
       * with scattered writes and the complex multiplication out of line
       * (__muldc3): K X and M X took a fifth of the mode search, C Psi for
       * the modal damping a tenth.
       */
      class SharedPattern
      {
      public:
        SharedPattern() = default;

        /// @throws NumericalError if the patterns differ.
        explicit SharedPattern(const std::vector<const periodic::SparseComplex *> &matrices);

        Eigen::Index
        size() const
        {
          return n;
        }

        /// out[a] = A_a X, the matrices in the order given, for the first
        /// one or two of them.
        /// @throws NumericalError if more products are asked than matrices held.
        void
        apply(const Eigen::MatrixXcd &X, const std::vector<Eigen::MatrixXcd *> &out) const;

      private:
        template <std::size_t wanted>
        void
        multiply(const Eigen::MatrixXcd &X, const std::vector<Eigen::MatrixXcd *> &out) const;

        std::size_t         count = 0;
        Eigen::Index        n     = 0;
        std::vector<int>    start, column;
        std::vector<double> values;
      };
    } // namespace internal
  }   // namespace synthesis
} // namespace greentread

#pragma once

#include <Eigen/Core>

#include <memory>

/**
 * @file
 * The product of a lattice's translation-invariant, even kernel with a
 * field on the lattice, by FFT: what makes the tread's local compliance on a
 * contact grid of tens of thousands of points affordable without its dense
 * matrix. Implemented in source/convolution/lattice_convolution.cc (FFTW 3).
 *
 * On an nx x ny lattice (point p = i_x ny + i_y), the matrix
 * \f$L_{pq} = T(|i_x - j_x|, |i_y - j_y|)\f$ is block Toeplitz with Toeplitz
 * blocks. It is embedded in a circulant of period 2 nx x 2 ny (the kernel
 * wrapped around, 0 at the offsets nx and ny that no pair has): the field
 * padded with zeros, transformed, multiplied by the kernel's transform and
 * transformed back gives \f$L x\f$ exactly, up to round-off, in
 * \f$O(n_x n_y \log(n_x n_y))\f$ operations and memory, against
 * \f$O(n_x^2 n_y^2)\f$ for the dense product.
 */

namespace greentread
{
  namespace convolution
  {
    /**
     * @brief \f$y = L x\f$ for the block Toeplitz matrix of an even kernel
     * T on a lattice, by FFT. Const products may run on several threads at
     * once (each thread has its own work arrays); the constructor plans the
     * transforms (FFTW's planner is not thread-safe: construct from one
     * thread at a time).
     */
    class LatticeConvolution
    {
    public:
      /**
       * @param[in] T The kernel, T(m, n) for the offsets m = 0 .. nx - 1,
       *            n = 0 .. ny - 1: an nx x ny matrix.
       * @throws InputError if T is empty or not finite.
       */
      explicit LatticeConvolution(const Eigen::MatrixXd &T);
      ~LatticeConvolution();
      LatticeConvolution(const LatticeConvolution &) = delete;
      LatticeConvolution &
      operator=(const LatticeConvolution &) = delete;

      /// y = L x, x and y of size nx ny (they may be the same vector).
      void
      apply(const Eigen::VectorXd &x, Eigen::VectorXd &y) const;

      /// The kernel T(m, n) of the constructor.
      const Eigen::MatrixXd &
      kernel_values() const
      {
        return kernel;
      }

      /// The dense matrix L, for checks on small lattices.
      Eigen::MatrixXd
      dense() const;

      unsigned int nx = 0, ny = 0;

    private:
      struct Plans;
      std::unique_ptr<Plans> plans;
      Eigen::MatrixXd        kernel;
    };
  } // namespace convolution
} // namespace greentread

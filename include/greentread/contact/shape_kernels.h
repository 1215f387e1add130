#pragma once

#include <cstddef>

/**
 * @file
 * The two products of the rank-one modal update (contact/patch_convolution.cc,
 * ModePatchConvolution) on one block of shape rows, as plain loops.
 *
 * Eigen's general products, built here for SSE2 only (no -march=native: see
 * CMakeLists.txt), spent most of a step packing the block for products with
 * two or four right-hand sides. These loops read each row once from cache and
 * are vectorised by the compiler (OpenMP SIMD reductions); where the CPU has
 * AVX2 and FMA they run in a copy built for them, chosen once at run time.
 * On the default tyre's 70,578 shape rows x 120 points (AVX2): 11.7 ms per
 * step with Eigen, 4.4 ms with these loops on one core, 2.2 ms on two.
 */

namespace greentread
{
  namespace contact
  {
    /**
     * @brief forces[4 r + g] = sum_p shapes[r P + p] loads[g P + p], for the
     * @p rows rows of the row-major @p shapes (P values each) and the four
     * load vectors @p loads (g = 0 .. 3, P values each).
     */
    void
    modal_forces(const double *shapes,
                 std::size_t   rows,
                 std::size_t   P,
                 const double *loads,
                 double       *forces);

    /**
     * @brief out[c P + p] += sum_r weights[2 r + c] shapes[r P + p], c = 0, 1.
     */
    void
    add_weighted_shapes(const double *shapes,
                        std::size_t   rows,
                        std::size_t   P,
                        const double *weights,
                        double       *out);
  } // namespace contact
} // namespace greentread

#pragma once

#include <cstddef>

/**
 * @file
 * The two products of the rank-one modal update
 * (greentread/convolution/mode_patch_convolution.h) on one block of shape rows, as
 * plain loops: step by step (one to four load vectors, one or two sums) and
 * in time blocks (J load vectors and J sums, register tiles).
 *
 * Eigen's general products, on the generic (SSE2) build, spent most of a step
 * packing the block for products with two or four right-hand sides. These
 * loops read each row once from cache and are vectorised by the compiler
 * (OpenMP SIMD reductions); where the CPU has AVX2 and FMA they run in a copy
 * built for them, chosen once at run time.
 *
 * The shapes are double or float (ShapePrecision in
 * greentread/convolution/patch_convolution.h): the update is memory bound, and
 * single precision halves the bytes read per step. The products run in the
 * shapes' precision: for float shapes each dot product (P terms) and each
 * call's sum over its rows are formed in float, and added to the results in
 * double.
 */

namespace greentread
{
  namespace convolution
  {
    /**
     * @brief forces[n_loads r + g] = sum_p shapes[r P + p] loads[g P + p], for
     * the @p rows rows of the row-major @p shapes (P values each) and the
     * @p n_loads (1 to 4) load vectors @p loads (P values each, in the
     * shapes' precision).
     */
    template <typename Shape>
    void
    modal_forces(const Shape *shapes,
                 std::size_t  rows,
                 std::size_t  P,
                 const Shape *loads,
                 unsigned int n_loads,
                 double      *forces);

    /**
     * @brief out[c P + p] += sum_r weights[2 r + c] shapes[r P + p], for
     * c = 0 .. @p n_out - 1 (1: the first sum alone, 2: both).
     */
    template <typename Shape>
    void
    add_weighted_shapes(const Shape  *shapes,
                        std::size_t   rows,
                        std::size_t   P,
                        const double *weights,
                        unsigned int  n_out,
                        double       *out);

    /**
     * @brief The time-blocked update's first product: forces[J r + j] =
     * sum_a shapes[r P + points[a]] loads[J a + j], for the @p rows rows of
     * @p shapes and @p J (4, 8 or 16) load vectors given at the @p n_points
     * @p points where any of them is not zero, point by point in @p loads
     * (J values per point). Loads, products and forces in the shapes'
     * precision.
     */
    template <typename Shape>
    void
    block_forces(const Shape        *shapes,
                 std::size_t         rows,
                 std::size_t         P,
                 const unsigned int *points,
                 std::size_t         n_points,
                 const Shape        *loads,
                 unsigned int        J,
                 Shape              *forces);

    /**
     * @brief Its second: out[J p + j] += sum_r weights[J r + j]
     * shapes[r P + p], with the weights in the shapes' precision and the
     * call's sum over its rows formed in it (added to @p out in double).
     */
    template <typename Shape>
    void
    add_block_weighted_shapes(const Shape *shapes,
                              std::size_t  rows,
                              std::size_t  P,
                              const Shape *weights,
                              unsigned int J,
                              double      *out);
  } // namespace convolution
} // namespace greentread

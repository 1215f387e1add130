#pragma once

#include <Eigen/Core>

#include <utility>
#include <vector>

/**
 * @file
 * The rank-one update's lag sums in single precision: modal::shape_sums()
 * (greentread/modal/patch_model.h) for shapes stored as float, used by the
 * single-precision rolling update (source/convolution/mode_patch_convolution.cc).
 */

namespace greentread
{
  namespace convolution
  {
    /// Shapes in float, one row per real shape (stride 1) or a pair of rows
    /// (real, imaginary part) per complex one (stride 2).
    using ShapesF = Eigen::Matrix<float, Eigen::Dynamic, Eigen::Dynamic, Eigen::RowMajor>;

    /**
     * @brief For each pair of weight vectors (one weight per term), the
     * symmetric N_p x N_p sum over the shapes that modal::shape_sums() forms
     * in double from the double shapes.
     *
     * Each chunk of 512 rows is summed in float (one triangle, Eigen's
     * triangular product: twice the rate of double) and the chunks are added
     * in double. Relative error about 1e-6, that of the single-precision
     * update's own sums.
     */
    std::vector<Eigen::MatrixXd>
    single_precision_shape_sums(
      const ShapesF                                                  &shapes,
      Eigen::Index                                                    stride,
      const std::vector<std::pair<Eigen::VectorXd, Eigen::VectorXd>> &weights);
  } // namespace convolution
} // namespace greentread

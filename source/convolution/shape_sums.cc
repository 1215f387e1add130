#include <greentread/convolution/shape_sums.h>

#include <algorithm>

namespace greentread
{
  namespace convolution
  {
    std::vector<Eigen::MatrixXd>
    single_precision_shape_sums(
      const ShapesF                                                  &shapes,
      const Eigen::Index                                              stride,
      const std::vector<std::pair<Eigen::VectorXd, Eigen::VectorXd>> &weights)
    {
      const Eigen::Index           n_p   = shapes.cols();
      constexpr Eigen::Index       chunk = 512;
      const Eigen::Index           R     = shapes.rows();
      std::vector<Eigen::MatrixXd> sums(weights.size(), Eigen::MatrixXd::Zero(n_p, n_p));
      Eigen::Matrix<float, Eigen::Dynamic, Eigen::Dynamic, Eigen::RowMajor> X(chunk, n_p);
      Eigen::MatrixXf                                                       part(n_p, n_p);
      for (Eigen::Index r = 0; r < R; r += chunk)
        {
          const Eigen::Index len = std::min(chunk, R - r);
          const auto         Sc  = shapes.middleRows(r, len);
          for (std::size_t s = 0; s < weights.size(); ++s)
            {
              // Rows a, b of a complex shape: X = [w1 a + w2 b; w2 a - w1 b].
              for (Eigen::Index i = 0; i < len; i += stride)
                {
                  const Eigen::Index k = (r + i) / stride;
                  const float w1 = float(weights[s].first(k)), w2 = float(weights[s].second(k));
                  if (stride == 1)
                    X.row(i) = w1 * Sc.row(i);
                  else
                    {
                      X.row(i)     = w1 * Sc.row(i) + w2 * Sc.row(i + 1);
                      X.row(i + 1) = w2 * Sc.row(i) - w1 * Sc.row(i + 1);
                    }
                }
              part.setZero();
              part.triangularView<Eigen::Lower>() += Sc.transpose() * X.topRows(len);
              sums[s].triangularView<Eigen::Lower>() += part.cast<double>();
            }
        }
      for (auto &sum : sums)
        sum = sum.selfadjointView<Eigen::Lower>();
      return sums;
    }
  } // namespace convolution
} // namespace greentread

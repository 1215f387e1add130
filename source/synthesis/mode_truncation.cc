#include <greentread/synthesis/mode_truncation.h>

#include <cmath>
#include <vector>

namespace greentread
{
  namespace synthesis
  {
    ModeSynthesis
    truncate(const ModeSynthesis                 &all,
             const double                         cutoff_hz,
             const base::FrequencyResponseMatrix &direct)
    {
      std::vector<Eigen::Index> keep;
      for (Eigen::Index k = 0; k < all.frequency_hz.size(); ++k)
        if (all.frequency_hz(k) <= cutoff_hz)
          keep.push_back(k);
      const Eigen::Index m       = Eigen::Index(keep.size());
      const bool         coupled = all.shapes_imag.size() > 0;
      Eigen::VectorXd    omega(m), xi(m);
      Eigen::MatrixXd    shapes(m, all.shapes.cols()), imag(coupled ? m : 0, all.shapes.cols());
      for (Eigen::Index r = 0; r < m; ++r)
        {
          omega(r)      = 2. * M_PI * all.frequency_hz(keep[r]);
          xi(r)         = all.damping_ratio(keep[r]);
          shapes.row(r) = all.shapes.row(keep[r]);
          if (coupled)
            imag.row(r) = all.shapes_imag.row(keep[r]);
        }
      return synthesise(omega, xi, shapes, imag, direct);
    }
  } // namespace synthesis
} // namespace greentread

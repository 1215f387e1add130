#include <greentread/base/exceptions.h>
#include <greentread/radiation/surface_mobility.h>

/**
 * @file
 * SurfaceMobility to and from flat arrays, for the radiation stage's saved
 * file (radiation/sound_model.h), and truncated to fewer harmonics.
 */

namespace greentread
{
  namespace radiation
  {
    SurfaceMobility
    SurfaceMobility::truncated(const unsigned int n) const
    {
      if (n == 0 || n > harmonics.size())
        throw InputError("surface mobility truncated to " + std::to_string(n) +
                         " harmonics; allowed: 1 to " + std::to_string(harmonics.size()));
      SurfaceMobility fewer = *this;
      fewer.harmonics.resize(n);
      return fewer;
    }



    SurfaceMobility::Saved
    SurfaceMobility::saved() const
    {
      Saved s;
      s.cell_segment = cell_segment;
      s.point_strip  = point_strip;
      s.cell_angle   = cell_angle;
      s.point_angle  = point_angle;
      const Eigen::Index S =
        harmonics.empty() ? 0 : static_cast<Eigen::Index>(harmonics.front().residual.rows());
      s.sizes = {static_cast<double>(n_strips), static_cast<double>(S), cell_arc, point_arc};
      for (const Harmonic &h : harmonics)
        {
          const Eigen::Index m = h.omega.size();
          s.modes.push_back(static_cast<int>(m));
          s.coupled.push_back(h.coupled ? 1 : 0);
          for (Eigen::Index k = 0; k < m; ++k)
            {
              s.omega.push_back(h.omega(k));
              s.damping_ratio.push_back(h.damping_ratio(k));
              for (Eigen::Index c = 0; c < h.at_segments.cols(); ++c)
                s.at_segments.push_back(h.at_segments(k, c));
              for (Eigen::Index c = 0; c < h.at_strips.cols(); ++c)
                s.at_strips.push_back(h.at_strips(k, c));
            }
          for (Eigen::Index r = 0; r < h.residual.rows(); ++r)
            for (Eigen::Index c = 0; c < h.residual.cols(); ++c)
              s.residual.push_back(h.residual(r, c));
          for (Eigen::Index r = 0; r < h.strip_residual.rows(); ++r)
            for (Eigen::Index c = 0; c < h.strip_residual.cols(); ++c)
              s.strip_residual.push_back(h.strip_residual(r, c));
        }
      return s;
    }



    SurfaceMobility::SurfaceMobility(const Saved &s)
        : cell_segment(s.cell_segment)
        , cell_angle(s.cell_angle)
        , point_angle(s.point_angle)
        , point_strip(s.point_strip)
    {
      const auto fail = [](const std::string &what) {
        throw InputError("saved surface mobility: " + what +
                         "; delete the radiation stage's file to recompute it");
      };
      if (s.sizes.size() != 4 || s.modes.size() != s.coupled.size() ||
          cell_segment.size() != cell_angle.size() || point_strip.size() != point_angle.size())
        fail("its arrays' sizes do not fit together");
      n_strips             = static_cast<unsigned int>(s.sizes[0]);
      const auto J         = static_cast<Eigen::Index>(n_strips);
      const auto S         = static_cast<Eigen::Index>(s.sizes[1]);
      cell_arc             = s.sizes[2];
      point_arc            = s.sizes[3];
      std::size_t mode     = 0;
      std::size_t residual = 0, strip_residual = 0;
      for (std::size_t n = 0; n < s.modes.size(); ++n)
        {
          const Eigen::Index m = s.modes[n];
          if (m < 0 || s.omega.size() < mode + m || s.damping_ratio.size() < mode + m ||
              s.at_segments.size() < (mode + m) * S || s.at_strips.size() < (mode + m) * J ||
              s.residual.size() < residual + S * J ||
              s.strip_residual.size() < strip_residual + J * J)
            fail("harmonic " + std::to_string(n) + " is cut short");
          Harmonic h;
          h.coupled       = s.coupled[n] != 0;
          h.omega         = Eigen::Map<const Eigen::VectorXd>(s.omega.data() + mode, m);
          h.damping_ratio = Eigen::Map<const Eigen::VectorXd>(s.damping_ratio.data() + mode, m);
          using RowMajorC =
            Eigen::Matrix<std::complex<double>, Eigen::Dynamic, Eigen::Dynamic, Eigen::RowMajor>;
          using RowMajorR = Eigen::Matrix<double, Eigen::Dynamic, Eigen::Dynamic, Eigen::RowMajor>;
          h.at_segments   = Eigen::Map<const RowMajorC>(s.at_segments.data() + mode * S, m, S);
          h.at_strips     = Eigen::Map<const RowMajorC>(s.at_strips.data() + mode * J, m, J);
          h.residual      = Eigen::Map<const RowMajorR>(s.residual.data() + residual, S, J);
          h.strip_residual =
            Eigen::Map<const RowMajorR>(s.strip_residual.data() + strip_residual, J, J);
          mode += m;
          residual += S * J;
          strip_residual += J * J;
          harmonics.push_back(std::move(h));
        }
      if (mode != s.omega.size() || residual != s.residual.size())
        fail("it holds more modes than its harmonics count");
      for (const int j : point_strip)
        if (j < 0 || j >= static_cast<int>(n_strips))
          fail("a point's strip is out of range");
      for (const int seg : cell_segment)
        if (seg >= static_cast<int>(S))
          fail("a cell's segment is out of range");
    }
  } // namespace radiation
} // namespace greentread

// What the contact grid's tests share (test_contact_grid.cc,
// test_projected_cg.cc): the tread's layer, the Green's functions' points, a
// synthetic coarse compliance and a synthetic modal model on those points.
#pragma once

#include <greentread/contact/elastic_layer.h>
#include <greentread/synthesis/mode_synthesis.h>

#include <Eigen/Core>

#include <algorithm>
#include <array>
#include <cmath>
#include <random>
#include <vector>

namespace test
{
  inline const greentread::contact::ElasticLayer tread_layer{7e6, 0.49, 0.008};

  /// n standard normal values from @p seed.
  inline Eigen::VectorXd
  random_vector(const unsigned int n, const unsigned int seed)
  {
    std::mt19937                     rng(seed);
    std::normal_distribution<double> z(0., 1.);
    Eigen::VectorXd                  v(n);
    for (auto &x : v)
      x = z(rng);
    return v;
  }

  /// The Green's functions' points: nx x ny rectangles of 6 x 6.667 mm,
  /// symmetric about the centre, listed across first (as the Green's stage
  /// does); with @p shuffled in a shuffled order, which the grid must not
  /// depend on.
  inline std::vector<std::array<double, 3>>
  coarse_points(const unsigned int nx, const unsigned int ny, const bool shuffled = true)
  {
    std::vector<std::array<double, 3>> p;
    for (unsigned int i = 0; i < nx; ++i)
      for (unsigned int j = 0; j < ny; ++j)
        p.push_back({{(i + 0.5 - 0.5 * nx) * 6e-3, (j + 0.5 - 0.5 * ny) * (0.08 / 12), 0.27}});
    if (shuffled)
      {
        std::mt19937 rng(5);
        std::shuffle(p.begin(), p.end(), rng);
      }
    return p;
  }

  /// A symmetric positive definite "Green's function" for the coarse cells:
  /// a smooth global part plus a local one.
  inline Eigen::MatrixXd
  coarse_compliance(const std::vector<std::array<double, 3>> &points)
  {
    const unsigned int n = points.size();
    Eigen::MatrixXd    G(n, n);
    for (unsigned int a = 0; a < n; ++a)
      for (unsigned int b = 0; b < n; ++b)
        {
          const double r = std::hypot(points[a][0] - points[b][0], points[a][1] - points[b][1]);
          G(a, b)        = 4e-6 * std::exp(-r / 0.03);
        }
    return G + 6e-6 * Eigen::MatrixXd::Identity(n, n);
  }

  /// 12 modes (200 to 3000 Hz, 4% damping) on @p coarse with
  /// coarse_compliance() as G_r.
  inline greentread::synthesis::ModeSynthesis
  synthetic_modes(const std::vector<std::array<double, 3>> &coarse)
  {
    const unsigned int                   n_c = coarse.size(), m = 12;
    greentread::synthesis::ModeSynthesis s;
    s.frequency_hz  = Eigen::VectorXd::LinSpaced(m, 200., 3000.);
    s.damping_ratio = Eigen::VectorXd::Constant(m, 0.04);
    s.shapes.resize(m, n_c);
    for (unsigned int k = 0; k < m; ++k)
      for (unsigned int c = 0; c < n_c; ++c)
        s.shapes(k, c) = 0.3 * std::cos(0.7 * k + 1.3 * c) + 0.1;
    s.instantaneous = coarse_compliance(coarse);
    s.points        = coarse;
    s.wavenumber.assign(m, 0);
    s.dispersion.frequency_hz  = {Eigen::VectorXd::LinSpaced(2, 200., 3000.)};
    s.dispersion.damping_ratio = {Eigen::VectorXd::Constant(2, 0.04)};
    return s;
  }
} // namespace test

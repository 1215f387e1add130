#pragma once

// A synthetic contact patch whose Green's functions are known in closed form,
// shared by the rolling-contact checks (test_patch_contact.cc) and the
// statistics of rolling spectra (test_spectrum_statistics.cc).

#include <greentread/modal/patch_model.h>

#include <Eigen/Core>

#include <cmath>
#include <complex>
#include <vector>

namespace test
{
  /// The ring radius under the synthetic patch [m].
  constexpr double ring_radius = 0.3;

  /**
   * A 4 x 3 patch (6 mm by 7 mm) whose Green's functions are known in closed
   * form: five damped modes with smooth shapes over the patch, residues
   * \f$\phi\phi^T / (2 j m \omega_d)\f$ (so g(0+) = 0), and a local
   * compliance G_r (diagonal 5e-6 m/N, neighbours 1e-6 m/N: symmetric,
   * diagonally dominant, so positive definite). Points are numbered
   * i_x * 3 + i_y, as the Green's stage numbers them.
   */
  inline greentread::modal::PatchModel
  synthetic_patch(const double zeta = 0.05, const bool local = true)
  {
    const unsigned int            nx = 4, ny = 3, n = nx * ny;
    const double                  dx = 6e-3, dy = 7e-3;
    greentread::modal::PatchModel m;
    for (unsigned int i = 0; i < nx; ++i)
      for (unsigned int j = 0; j < ny; ++j)
        m.points.push_back({{(i - 1.5) * dx, (j - 1.) * dy, ring_radius}});
    const std::vector<double> f = {120., 180., 260., 340., 450.};
    for (unsigned int k = 0; k < f.size(); ++k)
      {
        Eigen::VectorXd phi(n);
        for (unsigned int p = 0; p < n; ++p)
          {
            const double x = m.points[p][0] / (2. * dx), y = m.points[p][1] / dy;
            const double shapes[5] = {1., x, y, std::cos(M_PI * x), x * y};
            phi[p]                 = shapes[k];
          }
        const double w = 2. * M_PI * f[k], wd = w * std::sqrt(1. - zeta * zeta), mass = 2.;
        m.lambda.emplace_back(-zeta * w, wd);
        m.real.push_back(false);
        m.residues.push_back((phi * phi.transpose()).cast<std::complex<double>>() /
                             std::complex<double>(0., 2. * mass * wd));
      }
    if (local)
      {
        m.instantaneous = Eigen::MatrixXd::Zero(n, n);
        for (unsigned int p = 0; p < n; ++p)
          for (unsigned int q = 0; q < n; ++q)
            {
              const double r        = std::hypot((m.points[p][0] - m.points[q][0]) / dx,
                                                 (m.points[p][1] - m.points[q][1]) / dy);
              m.instantaneous(p, q) = r < 1e-9 ? 5e-6 : (r < 1.01 ? 1e-6 : 0.);
            }
      }
    m.errors = Eigen::MatrixXd::Zero(n, n);
    m.f_max  = 1000.;
    return m;
  }

  /// The tread's own height x^2 / (2 R) under each point.
  inline Eigen::VectorXd
  tread_height(const greentread::modal::PatchModel &m)
  {
    Eigen::VectorXd t(m.n_points());
    for (unsigned int p = 0; p < m.n_points(); ++p)
      t[p] = m.points[p][0] * m.points[p][0] / (2. * ring_radius);
    return t;
  }

} // namespace test

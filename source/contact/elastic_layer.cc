#include <greentread/base/exceptions.h>
#include <greentread/contact/elastic_layer.h>

#include <Eigen/Dense>

#include <algorithm>
#include <cmath>
#include <limits>

namespace greentread
{
  namespace contact
  {
    namespace
    {
      void
      check_layer(const ElasticLayer &layer)
      {
        if (!(layer.youngs_modulus > 0.) || !std::isfinite(layer.youngs_modulus))
          throw InputError("elastic layer: Young's modulus = " +
                           format_short(layer.youngs_modulus) + " Pa; allowed: > 0");
        if (!(layer.poissons_ratio > -1. && layer.poissons_ratio < 0.5))
          throw InputError("elastic layer: Poisson's ratio = " +
                           format_short(layer.poissons_ratio) + "; allowed: (-1, 0.5)");
        if (!(layer.thickness > 0.) || !std::isfinite(layer.thickness))
          throw InputError("elastic layer: thickness = " + format_short(layer.thickness) +
                           " m; allowed: > 0");
      }

      /// C(0) = h / (lambda + 2 mu).
      double
      column_compliance(const ElasticLayer &l)
      {
        const double nu = l.poissons_ratio;
        return l.thickness * (1. + nu) * (1. - 2. * nu) / (l.youngs_modulus * (1. - nu));
      }

      /// The half-space's C(k) k.
      double
      half_space_factor(const ElasticLayer &l)
      {
        return 2. * (1. - l.poissons_ratio * l.poissons_ratio) / l.youngs_modulus;
      }

      /// C(k) k at k = 1 for a layer x = kh thick (lengths in units of 1/k).
      double
      scaled_compliance(const ElasticLayer &l, const double x)
      {
        const double nu     = l.poissons_ratio;
        const double mu     = l.youngs_modulus / (2. * (1. + nu));
        const double lambda = 2. * mu * nu / (1. - 2. * nu);
        const double c      = 3. - 4. * nu;
        // Field values (a, a', b, b') of each of the four solutions at z;
        // u_x = a sin(x), u_z = b cos(x). Type 1: grad(e^{sz} cos x); type
        // 2: 4(1-nu) psi - grad(z psi), psi = e^{sz} cos x. The s = +1
        // exponentials are written as e^{z - x}, the s = -1 ones as e^{-z}.
        const auto field = [&](const unsigned int i, const double z) {
          const double s = i < 2 ? 1. : -1.;
          const double f = i < 2 ? std::exp(z - x) : std::exp(-z);
          if (i % 2 == 0)
            return Eigen::Vector4d(-f, -s * f, s * f, f);
          return Eigen::Vector4d(z * f, f + s * z * f, (c - s * z) * f, (-s + s * c - z) * f);
        };
        Eigen::Matrix4d A;
        for (unsigned int i = 0; i < 4; ++i)
          {
            const Eigen::Vector4d top = field(i, 0.), base = field(i, x);
            A(0, i) = lambda * (top[0] + top[3]) + 2. * mu * top[3]; // sigma_zz(0)
            A(1, i) = mu * (top[1] - top[2]);                        // tau(0)
            A(2, i) = base[0];                                       // u_x(h)
            A(3, i) = base[2];                                       // u_z(h)
          }
        const Eigen::Vector4d rhs(-1., 0., 0., 0.); // sigma_zz = -p: a pressure into the layer
        const Eigen::Vector4d amp = A.fullPivLu().solve(rhs);
        double                b0  = 0.;
        for (unsigned int i = 0; i < 4; ++i)
          b0 += amp[i] * field(i, 0.)[2];
        return b0;
      }

      constexpr double       table_low = 1e-3, table_high = 40.;
      constexpr unsigned int table_size = 20000;
    } // namespace



    double
    layer_compliance(const ElasticLayer &layer, const double k)
    {
      check_layer(layer);
      if (!(k >= 0.) || !std::isfinite(k))
        throw InputError("elastic layer: wavenumber = " + format_short(k) + " 1/m; allowed: >= 0");
      if (k == 0.)
        return column_compliance(layer);
      const double x = k * layer.thickness;
      if (x > 700.)
        return half_space_factor(layer) / k;
      return scaled_compliance(layer, x) / k;
    }



    LayerComplianceTable::LayerComplianceTable(const ElasticLayer &layer_)
        : layer(layer_)
    {
      check_layer(layer);
      c0     = column_compliance(layer);
      log_x0 = std::log(table_low);
      dlog   = (std::log(table_high) - log_x0) / (table_size - 1);
      s.resize(table_size);
      for (unsigned int i = 0; i < table_size; ++i)
        s[i] = scaled_compliance(layer, std::exp(log_x0 + i * dlog)) / half_space_factor(layer);
    }



    double
    LayerComplianceTable::operator()(const double k) const
    {
      const double x = k * layer.thickness;
      if (x < table_low)
        {
          // C - C(0) grows as (kh)^2 (17 (kh)^2 relative for nu = 0.49):
          // quadratic from C(0) to the table's first point.
          const double first = s[0] * half_space_factor(layer) / (table_low / layer.thickness);
          return c0 + (first - c0) * (x / table_low) * (x / table_low);
        }
      if (x >= table_high)
        return half_space_factor(layer) / k;
      const double       r = (std::log(x) - log_x0) / dlog;
      const unsigned int i = std::min<unsigned int>(r, table_size - 2);
      const double       w = r - i;
      return ((1. - w) * s[i] + w * s[i + 1]) * half_space_factor(layer) / k;
    }



    Eigen::MatrixXd
    rectangle_lattice_compliance(const std::function<double(double)> &compliance,
                                 const double                         a,
                                 const double                         b,
                                 const unsigned int                   mx,
                                 const unsigned int                   my,
                                 const unsigned int                   nx,
                                 const unsigned int                   ny,
                                 const unsigned int                   harmonics)
    {
      if (nx < 2 * mx + 1 || ny < 2 * my + 1)
        throw InputError(
          "rectangle lattice compliance: the period of " + std::to_string(nx) + " x " +
          std::to_string(ny) + " rectangles is too short for offsets up to " + std::to_string(mx) +
          " x " + std::to_string(my) + "; allowed: at least 2 m + 1 rectangles in each direction");
      if (!(a > 0.) || !(b > 0.) || harmonics == 0)
        throw InputError("rectangle lattice compliance: rectangle " + format_short(a) + " x " +
                         format_short(b) + " m, " + std::to_string(harmonics) +
                         " harmonics; allowed: positive sizes, at least one harmonic");
      const double       px = nx * a, py = ny * b;
      const unsigned int jx_max = harmonics * nx, jy_max = harmonics * ny;
      // sinc^2 of each wavenumber along each direction: sin(pi j / n)^2 / (pi j / n)^2.
      const auto sinc2 = [](const unsigned int j, const unsigned int n) {
        if (j == 0)
          return 1.;
        const double t = M_PI * j / n;
        return std::pow(std::sin(t) / t, 2);
      };
      std::vector<double> sx(jx_max + 1), sy(jy_max + 1);
      for (unsigned int j = 0; j <= jx_max; ++j)
        sx[j] = sinc2(j, nx);
      for (unsigned int j = 0; j <= jy_max; ++j)
        sy[j] = sinc2(j, ny);
      // The series folded onto one period of wavenumbers (cos(2 pi j m / n)
      // depends on j mod n only), the four quadrants at once.
      Eigen::MatrixXd F = Eigen::MatrixXd::Zero(nx, ny);
      for (unsigned int jx = 0; jx <= jx_max; ++jx)
        {
          const double kx = 2. * M_PI * jx / px;
          const double wx = jx > 0 ? 2. : 1.;
          if (sx[jx] == 0.)
            continue;
          for (unsigned int jy = 0; jy <= jy_max; ++jy)
            {
              if (jx == 0 && jy == 0)
                {
                  const double c = compliance(0.);
                  if (std::isfinite(c))
                    F(0, 0) += c;
                  continue;
                }
              if (sy[jy] == 0.)
                continue;
              const double ky = 2. * M_PI * jy / py;
              F(jx % nx, jy % ny) +=
                wx * (jy > 0 ? 2. : 1.) * compliance(std::hypot(kx, ky)) * sx[jx] * sy[jy];
            }
        }
      Eigen::MatrixXd cx(nx, mx + 1), cy(ny, my + 1);
      for (unsigned int i = 0; i < nx; ++i)
        for (unsigned int m = 0; m <= mx; ++m)
          cx(i, m) = std::cos(2. * M_PI * ((static_cast<unsigned long>(i) * m) % nx) / nx);
      for (unsigned int i = 0; i < ny; ++i)
        for (unsigned int n = 0; n <= my; ++n)
          cy(i, n) = std::cos(2. * M_PI * ((static_cast<unsigned long>(i) * n) % ny) / ny);
      return cx.transpose() * F * cy / (px * py);
    }



    Eigen::MatrixXd
    layer_lattice_kernel(const ElasticLayer &layer,
                         const double        a,
                         const double        b,
                         const unsigned int  nx,
                         const unsigned int  ny,
                         const double        margin)
    {
      const LayerComplianceTable table(layer);
      const unsigned int         px =
        std::max(2 * nx, nx + 2 * static_cast<unsigned int>(std::ceil(margin / a)));
      const unsigned int py =
        std::max(2 * ny, ny + 2 * static_cast<unsigned int>(std::ceil(margin / b)));
      return rectangle_lattice_compliance(
        [&](const double k) {
          return table(k);
        },
        a, b, nx - 1, ny - 1, px, py);
    }



    Eigen::MatrixXd
    layer_patch_compliance(const ElasticLayer &layer,
                           const double        a,
                           const double        b,
                           const unsigned int  nx,
                           const unsigned int  ny,
                           const double        margin)
    {
      const Eigen::MatrixXd T = layer_lattice_kernel(layer, a, b, nx, ny, margin);
      const unsigned int    n = nx * ny;
      Eigen::MatrixXd       L(n, n);
      for (unsigned int p = 0; p < n; ++p)
        for (unsigned int q = 0; q < n; ++q)
          {
            const int dx = static_cast<int>(p / ny) - static_cast<int>(q / ny);
            const int dy = static_cast<int>(p % ny) - static_cast<int>(q % ny);
            L(p, q)      = T(std::abs(dx), std::abs(dy));
          }
      return L;
    }
  } // namespace contact
} // namespace greentread

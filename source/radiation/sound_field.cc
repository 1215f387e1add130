#include <greentread/base/exceptions.h>
#include <greentread/radiation/sound_field.h>

#include <deal.II/base/numbers.h>
#include <deal.II/base/quadrature_lib.h>

#include <algorithm>
#include <cmath>

namespace greentread
{
  namespace radiation
  {
    std::vector<Microphone>
    cpx_microphones(const TyreSurface &surface)
    {
      const double y = surface.axial_max + 0.2;
      return {{"front", dealii::Point<3>(0.2, y, 0.1)}, {"rear", dealii::Point<3>(-0.2, y, 0.1)}};
    }



    Hemisphere
    hemisphere(const double radius, const unsigned int n_polar, const unsigned int n_azimuth)
    {
      if (!(radius > 0.) || n_polar == 0 || n_azimuth == 0)
        throw InputError("far-field hemisphere of radius " + format_number(radius) + " m, " +
                         std::to_string(n_polar) + " x " + std::to_string(n_azimuth) +
                         " points; allowed: a radius > 0 and at least one point each way");
      const dealii::QGauss<1> gauss(n_polar); // cos(polar angle) on (0, 1)
      const double            step = 2. * dealii::numbers::PI / n_azimuth;
      Hemisphere              h;
      for (unsigned int i = 0; i < n_polar; ++i)
        {
          const double mu = gauss.point(i)[0], sine = std::sqrt(1. - mu * mu);
          for (unsigned int j = 0; j < n_azimuth; ++j)
            {
              const double phi = (j + 0.5) * step;
              h.points.emplace_back(radius * sine * std::cos(phi), radius * sine * std::sin(phi),
                                    radius * mu);
              h.area.push_back(radius * radius * gauss.weight(i) * step);
            }
        }
      return h;
    }



    Hemisphere
    far_field_for(const Air &air, const double frequency, const double size)
    {
      const double k       = 2. * dealii::numbers::PI * frequency / air.sound_speed;
      const auto   n_polar = static_cast<unsigned int>(std::ceil(k * size)) + 6;
      return hemisphere(50., n_polar, 2 * n_polar);
    }



    BandTransfer
    band_transfer(HelmholtzBem                        &bem,
                  const TyreSurface                   &surface,
                  const Air                           &air,
                  const double                         frequency,
                  const std::vector<dealii::Point<3>> &microphones)
    {
      bem.assemble(air, frequency, surface.interior_points);
      BandTransfer t;
      t.frequency   = frequency;
      t.microphones = bem.field_transfer(microphones);
      const double size =
        std::hypot(surface.axle_height + surface.outer_radius,
                   std::max(std::abs(surface.axial_min), std::abs(surface.axial_max)));
      const Hemisphere far = far_field_for(air, frequency, size);
      t.power              = bem.field_transfer(far.points);
      for (std::size_t f = 0; f < far.area.size(); ++f)
        t.power.row(static_cast<Eigen::Index>(f)) *=
          std::sqrt(far.area[f] / (air.density * air.sound_speed));
      return t;
    }



    std::vector<analysis::BandSpectrum>
    sound_spectra(const std::vector<std::vector<double>> &forces,
                  const double                            dt,
                  const SurfaceMobility                  &mobility,
                  const std::vector<BandTransfer>        &transfers,
                  const double                            f_low,
                  const double                            f_high,
                  const unsigned int                      lines_per_segment)
    {
      const auto bands = analysis::third_octave_bands(f_low, f_high);
      if (transfers.size() != bands.size())
        throw NumericalError("sound spectra: " + std::to_string(transfers.size()) +
                             " band transfers for " + std::to_string(bands.size()) + " bands");
      if (forces.size() != mobility.n_points())
        throw NumericalError("sound spectra: forces at " + std::to_string(forces.size()) +
                             " points, the surface mobility has " +
                             std::to_string(mobility.n_points()));
      const Eigen::Index  n_microphones = transfers.front().microphones.rows();
      std::vector<double> references(n_microphones, pressure_reference);
      references.push_back(power_reference);
      references.push_back(power_reference);
      return analysis::welch_band_spectra(
        forces, dt, references, f_low, f_high, lines_per_segment,
        [&](const double frequency, const std::size_t band, const Eigen::MatrixXcd &coefficients,
            Eigen::MatrixXd &powers) {
          const Eigen::MatrixXcd v =
            mobility.velocity(2. * dealii::numbers::PI * frequency, coefficients);
          const BandTransfer &t         = transfers[band];
          powers.topRows(n_microphones) = (t.microphones * v).cwiseAbs2();
          powers.row(n_microphones)     = (t.power * v).cwiseAbs2().colwise().sum();
          // What the forces put in: Re F^H v at the points.
          const Eigen::MatrixXcd at_points =
            mobility.point_velocity(2. * dealii::numbers::PI * frequency, coefficients);
          powers.row(n_microphones + 1) =
            (coefficients.conjugate().cwiseProduct(at_points)).colwise().sum().real();
        });
    }
  } // namespace radiation
} // namespace greentread

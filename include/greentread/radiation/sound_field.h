#pragma once

#include <greentread/analysis/third_octave.h>
#include <greentread/radiation/helmholtz_bem.h>
#include <greentread/radiation/surface_mobility.h>
#include <greentread/radiation/tyre_surface.h>

#include <deal.II/base/point.h>

#include <Eigen/Dense>

#include <string>
#include <vector>

/**
 * @file
 * Where the sound is heard: microphones beside the tyre, the far field on a
 * hemisphere over the road for the sound power, the transfers from the
 * tyre's surface velocity to both at one frequency, and the one-third-octave
 * sound spectra of a rolling run from its contact forces.
 */
namespace greentread
{
  namespace radiation
  {
    /// A named listening point [m], in the tyre surface's coordinates.
    struct Microphone
    {
      std::string      name;
      dealii::Point<3> position;
    };

    /**
     * @brief The close-proximity microphones of ISO 11819-2 beside
     * @p surface: 0.1 m above the road, 0.2 m out from the tyre's side plane
     * (y = axial_max + 0.2 m), 0.2 m ahead of the axle ("front", x > 0, the
     * rolling direction) and 0.2 m behind it ("rear").
     */
    std::vector<Microphone>
    cpx_microphones(const TyreSurface &surface);

    /**
     * @brief Points on the hemisphere of @p radius [m] about the patch centre
     * over the road, and their areas [m^2], for the radiated power
     * W = sum_f area_f |p_f|^2 / (2 rho c) in the far field: Gauss-Legendre
     * in cos(polar angle) over (0, 1] and equal steps in the azimuth.
     */
    struct Hemisphere
    {
      std::vector<dealii::Point<3>> points;
      std::vector<double>           area;
    };

    /**
     * @param[in] radius    [m], far from the tyre (kr >> 1 at the lowest
     *                      frequency: the intensity is |p|^2 / (rho c) there
     *                      to 1 / (kr)^2).
     * @param[in] n_polar   Gauss points in cos(polar angle).
     * @param[in] n_azimuth Steps round the vertical.
     */
    Hemisphere
    hemisphere(double radius, unsigned int n_polar, unsigned int n_azimuth);

    /**
     * @brief The hemisphere that resolves the far field of a body of
     * @p size [m] (its largest distance from the patch centre) at
     * @p frequency: its directivity's lobes are about 1 / (k size) wide, so
     * k size + 6 Gauss points in cos(polar angle) and twice as many
     * azimuths, at 50 m.
     */
    Hemisphere
    far_field_for(const Air &air, double frequency, double size);

    /// The transfers of one band from the cells' normal velocities [m/s].
    struct BandTransfer
    {
      /// The frequency [Hz] they were computed at (the band's centre).
      double frequency = 0.;
      /// Pressure at each microphone [Pa s/m], microphones by cells.
      Eigen::MatrixXcd microphones;
      /// Pressure on the far hemisphere, its points by cells, each row
      /// scaled by sqrt(area / (rho c)), so that the band's mean power is
      /// the mean square of these pressures summed.
      Eigen::MatrixXcd power;
    };

    /**
     * @brief The transfers at @p frequency on @p bem (its surface that of
     * @p surface), with @p surface's CHIEF points.
     */
    BandTransfer
    band_transfer(HelmholtzBem                        &bem,
                  const TyreSurface                   &surface,
                  const Air                           &air,
                  double                               frequency,
                  const std::vector<dealii::Point<3>> &microphones);

    /**
     * @brief The one-third-octave spectra of the sound of a run: the
     * pressure at each microphone, the radiated power, and last the power
     * the forces put into the tyre (a lower bound of it:
     * SurfaceMobility::point_velocity()), by Welch's
     * method (analysis::welch_band_spectra()) over the contact forces
     * @p forces at the points of @p mobility (one signal per point, [N],
     * @p dt apart). At each Fourier line of band b, the cells' velocity
     * Y(w) F and the transfers[b] of that band give the microphones'
     * pressures and the far field's, and the points' velocity the forces'
     * power. A power's "rms" is sqrt(W) [sqrt(W)],
     * so that its level against 1e-6 is 10 log10(W / 1e-12 W).
     * @param[in] transfers One per band of analysis::third_octave_bands(
     *                      @p f_low, @p f_high), in order.
     */
    std::vector<analysis::BandSpectrum>
    sound_spectra(const std::vector<std::vector<double>> &forces,
                  double                                  dt,
                  const SurfaceMobility                  &mobility,
                  const std::vector<BandTransfer>        &transfers,
                  double                                  f_low,
                  double                                  f_high,
                  unsigned int                            lines_per_segment);

    /// The reference of sound pressure levels [Pa], and of power levels'
    /// "rms" [sqrt(W)], 20 log10(sqrt(W) / 1e-6) = 10 log10(W / 1e-12).
    constexpr double pressure_reference = 2e-5;
    constexpr double power_reference    = 1e-6;
  } // namespace radiation
} // namespace greentread

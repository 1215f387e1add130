// The sound of the tyre (radiation/sound_field.h) on the coarse tyre: the
// power on the far hemisphere against the power through the tyre's surface
// (the same energy by two integrals), and the band levels of a run's sound
// from its contact forces against a second route, the pressure's time
// history synthesised from the same transfers and its own Welch spectrum.
#include "bounds.h"
#include "radiating_tyre.h"
#include <greentread/analysis/third_octave.h>
#include <greentread/fe/harmonic_section.h>
#include <greentread/radiation/helmholtz_bem.h>
#include <greentread/radiation/sound_field.h>
#include <greentread/radiation/surface_mobility.h>
#include <greentread/radiation/tyre_surface.h>

#include <deal.II/base/multithread_info.h>
#include <deal.II/fe/mapping_q1.h>

#include <Eigen/SparseLU>

#include <boost/test/unit_test.hpp>

#include <array>
#include <cmath>
#include <complex>
#include <cstring>

using namespace greentread;

namespace
{
  using Complex = std::complex<double>;

  /// The radiating tyre and its boundary elements over the road.
  struct Tyre : test::RadiatingTyre
  {
    const dealii::MappingQ1<2, 3> mapping;
    radiation::HelmholtzBem       bem;
    radiation::Air                air;

    Tyre()
        : bem(surface.mesh, mapping, surface.outward)
    {
      air.ground = true;
    }
  };
} // namespace

BOOST_AUTO_TEST_SUITE(sound_field)

// Energy: what flows through the tyre's surface, 1/2 Re int p v*, flows
// through the far hemisphere, int |p|^2 / (2 rho c); the road carries none.
// Two smooth velocities: the body breathing and moving along the axle. The
// hemisphere's quadrature is converged (26 more Gauss points each way move
// neither figure); what is left is the boundary elements' own error, the
// two integrals weighing it differently, and it falls as the cells shrink.
BOOST_AUTO_TEST_CASE(far_field_power_is_the_surface_power)
{
  Tyre                  t;
  std::array<double, 2> difference{}, at_800{};
  for (const std::size_t level : {0u, 1u})
    {
      const radiation::TyreSurface surface(radiation::outer_contour(t.tyre.cell->section()),
                                           0.04 / std::pow(std::sqrt(2.), level), 0.01);
      radiation::HelmholtzBem      bem(surface.mesh, t.mapping, surface.outward);
      // The body breathing, and moving along the axle.
      Eigen::MatrixXcd v(bem.n_cells(), 2);
      for (unsigned int i = 0; i < bem.n_cells(); ++i)
        {
          v(i, 0) = 1e-3;
          v(i, 1) = 1e-3 * bem.normal(i)[1];
        }
      for (const double f : {200., 800.})
        {
          const auto transfer =
            radiation::band_transfer(bem, surface, t.air, f, {dealii::Point<3>(0.3, 0.3, 0.1)});
          const Eigen::VectorXd through = bem.sound_power(bem.surface_pressure(v), v);
          const Eigen::VectorXd far =
            0.5 * (transfer.power * v).cwiseAbs2().colwise().sum().transpose();
          const double d = (far.cwiseQuotient(through).array() - 1.).abs().maxCoeff();
          BOOST_TEST_MESSAGE(f << " Hz: " << bem.n_cells() << " cells, " << transfer.power.rows()
                               << " far points, surface power " << through.transpose()
                               << " W, relative difference " << d);
          difference[level] = std::max(difference[level], d);
          if (f == 800.)
            at_800[level] = d;
        }
    }
  // Measured 0.0062 and 0.0044 on 4 cm cells, 0.0052 and 0.0024 on 2.8 cm
  // ones: at 800 Hz it falls as the square of the cell size (0.55), at
  // 200 Hz more slowly.
  CHECK_BOUND(difference[1], 0.015);
  CHECK_BOUND(at_800[1] / at_800[0], 0.75);
}

// A tone of force at the patch centre: the microphones' band levels and the
// power level through sound_spectra() (the velocity at each Fourier line,
// Y(w) F, then the band's transfers) against the pressure's history at
// each microphone synthesised at the tone's frequency, p(t) = Re(T Y(w0)
// F e^{j w0 t}), and its own Welch spectrum; the power against the same
// synthesis on the far hemisphere, W = 1/2 sum |T_f Y F|^2 in the band; the
// power the forces put in against 1/2 A^2 Re Y_qq(w0) by direct solves of
// D_n(w0). Energy: the radiated power is below it in every band. The
// routes differ in Y's change across the window's main lobe, two lines
// each side of the tone: 5.6 % of its frequency with 8 lines in a band's
// segment, 0.7 % with 64, near the tyre's resonances.
BOOST_AUTO_TEST_CASE(a_force_tone_gives_the_sound_of_its_transfer)
{
  Tyre                             t;
  const unsigned int               N = 12;
  const radiation::SurfaceMobility mobility(t.section, t.tyre.patch, t.surface, 2. * M_PI * 3000.,
                                            N);
  const auto                       bands       = analysis::third_octave_bands(400., 500.);
  const auto                       microphones = radiation::cpx_microphones(t.surface);
  std::vector<dealii::Point<3>>    positions;
  for (const auto &m : microphones)
    positions.push_back(m.position);
  std::vector<radiation::BandTransfer> transfers;
  for (const auto &band : bands)
    transfers.push_back(radiation::band_transfer(t.bem, t.surface, t.air, band.centre, positions));

  // 10 N at the 500 Hz band's centre on the middle point, 1.2 s at 25.6 kHz.
  const double      dt = 1. / 25600., f0 = bands[1].centre, w0 = 2. * M_PI * f0, A = 10.;
  const std::size_t n_samples = 30720, P = mobility.n_points(), centre = P / 2;
  std::vector<std::vector<double>> forces(P, std::vector<double>(n_samples, 0.));
  for (std::size_t n = 0; n < n_samples; ++n)
    forces[centre][n] = A * std::cos(w0 * n * dt);
  Eigen::MatrixXcd F       = Eigen::MatrixXcd::Zero(P, 1);
  F(centre, 0)             = A;
  const Eigen::MatrixXcd v = mobility.velocity(w0, F);
  // The power the tone puts in, 1/2 A^2 Re Y_qq(w0), with Y_qq by direct
  // solves of each harmonic's D_n(w0) on the point's strip and its box.
  const std::size_t strip = centre % t.tyre.patch.points_across;
  const double      y = t.tyre.patch.points[strip].y, dy = t.tyre.patch.dy;
  const auto [w, W]  = t.section.tread_strip(y - 0.5 * dy, y + 0.5 * dy);
  const auto parts   = t.section.dynamic_stiffness(w0);
  Complex    driving = 0.;
  for (unsigned int n = 0; n < N; ++n)
    {
      const Eigen::SparseMatrix<Complex> D =
        parts[0] + double(n) * parts[1] + double(n * n) * parts[2];
      Eigen::SparseLU<Eigen::SparseMatrix<Complex>> lu(D);
      const Eigen::VectorXcd                        x   = lu.solve((w / W).cast<Complex>());
      const double                                  arc = t.tyre.patch.arc;
      const double box = n == 0 ? 1. : std::pow(std::sin(0.5 * n * arc) / (0.5 * n * arc), 2);
      driving += (n == 0 ? 1. : 2.) / (2. * M_PI) * box * ((w / W).cast<Complex>().dot(x));
    }
  const double input_level =
    10. * std::log10(0.5 * A * A * (Complex(0., w0) * driving).real() / 1e-12);

  // The routes' difference with 8 and 64 lines in a band's segment.
  std::array<double, 2> worst{};
  for (const std::size_t k : {0u, 1u})
    {
      const unsigned int lines = k == 0 ? 8 : 64;
      const auto         spectra =
        radiation::sound_spectra(forces, dt, mobility, transfers, 400., 500., lines);
      BOOST_TEST_REQUIRE(spectra.size() == microphones.size() + 2);
      for (std::size_t m = 0; m < microphones.size(); ++m)
        {
          const Complex       p = (transfers[1].microphones.row(m) * v)(0, 0);
          std::vector<double> history(n_samples);
          for (std::size_t n = 0; n < n_samples; ++n)
            history[n] = (p * std::polar(1., w0 * n * dt)).real();
          const auto reference = analysis::welch_band_spectrum(
            history, dt, radiation::pressure_reference, 400., 500., lines);
          BOOST_TEST_MESSAGE(lines << " lines, " << microphones[m].name << ": "
                                   << spectra[m].level[1] << " dB against " << reference.level[1]
                                   << " dB");
          worst[k] = std::max(worst[k], std::abs(spectra[m].level[1] - reference.level[1]));
          BOOST_TEST(spectra[m].level[0] < spectra[m].level[1] - 20.);
        }
      // The power's synthesis: a tone's mean power, which the window
      // keeps whole in its band to 1.2 % (unit/third_octave).
      const double power_level =
        10. * std::log10(0.5 * (transfers[1].power * v).cwiseAbs2().sum() / 1e-12);
      const auto &radiated = spectra[microphones.size()], &input = spectra.back();
      BOOST_TEST_MESSAGE(lines << " lines, power: " << radiated.level[1] << " dB against "
                               << power_level << " dB; put in " << input.level[1] << " dB against "
                               << input_level << " dB");
      if (k == 1)
        worst[k] = std::max({worst[k], std::abs(radiated.level[1] - power_level),
                             std::abs(input.level[1] - input_level)});
      // Energy: the air takes less than the forces put in, in every band.
      for (std::size_t b = 0; b < bands.size(); ++b)
        BOOST_TEST(radiated.rms[b] < input.rms[b]);
    }
  // Measured 0.014 dB and 0.028: the difference falls as the square of the
  // lobe's width (1/64).
  CHECK_BOUND(worst[1], 0.04);
  CHECK_BOUND(worst[1] / worst[0], 0.075);
}

// The surface mobility (its harmonics on the threads) and the sound spectra
// of a record of forces, on one thread and on two: the same bytes.
BOOST_AUTO_TEST_CASE(the_same_bytes_with_any_thread_count)
{
  Tyre                                 t;
  const auto                           bands = analysis::third_octave_bands(400., 400.);
  std::vector<radiation::BandTransfer> transfers{radiation::band_transfer(
    t.bem, t.surface, t.air, bands[0].centre, {radiation::cpx_microphones(t.surface)[0].position})};
  std::vector<std::vector<double>>     forces(9, std::vector<double>(6400));
  for (std::size_t q = 0; q < forces.size(); ++q)
    for (std::size_t n = 0; n < forces[q].size(); ++n)
      forces[q][n] = std::sin(0.37 * n * (q + 1)) + std::cos(0.011 * n * n + q);
  const auto run = [&](const unsigned int threads) {
    dealii::MultithreadInfo::set_thread_limit(threads);
    const radiation::SurfaceMobility mobility(t.section, t.tyre.patch, t.surface, 2. * M_PI * 3000.,
                                              12);
    const auto                       spectra =
      radiation::sound_spectra(forces, 1. / 25600., mobility, transfers, 400., 400., 8);
    std::vector<double>    out{spectra[0].rms[0], spectra[1].rms[0]};
    const Eigen::MatrixXcd y = mobility.at(2. * M_PI * 400.);
    for (Eigen::Index i = 0; i < y.size(); ++i)
      out.push_back(std::abs(y(i)));
    return out;
  };
  const auto one = run(1), two = run(2);
  dealii::MultithreadInfo::set_thread_limit();
  BOOST_TEST_REQUIRE(one.size() == two.size());
  BOOST_TEST(std::memcmp(one.data(), two.data(), sizeof(double) * one.size()) == 0);
}

BOOST_AUTO_TEST_SUITE_END()

// A tread pattern in the contact (contact/tread_pattern.h), rolled on a
// contact grid over a synthetic modal model: a uniform pitch on a flat road
// gives force lines at exactly k V / p and nothing between them; a pitch
// sequence gives the tonal lines that the phasor sum of its grooves'
// positions (Willett 1975), computed here independently, predicts from the
// response to one groove; a groove carries no force at any step, at any
// time step.
#include "bounds.h"
#include "contact_grid_fixture.h"
#include "scratch.h"

#include <greentread/contact/contact_grid.h>
#include <greentread/contact/rolling.h>
#include <greentread/contact/tread_pattern.h>
#include <greentread/road/patch_road.h>
#include <greentread/road/texture.h>
#include <greentread/synthesis/mode_synthesis.h>

#include <boost/test/unit_test.hpp>

#include <cmath>
#include <complex>
#include <fstream>
#include <functional>
#include <numeric>
#include <vector>

using namespace greentread;

namespace
{
  constexpr double speed = 20.; // m/s

  /// A synthetic modal model on 8 x 6 coarse cells (48 x 40 mm), split 3 x 3.
  struct Patch
  {
    Patch()
        : coarse(test::coarse_points(8, 6, false))
        , model(synthesis::to_patch_model(test::synthetic_modes(coarse),
                                          Eigen::MatrixXd::Zero(coarse.size(), coarse.size()),
                                          4000.))
        , grid(coarse, 3, test::tread_layer, true, true)
        , tread(contact::tread_heights(grid.points))
        , G0(model.static_compliance())
    {
    }
    std::vector<std::array<double, 3>> coarse;
    modal::PatchModel                  model;
    contact::ContactGrid               grid;
    Eigen::VectorXd                    tread;
    Eigen::MatrixXd                    G0;
  };

  const Patch &
  patch()
  {
    static const Patch p;
    return p;
  }

  contact::TreadPatternParameters
  blocks(const std::vector<double> &lengths, const std::vector<unsigned int> &sequence)
  {
    contact::TreadPatternParameters p;
    p.pattern              = "blocks";
    p.pitch_lengths        = lengths;
    p.sequence             = sequence;
    p.groove_depth         = 0.008;
    p.lateral_groove_width = 0.006;
    return p;
  }

  /// Roll the patch with @p pattern over @p road (or a flat road) at 20 m/s
  /// under 300 N for @p steps of @p dt from the static start; @p observe
  /// sees each step.
  void
  roll(const contact::TreadPattern                             &pattern,
       const road::PatchRoad                                   *road,
       const double                                             dt,
       const unsigned int                                       steps,
       const std::function<void(const contact::RollingStep &)> &observe,
       Eigen::VectorXd                                         *start_force = nullptr)
  {
    const Patch                    &p       = patch();
    const contact::PatchRoadHeights heights = [&](const double s, Eigen::VectorXd &z,
                                                  Eigen::VectorXd &slope) {
      if (road != nullptr)
        road->heights(s, z, slope);
      else
        {
          z.setZero(p.grid.n_points());
          slope.setZero(p.grid.n_points());
        }
      pattern.recess(p.grid.points, s, z);
    };
    contact::RollingSetup setup;
    setup.speed       = speed;
    setup.time_step   = dt;
    setup.n_steps     = steps;
    setup.static_load = 300.;
    const auto start  = contact::start_grid_contact(p.grid, p.G0, p.tread, heights, setup);
    if (start_force != nullptr)
      *start_force = start.q;
    auto convolution = contact::make_grid_convolution(
      contact::make_patch_convolution(setup.convolution, p.model, dt, steps, 0, 1), p.grid);
    const auto summary = contact::roll_patch(*convolution, p.tread, heights, start, setup, observe);
    BOOST_TEST(summary.failed_steps == 0u);
  }

  /// The total force's Fourier coefficients (magnitudes) over the last
  /// @p record steps of @p total.
  std::vector<double>
  lines(const std::vector<double> &total, const std::size_t record)
  {
    const std::size_t   first = total.size() - record;
    double              mean  = 0.;
    std::vector<double> a(record / 2 + 1, 0.);
    for (std::size_t n = first; n < total.size(); ++n)
      mean += total[n] / double(record);
    for (std::size_t m = 1; m < a.size(); ++m)
      {
        std::complex<double> c = 0.;
        for (std::size_t n = 0; n < record; ++n)
          c += (total[first + n] - mean) *
               std::polar(1., -2. * M_PI * double(m) * double(n) / double(record));
        a[m] = std::abs(c) / double(record);
      }
    return a;
  }

  /// The total force of each step of a roll on a flat road.
  std::vector<double>
  total_force(const contact::TreadPattern &pattern, const double dt, const unsigned int steps)
  {
    std::vector<double> total;
    roll(pattern, nullptr, dt, steps, [&](const contact::RollingStep &s) {
      total.push_back(s.force.sum());
    });
    return total;
  }
} // namespace

BOOST_AUTO_TEST_SUITE(tread_pattern)

BOOST_AUTO_TEST_CASE(pitches_fill_the_circumference)
{
  // Three lengths in a sequence of 7: scaled by one factor so that whole
  // sequences fill 2 pi r exactly, the grooves where the pitches start.
  const contact::TreadPattern pattern(blocks({0.025, 0.03, 0.035}, {1, 2, 3, 2, 1, 3, 3}), 0.27);
  const double                C = 2. * M_PI * 0.27;
  const auto                 &p = pattern.pitches();
  BOOST_TEST(std::accumulate(p.begin(), p.end(), 0.) == C, boost::test_tools::tolerance(1e-12));
  BOOST_TEST(p.size() % 7 == 0u);
  BOOST_TEST(p[1] / p[0] == 0.03 / 0.025, boost::test_tools::tolerance(1e-12));
  BOOST_TEST(pattern.in_groove(pattern.pitch_starts()[5] + 0.005, 0.));
  BOOST_TEST(!pattern.in_groove(pattern.pitch_starts()[5] + 0.007, 0.));
  BOOST_TEST(pattern.in_groove(C + 0.001, 0.)); // round the tyre
  BOOST_TEST(pattern.in_groove(-0.001 + pattern.pitch_starts()[1], 0.) == false);
}

BOOST_AUTO_TEST_CASE(a_footprint_image_is_the_same_pattern)
{
  // One pitch's footprint drawn as a PGM image, 120 mm across in 60
  // columns and 50 rows along: a lateral groove in the first 10 rows (a
  // fifth of the pitch, 6 mm of 30) and a circumferential groove over
  // columns 32 to 35 (4 to 12 mm), written in both PGM forms (P2 text,
  // P5 bytes); against the same pattern from the parameters, at points
  // away from the edges (half a pixel or more).
  const auto dir = test::scratch_directory("tread_pattern");
  for (const std::string magic : {"P2", "P5"})
    BOOST_TEST_CONTEXT(magic)
    {
      const std::string file = (dir / (magic + ".pgm")).string();
      {
        std::ofstream out(file, std::ios::binary);
        out << magic << "\n# one pitch\n60 50\n255\n";
        for (int r = 0; r < 50; ++r)
          for (int c = 0; c < 60; ++c)
            {
              const bool groove = r < 10 || (c >= 32 && c < 36);
              if (magic == "P2")
                out << (groove ? 0 : 255) << (c == 59 ? '\n' : ' ');
              else
                out.put(char(groove ? 0 : 255));
            }
      }
      contact::TreadPatternParameters image = blocks({0.03}, {});
      image.pattern                         = "image";
      image.footprint_image                 = file;
      image.footprint_width                 = 0.12;
      contact::TreadPatternParameters drawn = blocks({0.03}, {});
      drawn.lateral_groove_width            = 0.006;
      drawn.circumferential_centres         = {0.008};
      drawn.circumferential_width           = 0.008;
      const contact::TreadPattern a(image, 0.27), b(drawn, 0.27);
      const double                scale  = a.scale(); // the pitch's stretch
      unsigned int                differ = 0, grooves = 0;
      for (double sigma = 0.0003; sigma < 0.3; sigma += 0.0006)
        for (double y = -0.059; y < 0.06; y += 0.002)
          {
            const double along = std::fmod(sigma, a.pitches()[0]);
            if (std::abs(along - 0.006 * scale) < 0.0003 ||
                std::abs(std::abs(y - 0.008) - 0.004) < 0.001)
              continue; // on an edge: the image's pixels decide
            differ += a.in_groove(sigma, y) != b.in_groove(sigma, y);
            grooves += a.in_groove(sigma, y);
          }
      BOOST_TEST(grooves > 0u);
      BOOST_TEST(differ == 0u);
    }
}

BOOST_AUTO_TEST_CASE(uniform_pitch_gives_lines_at_V_over_p)
{
  // A uniform pitch p on a flat road: the force is periodic with p / V, so
  // its lines lie at exactly k V / p. The step divides p / V into 32; over
  // the last 64 periods (after 0.3 s, 15 decay times of the slowest mode)
  // all but a small part of the force's variance lies on the harmonics:
  // measured 7.3e-12 (the slowest mode's transient, e^-15, and the
  // solver's tolerance), bound 2e-11.
  const contact::TreadPattern pattern(blocks({0.03}, {}), 0.27);
  const double                p      = pattern.pitches()[0];
  const double                dt     = p / speed / 32.;
  const unsigned int          record = 64 * 32;
  const unsigned int steps     = record + static_cast<unsigned int>(std::ceil(0.3 / dt / 32.)) * 32;
  const std::vector<double> a  = lines(total_force(pattern, dt, steps), record);
  double                    on = 0., off = 0.;
  std::size_t               peak = 1;
  for (std::size_t m = 1; m < a.size(); ++m)
    {
      (m % 64 == 0 ? on : off) += a[m] * a[m];
      if (a[m] > a[peak])
        peak = m;
    }
  BOOST_TEST_MESSAGE("uniform pitch " << 1e3 * p << " mm: the largest line at "
                                      << peak / (record * dt) << " Hz, V / p = " << speed / p
                                      << " Hz; the variance off the harmonics " << off / on);
  BOOST_TEST(peak % 64 == 0u);
  BOOST_TEST(on > 0.);
  CHECK_BOUND(off / on, 2e-11);
}

BOOST_AUTO_TEST_CASE(pitch_sequence_against_the_phasor_sum)
{
  // Willett's phasor sum: if each lateral groove makes the same force as it
  // passes, the force over one revolution of circumference C is
  // H(f) sum_k exp(-2 pi i m s_k / C) at the lines f = m V / C, s_k the
  // grooves' positions. H is measured here by the tyre with one groove
  // round it (its lines are H itself), the sum computed from the positions;
  // both against the sequence rolled. The step divides one revolution into
  // 2048; the record is one revolution after 0.3 s. Measured: 60 pitches,
  // the peak lowered by 3.17 dB against the sum's 3.07 (bound 0.3 dB), the
  // lines from half to 1.5 times the mean pitch's within 2.1% r.m.s. of the
  // prediction (bound 6%): the grooves' forces add almost linearly.
  const contact::TreadPattern one(blocks({1.69}, {}), 0.27);
  const contact::TreadPattern sequence(
    blocks({0.025, 0.03, 0.035}, {1, 2, 3, 2, 1, 3, 3, 2, 1, 1, 2, 3, 3, 2, 1}), 0.27);
  const double       C      = sequence.circumference();
  const unsigned int record = 2048;
  const double       dt     = C / speed / record;
  const unsigned int steps = record * (1 + static_cast<unsigned int>(std::ceil(0.3 / (C / speed))));
  const std::vector<double> h = lines(total_force(one, dt, steps), record);
  const std::vector<double> f = lines(total_force(sequence, dt, steps), record);
  const auto               &s = sequence.pitch_starts();
  const double              n = double(s.size());
  // The lines around the mean pitch's: m from n / 2 to 3 n / 2.
  double      predicted_peak = 0., rolled_peak = 0., error = 0., energy = 0.;
  std::size_t m_peak = 0;
  for (std::size_t m = std::size_t(n / 2); m <= std::size_t(1.5 * n); ++m)
    {
      std::complex<double> sum = 0.;
      for (const double x : s)
        sum += std::polar(1., -2. * M_PI * double(m) * x / C);
      const double predicted = h[m] * std::abs(sum);
      if (predicted > predicted_peak)
        predicted_peak = predicted;
      if (f[m] > rolled_peak)
        {
          rolled_peak = f[m];
          m_peak      = m;
        }
      error += (f[m] - predicted) * (f[m] - predicted);
      energy += f[m] * f[m];
    }
  // The uniform pitch of as many pitches: all its tone on line n, where the
  // sum is n.
  const double uniform   = h[std::size_t(n)] * n;
  const double lowering  = 20. * std::log10(rolled_peak / uniform);
  const double predicted = 20. * std::log10(predicted_peak / uniform);
  BOOST_TEST_MESSAGE(s.size() << " pitches: the largest tonal line " << m_peak * speed / C
                              << " Hz; lowered against the uniform pitch by " << lowering
                              << " dB, the phasor sum predicts " << predicted
                              << " dB; the lines' relative r.m.s. difference "
                              << std::sqrt(error / energy));
  CHECK_BOUND(std::abs(lowering - predicted), 0.3);
  CHECK_BOUND(std::sqrt(error / energy), 0.06);
}

BOOST_AUTO_TEST_CASE(a_groove_carries_no_force_at_any_step)
{
  // Lateral grooves 6 mm and a circumferential groove 8 mm wide (3 and 4
  // contact rectangles), 8 mm deep, on road-A at one road sample per step,
  // 20 samples and 1/20 of a sample: every point whose centre is in a
  // groove ends every step without force. The step's end force is taken
  // from its mean (2 mean - start), whose rounding grows over the steps:
  // measured up to 2.6e-15 of the largest force, bound 1e-14 of it; a force
  // the groove really carried would be of the order of the others.
  contact::TreadPatternParameters parameters = blocks({0.03}, {});
  parameters.circumferential_centres         = {0.004};
  parameters.circumferential_width           = 0.008;
  const contact::TreadPattern       pattern(parameters, 0.27);
  std::vector<road::WavelengthBand> bands;
  std::vector<double>               levels;
  road::texture_preset("road-A", bands, levels);
  const road::Texture   texture = road::synthetic_texture(bands, levels, 3.84e-4, 2048, 128, 11);
  const road::PatchRoad road_a(texture, patch().grid.points, road::RoadSampling::envelope, "test");
  for (const double samples : {1., 20., 0.05})
    BOOST_TEST_CONTEXT("dt = " << samples << " road samples")
    {
      const double       dt    = samples * texture.dx / speed;
      const unsigned int steps = samples < 1. ? 2000 : samples > 1. ? 60 : 400;
      Eigen::VectorXd    end;
      double             worst = 0., largest = 0.;
      unsigned int       in_grooves = 0;
      roll(
        pattern, &road_a, dt, steps,
        [&](const contact::RollingStep &s) {
          end = 2. * s.force - end; // the force is linear within a step
          for (unsigned int p = 0; p < patch().grid.n_points(); ++p)
            if (pattern.in_groove(speed * s.time + patch().grid.points[p][0],
                                  patch().grid.points[p][1]))
              {
                worst = std::max(worst, std::abs(end[p]));
                ++in_grooves;
              }
          largest = std::max(largest, end.maxCoeff());
        },
        &end);
      BOOST_TEST_MESSAGE("dt = " << samples << " samples: " << in_grooves
                                 << " point-steps in grooves, largest force there " << worst
                                 << " N, elsewhere up to " << largest << " N");
      BOOST_TEST(in_grooves > 0u);
      BOOST_TEST(largest > 0.);
      CHECK_BOUND(worst, 1e-14 * largest);
    }
}

BOOST_AUTO_TEST_SUITE_END()

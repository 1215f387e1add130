// Multi-point rolling contact on a real tyre's patch model: the one the test
// tyre_road_contact/coarse computes through the whole pipeline (a coarse 165/65 R13 tyre,
// 4 x 3 points, its Green's functions and their LSCE fit). test_patch_contact.cc
// checks the same code on a synthetic patch whose modes are known in closed
// form; here the matrices are a tyre's. Checked:
// - every LCP of a rolling run (the real instances) against Siconos' Lemke;
// - direct against modal-recursive convolution;
// - a flat road from the static equilibrium stays there;
// - the stiff and extreme cases stay sound.

#include "bounds.h"
#include "patch_rolling.h"
#include "siconos_reference.h"

#include <greentread/base/exceptions.h>
#include <greentread/contact/patch_contact.h>
#include <greentread/contact/rolling.h>
#include <greentread/modal/patch_model.h>
#include <greentread/road/texture.h>

#include <boost/test/unit_test.hpp>

#include <cmath>
#include <filesystem>
#include <string>
#include <vector>

using namespace greentread;

namespace
{
  /// The coarse tyre's patch model, road-A under it, and the tread's height.
  struct CoarseTyre
  {
    modal::PatchModel       model;
    Eigen::VectorXd         tread;
    road::Texture           texture;
    static constexpr double spacing = 3.84e-4;

    CoarseTyre()
    {
      const std::string file = GREENTREAD_COARSE_PATCH_MODEL;
      BOOST_TEST_REQUIRE(std::filesystem::exists(file),
                         file << " is missing: it is written by the test tyre_road_contact/coarse "
                                 "(ctest runs it first; alone: ctest -R tyre_road_contact/coarse)");
      model = modal::read_patch_model(file);
      tread = contact::tread_heights(model.points);
      std::vector<road::WavelengthBand> bands;
      std::vector<double>               levels;
      road::texture_preset("road-A", bands, levels);
      double y_min = 0., y_max = 0.;
      for (const auto &p : model.points)
        {
          y_min = std::min(y_min, p[1]);
          y_max = std::max(y_max, p[1]);
        }
      const unsigned int ny = 2 * static_cast<unsigned int>((y_max - y_min + 0.06) / spacing / 2);
      texture               = road::synthetic_texture(bands, levels, spacing, 1564, ny, 3);
    }

    /// Roll from the static equilibrium; @p observe sees every step.
    contact::RollingSummary
    roll(const test::RollingCase                                 &run,
         const std::function<void(const contact::RollingStep &)> &observe,
         Eigen::VectorXd                                         *start = nullptr) const
    {
      return test::roll_on_texture(model, tread, texture, run, observe, start);
    }
  };
} // namespace

BOOST_AUTO_TEST_SUITE(tyre_contact)

BOOST_AUTO_TEST_CASE(lcp_instances_of_the_rolling_tyre_match_siconos)
{
  // The LCPs the contact solve meets on a real tyre, at 90 km/h on road-A and
  // at 130 km/h on a road five times rougher (more points leave and regain
  // contact), every third step: the same z as Siconos' Lemke method.
  const CoarseTyre tyre;
  unsigned int     instances = 0, mixed = 0, iterations = 0;
  double           max_difference = 0.;
  for (const double roughness : {1., 5.})
    {
      test::RollingCase run;
      run.roughness      = roughness;
      run.speed_kmh      = roughness > 1. ? 130. : 90.;
      const auto observe = [&](const contact::RollingStep &s) {
        if (s.step % 3 != 0)
          return;
        BOOST_TEST_REQUIRE(s.report.lcp_matrix != nullptr);
        const Eigen::MatrixXd &M = *s.report.lcp_matrix;
        const auto             r = test::siconos_lemke(M, s.report.lcp_q);
        BOOST_TEST_REQUIRE(r.info == 0, "Siconos failed at step " << s.step);
        const double difference = test::relative_difference(s.report.lcp_z, r.z, M, s.report.lcp_q);
        // Measured 4e-16: round-off, which differs between machines.
        BOOST_TEST(difference <= 1e-14, "step " << s.step);
        for (Eigen::Index j = 0; j < r.z.size(); ++j)
          BOOST_TEST((s.report.lcp_z[j] > 0.) == (r.z[j] > 1e-12 * r.z.maxCoeff()),
                     "step " << s.step << ", point " << j);
        max_difference = std::max(max_difference, difference);
        iterations += r.iterations;
        ++instances;
        if (s.report.n_contact > 0 && s.report.n_contact < M.rows())
          ++mixed;
      };
      const auto summary = tyre.roll(run, observe);
      BOOST_TEST(summary.failed_steps == 0u);
    }
  BOOST_TEST_MESSAGE(instances << " LCPs of the rolling tyre (" << tyre.model.n_points()
                               << " points), " << mixed
                               << " with some points out of contact: max |z - z_siconos| "
                               << max_difference << " of the scale, Siconos' Lemke took "
                               << double(iterations) / instances << " pivots on average");
  BOOST_TEST(instances > 100u);
  BOOST_TEST(mixed > instances / 10); // not all trivially in or out of contact
}

BOOST_AUTO_TEST_CASE(direct_and_modal_recursive_convolutions_agree_on_the_tyre)
{
  // 5 cm of road-A at 90 km/h: the convolution sum over every past step
  // against the modal recursion, both from the same patch model.
  const CoarseTyre  tyre;
  test::RollingCase run;
  run.distance = 0.05;
  std::vector<Eigen::VectorXd> modal, direct;
  tyre.roll(run, [&](const contact::RollingStep &s) {
    modal.push_back(s.force);
  });
  run.direct = true;
  tyre.roll(run, [&](const contact::RollingStep &s) {
    direct.push_back(s.force);
  });
  BOOST_TEST_REQUIRE(modal.size() == direct.size());
  double difference = 0., scale = 0.;
  for (std::size_t n = 0; n < modal.size(); ++n)
    {
      difference = std::max(difference, (modal[n] - direct[n]).cwiseAbs().maxCoeff());
      scale      = std::max(scale, direct[n].cwiseAbs().maxCoeff());
    }
  BOOST_TEST_MESSAGE(modal.size() << " steps: max |q_modal - q_direct| " << difference << " N of "
                                  << scale << " N");
  // Measured 1.5e-14 of the peak: round-off, which differs between machines.
  BOOST_TEST(difference <= 1e-13 * scale);
}

BOOST_AUTO_TEST_CASE(flat_road_from_the_static_equilibrium_stays_there_on_the_tyre)
{
  // The run starts from the static contact of the model's own static
  // compliance: on a flat road nothing moves.
  const CoarseTyre  tyre;
  test::RollingCase run;
  run.flat     = true;
  run.distance = 0.1;
  Eigen::VectorXd q0;
  double          drift   = 0.;
  const auto      summary = tyre.roll(
         run,
         [&](const contact::RollingStep &s) {
      drift = std::max(drift, (s.force - q0).cwiseAbs().maxCoeff());
    },
         &q0);
  BOOST_TEST_MESSAGE("flat road: the forces stay within " << drift << " N of the static "
                                                          << q0.sum() << " N");
  BOOST_TEST(summary.failed_steps == 0u);
  // Measured 6.6e-14 of the largest static force: round-off, which differs
  // between machines, so 10 times that.
  CHECK_BOUND(drift / q0.cwiseAbs().maxCoeff(), 7e-13);
}

BOOST_AUTO_TEST_CASE(stiff_and_extreme_cases_stay_sound_on_the_tyre)
{
  // The extremes of patch_rolling.h on the tyre's own matrices, 600 N over
  // 20 cm at 90 km/h (5 cm for the finest step).
  const CoarseTyre tyre;
  // Measured at most 1.5e-4 of the displacement change (dt = 20 samples).
  test::check_extreme_cases(tyre.model, tyre.tread, tyre.texture, test::RollingCase(), 0.05,
                            4.5e-4);
}

BOOST_AUTO_TEST_SUITE_END()

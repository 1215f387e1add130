#pragma once

// One rolling run of a patch model over a texture through the recipe the
// tyre-road-contact scene uses (contact/rolling.h: envelope sampling, a start
// from the static contact that carries the load at x = 0, the indentation
// held), with the model's own static compliance: shared by the checks on
// a synthetic patch (test_patch_contact.cc) and on a real tyre
// (test_tyre_contact.cc).

#include "complementarity.h"
#include "frequency_synthesis.h"

#include <greentread/contact/patch_contact.h>
#include <greentread/contact/rolling.h>
#include <greentread/modal/patch_model.h>
#include <greentread/road/patch_road.h>
#include <greentread/road/texture.h>

#include <Eigen/Core>

#include <boost/test/unit_test.hpp>

#include <cmath>
#include <functional>
#include <string>
#include <vector>

namespace test
{
  struct RollingCase
  {
    double speed_kmh = 90.;   ///< km/h
    double load      = 600.;  ///< static load [N]
    double roughness = 1.;    ///< the texture's heights are multiplied by this
    double dt_factor = 1.;    ///< dt in road samples
    double distance  = 0.2;   ///< m
    bool   direct    = false; ///< direct convolution instead of modal-recursive
    bool   flat      = false; ///< a flat road instead of the texture

    double
    time_step(const greentread::road::Texture &texture) const
    {
      return dt_factor * texture.dx / (speed_kmh / 3.6);
    }
  };

  /**
   * Roll @p model (tread heights @p tread under its points) over @p texture
   * from the static equilibrium; @p observe sees every step, @p start (if
   * given) receives the static forces.
   */
  inline greentread::contact::RollingSummary
  roll_on_texture(const greentread::modal::PatchModel                                 &model,
                  const Eigen::VectorXd                                               &tread,
                  const greentread::road::Texture                                     &texture,
                  const RollingCase                                                   &run,
                  const std::function<void(const greentread::contact::RollingStep &)> &observe,
                  Eigen::VectorXd *start = nullptr)
  {
    using namespace greentread;
    road::Texture t = texture;
    for (auto &z : t.z)
      z = run.flat ? 0. : z * run.roughness;
    const road::PatchRoad           road(t, model.points, road::RoadSampling::envelope, "test");
    const contact::PatchRoadHeights heights = [&road](const double s, Eigen::VectorXd &z,
                                                      Eigen::VectorXd &slope) {
      road.heights(s, z, slope);
    };
    contact::RollingSetup setup;
    setup.speed       = run.speed_kmh / 3.6;
    setup.time_step   = run.time_step(texture);
    setup.n_steps     = static_cast<unsigned int>(run.distance / (setup.speed * setup.time_step));
    setup.static_load = run.load;
    setup.convolution =
      run.direct ? convolution::Method::direct : convolution::Method::modal_recursive;
    const auto eq = contact::start_contact(model.static_compliance(), tread, heights, setup);
    if (start)
      *start = eq.q;
    return contact::roll_patch(model, tread, heights, eq, setup, observe);
  }

  /// What check_run() measured of one rolling run.
  struct RunCheck
  {
    /// The step's LCP measured here from its matrix, demand and force (the
    /// worst over the steps, complementarity.h): the gap's lowest value and
    /// the largest complementarity residual.
    /// Not measured: the sign of the step's mean force (RollingStep::force,
    /// built from the LCP's forces and the load shapes, each clamped to 0 or
    /// more) and what the projection onto z >= 0 removed
    /// (LcpResult::projected, at most the tolerance by the pivoting solver's
    /// own stopping rule): neither can fail. A projection that removed a real
    /// negative force moves w = M z + q, which the two measures above see.
    double lcp_gap = 0., lcp_complementarity = 0.;
    /// Largest penetration max(d - u) of the synthesised displacement, and the
    /// largest |u - d| of a point that carries a force, relative to the
    /// largest displacement change max |u - u(0)|.
    double penetration = 0., gap_in_contact = 0.;
  };

  /**
   * Record every step of a run (@p roll calls the observer it is given and
   * returns the start force), then
   * check it against what does not come from the contact solve: the raw LCP
   * forces are not negative, and the displacements that the frequency-domain
   * synthesis of frequency_synthesis.h gives for the recorded forces keep
   * every point on or above the road, and every loaded point on it.
   */
  inline RunCheck
  check_run(
    const greentread::modal::PatchModel                     &model,
    const double                                             dt,
    const std::function<void(const std::function<void(const greentread::contact::RollingStep &)> &,
                             Eigen::VectorXd &start_force)> &roll)
  {
    RunCheck                     c;
    std::vector<Eigen::VectorXd> q(1), d(1);
    roll(
      [&](const greentread::contact::RollingStep &s) {
        if (s.report.lcp_matrix)
          {
            const Complementarity lcp =
              complementarity(*s.report.lcp_matrix, s.report.lcp_q, s.report.lcp_z);
            c.lcp_gap             = std::min(c.lcp_gap, lcp.gap);
            c.lcp_complementarity = std::max({c.lcp_complementarity, lcp.natural, lcp.product});
          }
        q.push_back(s.report.lcp_z);
        d.push_back(s.d);
      },
      q[0]);
    const auto u     = synthesise_displacements(model, dt, q);
    double     scale = 0.;
    for (std::size_t n = 1; n < u.size(); ++n)
      scale = std::max(scale, (u[n] - u[0]).cwiseAbs().maxCoeff());
    scale = std::max(scale, 1e-300);
    for (std::size_t n = 1; n < u.size(); ++n)
      for (Eigen::Index j = 0; j < u[n].size(); ++j)
        {
          c.penetration = std::max(c.penetration, (d[n][j] - u[n][j]) / scale);
          if (q[n][j] > 0.)
            c.gap_in_contact = std::max(c.gap_in_contact, std::abs(u[n][j] - d[n][j]) / scale);
        }
    return c;
  }

  /**
   * The stiff and extreme cases of the issue, each a change of @p base: a
   * texture five times rougher (many points lose contact), 130 km/h, a tyre
   * that barely touches (0.01 N: some steps lose all contact), dt = 20 road
   * samples and dt = 1/20 of one (over @p fine_distance). Each run must
   * converge at every step, have every step's LCP complementary and its gap
   * non-negative when measured here from its matrix (to the pivoting
   * solver's tolerance, 1e-10 of the scale, twice: once for the accepted
   * iterate, once for its projection), keep the synthesised displacement on
   * or above the road and every loaded point on it (to @p tolerance of the
   * displacement change), and have a finite mean force.
   */
  inline void
  check_extreme_cases(const greentread::modal::PatchModel &model,
                      const Eigen::VectorXd               &tread,
                      const greentread::road::Texture     &texture,
                      const RollingCase                   &base,
                      const double                         fine_distance,
                      const double                         tolerance)
  {
    struct Case
    {
      std::string name;
      RollingCase run;
    };
    std::vector<Case> cases(5, Case{"", base});
    cases[0].name          = "very rough road (texture x 5)";
    cases[0].run.roughness = 5. * base.roughness;
    cases[1].name          = "130 km/h";
    cases[1].run.speed_kmh = 130.;
    cases[2].name          = "barely touching (0.01 N)";
    cases[2].run.load      = 0.01;
    cases[3].name          = "dt = 20 road samples";
    cases[3].run.dt_factor = 20.;
    cases[4].name          = "dt = 1/20 road sample";
    cases[4].run.dt_factor = 0.05;
    cases[4].run.distance  = fine_distance;
    for (const auto &c : cases)
      BOOST_TEST_CONTEXT(c.name)
      {
        greentread::contact::RollingSummary s;
        const RunCheck                      checked = check_run(
                               model, c.run.time_step(texture),
                               [&](const std::function<void(const greentread::contact::RollingStep &)> &observe,
              Eigen::VectorXd                                                     &start) {
            s = roll_on_texture(model, tread, texture, c.run, observe, &start);
          });
        const double mean = s.impulse / (s.steps * c.run.time_step(texture));
        BOOST_TEST_MESSAGE(
          c.name << ": " << s.steps << " steps, points in contact " << 100. * s.min_contact_fraction
                 << "% to " << 100. * s.max_contact_fraction << "%, mean force " << mean
                 << " N (static " << c.run.load << " N), failed steps " << s.failed_steps
                 << "; LCP measured here: gap down to " << checked.lcp_gap << ", complementarity "
                 << checked.lcp_complementarity << "; synthesised displacement: penetration "
                 << checked.penetration << ", loaded points off the road " << checked.gap_in_contact
                 << " of the displacement change");
        BOOST_TEST(s.failed_steps == 0u, "first failure: " << s.first_failure);
        BOOST_TEST(checked.lcp_gap >= -2e-10);
        BOOST_TEST(checked.lcp_complementarity <= 2e-10);
        BOOST_TEST(checked.penetration <= tolerance);
        BOOST_TEST(checked.gap_in_contact <= tolerance);
        BOOST_TEST(std::isfinite(mean));
        if (c.name.rfind("very rough", 0) == 0)
          BOOST_TEST(s.min_contact_fraction < 0.5);
        if (c.name.rfind("barely", 0) == 0)
          BOOST_TEST(s.min_contact_fraction == 0.);
      }
  }
} // namespace test

#pragma once

// The synthetic patch (synthetic_patch.h) on a contact grid, rolled over a
// synthetic road-A: shared by the error bars' checks on band levels
// (test_error_bars.cc) and on the rolling resistance
// (test_rolling_resistance.cc).

#include "synthetic_patch.h"

#include <greentread/contact/contact_grid.h>
#include <greentread/contact/rolling.h>
#include <greentread/road/patch_road.h>
#include <greentread/road/texture.h>

#include <Eigen/Core>

#include <cmath>
#include <functional>
#include <vector>

namespace test
{
  /// What roll_grid() rolled.
  struct GridRun
  {
    double       time_step    = 0.; ///< [s]
    double       speed        = 0.; ///< [m/s]
    unsigned int failed_steps = 0;
  };

  /**
   * Roll the synthetic patch (5% damping) on @p subdivisions contact points
   * per Green's-function rectangle over road-A at 25 m/s under 150 N for
   * @p duration s at @p dt_factor road samples per step, from its static
   * start (given to @p start with the time step). @p observe sees the grid
   * and every step.
   */
  inline GridRun
  roll_grid(
    const unsigned int                                                             subdivisions,
    const double                                                                   dt_factor,
    const double                                                                   duration,
    const std::function<void(const greentread::contact::ContactGrid &,
                             const greentread::contact::RollingStep &)>           &observe,
    const std::function<void(const greentread::contact::StaticContact &, double)> &start = {})
  {
    using namespace greentread;
    static const road::Texture texture = [] {
      std::vector<road::WavelengthBand> bands;
      std::vector<double>               levels;
      road::texture_preset("road-A", bands, levels);
      return road::synthetic_texture(bands, levels, 3.84e-4, 8000, 96, 11);
    }();
    static const modal::PatchModel model = synthetic_patch(0.05);
    const contact::ContactGrid     grid(model.points, subdivisions, contact::ElasticLayer{},
                                        subdivisions > 2, true);
    const road::PatchRoad          road(texture, grid.points, road::RoadSampling::envelope, "test");
    const contact::PatchRoadHeights heights = [&](const double x, Eigen::VectorXd &z,
                                                  Eigen::VectorXd &slope) {
      road.heights(x, z, slope);
    };
    const Eigen::VectorXd tread = contact::tread_heights(grid.points);
    contact::RollingSetup setup;
    setup.speed       = 25.;
    setup.time_step   = dt_factor * 3.84e-4 / 25.;
    setup.n_steps     = unsigned(std::lround(duration / setup.time_step));
    setup.static_load = 150.;
    const auto static_start =
      contact::start_grid_contact(grid, model.static_compliance(), tread, heights, setup);
    if (start)
      start(static_start, setup.time_step);
    const auto convolution = contact::make_grid_convolution(
      contact::make_patch_convolution(setup.convolution, model, setup.time_step, setup.n_steps, 0,
                                      1),
      grid);
    const auto summary = contact::roll_patch(*convolution, tread, heights, static_start, setup,
                                             [&](const contact::RollingStep &step) {
                                               observe(grid, step);
                                             });
    return {setup.time_step, setup.speed, summary.failed_steps};
  }
} // namespace test

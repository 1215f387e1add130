// The roll that the contact grid's solver tests compare (test_projected_cg.cc,
// test_candidate_set.cc): a patch model rolled on road-A (seed 11) at 25 m/s,
// one road sample per step, 400 steps under 150 N from the static start, on
// two contact grids of the same points, and the largest force difference
// between the two.
#pragma once

#include <greentread/contact/contact_grid.h>
#include <greentread/contact/rolling.h>
#include <greentread/road/patch_road.h>
#include <greentread/road/texture.h>

#include <Eigen/Core>

#include <algorithm>
#include <array>
#include <vector>

namespace test
{
  /// Both grids' force histories and summaries, from the first grid's static start.
  struct GridRolls
  {
    std::array<std::vector<Eigen::VectorXd>, 2>              forces;
    std::array<greentread::contact::RollingSummary, 2>       summary;
    std::array<greentread::contact::StaticContact, 2>        start;
    /// The largest force over the run, and the largest difference between the grids.
    double peak = 0., worst = 0.;
  };

  inline GridRolls
  roll_on_two_grids(const greentread::modal::PatchModel       &model,
                    const greentread::contact::ContactGrid    &first,
                    const greentread::contact::ContactGrid    &second)
  {
    using namespace greentread;
    std::vector<road::WavelengthBand> bands;
    std::vector<double>               levels;
    road::texture_preset("road-A", bands, levels);
    const road::Texture   texture = road::synthetic_texture(bands, levels, 3.84e-4, 2048, 96, 11);
    const road::PatchRoad road(texture, first.points, road::RoadSampling::envelope, "test");
    const contact::PatchRoadHeights heights = [&](const double x, Eigen::VectorXd &z,
                                                  Eigen::VectorXd &slope) {
      road.heights(x, z, slope);
    };
    contact::RollingSetup setup;
    setup.speed       = 25.;
    setup.time_step   = 3.84e-4 / 25.;
    setup.n_steps     = 400;
    setup.static_load = 150.;
    const Eigen::VectorXd tread = contact::tread_heights(first.points);
    const Eigen::MatrixXd G0    = model.static_compliance();
    GridRolls             r;
    const contact::ContactGrid *grids[2] = {&first, &second};
    for (unsigned int k = 0; k < 2; ++k)
      r.start[k] = contact::start_grid_contact(*grids[k], G0, tread, heights, setup);
    for (unsigned int k = 0; k < 2; ++k)
      {
        auto convolution = contact::make_grid_convolution(
          contact::make_patch_convolution(setup.convolution, model, setup.time_step,
                                          setup.n_steps, 0, 1),
          *grids[k]);
        r.summary[k] = contact::roll_patch(*convolution, tread, heights, r.start[0], setup,
                                           [&](const contact::RollingStep &step) {
                                             r.forces[k].push_back(step.force);
                                           });
      }
    for (std::size_t k = 0; k < r.forces[0].size(); ++k)
      {
        r.peak  = std::max(r.peak, r.forces[0][k].cwiseAbs().maxCoeff());
        r.worst = std::max(r.worst, (r.forces[0][k] - r.forces[1][k]).cwiseAbs().maxCoeff());
      }
    return r;
  }
} // namespace test

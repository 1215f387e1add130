// The roll that the contact grid's tests share (test_contact_grid.cc,
// test_projected_cg.cc, test_candidate_set.cc): road-A (seed 11) at 25 m/s,
// one road sample per step, 400 steps under 150 N from the static start; and
// a patch model rolled so on two contact grids of the same points, with the
// largest force difference between the two.
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
  /// Road-A (seed 11) under @p points, rolled at 25 m/s, one road sample
  /// per step, 400 steps under 150 N: the roll of the contact grid's tests.
  /// Not copyable (the heights refer to the road, the road to its texture).
  struct RoadARoll
  {
    explicit RoadARoll(const std::vector<std::array<double, 3>> &points)
        : texture(make_texture())
        , road(texture, points, greentread::road::RoadSampling::envelope, "test")
        , heights([this](const double x, Eigen::VectorXd &z, Eigen::VectorXd &slope) {
          road.heights(x, z, slope);
        })
        , tread(greentread::contact::tread_heights(points))
    {
      setup.speed       = 25.;
      setup.time_step   = 3.84e-4 / 25.;
      setup.n_steps     = 400;
      setup.static_load = 150.;
    }
    RoadARoll(const RoadARoll &) = delete;
    RoadARoll &
    operator=(const RoadARoll &) = delete;

    static greentread::road::Texture
    make_texture()
    {
      std::vector<greentread::road::WavelengthBand> bands;
      std::vector<double>                           levels;
      greentread::road::texture_preset("road-A", bands, levels);
      return greentread::road::synthetic_texture(bands, levels, 3.84e-4, 2048, 96, 11);
    }

    const greentread::road::Texture             texture;
    const greentread::road::PatchRoad           road;
    const greentread::contact::PatchRoadHeights heights;
    const Eigen::VectorXd                       tread;
    greentread::contact::RollingSetup           setup;
  };

  /// Both grids' force histories and summaries, from the first grid's static start.
  struct GridRolls
  {
    std::array<std::vector<Eigen::VectorXd>, 2>        forces;
    std::array<greentread::contact::RollingSummary, 2> summary;
    std::array<greentread::contact::StaticContact, 2>  start;
    /// The largest force over the run, and the largest difference between the grids.
    double peak = 0., worst = 0.;
  };

  inline GridRolls
  roll_on_two_grids(const greentread::modal::PatchModel    &model,
                    const greentread::contact::ContactGrid &first,
                    const greentread::contact::ContactGrid &second)
  {
    using namespace greentread;
    const RoadARoll             roll(first.points);
    const Eigen::MatrixXd       G0 = model.static_compliance();
    GridRolls                   r;
    const contact::ContactGrid *grids[2] = {&first, &second};
    for (unsigned int k = 0; k < 2; ++k)
      r.start[k] = contact::start_grid_contact(*grids[k], G0, roll.tread, roll.heights, roll.setup);
    for (unsigned int k = 0; k < 2; ++k)
      {
        auto convolution = contact::make_grid_convolution(
          contact::make_patch_convolution(roll.setup.convolution, model, roll.setup.time_step,
                                          roll.setup.n_steps, 0, 1),
          *grids[k]);
        r.summary[k] = contact::roll_patch(*convolution, roll.tread, roll.heights, r.start[0],
                                           roll.setup, [&](const contact::RollingStep &step) {
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

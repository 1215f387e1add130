#pragma once

// One rolling run of a patch model over a texture, as the tire-road-contact
// scene does it (envelope sampling, a start from the static contact that
// carries the load at x = 0, the indentation held): shared by the checks on
// a synthetic patch (test_patch_contact.cc) and on a real tyre
// (test_tyre_contact.cc).

#include <greentread/contact/patch_contact.h>
#include <greentread/modal/patch_model.h>
#include <greentread/road/texture.h>
#include <greentread/scenes/road_scene.h>

#include <Eigen/Core>

#include <functional>

namespace test
{
  struct RollingCase
  {
    double speed_kmh = 90.;  ///< km/h
    double load      = 600.; ///< static load [N]
    double roughness = 1.;   ///< the texture's heights are multiplied by this
    double dt_factor = 1.;   ///< dt in road samples
    double distance  = 0.2;  ///< m
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
  roll_on_texture(const greentread::modal::PatchModel                            &model,
                  const Eigen::VectorXd                                          &tread,
                  const greentread::road::Texture                                &texture,
                  const RollingCase                                              &run,
                  const std::function<void(const greentread::contact::RollingStep &)> &observe,
                  Eigen::VectorXd *start = nullptr)
  {
    using namespace greentread;
    road::Texture t = texture;
    for (auto &z : t.z)
      z = run.flat ? 0. : z * run.roughness;
    const scenes::PatchRoad road(t, model.points, scenes::RoadSampling::envelope, "test");
    const double            V  = run.speed_kmh / 3.6;
    const double            dt = run.time_step(texture);
    Eigen::VectorXd         z(model.n_points()), slope(model.n_points());
    const auto              sample = [&](const double x) {
      for (unsigned int p = 0; p < model.n_points(); ++p)
        road.height(p, x, z[p], slope[p]);
    };
    sample(0.);
    const auto eq = contact::solve_static_contact(model.static_compliance(), z - tread, run.load, 0.);
    if (start)
      *start = eq.q;
    const auto demand = [&](const double time, Eigen::VectorXd &d, Eigen::VectorXd &dd) {
      sample(V * time);
      d  = (eq.delta + z.array() - tread.array()).matrix();
      dd = V * slope;
    };
    const unsigned int n_steps = static_cast<unsigned int>(run.distance / (V * dt));
    auto conv = run.direct ? contact::make_direct_patch_convolution(model, dt, n_steps + 1) :
                             contact::make_modal_patch_convolution(model, dt);
    return contact::roll(*conv, demand, n_steps, eq.q, observe);
  }
} // namespace test

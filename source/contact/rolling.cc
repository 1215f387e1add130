#include <greentread/base/exceptions.h>
#include <greentread/base/output.h>
#include <greentread/contact/rolling.h>

#include <algorithm>
#include <cmath>

namespace greentread
{
  namespace contact
  {
    unsigned int
    steps_to_cover(const double distance, const double speed, const double dt)
    {
      const double steps = distance / (speed * dt);
      return static_cast<unsigned int>(std::ceil(steps * (1. - 1e-9)));
    }



    Eigen::VectorXd
    tread_heights(const std::vector<std::array<double, 3>> &points)
    {
      Eigen::VectorXd t(points.size());
      for (std::size_t p = 0; p < points.size(); ++p)
        {
          const double r = points[p][2], x = points[p][0];
          t[p] = r - std::sqrt(r * r - x * x);
        }
      return t;
    }



    StaticContact
    start_contact(const Eigen::MatrixXd  &G0,
                  const Eigen::VectorXd  &tread,
                  const PatchRoadHeights &road,
                  const RollingSetup     &setup)
    {
      Eigen::VectorXd z(tread.size()), slope(tread.size());
      road(0., z, slope);
      return solve_static_contact(G0, z - tread, setup.static_load, setup.indentation);
    }



    StaticContact
    start_contact(const StaticSolve      &solve,
                  const Eigen::VectorXd  &tread,
                  const PatchRoadHeights &road,
                  const RollingSetup     &setup)
    {
      Eigen::VectorXd z(tread.size()), slope(tread.size());
      road(0., z, slope);
      return solve_static_contact(solve, z - tread, setup.static_load, setup.indentation);
    }



    std::unique_ptr<convolution::PatchConvolution>
    make_patch_convolution(const convolution::Method         method,
                           const modal::PatchModel          &model,
                           const double                      dt,
                           const unsigned int                n_steps,
                           const unsigned int                direct_kernel,
                           const unsigned int                threads,
                           const convolution::ShapePrecision precision)
    {
      if (method == convolution::Method::modal_recursive)
        return make_modal_patch_convolution(model, dt, threads, precision);
      if (method != convolution::Method::direct)
        throw InputError("parameter 'Convolution/Method' = " + convolution::to_string(method) +
                         " is not allowed for a contact patch; allowed: direct, modal-recursive");
      const unsigned int n_p = model.n_points();
      const unsigned int n_kernel =
        direct_kernel > 0 ? std::min(direct_kernel, n_steps + 1) : n_steps + 1;
      const double bytes = 8. * 8. * n_p * n_p * n_kernel;
      if (bytes > 8e9)
        throw InputError("'Convolution/Method' = direct would store " + format_short(bytes / 1e9) +
                         " GB of kernels; shorten 'Rolling/Distance' or set "
                         "'Rolling/Direct kernel length' (at most " +
                         std::to_string(static_cast<unsigned int>(8e9 / (64. * n_p * n_p))) +
                         " steps)");
      return convolution::make_direct_patch_convolution(model, dt, n_kernel);
    }



    RollingSummary
    roll_patch(const modal::PatchModel                        &model,
               const Eigen::VectorXd                          &tread,
               const PatchRoadHeights                         &road,
               const StaticContact                            &start,
               const RollingSetup                             &setup,
               const std::function<void(const RollingStep &)> &observe)
    {
      const auto conv =
        make_patch_convolution(setup.convolution, model, setup.time_step, setup.n_steps,
                               setup.direct_kernel, setup.threads, setup.shape_precision);
      return roll_patch(*conv, tread, road, start, setup, observe);
    }



    RollingSummary
    roll_patch(convolution::PatchConvolution                   &convolution,
               const Eigen::VectorXd                           &tread,
               const PatchRoadHeights                          &road,
               const StaticContact                             &start,
               const RollingSetup                              &setup,
               const std::function<void(const RollingStep &)>  &observe,
               const std::function<unsigned int(unsigned int)> &more_steps)
    {
      Eigen::VectorXd z(tread.size()), slope(tread.size());
      const auto      demand = [&](const double t, Eigen::VectorXd &d, Eigen::VectorXd &dd) {
        road(setup.speed * t, z, slope);
        d  = (start.delta + z.array() - tread.array()).matrix();
        dd = setup.speed * slope;
      };
      return roll(convolution, demand, setup.n_steps,
                  setup.static_start ? start.q : Eigen::VectorXd(), observe, more_steps);
    }
  } // namespace contact
} // namespace greentread

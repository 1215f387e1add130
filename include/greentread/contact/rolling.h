#pragma once

#include <greentread/contact/patch_contact.h>
#include <greentread/convolution/convolution_parameters.h>
#include <greentread/modal/patch_model.h>

#include <Eigen/Core>

#include <array>
#include <functional>
#include <memory>
#include <string>
#include <vector>

/**
 * @file
 * The one rolling recipe of a contact patch, shared by the tyre-road-contact
 * scene, the tests and the benchmarks: the static contact that carries the
 * load at the start position, then contact::roll() over the road with the
 * indentation held. Implemented in source/contact/rolling.cc.
 */

namespace greentread
{
  namespace contact
  {
    /// Everything a rolling run needs besides the model and the road.
    struct RollingSetup
    {
      double       speed     = 25.;  ///< V [m/s]
      double       time_step = 1e-5; ///< dt [s]
      unsigned int n_steps   = 0;
      /// The load the start position carries [N]; 0: @p indentation is used.
      double static_load = 600.;
      double indentation = 0.; ///< [m], with static_load = 0
      /// Start from the static contact (forces held since t = -infinity) or from rest.
      bool                static_start  = true;
      convolution::Method convolution   = convolution::Method::modal_recursive;
      unsigned int        direct_kernel = 0; ///< steps kept by `direct`; 0: the whole run
      unsigned int        threads       = 1; ///< of the modal recursion
      /// of the rank-one modal recursion's shapes
      convolution::ShapePrecision shape_precision = convolution::ShapePrecision::double_precision;
    };

    /**
     * @brief The road under the points at patch position @p s along it [m]:
     * the height z_p [m] and the slope dz_p/ds of each point.
     */
    using PatchRoadHeights =
      std::function<void(double s, Eigen::VectorXd &z, Eigen::VectorXd &slope)>;

    /**
     * @brief The steps of @p dt that cover @p distance at @p speed: the
     * ratio rounded up, except that a ratio whole to 1e-9 (1.2 m at 7.68 us
     * and 25 m/s: 6250.000000001 in floating point) is that whole number, so
     * that a run's record, and with it the spectrum's Fourier lines, does
     * not change with the rounding.
     */
    unsigned int
    steps_to_cover(double distance, double speed, double dt);

    /// The tread's own height above the bottom of the tyre under each point,
    /// \f$r - \sqrt{r^2 - x^2}\f$ (its curvature along x) [m].
    Eigen::VectorXd
    tread_heights(const std::vector<std::array<double, 3>> &points);

    /**
     * @brief The static contact at the start position s = 0 that carries
     * @p setup.static_load, with the static compliance @p G0 (the
     * structure's or the model's): the demand is \f$\delta + z - t\f$ with
     * the tread heights t.
     */
    StaticContact
    start_contact(const Eigen::MatrixXd  &G0,
                  const Eigen::VectorXd  &tread,
                  const PatchRoadHeights &road,
                  const RollingSetup     &setup);

    /// start_contact() with the static LCP solved by @p solve.
    StaticContact
    start_contact(const StaticSolve      &solve,
                  const Eigen::VectorXd  &tread,
                  const PatchRoadHeights &road,
                  const RollingSetup     &setup);

    /**
     * @brief The convolution of @p method for @p model at @p dt over
     * @p n_steps steps.
     * @throws InputError if `direct` would store more than 8 GB of kernels,
     * naming the parameters that shorten it.
     */
    std::unique_ptr<convolution::PatchConvolution>
    make_patch_convolution(
      convolution::Method         method,
      const modal::PatchModel    &model,
      double                      dt,
      unsigned int                n_steps,
      unsigned int                direct_kernel,
      unsigned int                threads,
      convolution::ShapePrecision precision = convolution::ShapePrecision::double_precision);

    /**
     * @brief Roll @p model over @p road from @p start (start_contact()): the
     * demand \f$d = \delta + z(Vt) - t\f$, \f$\dot d = V\,z'(Vt)\f$, with the
     * indentation held; @p observe sees every step (may be empty).
     */
    RollingSummary
    roll_patch(const modal::PatchModel                        &model,
               const Eigen::VectorXd                          &tread,
               const PatchRoadHeights                         &road,
               const StaticContact                            &start,
               const RollingSetup                             &setup,
               const std::function<void(const RollingStep &)> &observe);

    /// roll_patch() with a convolution made beforehand (benchmarks time the
    /// run without the making of the kernels); @p setup.convolution and
    /// @p setup.threads are not used. @p more_steps as in contact::roll():
    /// the run may go on past setup.n_steps (the road must be long enough).
    RollingSummary
    roll_patch(convolution::PatchConvolution                   &convolution,
               const Eigen::VectorXd                           &tread,
               const PatchRoadHeights                          &road,
               const StaticContact                             &start,
               const RollingSetup                              &setup,
               const std::function<void(const RollingStep &)>  &observe,
               const std::function<unsigned int(unsigned int)> &more_steps = {});
  } // namespace contact
} // namespace greentread

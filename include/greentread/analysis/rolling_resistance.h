#pragma once

#include <greentread/analysis/error_bars.h>
#include <greentread/base/output.h>
#include <greentread/contact/patch_contact.h>

#include <Eigen/Core>

#include <cmath>
#include <filesystem>
#include <map>
#include <ostream>
#include <string>
#include <vector>

/**
 * @file
 * The rolling resistance a road's texture adds, from a rolling run: the
 * mean power the contact forces put into the tyre, P = <sum_i f_i du_i/dt>,
 * as a force F_RR = P / V and a coefficient F_RR / F_z, each with its
 * standard error. Implemented in source/analysis/rolling_resistance.cc.
 *
 * The tyre here does not turn: its points stay under the axle while the
 * road passes, so the static deflection does no cyclic work and the
 * hysteresis of the rubber passing through the patch, most of a tyre's
 * rolling resistance (a coefficient of about 0.01), is not in it. What is
 * measured is the part the texture adds, through the vibration it excites;
 * on a flat road it is zero.
 */

namespace greentread
{
  namespace analysis
  {
    /// A run's rolling resistance, each value with its standard error.
    struct RollingResistance
    {
      double       power = 0., power_error = 0.;             ///< P [W]
      double       force = 0., force_error = 0.;             ///< F_RR = P / V [N]
      double       coefficient = 0., coefficient_error = 0.; ///< F_RR / F_z
      double       load     = 0.;                            ///< F_z, the mean total force [N]
      double       skipped  = 0.;                            ///< the start left out [s]
      double       duration = 0.;                            ///< the record averaged [s]
      unsigned int segments = 0;                             ///< of the standard error
      /// The discretisations' error bars on the coefficient
      /// (rolling_resistance_level_error()), those whose other level was rolled.
      std::map<Discretisation, double> coefficient_errors;

      /// The standard error and the error bars in quadrature.
      double
      coefficient_total_error() const;
    };

    /**
     * The order the rolling resistance's error bars assume in the time step,
     * the contact grid, the ring section and the blocks' mesh: 1. In the time
     * step it is below the spectra's 2 and below the orders
     * benchmarks/rolling_resistance measures (1.5 to 1.75 on the main job's
     * ring, 1.2 to 1.4 on the coarse ring), so that the error bar does not
     * understate the error. In the contact grid it is the order
     * benchmarks/contact_grid_study measures on the main job's tyre (1.03 and
     * 1.17 from 4 to 8 to 16 subdivisions); in the section and the blocks'
     * mesh the rolling resistance's order is not measured, and 1 is below the
     * band levels' in the section (1.5, analysis/error_bars.h) and equal to
     * it in the blocks' mesh.
     */
    constexpr double rolling_resistance_order = 1.;

    /**
     * @brief The factor that scales the relative change of the mean power
     * from a run to its other level of @p estimate into the run's error
     * bar: 1 + richardson_factor() at rolling_resistance_order for the time
     * step (the other level is finer), richardson_factor() at that order for
     * the contact grid, the ring section and the blocks' mesh (coarser), and
     * the estimate's own factor for the mode cut-off (how much closer to the
     * direct lines the finer modes are: a property of the modal model, not
     * of the band levels).
     */
    double
    rolling_resistance_factor(const EstimateRun &estimate);

    /**
     * @brief The mean power [W] of a work record @p work (one value per step
     * of @p dt [s], RollingPowerMeter::step_work()) over the steps that start
     * in [@p from, @p to) [s].
     * @throws std::invalid_argument if no step starts there.
     */
    double
    mean_power(const std::vector<double> &work, double dt, double from, double to);

    /**
     * @brief A discretisation's error bar on the coefficient of @p run, whose
     * work record @p work is at step @p dt, from its other level
     * (@p other_work at step @p other_dt) rolled over the same road from the
     * same start for @p window [s]: over that window after its first
     * @p skip_fraction, the relative change of the mean power, scaled to
     * the run's error by @p factor (rolling_resistance_factor()) and applied
     * to the run's coefficient: |P_other / P - 1| factor C_RR. For the time
     * step at half the step, factor = 1 + 1 / (2^p - 1). The relative change,
     * not the absolute: the window is short and its vibration still building
     * up, while the share of the power a discretisation misses is nearly the
     * same over any window (doc/methods/analysis.md).
     * @return NaN if the run has no coefficient or the window's power is 0.
     */
    double
    rolling_resistance_level_error(const RollingResistance   &run,
                                   const std::vector<double> &work,
                                   double                     dt,
                                   const std::vector<double> &other_work,
                                   double                     other_dt,
                                   double                     window,
                                   double                     factor,
                                   double                     skip_fraction = 0.2);

    /**
     * @brief The work the contact forces do on the tyre, step by step: each
     * step's mean force times its change of displacement, sum_i f_i (u_i(t_{n+1})
     * - u_i(t_n)). The force is linear within a step, so this is the work to
     * O((omega dt)^2). The tread layer's local compliance is elastic: its
     * share of the work telescopes and adds nothing to the mean.
     */
    class RollingPowerMeter
    {
    public:
      /// @p u_start: the displacement at the static start (t = 0).
      RollingPowerMeter(const Eigen::VectorXd &u_start, double time_step);

      void
      add(const contact::RollingStep &step);

      /// The work of each step [J].
      const std::vector<double> &
      step_work() const
      {
        return work;
      }

      /**
       * @brief The mean power after the first @p skip_fraction of the record
       * (the vibration the texture excites builds up from the static start),
       * with its standard error from the scatter of the means of
       * @p segments consecutive segments (batch means).
       * @param speed V [m/s].
       * @return NaN values if the record has fewer steps than segments.
       * @throws NumericalError if a step's work is not finite.
       */
      RollingResistance
      result(double speed, double skip_fraction = 0.2, unsigned int segments = 10) const;

    private:
      Eigen::VectorXd     u_last;
      double              dt;
      std::vector<double> work, load;
    };

    /// One run's rolling resistance, as rolling_resistance.csv lists it.
    struct RunRollingResistance
    {
      std::string       road, run;
      bool              error_bar = false; ///< a run of an error bar's other level, not of the plan
      double            speed_kmh = 0., mpd = 0., time_step = 0., distance = 0.;
      RollingResistance value;
    };

    /// A line on @p out for each run of @p runs with an error bar: its
    /// coefficient, standard error and each discretisation's error bar (none
    /// if no run has one).
    void
    print_rolling_resistance_errors(std::ostream                            &out,
                                    const std::vector<RunRollingResistance> &runs);

    /**
     * @brief rolling_resistance.csv (every run, those of the error bars'
     * other levels marked) and rolling_resistance.png (the coefficient
     * against the roads' MPD, one line per speed, with its standard error
     * and its error bars combined in quadrature,
     * from each case's run of the plan at the finest time step: a coarser
     * step resolves less of the power), under temporary names renamed when
     * complete.
     */
    void
    write_rolling_resistance(const std::filesystem::path             &directory,
                             const std::vector<RunRollingResistance> &runs,
                             const base::ParameterRecord             &record);
  } // namespace analysis
} // namespace greentread

#pragma once

#include <greentread/analysis/error_bars.h>
#include <greentread/analysis/tread_losses.h>
#include <greentread/base/output.h>
#include <greentread/contact/patch_contact.h>

#include <Eigen/Core>

#include <array>
#include <cmath>
#include <filesystem>
#include <functional>
#include <map>
#include <optional>
#include <ostream>
#include <string>
#include <vector>

/**
 * @file
 * The rolling resistance a road's texture adds, from a rolling run, in two
 * parts: the mean power the contact forces put into the tyre's structure,
 * P = <sum_i f_i du_i/dt> (its modes' damping dissipates it), and the
 * tread's small-scale losses (greentread/analysis/tread_losses.h: the
 * rubber's loss factor in the deformation below the Green's functions'
 * scale, which the contact solve treats as elastic); each part and their sum
 * as a force F_RR = P / V and a coefficient F_RR / F_z, with its standard
 * error. Implemented in source/analysis/rolling_resistance.cc.
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
    /// The parts of the rolling resistance (file documentation).
    enum class PowerPart
    {
      structure, ///< the contact forces' work on the tyre
      tread,     ///< the tread's small-scale losses
      sum        ///< the two together
    };

    /// Every part, in the order rolling_resistance.csv lists them.
    constexpr std::array<PowerPart, 3> all_power_parts = {
      {PowerPart::structure, PowerPart::tread, PowerPart::sum}};

    /// A part's prefix in rolling_resistance.csv's columns: "" for the
    /// structure (its columns came first), "tread_", "sum_".
    std::string
    column_prefix(PowerPart part);

    /// One part of a run's rolling resistance, each value with its standard error.
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

    /// w = the local term's displacement at the contact points under the
    /// end forces f (TreadLossMeter's w).
    using LocalDisplacement = std::function<void(const Eigen::VectorXd &f, Eigen::VectorXd &w)>;

    /**
     * @brief The work the contact forces do on the tyre, step by step: each
     * step's mean force times its change of displacement, sum_i f_i (u_i(t_{n+1})
     * - u_i(t_n)). The force is linear within a step, so this is the work to
     * O((omega dt)^2). The tread layer's local compliance is elastic: its
     * share of the work telescopes and adds nothing to the mean. With
     * track_tread_losses(), also the work the tread's rubber dissipates
     * (TreadLossMeter); without, that part is 0.
     */
    class RollingPowerMeter
    {
    public:
      /// @p u_start: the displacement at the static start (t = 0).
      RollingPowerMeter(const Eigen::VectorXd &u_start, double time_step);

      /**
       * @brief Measure the tread's losses at loss factor @p loss_factor too,
       * at @p speed [m/s] on @p grid, the local displacement of each step's
       * end force given by @p local, from the static start's force
       * @p start_force.
       */
      void
      track_tread_losses(double                   loss_factor,
                         double                   speed,
                         const TreadLossGrid     &grid,
                         const LocalDisplacement &local,
                         const Eigen::VectorXd   &start_force);

      void
      add(const contact::RollingStep &step);

      /// The contact forces' work on the structure at each step [J].
      const std::vector<double> &
      step_work() const
      {
        return work;
      }

      /// The tread's losses at each step [J] (0 without track_tread_losses()).
      const std::vector<double> &
      tread_step_work() const
      {
        return tread_work;
      }

      /**
       * @brief The mean power of @p part after the first @p skip_fraction of
       * the record (the vibration the texture excites builds up from the
       * static start), with its standard error from the scatter of the means
       * of @p segments consecutive segments (batch means).
       * @param speed V [m/s].
       * @return NaN values if the record has fewer steps than segments.
       * @throws NumericalError if a step's work is not finite.
       */
      RollingResistance
      result(double       speed,
             double       skip_fraction = 0.2,
             unsigned int segments      = 10,
             PowerPart    part          = PowerPart::structure) const;

    private:
      Eigen::VectorXd               u_last;
      double                        dt;
      std::vector<double>           work, tread_work, load;
      std::optional<TreadLossMeter> tread;
      LocalDisplacement             local;
      Eigen::VectorXd               w;
    };

    /// The work record of @p part from the structure's and the tread's.
    std::vector<double>
    part_work(PowerPart                  part,
              const std::vector<double> &structure,
              const std::vector<double> &tread);

    /// One run's rolling resistance, as rolling_resistance.csv lists it.
    struct RunRollingResistance
    {
      std::string road, run;
      bool        error_bar = false; ///< a run of an error bar's other level, not of the plan
      double      speed_kmh = 0., mpd = 0., time_step = 0., distance = 0.;
      /// Each part, in the order of all_power_parts.
      std::array<RollingResistance, 3> parts;

      const RollingResistance &
      operator[](const PowerPart part) const
      {
        return parts[static_cast<std::size_t>(part)];
      }

      RollingResistance &
      operator[](const PowerPart part)
      {
        return parts[static_cast<std::size_t>(part)];
      }
    };

    /// Lines on @p out for each run of @p runs with an error bar: each
    /// part's coefficient, standard error and each discretisation's error
    /// bar (none if no run has one).
    void
    print_rolling_resistance_errors(std::ostream                            &out,
                                    const std::vector<RunRollingResistance> &runs);

    /**
     * @brief rolling_resistance.csv (every run, those of the error bars'
     * other levels marked, each part) and rolling_resistance.png (the sum's
     * coefficient against the roads' MPD, one line per speed, with its
     * standard error and its error bars combined in quadrature, and the
     * structure's part dashed,
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

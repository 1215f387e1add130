#pragma once

#include <Eigen/Core>

#include <vector>

/**
 * @file
 * The tread's small-scale losses: the power the rubber dissipates in the
 * deformation the contact grid's local term carries (the tread below the
 * Green's functions' rectangles, greentread/contact/contact_grid.h, and the
 * finite blocks of a tread pattern, greentread/contact/tread_block.h), which
 * the contact solve treats as elastic. Implemented in
 * source/analysis/tread_losses.cc.
 *
 * **In the rubber's own frame.** The contact points stay under the axle
 * while the road, and the tread with it (it does not slip), pass under them
 * at V towards -x. A summit's imprint passes a fixed point in a few
 * hundred microseconds, but the rubber that carries it keeps it: what the
 * rubber undergoes is the load of its passage through the patch, the
 * texture's imprint, and the tyre's vibration. So the meter follows the
 * rubber: every m steps (m = dx / (V dt) rounded, at least 1: the strips
 * about one rectangle apart, whatever the step) a strip of tread, m V dt
 * long and one row of points wide, enters at the patch's leading edge (the
 * last column of points) and moves with the road, its end force f and local
 * displacement w (w = L f, the local term) read from the grid at every step
 * by linear interpolation along x, until it leaves behind the first column.
 * Its history of N samples, N dt the time it spends in the patch, is then
 * complete. The cost is N^2 per row and strip: at a step m times finer, m^2
 * times the work per unit time (a strip per step would make it m^3).
 *
 * **The rubber's law.** A loss factor eta independent of frequency
 * (`Materials/Tread pattern/Loss factor`, the one the finite-element tread turns into
 * Rayleigh damping at the Green's functions' scale). A layer with that
 * hysteresis dissipates, over a history that starts and ends at rest,
 * \f[
 *   E = \frac{\eta}{2\pi} \int |\omega|\, \mathrm{Re}\big(F^*(\omega) W(\omega)\big)\, d\omega
 *     = \eta \sum_{k,l} c_{k-l}\, f_k w_l,
 * \f]
 * the second form exact for samples read as band-limited at the step (the
 * integral over |omega| < pi / dt), with \f$c_0 = \pi/2\f$, \f$c_m =
 * -2/(\pi m^2)\f$ for odd m and 0 for even m. The loss is not fed back into
 * the contact: the run stays elastic below the Green's functions' scale, and
 * the power is the first term of an expansion in eta.
 *
 * **What the texture adds.** A strip's history is its passage's load (the
 * mean over the strips of its row) and a fluctuation: the texture's imprint,
 * the vibration, and a tread pattern's blocks and grooves. The meter counts
 * the fluctuation's share,
 * \f$\sum_X Q(f_X - \bar f,\, w_X - \bar w)\f$ with \f$\bar f\f$ the
 * row's mean history, over the last @p memory metres of road (a running
 * mean; the static start's strip begins it): on a flat road a slick tyre's
 * strips are all alike and the part is 0, as the structure's part of the
 * rolling resistance is. The passage's own hysteresis belongs to a turning
 * tyre's main rolling resistance, which the model does not have
 * (rolling_resistance.h). The running mean's own scatter adds about
 * 1 / (2 N) of the part, N the strips it holds (0.15% at 0.25 m of road,
 * strips 0.77 mm apart on the main job's grid and step).
 *
 * **Power.** Each strip carries the forces of an m V dt long part of the
 * dx long rectangles it crosses, so it dissipates (m V dt / dx) E, and the
 * strip that leaves at a step puts that energy in the step's record.
 */

namespace greentread
{
  namespace analysis
  {
    /// The contact grid as the meter reads it: points p = i_x ny + i_y, x increasing.
    struct TreadLossGrid
    {
      unsigned int nx = 0, ny = 0;
      double       dx = 0.; ///< [m]
    };

    /**
     * @brief The tread's losses, step by step (file documentation): one per
     * run, fed each step's end force and local displacement on the grid.
     */
    class TreadLossMeter
    {
    public:
      /**
       * @param[in] loss_factor eta, at least 0.
       * @param[in] time_step dt [s], above 0.
       * @param[in] speed V [m/s], above 0.
       * @param[in] grid The contact grid, at least 2 points along x.
       * @param[in] f_start, w_start The end force and local displacement at
       *            the static start, held since t = -infinity: the strips
       *            already in the patch read them for their past.
       * @param[in] memory The running mean's length of road [m].
       * @throws InputError naming 'Materials/Tread pattern/Loss factor' if eta is
       *         negative or not finite; std::invalid_argument for the others.
       */
      TreadLossMeter(double                 loss_factor,
                     double                 time_step,
                     double                 speed,
                     const TreadLossGrid   &grid,
                     const Eigen::VectorXd &f_start,
                     const Eigen::VectorXd &w_start,
                     double                 memory = 0.25);

      /**
       * @brief The energy [J] the strips that leave the patch at this step
       * dissipated beyond their row's mean passage, from the step's end
       * force @p f and local displacement @p w.
       */
      double
      add(const Eigen::VectorXd &f, const Eigen::VectorXd &w);

      /// The samples of a strip's history: the steps it spends in the patch.
      unsigned int
      history_length() const
      {
        return n_age;
      }

      /**
       * @brief The hysteretic energy of one history, \f$\sum_{k,l} c_{k-l}
       * f_k w_l\f$ (file documentation; eta = 1): @p f and @p w as columns of
       * equal length, summed over the columns.
       */
      static double
      hysteresis(const Eigen::MatrixXd &f, const Eigen::MatrixXd &w);

    private:
      void
      fill(unsigned int slot, unsigned int age, const Eigen::VectorXd &f, const Eigen::VectorXd &w);

      /// The slot of the strip that entered at time index @p entry (a multiple of stride).
      unsigned int
      slot_of(long entry) const;

      double        eta, strip = 0.; ///< eta, and the strips' spacing over dx, stride V dt / dx
      TreadLossGrid grid;
      /// A strip enters every stride steps; n_slots strips are in the patch at most.
      unsigned int stride = 1, n_slots = 0;
      unsigned int n_age = 0, n_memory = 0, seen = 0;
      long         next = 1;            ///< the time index of the next add() (0: the static start)
      std::vector<unsigned int> column; ///< per age: the column at or behind the strip
      std::vector<double>       weight; ///< per age: the next column's interpolation weight
      /// Per strip in the patch (slot_of() its entry's time index):
      /// its history, one row per age, one column per row of points.
      std::vector<Eigen::MatrixXd> history_f, history_w;
      Eigen::MatrixXd              mean_f, mean_w, kernel, cw;
    };
  } // namespace analysis
} // namespace greentread

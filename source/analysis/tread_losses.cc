#include <greentread/analysis/tread_losses.h>
#include <greentread/base/exceptions.h>

#include <cmath>
#include <stdexcept>

namespace greentread
{
  namespace analysis
  {
    namespace
    {
      /// The chain's relaxation frequencies: 10^(k/2) Hz, k = -2 .. 12.
      constexpr int first_half_decade = -2, last_half_decade = 12;
      /// Where the chain's loss factor is eta: the geometric centre.
      constexpr double centre_frequency = 316.22776601683796;

      double
      debye_sum(const std::vector<double> &tau, const double frequency)
      {
        const double omega = 2. * M_PI * frequency;
        double       sum   = 0.;
        for (const double t : tau)
          sum += omega * t / (1. + omega * t * omega * t);
        return sum;
      }
    } // namespace



    std::vector<double>
    TreadLossMeter::relaxation_frequencies()
    {
      std::vector<double> f;
      for (int k = first_half_decade; k <= last_half_decade; ++k)
        f.push_back(std::pow(10., 0.5 * k));
      return f;
    }



    TreadLossMeter::TreadLossMeter(const double           loss_factor,
                                   const double           time_step,
                                   const Eigen::VectorXd &f_start,
                                   const Eigen::VectorXd &w_start)
        : dt(time_step)
        , f_last(f_start)
        , w_last(w_start)
    {
      if (f_start.size() != w_start.size())
        throw std::invalid_argument("TreadLossMeter: " + std::to_string(f_start.size()) +
                                    " forces and " + std::to_string(w_start.size()) +
                                    " displacements at the start");
      if (!(loss_factor >= 0.) || !std::isfinite(loss_factor))
        throw InputError("parameter 'Materials/Tread pattern/Loss factor' = " + format_short(loss_factor) +
                         "; allowed: a finite number >= 0");
      if (!(dt > 0.))
        throw std::invalid_argument("TreadLossMeter: the time step " + format_short(dt) +
                                    " s is not above 0");
      for (const double f : relaxation_frequencies())
        {
          const double t = 1. / (2. * M_PI * f);
          // e = exp(-dt / tau) and (1 - e) tau / dt, the latter by expm1 so
          // that it keeps its digits when dt << tau (it tends to 1).
          const double e = std::exp(-dt / t);
          tau.push_back(t);
          decay.push_back(e);
          lag.push_back(-std::expm1(-dt / t) * t / dt);
        }
      c = loss_factor / debye_sum(tau, centre_frequency);
      // Relaxed at the static start: every element's displacement is w's.
      y = w_start.replicate(1, static_cast<Eigen::Index>(tau.size()));
      g = f_start.replicate(1, static_cast<Eigen::Index>(tau.size()));
    }



    double
    TreadLossMeter::add(const Eigen::VectorXd &f_end, const Eigen::VectorXd &w_end)
    {
      if (w_end.size() != w_last.size() || f_end.size() != w_last.size())
        throw std::invalid_argument("TreadLossMeter::add: " + std::to_string(f_end.size()) +
                                    " forces and " + std::to_string(w_end.size()) +
                                    " displacements for " + std::to_string(w_last.size()) +
                                    " points");
      // Each element's step in place, point by point: no temporaries. The
      // work into the element over the step, exact for f and w linear in it:
      // int f dy = f_n dy + df (y_{n+1} - wbar + (tau / dt) dy), wbar the
      // step's mean w; less the change of the energy it stores, g . y / 2
      // (g the lagged force: y = L g for a constant L).
      const Eigen::Index n    = w_end.size();
      double             work = 0.;
      for (std::size_t j = 0; j < tau.size(); ++j)
        {
          double      *yj = y.col(static_cast<Eigen::Index>(j)).data();
          double      *gj = g.col(static_cast<Eigen::Index>(j)).data();
          const double e = decay[j], l = lag[j], r = tau[j] / dt;
          for (Eigen::Index p = 0; p < n; ++p)
            {
              const double y_next =
                e * yj[p] + w_end[p] - e * w_last[p] - l * (w_end[p] - w_last[p]);
              const double g_next =
                e * gj[p] + f_end[p] - e * f_last[p] - l * (f_end[p] - f_last[p]);
              const double dy = y_next - yj[p];
              work += f_last[p] * dy +
                      (f_end[p] - f_last[p]) * (y_next - 0.5 * (w_end[p] + w_last[p]) + r * dy) -
                      0.5 * (g_next * y_next - gj[p] * yj[p]);
              yj[p] = y_next;
              gj[p] = g_next;
            }
        }
      f_last = f_end;
      w_last = w_end;
      return c * work;
    }



    double
    TreadLossMeter::loss_factor(const double frequency) const
    {
      return c * debye_sum(tau, frequency);
    }
  } // namespace analysis
} // namespace greentread

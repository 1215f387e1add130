#include <greentread/analysis/tread_losses.h>
#include <greentread/base/exceptions.h>

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>

namespace greentread
{
  namespace analysis
  {
    namespace
    {
      /// The hysteresis kernel's Toeplitz matrix c_{k-l}, n x n (file documentation).
      Eigen::MatrixXd
      hysteresis_kernel(const Eigen::Index n)
      {
        Eigen::MatrixXd c(n, n);
        for (Eigen::Index k = 0; k < n; ++k)
          for (Eigen::Index l = 0; l < n; ++l)
            {
              const Eigen::Index m = std::abs(k - l);
              c(k, l) = m == 0 ? M_PI / 2. : m % 2 == 1 ? -2. / (M_PI * double(m * m)) : 0.;
            }
        return c;
      }
    } // namespace



    double
    TreadLossMeter::hysteresis(const Eigen::MatrixXd &f, const Eigen::MatrixXd &w)
    {
      if (f.rows() != w.rows() || f.cols() != w.cols())
        throw std::invalid_argument("TreadLossMeter::hysteresis: the force is " +
                                    std::to_string(f.rows()) + " x " + std::to_string(f.cols()) +
                                    ", the displacement " + std::to_string(w.rows()) + " x " +
                                    std::to_string(w.cols()));
      return (f.array() * (hysteresis_kernel(f.rows()) * w).array()).sum();
    }



    TreadLossMeter::TreadLossMeter(const double           loss_factor,
                                   const double           time_step,
                                   const double           speed,
                                   const TreadLossGrid   &grid_,
                                   const Eigen::VectorXd &f_start,
                                   const Eigen::VectorXd &w_start,
                                   const double           memory)
        : eta(loss_factor)
        , grid(grid_)
    {
      if (!std::isfinite(loss_factor) || loss_factor < 0.)
        throw InputError("'Materials/Tread pattern/Loss factor' is " + std::to_string(loss_factor) +
                         ": the tread's losses need a loss factor of 0 or more");
      if (!(time_step > 0.) || !(speed > 0.) || !(grid.dx > 0.) || grid.nx < 2 || grid.ny < 1 ||
          !(memory > 0.))
        throw std::invalid_argument("TreadLossMeter: the step " + std::to_string(time_step) +
                                    " s, the speed " + std::to_string(speed) +
                                    " m/s, the grid of " + std::to_string(grid.nx) + " x " +
                                    std::to_string(grid.ny) + " points " + std::to_string(grid.dx) +
                                    " m apart and the memory " + std::to_string(memory) +
                                    " m must be above 0, with 2 points along x at least");
      const std::size_t n_points = std::size_t(grid.nx) * grid.ny;
      if (std::size_t(f_start.size()) != n_points || std::size_t(w_start.size()) != n_points)
        throw std::invalid_argument("TreadLossMeter: the static start has " +
                                    std::to_string(f_start.size()) + " forces and " +
                                    std::to_string(w_start.size()) + " displacements for " +
                                    std::to_string(n_points) + " points");
      // A strip enters at the last column (position nx - 1 in columns)
      // every `stride` steps, about one rectangle apart, and is at
      // (nx - 1) - k V dt / dx at age k; it leaves once that is below 0.
      const double step_in_columns = speed * time_step / grid.dx;
      stride = std::max(1u, static_cast<unsigned int>(std::lround(1. / step_in_columns)));
      strip  = stride * step_in_columns;
      n_age =
        static_cast<unsigned int>(std::floor((grid.nx - 1) / step_in_columns * (1. + 1e-12))) + 1;
      n_slots  = (n_age + stride - 1) / stride + 1;
      n_memory = std::max(1u, static_cast<unsigned int>(std::round(memory / (strip * grid.dx))));
      for (unsigned int k = 0; k < n_age; ++k)
        {
          const double       u = std::max(0., (grid.nx - 1) - k * step_in_columns);
          const unsigned int i = std::min(grid.nx - 2, static_cast<unsigned int>(std::floor(u)));
          column.push_back(i);
          weight.push_back(u - i);
        }
      kernel = hysteresis_kernel(n_age);
      history_f.assign(n_slots, Eigen::MatrixXd::Zero(n_age, grid.ny));
      history_w = history_f;
      cw.resize(n_age, grid.ny);
      // The strips that entered at time indices 1 - n_age .. 0 have spent
      // their past in the static start.
      for (long entry = 0; entry > -long(n_age); entry -= stride)
        for (long k = 0; k <= -entry; ++k)
          fill(slot_of(entry), static_cast<unsigned int>(k), f_start, w_start);
    }



    unsigned int
    TreadLossMeter::slot_of(const long entry) const
    {
      const long s = entry / long(stride), n = long(n_slots);
      return static_cast<unsigned int>((s % n + n) % n);
    }



    void
    TreadLossMeter::fill(const unsigned int     slot,
                         const unsigned int     age,
                         const Eigen::VectorXd &f,
                         const Eigen::VectorXd &w)
    {
      const unsigned int i = column[age], ny = grid.ny;
      const double       a = weight[age];
      history_f[slot].row(age) =
        ((1. - a) * f.segment(i * ny, ny) + a * f.segment((i + 1) * ny, ny)).transpose();
      history_w[slot].row(age) =
        ((1. - a) * w.segment(i * ny, ny) + a * w.segment((i + 1) * ny, ny)).transpose();
    }



    double
    TreadLossMeter::add(const Eigen::VectorXd &f, const Eigen::VectorXd &w)
    {
      if (f.size() != history_f[0].cols() * Eigen::Index(grid.nx) || w.size() != f.size())
        throw std::invalid_argument("TreadLossMeter::add: " + std::to_string(f.size()) +
                                    " forces and " + std::to_string(w.size()) +
                                    " displacements for a grid of " +
                                    std::to_string(grid.nx * grid.ny) + " points");
      const long n = next++;
      // The strip that entered at time index n - k is at age k.
      for (unsigned int k = 0; k < n_age; ++k)
        if ((n - long(k)) % long(stride) == 0)
          fill(slot_of(n - long(k)), k, f, w);
      // The strip at the last age leaves, if one entered then.
      const long entry = n - long(n_age) + 1;
      if (entry % long(stride) != 0)
        return 0.;
      const unsigned int     slot = slot_of(entry);
      const Eigen::MatrixXd &hf = history_f[slot], &hw = history_w[slot];
      double                 energy = 0.;
      if (seen == 0)
        {
          // The first strip to leave starts the mean: its passage is the
          // static start's.
          mean_f = hf;
          mean_w = hw;
        }
      else
        {
          cw.noalias()   = kernel * (hw - mean_w);
          energy         = eta * strip * ((hf - mean_f).array() * cw.array()).sum();
          const double a = 1. / std::min(seen + 1, n_memory);
          mean_f += a * (hf - mean_f);
          mean_w += a * (hw - mean_w);
        }
      ++seen;
      if (!std::isfinite(energy))
        throw NumericalError("the tread's losses are not finite at time index " +
                             std::to_string(n) + " (a contact force or local displacement is not)");
      return energy;
    }
  } // namespace analysis
} // namespace greentread

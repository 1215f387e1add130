#include <greentread/base/exceptions.h>
#include <greentread/convolution/direct_convolution.h>

#include <deal.II/base/quadrature_lib.h>

#include <Eigen/Core>

#include <algorithm>
#include <cmath>

namespace greentread
{
  namespace convolution
  {
    unsigned int
    truncation_length(const std::function<double(double)> &g,
                      const double                         dt,
                      const double                         threshold,
                      const unsigned int                   n_max)
    {
      if (threshold <= 0.)
        return n_max + 1;
      std::vector<double> amplitude(n_max + 1);
      double              largest = 0.;
      for (unsigned int m = 0; m <= n_max; ++m)
        {
          amplitude[m] = std::abs(g(m * dt));
          largest      = std::max(largest, amplitude[m]);
        }
      unsigned int last = 0;
      for (unsigned int m = 0; m <= n_max; ++m)
        if (amplitude[m] >= threshold * largest)
          last = m;
      return last + 1;
    }



    DirectConvolution::DirectConvolution(const std::function<double(double)> &g,
                                         const std::function<double(double)> &dg,
                                         const double                         dt_,
                                         const unsigned int                   n_kernel_,
                                         const unsigned int                   n_steps_,
                                         const double                         rate)
        : Convolution(dt_)
        , n_kernel(std::max(1u, n_kernel_))
        , n_steps(n_steps_)
    {
      // Gauss-Legendre on [0,1], 8 points per sub-interval, with sub-intervals
      // short enough that the kernel turns by less than half a radian on each.
      const dealii::QGauss<1> gauss(8);
      const unsigned int      n_sub =
        std::max(1u, static_cast<unsigned int>(std::ceil(rate * dt / 0.5)));

      const auto weights = [&](const std::function<double(double)> &f, const unsigned int lag,
                               double &wa, double &wb) {
        wa = wb = 0.;
        for (unsigned int s = 0; s < n_sub; ++s)
          for (unsigned int q = 0; q < gauss.size(); ++q)
            {
              const double x     = (s + gauss.point(q)[0]) / n_sub; // r / dt
              const double w     = gauss.weight(q) / n_sub * dt;
              const double value = f((lag + x) * dt);
              wa += w * value * x;
              wb += w * value * (1. - x);
            }
      };

      rev_wa.resize(n_kernel);
      rev_wb.resize(n_kernel);
      rev_va.resize(n_kernel);
      rev_vb.resize(n_kernel);
      rev_gu.resize(n_kernel);
      rev_gv.resize(n_kernel);
      for (unsigned int lag = 0; lag < n_kernel; ++lag)
        {
          const unsigned int i = n_kernel - 1 - lag;
          weights(g, lag, rev_wa[i], rev_wb[i]);
          weights(dg, lag, rev_va[i], rev_vb[i]);
          rev_gu[i] = g(lag * dt);
          rev_gv[i] = dg(lag * dt);
        }

      // The current step, independent of the truncation.
      double wa0, wb0, va0, vb0;
      weights(g, 0, wa0, wb0);
      weights(dg, 0, va0, vb0);
      const double g0 = g(0.);
      psi.u           = {{g(dt), wa0, wb0, g0}};
      psi.v           = {{dg(dt), va0, vb0 + g0, dg(0.)}};

      for (const double x : psi.u)
        if (!std::isfinite(x))
          throw NumericalError("direct convolution: the Green's function is not finite near t = 0");

      start_values.assign(n_steps + 1, 0.);
      end_values.assign(n_steps + 1, 0.);
      impulses.assign(n_steps + 2, 0.);
    }



    Response
    DirectConvolution::history()
    {
      using Map                  = Eigen::Map<const Eigen::VectorXd>;
      const unsigned int L_steps = std::min(n, n_kernel - 1);
      const unsigned int L_nodes = std::min(n + 1, n_kernel - 1);
      const unsigned int k_steps = n_kernel - 1 - L_steps;
      const unsigned int k_nodes = n_kernel - 1 - L_nodes;

      const Map a(start_values.data() + (n - L_steps), L_steps);
      const Map b(end_values.data() + (n - L_steps), L_steps);
      const Map p(impulses.data() + (n + 1 - L_nodes), L_nodes);

      Response r;
      r.u = Map(rev_wa.data() + k_steps, L_steps).dot(a) +
            Map(rev_wb.data() + k_steps, L_steps).dot(b) +
            Map(rev_gu.data() + k_nodes, L_nodes).dot(p);
      r.v = Map(rev_va.data() + k_steps, L_steps).dot(a) +
            Map(rev_vb.data() + k_steps, L_steps).dot(b) +
            Map(rev_gv.data() + k_nodes, L_nodes).dot(p);
      return r;
    }



    void
    DirectConvolution::advance(const StepLoad &load)
    {
      if (n >= n_steps)
        throw NumericalError("direct convolution: more steps than it was set up for (" +
                             std::to_string(n_steps) + ")");
      impulses[n] += load.impulse_start;
      start_values[n] = load.start;
      end_values[n]   = load.end;
      impulses[n + 1] += load.impulse_end;
      ++n;
    }
  } // namespace convolution
} // namespace greentread

#include <greentread/sdof/oscillator.h>

#include <cmath>

namespace greentread
{
  namespace sdof
  {
    Oscillator::Oscillator(const OscillatorParameters &p)
        : M(p.mass)
        , K(p.stiffness)
        , xi(p.damping_ratio)
        , g(p.gravity)
        , C(2. * p.damping_ratio * std::sqrt(p.stiffness * p.mass))
        , omega0(std::sqrt(p.stiffness / p.mass))
        , sigma(p.damping_ratio * std::sqrt(p.stiffness / p.mass))
        , delta(K / M * (1. - p.damping_ratio) * (1. + p.damping_ratio))
    {
    }



    namespace
    {
      /// cos(sqrt(mu)) and sin(sqrt(mu))/sqrt(mu) as power series in mu, |mu| < 1.
      void
      trigonometric_series(const double mu, double &c, double &s)
      {
        c           = 0.;
        s           = 0.;
        double term = 1.; // (-mu)^k / (2k)!
        for (unsigned int k = 0; k < 14; ++k)
          {
            c += term;
            s += term / double(2 * k + 1);
            term *= -mu / double((2 * k + 1) * (2 * k + 2));
          }
      }
    } // namespace



    void
    Oscillator::damped_functions(const double t, double &c, double &s) const
    {
      const double decay = std::exp(-sigma * t);
      const double mu    = delta * t * t;
      if (std::abs(mu) < 1.)
        {
          trigonometric_series(mu, c, s);
          c *= decay;
          s *= decay * t;
        }
      else if (delta > 0.)
        {
          const double omega_d = std::sqrt(delta);
          c                    = decay * std::cos(omega_d * t);
          s                    = decay * std::sin(omega_d * t) / omega_d;
        }
      else
        {
          // e^{-sigma t} cosh(beta t) and sinh: the exponentials folded
          // together so that neither overflows (beta < sigma), and no
          // cancellation since beta t >= 1 here.
          const double beta = std::sqrt(-delta);
          const double grow = std::exp((beta - sigma) * t), fall = std::exp(-(beta + sigma) * t);
          c = 0.5 * (grow + fall);
          s = (grow - fall) / (2. * beta);
        }
    }



    double
    Oscillator::damped_cos(const double t) const
    {
      double c, s;
      damped_functions(t, c, s);
      return c;
    }



    double
    Oscillator::damped_sin(const double t) const
    {
      double c, s;
      damped_functions(t, c, s);
      return s;
    }



    double
    Oscillator::green(const double t) const
    {
      return t < 0. ? 0. : damped_sin(t) / M;
    }



    double
    Oscillator::green_derivative(const double t) const
    {
      if (t < 0.)
        return 0.;
      double c, s;
      damped_functions(t, c, s);
      return (c - sigma * s) / M;
    }



    std::complex<double>
    Oscillator::frequency_response(const double omega) const
    {
      return 1. / std::complex<double>(K - omega * omega * M, omega * C);
    }



    modal::ModalModel
    Oscillator::modal_model() const
    {
      modal::ModalModel model;
      if (std::abs(xi - 1.) <= 1e-8)
        model.add_double(-sigma, 0., 1. / M);
      else if (xi < 1.)
        {
          const double omega_d = std::sqrt(delta);
          model.add_pair({-sigma, omega_d}, {0., -1. / (2. * M * omega_d)});
        }
      else
        {
          // Over-damped: the two roots of M s^2 + C s + K, the smaller one
          // without cancellation (product of the roots is K/M).
          const double beta    = std::sqrt(-delta);
          const double fast    = -(sigma + beta);
          const double slow    = (K / M) / fast;
          const double residue = 1. / (M * (slow - fast));
          model.add_real(slow, residue);
          model.add_real(fast, -residue);
        }
      return model;
    }



    void
    Oscillator::free_motion(const double u0, const double v0, const double t, double &u, double &v)
      const
    {
      const double x0 = u0 - static_deflection();
      double       c, s;
      damped_functions(t, c, s);
      u = static_deflection() + c * x0 + s * (v0 + sigma * x0);
      v = c * v0 - s * (omega0 * omega0 * x0 + sigma * v0);
    }
  } // namespace sdof
} // namespace greentread

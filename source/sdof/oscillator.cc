#include <greentread/base/exceptions.h>
#include <greentread/base/parameters.h>
#include <greentread/sdof/oscillator.h>

#include <cmath>

namespace greentread
{
  namespace sdof
  {
    void
    OscillatorParameters::declare_parameters(dealii::ParameterHandler &prm)
    {
      prm.enter_subsection("Oscillator");
      {
        using base::RangePattern;
        prm.declare_entry("Mass", "1", base::RangePattern::positive("kg"),
                          "Mass M. Unit: kg. Table A.1: 1 kg.");
        prm.declare_entry("Stiffness", "4e5", base::RangePattern::positive("N/m"),
                          "Spring stiffness K. Unit: N/m. Table A.1: 4e5 N/m.");
        prm.declare_entry("Damping ratio", "0.02", base::RangePattern::closed(0., 1000., ""),
                          "Viscous damping ratio xi = C / (2 sqrt(K M)); xi < 0 would feed "
                          "energy in. Values >= 1 give real poles. Unit: 1. Table A.1: 0.02.");
        prm.declare_entry("Gravity", "9.81", base::RangePattern::non_negative("m/s^2"),
                          "Gravitational acceleration g pressing the mass onto the road "
                          "(the load -M g of Eq. 30). Unit: m/s^2.");
        prm.declare_entry("Speed (kph)", "0.36", base::RangePattern::positive("km/h"),
                          "Speed V0 at which the oscillator travels over the road. "
                          "Unit: km/h, as every speed of GreenTread. Paper, Section 3: "
                          "0.1 m/s = 0.36 km/h.");
        prm.declare_entry("Green's function", "analytic",
                          dealii::Patterns::Selection("analytic|identified"),
                          "'analytic': the closed-form g(t) and its exact modal form. "
                          "'identified': the modal model that LSCE (subsection "
                          "Identification) finds from the oscillator's own FRF, sampled "
                          "from 0 to 'FRF maximum frequency'; the scene then also reports "
                          "the difference from the run with the exact modal form.");
        prm.declare_entry("FRF maximum frequency", "1000", base::RangePattern::positive("Hz"),
                          "Highest line of the FRF identified when Green's function = "
                          "identified. Unit: Hz.");
        prm.declare_entry("FRF line spacing", "1", base::RangePattern::positive("Hz"),
                          "Line spacing of that FRF. Unit: Hz.");
      }
      prm.leave_subsection();
    }



    void
    OscillatorParameters::parse_parameters(dealii::ParameterHandler &prm)
    {
      prm.enter_subsection("Oscillator");
      {
        mass          = prm.get_double("Mass");
        stiffness     = prm.get_double("Stiffness");
        damping_ratio = prm.get_double("Damping ratio");
        gravity       = prm.get_double("Gravity");
        speed         = prm.get_double("Speed (kph)") * 1000. / 3600.; // m/s (0.36 -> 0.1 exactly)
        identified_green  = prm.get("Green's function") == "identified";
        frf_max_frequency = prm.get_double("FRF maximum frequency");
        frf_line_spacing  = prm.get_double("FRF line spacing");
      }
      prm.leave_subsection();
      require_parameter(frf_line_spacing <= 0.5 * frf_max_frequency &&
                          frf_max_frequency / frf_line_spacing <= 1e6,
                        "Oscillator/FRF line spacing", frf_line_spacing,
                        "a spacing that gives from 2 to 1e6 lines up to 'FRF maximum "
                        "frequency' = " + format_number(frf_max_frequency) + " Hz");
    }



    Oscillator::Oscillator(const OscillatorParameters &p)
      : M(p.mass)
      , K(p.stiffness)
      , xi(p.damping_ratio)
      , g(p.gravity)
      , C(2. * p.damping_ratio * std::sqrt(p.stiffness * p.mass))
      , omega0(std::sqrt(p.stiffness / p.mass))
      , sigma(p.damping_ratio * std::sqrt(p.stiffness / p.mass))
      , delta(K / M * (1. - p.damping_ratio) * (1. + p.damping_ratio))
    {}



    namespace
    {
      /// cos(sqrt(mu)) and sin(sqrt(mu))/sqrt(mu) as power series in mu, |mu| < 1.
      void
      trigonometric_series(const double mu, double &c, double &s)
      {
        c = 0.;
        s = 0.;
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
          c                 = 0.5 * (grow + fall);
          s                 = (grow - fall) / (2. * beta);
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
          const double beta = std::sqrt(-delta);
          const double fast = -(sigma + beta);
          const double slow = (K / M) / fast;
          const double residue = 1. / (M * (slow - fast));
          model.add_real(slow, residue);
          model.add_real(fast, -residue);
        }
      return model;
    }



    void
    Oscillator::free_motion(const double u0,
                            const double v0,
                            const double t,
                            double      &u,
                            double      &v) const
    {
      const double x0 = u0 - static_deflection();
      double       c, s;
      damped_functions(t, c, s);
      u               = static_deflection() + c * x0 + s * (v0 + sigma * x0);
      v               = c * v0 - s * (omega0 * omega0 * x0 + sigma * v0);
    }
  } // namespace sdof
} // namespace greentread

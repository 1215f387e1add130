#pragma once

#include <array>
#include <string>

/**
 * @file
 * The common interface of the three ways to evaluate
 * \f$u(t) = \int_0^t g(t-\tau)\,q(\tau)\,d\tau\f$ (Eq. 4) step by step.
 *
 * The load q is described step by step: on \f$[t_n, t_{n+1}]\f$ it is linear
 * between a start and an end value (the two Gauss-point forces of Eq. 23
 * define exactly such a line), plus impulses at the two ends. The impulses let
 * the kinematic contact represent an impact, which a bounded force inside one
 * step cannot (see greentread/contact/kinematic_contact.h).
 */

namespace greentread
{
  namespace convolution
  {
    /**
     * @brief The load on one time step \f$[t_n, t_{n+1}]\f$.
     */
    struct StepLoad
    {
      /// Impulse at \f$t_n\f$ [N s].
      double impulse_start = 0.;
      /// Force at \f$t_n^+\f$ of the part linear in time [N].
      double start = 0.;
      /// Force at \f$t_{n+1}^-\f$ of the part linear in time [N].
      double end = 0.;
      /// Impulse at \f$t_{n+1}\f$ [N s].
      double impulse_end = 0.;

      StepLoad &
      operator+=(const StepLoad &other)
      {
        impulse_start += other.impulse_start;
        start += other.start;
        end += other.end;
        impulse_end += other.impulse_end;
        return *this;
      }

      /// Total impulse of the step [N s].
      double
      impulse(double time_step) const
      {
        return impulse_start + impulse_end + 0.5 * (start + end) * time_step;
      }
    };

    /**
     * @brief Displacement and velocity at one instant.
     */
    struct Response
    {
      double u = 0.;
      double v = 0.;
    };

    /**
     * @brief The response at \f$t_{n+1}\f$ to a unit value of each component of
     * StepLoad, in the order impulse_start, start, end, impulse_end. The
     * velocity is the one just after \f$t_{n+1}\f$ (after impulse_end).
     *
     * This is the operator \f$\Psi\f$ of Eq. (20), for one point.
     */
    struct Influence
    {
      std::array<double, 4> u{};
      std::array<double, 4> v{};

      /// The response to @p load of the current step alone.
      Response
      of(const StepLoad &load) const
      {
        const std::array<double, 4> x = {
          {load.impulse_start, load.start, load.end, load.impulse_end}};
        Response r;
        for (unsigned int i = 0; i < 4; ++i)
          {
            r.u += u[i] * x[i];
            r.v += v[i] * x[i];
          }
        return r;
      }
    };

    /**
     * @brief Step-by-step convolution of one Green's function with one load
     * history (a single point). Use:
     * @code
     *   for (n = 0; n < N; ++n) {
     *     Response h = conv.history();      // t_{n+1}, current step unloaded
     *     StepLoad q = ...;                 // decided from h and influence()
     *     conv.advance(q);                  // record the step, n -> n+1
     *   }
     * @endcode
     * history() must be called exactly once before each advance().
     */
    class Convolution
    {
    public:
      explicit Convolution(double time_step)
          : dt(time_step)
      {
      }

      virtual ~Convolution() = default;

      /**
       * @brief The displacement and velocity at \f$t_{n+1}\f$ due to every
       * load recorded so far, the current step carrying none: the history
       * term \f$u^h, v^h\f$ of Eqs. (16)-(18).
       */
      virtual Response
      history() = 0;

      /// The response to unit loads of the current step.
      const Influence &
      influence() const
      {
        return psi;
      }

      /// Record the load of the current step and move to the next one.
      virtual void
      advance(const StepLoad &load) = 0;

      /// The index n of the current step \f$[t_n, t_{n+1}]\f$.
      unsigned int
      step() const
      {
        return n;
      }

      double
      time_step() const
      {
        return dt;
      }

      /// "direct", "modal-paper" or "modal-recursive".
      virtual std::string
      name() const = 0;

      /// N_g (kernel length) for direct, N_m (modes) for the modal methods.
      virtual unsigned int
      size() const = 0;

    protected:
      double       dt;
      unsigned int n = 0;
      Influence    psi;
    };
  } // namespace convolution
} // namespace greentread

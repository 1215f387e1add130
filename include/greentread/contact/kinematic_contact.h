#pragma once

#include <greentread/convolution/convolution.h>

#include <string>

/**
 * @file
 * The kinematic contact condition of Eqs. (16)-(28) for one point, with the
 * impact rule that keeps every force non-negative.
 *
 * At the end of a step in contact the point must sit on the road and move
 * with it: \f$u(t_{n+1}) = u^r\f$ and \f$v(t_{n+1}) = v^r\f$ (Eq. 21). The paper
 * meets both with two forces at the Gauss points of the step (Eq. 23), i.e.
 * with a load linear over the step. That works while the point rides on the
 * road. At an impact it does not: the approach velocity has to be removed by
 * an impulse, and two bounded forces inside the step can only imitate an
 * impulse at its start by a large positive and a negative force.
 *
 * **The rule (impulse completion).** The load of a contact step is sought
 * as a non-negative combination of four generators, ordered by where in the
 * step they act: an impulse at \f$t_n\f$, the linear load's start value, its
 * end value, an impulse at \f$t_{n+1}\f$. Both conditions are met exactly,
 * with the first pair of neighbours that does so with non-negative values:
 *   1. (start, end): the paper's two Gauss forces, used while riding;
 *   2. (impulse at t_n, start): an impact early in the step;
 *   3. (end, impulse at t_{n+1}): an impact late in the step.
 * For one point the four generators move (u, v) in directions of increasing
 * u/v ratio (about 0, dt/3, 2dt/3 and dt for a mass), so 1-3 cover every
 * approach with \f$0 \le \Delta u \le \Delta v\,g(\Delta t)/g'(\Delta t)\f$;
 * each impact is then met exactly at the end of its step and no error is
 * carried into the contact that follows.
 *
 * **Fallback.** Outside that cone (the point already separating while
 * penetrating, or a penetration left from before), the displacement is
 * matched with the impulse at \f$t_n\f$ alone, the generator that moves u
 * most per unit of velocity: no penetration, the smallest velocity error.
 * Such steps are counted and reported.
 */

namespace greentread
{
  namespace contact
  {
    /// Which branch of the rule decided a step.
    enum class KinematicBranch
    {
      separated,    ///< predicted position above the road: no force
      riding,       ///< (start, end): both Gauss forces >= 0
      impact_early, ///< impulse at t_n and start force
      impact_late,  ///< end force and impulse at t_{n+1}
      fallback      ///< impulse at t_n matching the displacement only
    };

    std::string
    to_string(KinematicBranch branch);

    /// The outcome of one step of kinematic contact.
    struct KinematicStep
    {
      convolution::StepLoad load;
      KinematicBranch       branch = KinematicBranch::separated;
    };

    /**
     * @brief The rule for one point, with the three 2x2 systems inverted once:
     * the influence is the same at every step of a run.
     */
    class KinematicContact
    {
    public:
      explicit KinematicContact(const convolution::Influence &psi);

      /**
       * @brief The contact load of one step.
       *
       * @param[in] du \f$u^r - u^h\f$: what the load must add to u.
       * @param[in] dv \f$v^r - v^h\f$: what it must add to v.
       * @return The non-negative load and the branch that produced it.
       * @throws NumericalError if not even the fallback can raise u (time
       * step longer than half a period of the structure).
       */
      KinematicStep
      solve(double du, double dv) const;

    private:
      struct Pair
      {
        unsigned int i, j;
        bool         regular;
        double       inverse[2][2]; // of [[u_i, u_j], [v_i, v_j]]
      };
      Pair   pairs[3];
      double fallback_weight; // 1 / u-influence of the start impulse
    };

    /// One step of the rule with a given influence (builds a KinematicContact).
    KinematicStep
    solve_kinematic_step(const convolution::Influence &psi, double du, double dv);
  } // namespace contact
} // namespace greentread

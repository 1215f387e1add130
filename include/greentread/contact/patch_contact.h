#pragma once

#include <greentread/contact/candidate_set.h>
#include <greentread/contact/kinematic_contact.h>
#include <greentread/contact/lcp.h>
#include <greentread/convolution/patch_convolution.h>
#include <greentread/modal/patch_model.h>

#include <Eigen/Core>

#include <array>
#include <functional>
#include <memory>
#include <string>
#include <vector>

/**
 * @file
 * Kinematic contact of a whole patch of N_p points (Section 5): the
 * complementarity problem of one step, and the time loop that advances the
 * convolution of greentread/convolution/patch_convolution.h. Implemented in
 * source/contact/patch_contact.cc.
 *
 * Conventions: a contact force q_j >= 0 pushes tread point j towards the
 * wheel centre; u_i is the displacement of point i in that direction
 * (\f$u = g * q\f$, g_ii(0) > 0). The road asks for an inward displacement
 * \f$d_i(t)\f$ (its height under the point, plus the indentation, minus the
 * tread's own height there), so the gap is \f$u_i - d_i \ge 0\f$.
 */

namespace greentread
{
  namespace contact
  {
    /// What the solve of one step reports.
    struct PatchStepReport
    {
      unsigned int n_contact        = 0;
      unsigned int outer_iterations = 0;
      unsigned int lcp_iterations   = 0;
      unsigned int n_fallback       = 0;
      bool         converged        = true;
      /// max |v_i - v_i^r| over the points in contact, relative to max |v^r - v^h|.
      double      velocity_residual = 0.;
      std::string message;
      /// The last LCP of the step, \f$w = M z + q\f$, and its solution z, for
      /// checks against another solver. @p lcp_matrix points into the solver
      /// and is valid until its next step.
      const Eigen::MatrixXd *lcp_matrix = nullptr;
      Eigen::VectorXd        lcp_q, lcp_z;
      /// LcpResult::projected of that LCP.
      double lcp_projected = 0.;
      /// The candidate-set solver's set (candidate_set.h); all 0 with the
      /// other solvers.
      CandidateSetReport candidates;
      bool               candidate_set = false;
    };

    /**
     * @brief The kinematic contact of one step for all points.
     *
     * The load of point j is a non-negative magnitude z_j times a shape
     * s_j, a unit load made of the four generators of StepLoad.
     * 1. Shapes: for each point, the one-point impact rule
     *    (greentread/contact/kinematic_contact.h) applied to what it needs,
     *    \f$(d_j - u_j^h, \dot d_j - v_j^h)\f$, with its own influence.
     * 2. Magnitudes: the LCP \f$w = M z + (u^h - d) \ge 0\f$, \f$z \ge 0\f$,
     *    \f$z^T w = 0\f$ with \f$M_{ij} = \Psi^u_{i\cdot}\,s_j\f$, solved by
     *    block principal pivoting (greentread/contact/lcp.h): no force is
     *    negative and no point ends the step inside the road.
     * 3. Every point in contact takes the rule again, now for what it still
     *    needs once the others' loads act on it; if a shape changed, back to 2.
     * Converged when no shape changes by more than 1e-9 (relative) and the LCP
     * converged; then each contact point meets the road's height exactly and
     * its velocity to the rule's accuracy. With one point this is exactly the
     * one-point rule. At most 50 rounds; a step that does not converge keeps
     * its last (non-negative, non-penetrating) iterate and is reported.
     */
    class PatchKinematicContact
    {
    public:
      /// @p n_points: the patch's (the influence's matrices may be empty,
      /// PatchInfluence::add_u).
      PatchKinematicContact(const convolution::PatchInfluence &psi, unsigned int n_points);

      /**
       * @param[in] uh, vh History terms at t_{n+1}.
       * @param[in] d, dd Road demand and its rate at t_{n+1}.
       * @param[out] load The loads of the step.
       */
      PatchStepReport
      solve(const Eigen::VectorXd  &uh,
            const Eigen::VectorXd  &vh,
            const Eigen::VectorXd  &d,
            const Eigen::VectorXd  &dd,
            convolution::PatchLoad &load);

      /// The force at the start of the next step (for a start from a static
      /// equilibrium, its loads).
      void
      set_force(const Eigen::VectorXd &q);

    private:
      /**
       * With an instantaneous compliance: the force is continuous and
       * linear over each step, from the last end value a to b; b solves the
       * LCP \f$w = \Psi^u_{end} b + (u^h + \Psi^u_{start} a - d) \ge 0\f$,
       * \f$b \ge 0\f$, \f$b^T w = 0\f$. \f$\Psi^u_{end}\f$ holds G_r, a
       * reciprocal positive matrix, so the LCP is well posed.
       */
      PatchStepReport
      solve_continuous(const Eigen::VectorXd  &uh,
                       const Eigen::VectorXd  &d,
                       convolution::PatchLoad &load);

      Eigen::VectorXd                    previous_end;
      double                             end_norm = 0.; // of psi.u[2], continuous path
      Eigen::MatrixXd                    lcp_matrix;    // the last round's, iterative path
      const convolution::PatchInfluence &psi;
      /// The matrix-free form: MPRGP (projected_cg.h) on \f$\Psi^u_{end}\f$.
      bool                               matrix_free = false;
      std::vector<KinematicContact>      rules;
      std::vector<bool>                  active;
      std::vector<std::array<double, 4>> shapes;
    };

    /// What one step of a rolling run hands to its observer.
    struct RollingStep
    {
      unsigned int step = 0;
      /// t_{n+1} [s].
      double time = 0.;
      /// Displacement, demand (road) and the step's mean contact force.
      Eigen::VectorXd u, d, force;
      /// The contact force at the step's end (the load's end component),
      /// which the contact grid's local term acts on.
      Eigen::VectorXd end_force;
      PatchStepReport report;
    };

    /// What a rolling run reports.
    struct RollingSummary
    {
      unsigned int steps           = 0;
      unsigned int failed_steps    = 0;
      unsigned int fallback_points = 0;
      /// The first failed step's message, if any.
      std::string first_failure;
      double      min_contact_fraction = 1.;
      double      max_contact_fraction = 0.;
      /// \f$\int \sum_j q_j\,dt\f$ over the run [N s].
      double impulse = 0.;
      /// Largest penetration \f$\max(d - u)\f$ at a step's end [m].
      double max_penetration = 0.;
      /// The candidate-set solver's sets (candidate_set.h), all 0 with the
      /// other solvers: the steps it solved, the largest set at a step's
      /// end, the steps at which points joined the set during the solve
      /// (pulled into the road by the others), those whose set started
      /// smaller than the last step's ended (points that left the contact),
      /// and those solved on the whole grid instead.
      unsigned int candidate_steps = 0, max_candidates = 0, grown_steps = 0, shrunk_steps = 0,
                   whole_grid_steps = 0;
    };

    /**
     * @brief Roll the patch for @p n_steps steps of the convolution's dt.
     *
     * Each step: the history term, the demand of the road at \f$t_{n+1}\f$
     * (@p demand fills d and its rate dd), the contact solve, the update of
     * the convolution, then @p observe (may be empty). With @p start_force
     * non-empty, the run starts from that force held since \f$t=-\infty\f$
     * (a static equilibrium), otherwise from rest. When the steps run out,
     * @p more_steps (may be empty) is asked, with the steps done so far, how
     * many more to roll: the run goes on from where it is (the same
     * convolution and contact state) until it answers 0.
     * RollingSummary::steps is the number rolled.
     * @throws NumericalError naming the step if a force or displacement is
     * not finite.
     */
    RollingSummary
    roll(convolution::PatchConvolution                                                &convolution,
         const std::function<void(double t, Eigen::VectorXd &d, Eigen::VectorXd &dd)> &demand,
         unsigned int                                                                  n_steps,
         const Eigen::VectorXd                                                        &start_force,
         const std::function<void(const RollingStep &)>                               &observe,
         const std::function<unsigned int(unsigned int steps_done)> &more_steps = {});

    /**
     * @brief The static contact: \f$G_0 q = u\f$, \f$u - d \ge 0\f$, \f$q \ge 0\f$,
     * complementary. With @p total_load > 0 the indentation \f$\delta\f$ that
     * carries it is found too (d = d_0 + delta, bisection on the monotone
     * total force); otherwise @p delta is used as given.
     * @throws NumericalError if the LCP fails or the load cannot be reached.
     */
    struct StaticContact
    {
      Eigen::VectorXd q, u;
      double          delta     = 0.;
      unsigned int    n_contact = 0;
    };

    StaticContact
    solve_static_contact(const Eigen::MatrixXd &G0,
                         const Eigen::VectorXd &d0,
                         double                 total_load,
                         double                 delta);

    /// The LCP \f$w = G_0 q + c\f$ of the static contact for a given c, by
    /// some solver (the matrix-free one of the contact grid).
    using StaticSolve = std::function<LcpResult(const Eigen::VectorXd &c)>;

    /// solve_static_contact() with the static LCP solved by @p solve.
    StaticContact
    solve_static_contact(const StaticSolve     &solve,
                         const Eigen::VectorXd &d0,
                         double                 total_load,
                         double                 delta);
  } // namespace contact
} // namespace greentread

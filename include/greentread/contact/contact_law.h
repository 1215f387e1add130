#pragma once

#include <greentread/contact/contact_parameters.h>
#include <greentread/contact/kinematic_contact.h>
#include <greentread/convolution/convolution.h>

#include <memory>
#include <string>

/**
 * @file
 * The contact laws of one point (the 1-DoF scene, Section 3), behind one
 * interface and one selection point, create(). Implemented in
 * source/contact/contact_law.cc.
 */

namespace greentread
{
  namespace contact
  {
    /// The contact load of one step and, for the kinematic law, its branch.
    struct ContactStep
    {
      convolution::StepLoad load;
      /// KinematicBranch as an index, or -1 for a law without branches.
      int branch = -1;
    };

    /**
     * @brief One point's contact law: the contact load of a step from what
     * the point does without it.
     */
    class OnePointContactLaw
    {
    public:
      virtual ~OnePointContactLaw() = default;

      /**
       * @param[in] history The response at t_{n+1} to the loads before the step.
       * @param[in] known   The known load of the step (gravity).
       * @param[in] ur, vr  The road's height and velocity at t_{n+1}.
       */
      virtual ContactStep
      step(const convolution::Response &history,
           const convolution::StepLoad &known,
           double                       ur,
           double                       vr) = 0;

      /// What to change when a run with this law diverges, or empty.
      virtual std::string
      divergence_hint(double dt) const
      {
        (void)dt;
        return {};
      }
    };

    /**
     * @brief The law of @p parameters for a point of influence @p psi, on an
     * oscillator of @p stiffness [N/m] and @p mass [kg] (the penalty law warns
     * when its contact mode is too fast for the time step).
     */
    std::unique_ptr<OnePointContactLaw>
    create(const ContactParameters      &parameters,
           const convolution::Influence &psi,
           double                        stiffness,
           double                        mass);
  } // namespace contact
} // namespace greentread

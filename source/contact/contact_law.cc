#include <greentread/base/exceptions.h>
#include <greentread/contact/contact_law.h>

#include <algorithm>
#include <cmath>
#include <iostream>

namespace greentread
{
  namespace contact
  {
    namespace
    {
      /// Eqs. (16)-(28) with the impact rule of kinematic_contact.h.
      class KinematicLaw : public OnePointContactLaw
      {
      public:
        explicit KinematicLaw(const convolution::Influence &psi)
            : psi(psi)
            , rule(psi)
        {
        }

        ContactStep
        step(const convolution::Response &history,
             const convolution::StepLoad &known,
             const double                 ur,
             const double                 vr) override
        {
          const convolution::Response known_response = psi.of(known);
          const convolution::Response predicted{history.u + known_response.u,
                                                history.v + known_response.v};
          KinematicStep               step;
          if (predicted.u <= ur)
            step = rule.solve(ur - predicted.u, vr - predicted.v);
          return {step.load, static_cast<int>(step.branch)};
        }

      private:
        const convolution::Influence psi;
        KinematicContact             rule;
      };

      /// Eq. (37): the force at t_{n+1} from the predicted penetration,
      /// linear in time from the force at t_n. Explicit, with the contact mode
      /// omega_c = sqrt((K + kc) / M).
      class PenaltyLaw : public OnePointContactLaw
      {
      public:
        PenaltyLaw(const convolution::Influence &psi, const double kc, const double omega_c)
            : psi(psi)
            , kc(kc)
            , omega_c(omega_c)
        {
        }

        ContactStep
        step(const convolution::Response &history,
             const convolution::StepLoad &known,
             const double                 ur,
             const double) override
        {
          convolution::StepLoad with_force = known;
          with_force.start += force;
          const double predicted = history.u + psi.of(with_force).u;
          const double next      = kc * std::max(ur - predicted, 0.);
          ContactStep  s;
          s.load = convolution::StepLoad{0., force, next, 0.};
          force  = next;
          return s;
        }

        std::string
        divergence_hint(const double dt) const override
        {
          return " The penalty contact mode has omega_c dt = sqrt((K + kc)/M) dt = " +
                 format_short(omega_c * dt) +
                 "; the explicit penalty of Eq. (37) needs a smaller time step or a "
                 "smaller 'Contact/Contact stiffness'.";
        }

      private:
        const convolution::Influence psi;
        double                       kc, omega_c;
        double                       force = 0.; // at t_n
      };
    } // namespace



    std::unique_ptr<OnePointContactLaw>
    create(const ContactParameters      &parameters,
           const convolution::Influence &psi,
           const double                  stiffness,
           const double                  mass)
    {
      if (parameters.law == ContactLaw::kinematic)
        return std::make_unique<KinematicLaw>(psi);
      // The explicit penalty of Eq. (37) is stable up to omega_c dt of about
      // 1.6 (measured, see README); say so before it matters. At 1 its
      // results match those of much smaller steps.
      const double omega_c    = std::sqrt((stiffness + parameters.contact_stiffness) / mass);
      const double dt         = parameters.time_step;
      const double omega_c_dt = omega_c * dt;
      if (omega_c_dt > 1.25)
        std::cerr << "warning: penalty contact: omega_c dt = sqrt((K + kc)/M) dt = "
                  << format_short(omega_c_dt)
                  << " > 1.25; the explicit penalty is stable only up to about 1.6 and "
                     "its results degrade before that. A time step below "
                  << format_short(dt / omega_c_dt) << " s keeps omega_c dt <= 1.\n";
      return std::make_unique<PenaltyLaw>(psi, parameters.contact_stiffness, omega_c);
    }
  } // namespace contact
} // namespace greentread

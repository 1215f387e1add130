#include <greentread/base/exceptions.h>
#include <greentread/contact/kinematic_contact.h>

#include <cmath>

namespace greentread
{
  namespace contact
  {
    std::string
    to_string(const KinematicBranch branch)
    {
      switch (branch)
        {
          case KinematicBranch::separated:
            return "separated";
          case KinematicBranch::riding:
            return "riding";
          case KinematicBranch::impact_early:
            return "impact-early";
          case KinematicBranch::impact_late:
            return "impact-late";
          case KinematicBranch::fallback:
            return "fallback";
        }
      return "unknown";
    }



    namespace
    {
      /// Set component i of a load, components ordered as in Influence.
      void
      set_component(convolution::StepLoad &load, const unsigned int i, const double x)
      {
        switch (i)
          {
            case 0:
              load.impulse_start = x;
              break;
            case 1:
              load.start = x;
              break;
            case 2:
              load.end = x;
              break;
            default:
              load.impulse_end = x;
          }
      }
    } // namespace



    namespace
    {
      constexpr KinematicBranch branch_of_pair[3] = {
        KinematicBranch::riding, KinematicBranch::impact_early, KinematicBranch::impact_late};
    } // namespace



    KinematicContact::KinematicContact(const convolution::Influence &psi)
    {
      // The pairs of neighbouring generators, in order of preference.
      const unsigned int indices[3][2] = {{1, 2}, {0, 1}, {2, 3}};
      for (unsigned int p = 0; p < 3; ++p)
        {
          Pair &pair     = pairs[p];
          pair.i         = indices[p][0];
          pair.j         = indices[p][1];
          const double a = psi.u[pair.i], b = psi.u[pair.j];
          const double c = psi.v[pair.i], d = psi.v[pair.j];
          const double det  = a * d - b * c;
          const double size = std::abs(a * d) + std::abs(b * c);
          pair.regular      = std::abs(det) > 1e-14 * size;
          if (pair.regular)
            {
              pair.inverse[0][0] = d / det;
              pair.inverse[0][1] = -b / det;
              pair.inverse[1][0] = -c / det;
              pair.inverse[1][1] = a / det;
            }
        }
      if (!(psi.u[0] > 0.))
        throw NumericalError(
          "kinematic contact: an impulse at the start of the step does not raise the "
          "displacement at its end (g(dt) = " +
          format_short(psi.u[0]) +
          " <= 0): the time step is longer than half a period of the structure; reduce "
          "'Time stepping/Time step'");
      fallback_weight = 1. / psi.u[0];
    }



    KinematicStep
    KinematicContact::solve(const double du, const double dv) const
    {
      constexpr double tolerance = 1e-12;
      for (unsigned int p = 0; p < 3; ++p)
        {
          const Pair &pair = pairs[p];
          if (!pair.regular)
            continue;
          const double xi    = pair.inverse[0][0] * du + pair.inverse[0][1] * dv;
          const double xj    = pair.inverse[1][0] * du + pair.inverse[1][1] * dv;
          const double scale = std::abs(xi) + std::abs(xj);
          if (xi < -tolerance * scale || xj < -tolerance * scale)
            continue;
          KinematicStep step;
          set_component(step.load, pair.i, std::max(xi, 0.));
          set_component(step.load, pair.j, std::max(xj, 0.));
          step.branch = branch_of_pair[p];
          return step;
        }
      KinematicStep step;
      step.load.impulse_start = std::max(du, 0.) * fallback_weight;
      step.branch             = KinematicBranch::fallback;
      return step;
    }



    KinematicStep
    solve_kinematic_step(const convolution::Influence &psi, const double du, const double dv)
    {
      return KinematicContact(psi).solve(du, dv);
    }
  } // namespace contact
} // namespace greentread

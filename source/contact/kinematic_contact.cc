#include <greentread/base/exceptions.h>
#include <greentread/contact/kinematic_contact.h>

#include <array>
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



    KinematicStep
    solve_kinematic_step(const convolution::Influence &psi, const double du, const double dv)
    {
      constexpr double tolerance = 1e-12;

      // The pairs of neighbouring generators, in order of preference.
      constexpr std::array<std::pair<unsigned int, unsigned int>, 3> pairs = {
        {{1, 2}, {0, 1}, {2, 3}}};
      constexpr std::array<KinematicBranch, 3> branches = {{KinematicBranch::riding,
                                                           KinematicBranch::impact_early,
                                                           KinematicBranch::impact_late}};
      for (unsigned int p = 0; p < pairs.size(); ++p)
        {
          const auto [i, j] = pairs[p];
          const double det  = psi.u[i] * psi.v[j] - psi.u[j] * psi.v[i];
          const double size = std::abs(psi.u[i] * psi.v[j]) + std::abs(psi.u[j] * psi.v[i]);
          if (!(std::abs(det) > 1e-14 * size))
            continue;
          double       xi = (du * psi.v[j] - dv * psi.u[j]) / det;
          double       xj = (psi.u[i] * dv - psi.v[i] * du) / det;
          const double scale = std::abs(xi) + std::abs(xj);
          if (xi < -tolerance * scale || xj < -tolerance * scale)
            continue;
          KinematicStep step;
          set_component(step.load, i, std::max(xi, 0.));
          set_component(step.load, j, std::max(xj, 0.));
          step.branch = branches[p];
          return step;
        }

      if (!(psi.u[0] > 0.))
        throw NumericalError(
          "kinematic contact: an impulse at the start of the step does not raise the "
          "displacement at its end (g(dt) = " + format_number(psi.u[0]) +
          " <= 0): the time step is longer than half a period of the structure; reduce "
          "'Time stepping/Time step'");
      KinematicStep step;
      step.load.impulse_start = std::max(du, 0.) / psi.u[0];
      step.branch             = KinematicBranch::fallback;
      return step;
    }
  } // namespace contact
} // namespace greentread

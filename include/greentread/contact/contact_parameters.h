#pragma once

#include <deal.II/base/parameter_handler.h>

#include <string>

namespace greentread
{
  namespace contact
  {
    /// The contact laws of the paper.
    enum class ContactLaw
    {
      kinematic, ///< Eqs. (16)-(28): displacement and velocity matching
      penalty    ///< Eq. (37): F = kc (u_r - u_h)
    };

    /**
     * @brief Subsections "Contact" and "Time stepping".
     */
    struct ContactParameters
    {
      ContactLaw law               = ContactLaw::kinematic;
      double     contact_stiffness = 1e7;
      double     time_step         = 1e-5;
      double     end_time          = 0.2;

      static void
      declare_parameters(dealii::ParameterHandler &prm);
      void
      parse_parameters(dealii::ParameterHandler &prm);

      /// The number of steps, end time / time step rounded to nearest.
      unsigned int
      n_steps() const;
    };

    std::string
    to_string(ContactLaw law);
  } // namespace contact
} // namespace greentread

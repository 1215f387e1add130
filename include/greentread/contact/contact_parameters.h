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
     * @brief Subsections "Contact" and "Time stepping" of the 1-DoF scene;
     * its 'auto' time step is 1e-5 s, the finer step of Table A.2.
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

      /// The law as the screen shows it: "kinematic", "penalty (kc = 1e+07 N/m)".
      std::string
      describe() const;

      /// The number of steps, end time / time step rounded to nearest.
      unsigned int
      n_steps() const;
    };

    std::string
    to_string(ContactLaw law);

    /**
     * @brief 'Time stepping/Time step', which every scene with a time loop
     * reads: 0 for 'auto' (the scene's own choice), else the step in s.
     * @throws InputError naming the parameter unless it is 'auto' or a
     * number from 1e-8 to 1e-2 s.
     */
    double
    read_time_step(dealii::ParameterHandler &prm);
  } // namespace contact
} // namespace greentread

#pragma once

#include <deal.II/base/parameter_handler.h>

#include <map>

/**
 * @file
 * Subsection "Materials": the elastic constants, densities and loss factors
 * of the tyre's layers (Table A.4) and the frequencies of their Rayleigh
 * damping (fe::MaterialParameters); the materials themselves are in
 * greentread/fe/material.h. Implemented in source/fe/material_parameters.cc.
 */

namespace greentread
{
  namespace fe
  {
    struct Material; // greentread/fe/material.h, which includes this file

    /**
     * @brief Subsection "Materials": the layers of Table A.4 and damping.
     */
    struct MaterialParameters
    {
      // Tread pattern: rubber.
      double tread_density = 1000., tread_E = 7e6, tread_nu = 0.49, tread_loss = 0.1;
      // Belt: rubber and steel, orthotropic in (r, theta, z).
      double belt_density = 2014.;
      double belt_E_r = 663e6, belt_E_theta = 624e6, belt_E_z = 663e6;
      double belt_nu_rtheta = 0.4, belt_nu_rz = 0.4, belt_nu_thetaz = 0.4;
      double belt_G_rtheta = 330e6, belt_G_rz = 330e6, belt_G_thetaz = 330e6;
      double belt_loss = 0.05;
      // Sidewall: rubber and nylon.
      double sidewall_density = 1000., sidewall_E = 109e6, sidewall_nu = 0.48, sidewall_loss = 0.1;
      // Bead: steel.
      double bead_density = 7850., bead_E = 162.6e9, bead_nu = 0.33, bead_loss = 0.002;
      // The two frequencies where the Rayleigh damping ratio equals eta/2.
      double damping_f1 = 200., damping_f2 = 2000.;
      /// 'Tread pattern/Surface mass': false = consistent, true = moved
      /// inward (the contact surface's nodes carry no mass, only beta K damping;
      /// see periodic::move_tread_mass_inward).
      bool tread_surface_mass_inward = false;

      static void
      declare_parameters(dealii::ParameterHandler &prm);
      void
      parse_parameters(dealii::ParameterHandler &prm);

      /// The materials by material id.
      std::map<unsigned int, Material>
      materials() const;
    };
  } // namespace fe
} // namespace greentread

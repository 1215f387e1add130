#include <greentread/base/exceptions.h>
#include <greentread/base/mesh_ids.h>
#include <greentread/base/parameters.h>
#include <greentread/fe/material.h>
#include <greentread/fe/material_parameters.h>

#include <map>
#include <string>
#include <tuple>

namespace greentread
{
  namespace fe
  {
    void
    MaterialParameters::declare_parameters(dealii::ParameterHandler &prm)
    {
      using base::RangePattern;
      const auto density = [&](const char *value) {
        prm.declare_entry("Density", value, base::RangePattern::positive("kg/m^3"),
                          "Mass density rho. Unit: kg/m^3.");
      };
      const auto loss = [&](const char *value, const char *what) {
        prm.declare_entry("Loss factor", value, base::RangePattern::closed(0., 2., ""),
                          std::string("Loss factor eta, turned into Rayleigh damping (subsection "
                                      "Damping). Not given by the paper; ") +
                            what + " Unit: 1.");
      };
      const auto isotropic = [&](const char *E, const char *nu, const char *what) {
        prm.declare_entry("Young's modulus", E, base::RangePattern::positive("Pa"),
                          std::string("Young's modulus E. Unit: Pa. Table A.4: ") + what + ".");
        prm.declare_entry("Poisson's ratio", nu,
                          base::RangePattern({-1., base::RangePattern::Bound::exclusive, 0.5,
                                              base::RangePattern::Bound::exclusive, ""}),
                          "Poisson's ratio nu, -1 < nu < 0.5. Unit: 1.");
      };
      prm.enter_subsection("Materials");
      {
        prm.enter_subsection("Tread pattern");
        density("1000");
        isotropic("7e6", "0.49", "rubber, 7 MPa, nu = 0.49");
        loss("0.1", "a typical tread compound.");
        prm.declare_entry(
          "Surface mass", "consistent", dealii::Patterns::Selection("consistent|moved inward"),
          "Where the mass of the tread's contact surface sits. 'consistent': the consistent mass "
          "matrix, so the contact nodes carry mass and kinematic contact on them is an impact "
          "whose force grows as the time step falls. 'moved inward': the velocity of each node of "
          "the contact surface is taken, in the kinetic energy and in the mass-proportional "
          "damping, as that of the nearest node inside the same element (mass redistribution, "
          "Khenous, Laborde and Renard 2008); the contact nodes then carry no mass (the "
          "stiffness-proportional damping stays, so they relax like a Kelvin-Voigt solid), an "
          "axial translation "
          "keeps its kinetic energy exactly, and the contact force converges as the time step "
          "falls. Not the default: on a coarse mesh it also removes the surface layer's own "
          "inertia.");
        prm.leave_subsection();

        prm.enter_subsection("Belt");
        density("2014");
        prm.declare_entry("Radial modulus", "663e6", base::RangePattern::positive("Pa"),
                          "E_r, the paper's E_r. Unit: Pa. Table A.4: 663 MPa.");
        prm.declare_entry("Circumferential modulus", "624e6", base::RangePattern::positive("Pa"),
                          "E_theta, the paper's E_x (x: the rolling direction). Unit: Pa. "
                          "Table A.4: 624 MPa.");
        prm.declare_entry("Axial modulus", "663e6", base::RangePattern::positive("Pa"),
                          "E_z (across the tread). Not in Table A.4; completed as E_r. Unit: Pa.");
        prm.declare_entry("Poisson's ratio r-theta", "0.4", base::RangePattern::closed(-1., 1., ""),
                          "nu_r,theta. Not in Table A.4; completed as nu_ry. Unit: 1.");
        prm.declare_entry(
          "Poisson's ratio r-z", "0.4", base::RangePattern::closed(-1., 1., ""),
          "nu_r,z, the paper's nu_ry (y: across the tread). Unit: 1. Table A.4: 0.4.");
        prm.declare_entry("Poisson's ratio theta-z", "0.4", base::RangePattern::closed(-1., 1., ""),
                          "nu_theta,z. Not in Table A.4; completed as nu_ry. Unit: 1.");
        prm.declare_entry("Shear modulus r-theta", "330e6", base::RangePattern::positive("Pa"),
                          "G_r,theta. Not in Table A.4; completed as G_ry. Unit: Pa.");
        prm.declare_entry("Shear modulus r-z", "330e6", base::RangePattern::positive("Pa"),
                          "G_r,z, the paper's G_ry. Unit: Pa. Table A.4: 330 MPa.");
        prm.declare_entry("Shear modulus theta-z", "330e6", base::RangePattern::positive("Pa"),
                          "G_theta,z. Not in Table A.4; completed as G_ry. Unit: Pa.");
        loss("0.05", "steel cords lower it below the rubber's.");
        prm.leave_subsection();

        prm.enter_subsection("Sidewall");
        density("1000");
        isotropic("109e6", "0.48", "rubber and nylon, 109 MPa, nu = 0.48");
        loss("0.1", "as the tread rubber.");
        prm.leave_subsection();

        prm.enter_subsection("Bead");
        density("7850");
        isotropic("162.6e9", "0.33", "steel, 162.6 GPa, nu = 0.33");
        loss("0.002", "a steel wire bundle.");
        prm.leave_subsection();

        prm.enter_subsection("Damping");
        prm.declare_entry("First frequency", "200", base::RangePattern::positive("Hz"),
                          "Rayleigh damping C = alpha M + beta K of each material gives the "
                          "damping ratio eta/2 at this frequency and the next. Unit: Hz.");
        prm.declare_entry("Second frequency", "2000", base::RangePattern::positive("Hz"),
                          "See 'First frequency'; must be larger. Unit: Hz.");
        prm.leave_subsection();
      }
      prm.leave_subsection();
    }



    void
    MaterialParameters::parse_parameters(dealii::ParameterHandler &prm)
    {
      prm.enter_subsection("Materials");
      {
        prm.enter_subsection("Tread pattern");
        tread_density             = prm.get_double("Density");
        tread_E                   = prm.get_double("Young's modulus");
        tread_nu                  = prm.get_double("Poisson's ratio");
        tread_loss                = prm.get_double("Loss factor");
        tread_surface_mass_inward = (prm.get("Surface mass") == "moved inward");
        prm.leave_subsection();

        prm.enter_subsection("Belt");
        belt_density   = prm.get_double("Density");
        belt_E_r       = prm.get_double("Radial modulus");
        belt_E_theta   = prm.get_double("Circumferential modulus");
        belt_E_z       = prm.get_double("Axial modulus");
        belt_nu_rtheta = prm.get_double("Poisson's ratio r-theta");
        belt_nu_rz     = prm.get_double("Poisson's ratio r-z");
        belt_nu_thetaz = prm.get_double("Poisson's ratio theta-z");
        belt_G_rtheta  = prm.get_double("Shear modulus r-theta");
        belt_G_rz      = prm.get_double("Shear modulus r-z");
        belt_G_thetaz  = prm.get_double("Shear modulus theta-z");
        belt_loss      = prm.get_double("Loss factor");
        prm.leave_subsection();

        prm.enter_subsection("Sidewall");
        sidewall_density = prm.get_double("Density");
        sidewall_E       = prm.get_double("Young's modulus");
        sidewall_nu      = prm.get_double("Poisson's ratio");
        sidewall_loss    = prm.get_double("Loss factor");
        prm.leave_subsection();

        prm.enter_subsection("Bead");
        bead_density = prm.get_double("Density");
        bead_E       = prm.get_double("Young's modulus");
        bead_nu      = prm.get_double("Poisson's ratio");
        bead_loss    = prm.get_double("Loss factor");
        prm.leave_subsection();

        prm.enter_subsection("Damping");
        damping_f1 = prm.get_double("First frequency");
        damping_f2 = prm.get_double("Second frequency");
        prm.leave_subsection();
      }
      prm.leave_subsection();
      require_parameter(damping_f2 > damping_f1, "Materials/Damping/Second frequency", damping_f2,
                        "a frequency above 'First frequency' = " + format_number(damping_f1) +
                          " Hz");
      // Surfaces the error of a bad set of belt constants now, naming them.
      try
        {
          materials();
        }
      catch (const InputError &e)
        {
          throw InputError(std::string("subsection Materials/Belt: ") + e.what());
        }
    }



    std::map<unsigned int, Material>
    MaterialParameters::materials() const
    {
      std::map<unsigned int, Material> m;
      const auto make = [&](const char *name, double density, dealii::SymmetricTensor<4, 3> c,
                            bool cylindrical, double loss) {
        Material material;
        material.name             = name;
        material.density          = density;
        material.stiffness        = c;
        material.cylindrical_axes = cylindrical;
        std::tie(material.alpha, material.beta) =
          rayleigh_coefficients(loss, damping_f1, damping_f2);
        return material;
      };
      m[tread_id] =
        make("tread", tread_density, isotropic_stiffness(tread_E, tread_nu), false, tread_loss);
      m[belt_id] =
        make("belt", belt_density,
             orthotropic_stiffness(belt_E_r, belt_E_theta, belt_E_z, belt_nu_rtheta, belt_nu_rz,
                                   belt_nu_thetaz, belt_G_rtheta, belt_G_rz, belt_G_thetaz),
             true, belt_loss);
      m[sidewall_id] = make("sidewall", sidewall_density,
                            isotropic_stiffness(sidewall_E, sidewall_nu), false, sidewall_loss);
      m[bead_id] =
        make("bead", bead_density, isotropic_stiffness(bead_E, bead_nu), false, bead_loss);
      return m;
    }
  } // namespace fe
} // namespace greentread

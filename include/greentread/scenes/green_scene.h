#pragma once

#include <greentread/fe/inflation.h>
#include <greentread/fe/material.h>
#include <greentread/geometry/tyre_cell.h>
#include <greentread/periodic/green_functions.h>
#include <greentread/scenes/scene.h>

namespace greentread
{
  namespace scenes
  {
    /**
     * @brief Scene "tyre-green": the Green's functions of the inflated ring
     * at the contact points (paper, Section 4.2, Eqs. 42-49), spread over
     * the MPI ranks.
     *
     * Writes green_functions.h5, green_<i>_<j>.csv for the chosen pairs,
     * green_functions.png (|g| and phase, as in Figure A.9),
     * contact_points.csv, and ring_deflection.vtu (the operating deflection
     * shape at one frequency).
     */
    class GreenScene : public Scene
    {
    public:
      GreenScene(dealii::ParameterHandler &prm, const GlobalParameters &global);

      void
      run() override;

    private:
      dealii::ParameterHandler    &prm;
      GlobalParameters             global;
      geometry::GeometryParameters geometry;
      fe::MaterialParameters       materials;
      fe::InflationParameters      inflation;
      periodic::GreenParameters    green;
    };
  } // namespace scenes
} // namespace greentread

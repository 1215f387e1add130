#pragma once

#include <greentread/fe/elastic_model.h>
#include <greentread/fe/inflation.h>
#include <greentread/fe/material.h>
#include <greentread/geometry/tyre_cell.h>
#include <greentread/scenes/scene.h>

#include <utility>

namespace greentread
{
  namespace scenes
  {
    /**
     * @brief Scenes "geometry-study" and "tyre-cell": the tyre's periodic
     * cell (paper, Section 4, Tables A.3-A.4, Eq. 41).
     *
     * Both mesh the section of subsection Geometry with gmsh, revolve it
     * into the cell, assemble the stiffness and mass with quadratic elements
     * in deal.II, report the mass of every layer against Pappus, and solve
     * the static inflation (rim seat clamped, rotational periodicity, the
     * pressure on the inner surface). "tyre-cell" also assembles the damping
     * C and the geometric stiffness Kp of the inflated state, and exports the
     * cell as an Abaqus file.
     *
     * Writes: section.vtu and section.png (the section with its materials),
     * inflated_cell.vtu and .pvd (displacement, von Mises stress),
     * mass_report.csv, and for "tyre-cell" tyre_cell.inp.
     */
    class TyreCellScene : public Scene
    {
    public:
      TyreCellScene(dealii::ParameterHandler &prm, const GlobalParameters &global);

      void
      run() override;

    private:
      dealii::ParameterHandler    &prm;
      GlobalParameters             global;
      bool                         full;
      geometry::GeometryParameters geometry;
      fe::MaterialParameters       materials;
      fe::InflationParameters      inflation;
    };
  } // namespace scenes
} // namespace greentread

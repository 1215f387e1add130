#pragma once

#include <greentread/base/output.h>
#include <greentread/fe/material.h>

#include <deal.II/fe/mapping.h>
#include <deal.II/grid/tria.h>

#include <filesystem>

namespace greentread
{
  namespace fe
  {
    /**
     * @brief Write a mesh of the tyre and its materials as an Abaqus input
     * file (CalculiX reads it too), for cross-checks in another solver.
     *
     * - C3D20 elements (20-node serendipity bricks): the corners of the
     *   cells, and the mid-edge nodes placed by @p mapping (on the curved
     *   geometry). Node numbers: vertices first, then edges.
     * - Element sets TREAD, BELT, SIDEWALL, BEAD and one *SOLID SECTION each;
     *   the belt with *ORIENTATION CYL, cylindrical about the z-axis (1
     *   radial, 2 circumferential, 3 axial) and *ELASTIC, TYPE=ENGINEERING
     *   CONSTANTS; the others isotropic.
     * - Node set RIMSEAT (boundary id 1) and the element surface INNER
     *   (boundary id 2, the pressurised faces), built from the element sets
     *   INNER_S1 .. INNER_S6.
     *
     * No step is written: an analysis *INCLUDEs this file and adds its own
     * boundary conditions, loads and steps.
     */
    void
    write_abaqus(const std::filesystem::path    &file,
                 const dealii::Triangulation<3> &triangulation,
                 const dealii::Mapping<3>       &mapping,
                 const MaterialParameters       &materials,
                 const base::ParameterRecord    &record);
  } // namespace fe
} // namespace greentread

#pragma once

#include <deal.II/grid/tria.h>
#include <greentread/base/mesh_ids.h>
#include <greentread/geometry/geometry_parameters.h>

#include <array>
#include <optional>
#include <vector>

/**
 * @file
 * The tyre cell: a parametric section (a gmsh .geo file, geometry/), meshed
 * with quadrilaterals and revolved by 2 pi / N about the tyre axis (z) into
 * one periodic cell of hexahedra.
 */

namespace greentread
{
  namespace geometry
  {
    /**
     * @brief One block of the section, for the analytic volume: its corners
     * in (radius, axial) order around it, and whether all its edges are
     * straight.
     */
    struct SectionBlock
    {
      unsigned int                       material_id;
      std::vector<std::array<double, 2>> corners;
      bool                               straight;
    };

    /**
     * @brief The meshed cell and its section.
     */
    class TyreCell
    {
    public:
      /**
       * @brief Mesh the section of @p parameters with gmsh, revolve it and
       * build the deal.II triangulations.
       * @throws InputError for a missing or broken .geo file, a gmsh error, a
       * mesh that is not all hexahedra, or missing physical groups.
       */
      explicit TyreCell(const GeometryParameters &parameters);

      /// The cell: hexahedra, material ids of MaterialId, boundary ids of BoundaryId.
      const dealii::Triangulation<3> &
      cell() const
      {
        return cell_triangulation;
      }

      /// The section in the (radius, axial) plane, with material ids and
      /// the boundary ids of the cell faces swept from its edges.
      const dealii::Triangulation<2> &
      section() const
      {
        return section_triangulation;
      }

      /// The blocks of the section, as the .geo defines them.
      const std::vector<SectionBlock> &
      blocks() const
      {
        return section_blocks;
      }

      double
      angle() const
      {
        return cell_angle;
      }

      unsigned int
      n_cells() const
      {
        return ring_cells;
      }

      /**
       * @brief Pappus: the volume of the layer @p material_id in the cell,
       * angle x integral of the radius over the section [m^3], or nothing
       * if a block of that layer has a curved edge (the formula would only
       * see its corners).
       */
      std::optional<double>
      analytic_volume(unsigned int material_id) const;

    private:
      dealii::Triangulation<3>  cell_triangulation;
      dealii::Triangulation<2>  section_triangulation;
      std::vector<SectionBlock> section_blocks;
      double                    cell_angle;
      unsigned int              ring_cells;
    };

    /**
     * @brief The full ring: N rotated copies of @p cell merged (coinciding
     * vertices joined), with the cylindrical manifold attached. Meant for
     * coarse checks (rigid-body modes, CalculiX comparisons).
     */
    void
    make_ring(const dealii::Triangulation<3> &cell,
              double                          angle,
              unsigned int                    n_cells,
              dealii::Triangulation<3>       &ring);

    /// Attach the cylindrical manifold about the z-axis to every cell.
    void
    attach_cylindrical_manifold(dealii::Triangulation<3> &triangulation);
  } // namespace geometry
} // namespace greentread

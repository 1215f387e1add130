#pragma once

#include <deal.II/base/parameter_handler.h>

#include <map>
#include <string>

/**
 * @file
 * Subsection "Geometry": the section's .geo file, its dimensions, the mesh
 * size, the number of cells in the ring and the elements' degree
 * (geometry::GeometryParameters); the cell itself is in
 * greentread/geometry/tyre_cell.h. Implemented in
 * source/geometry/geometry_parameters.cc.
 */

namespace greentread
{
  namespace geometry
  {
    /**
     * @brief Subsection "Geometry".
     *
     * The named dimensions are handed to the .geo file as the ONELAB numbers
     * "Parameters/<name>" (its DefineConstant defaults apply when it is
     * opened by hand); a new design may use other names through
     * 'Other constants'.
     */
    struct GeometryParameters
    {
      std::string  geo_file           = "geometry/tyre_165_65_r13.geo";
      double       rim_diameter       = 0.3302;
      double       section_height     = 0.10725;
      double       tread_width        = 0.165;
      double       section_width      = 0.175;
      double       rim_width          = 0.1143;
      double       tread_thickness    = 0.008;
      double       belt_thickness     = 0.006;
      double       sidewall_thickness = 0.006;
      double       bead_width         = 0.008;
      double       bead_height        = 0.008;
      double       bulge_height       = 0.5;
      double       mesh_size          = 0.008;
      unsigned int n_cells            = 256;
      /// 'Element degree': the Lagrange degree of the elements; 0 is 'auto'
      /// (see section_degree() and cell_degree()).
      unsigned int degree = 0;
      std::string  other_constants;

      static void
      declare_parameters(dealii::ParameterHandler &prm);

      /// The degree of the harmonic route's 2D section: 'auto' is quartic,
      /// the converged default (doc/benchmarks.md, converged_ring).
      unsigned int
      section_degree() const
      {
        return degree == 0 ? 4 : degree;
      }

      /// The degree of a 3D cell: 'auto' is quadratic.
      unsigned int
      cell_degree() const
      {
        return degree == 0 ? 2 : degree;
      }

      /**
       * @throws InputError for an impossible geometry (layers that overlap or
       * do not fit), naming the parameters.
       */
      void
      parse_parameters(dealii::ParameterHandler &prm);

      /// The cell angle 2 pi / N [rad].
      double
      angle() const;

      /// The tread surface's radius before inflation, rim / 2 + section height [m].
      double
      outer_radius() const
      {
        return 0.5 * rim_diameter + section_height;
      }

      /// The ONELAB numbers handed to the .geo file.
      std::map<std::string, double>
      onelab_numbers() const;
    };
  } // namespace geometry
} // namespace greentread

#pragma once

#include <deal.II/base/point.h>
#include <deal.II/grid/tria.h>

#include <array>
#include <vector>

/**
 * @file
 * The surface that radiates: the tyre's outer surface, revolved from the
 * section's outer boundary, closed by the wheel, standing on the road.
 */
namespace greentread
{
  namespace radiation
  {
    /// A line in the section's (radius, axial) plane [m], point by point.
    using SectionLine = std::vector<std::array<double, 2>>;

    /**
     * @brief The section's outer boundary, the faces in the air (the tread
     * surface and the untagged outer faces: sidewalls, the beads' outer
     * sides), from one bead to the other, in increasing axial coordinate at
     * its ends.
     * @throws InputError if those faces are not one line from bead to bead
     * (a .geo file whose physical curves leave another face untagged).
     */
    SectionLine
    outer_contour(const dealii::Triangulation<2> &section);

    /**
     * @brief The tyre and its wheel as a surface of quadrilaterals standing
     * on the road.
     *
     * Coordinates: x along the road (the rolling direction), y along the
     * axle (the section's axial coordinate), z up; the road is z = 0 and
     * the contact patch is centred on x = 0. The outer contour is revolved
     * about the axle, in cells of about `cell_size` on the contour and round
     * the circumference; two flat discs at its ends (the wheel) close it.
     * The tyre's load is its `deflection`: the circle is lowered by it and
     * cut flat at the road, and the cells that lie flat on the road (the
     * contact patch) are left out, since no air wets them: the road's image
     * closes the surface there (Air::ground). The patch's bulge and the
     * tread pattern are not modelled.
     *
     * The cells share no vertices (the boundary element method with a
     * constant value per cell needs none), and are flat (MappingQ1).
     */
    struct TyreSurface
    {
      /// Builds the surface. @throws InputError for a cell size or a
      /// deflection out of range, naming the value and what is allowed.
      TyreSurface(const SectionLine &contour, double cell_size, double deflection);

      dealii::Triangulation<2, 3> mesh;
      /// Per cell, +1 if its normal (MappingQ1) points into the air, else -1.
      std::vector<int> outward;
      /// Points inside the body, for CHIEF: off its centre and symmetry
      /// planes, where an interior mode has no node.
      std::vector<dealii::Point<3>> interior_points;
      /// The tread's largest radius before the load [m].
      double outer_radius = 0.;
      /// The wheel centre's height above the road [m].
      double axle_height = 0.;
      /// The contact patch's half length along x at the largest radius [m].
      double patch_half_length = 0.;
      /// The contour's axial extent [m], from side to side at its widest
      /// (the sidewalls' bulge): the tyre's width.
      double axial_min = 0., axial_max = 0.;
      /// The contour as resampled: cell row s of the revolved surface spans
      /// its segment s, from point s to point s + 1 ((radius, axial) [m]).
      SectionLine section_line;
      /// Per cell: the contour's segment it spans, or -1 for the wheel's
      /// discs; and the angle of its middle about the axle [rad], 0 at the
      /// bottom (the patch centre), positive along x.
      std::vector<int>    segment;
      std::vector<double> angle;
      /// The angle a cell of the revolved contour spans [rad].
      double arc = 0.;

      /// Whether a point [m] lies inside the tyre and wheel (or under the road).
      bool
      inside(const dealii::Point<3> &point) const;

    private:
      /// The closed line in the (radius, axial) plane that revolves into the body.
      SectionLine polygon;
    };
  } // namespace radiation
} // namespace greentread

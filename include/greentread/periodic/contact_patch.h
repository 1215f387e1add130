#pragma once

#include <greentread/periodic/periodic_cell.h>

#include <string>
#include <vector>

/**
 * @file
 * The contact points of the paper's Section 5.2: an N_x x N_y grid on the
 * tread surface, x along the rolling direction, y across the tread.
 */

namespace greentread
{
  namespace periodic
  {
    /// What a unit force at a contact point is ('Green's functions/Point load').
    enum class PointLoad
    {
      node,          ///< a radial force on one tread node (the paper's)
      tributary_area ///< a uniform traction over the point's rectangle
    };

    /// What the user asks for: the patch and its points.
    struct PatchRequest
    {
      double       length        = 0.06; ///< L_c along x [m]
      double       width         = 0.08; ///< l_c along y [m]
      unsigned int points_along  = 10;   ///< N_x
      unsigned int points_across = 12;   ///< N_y
      PointLoad    load          = PointLoad::node;
    };

    /// One radial DoF of a contact point's load, with its weight.
    struct LoadEntry
    {
      unsigned int cell;   ///< the ring cell, counted from the first contact cell
      unsigned int dof;    ///< the radial DoF in the reference cell's [L, I]
      double       weight; ///< the consistent nodal force of the unit load [1]
    };

    /**
     * @brief One contact point and the load that stands for it, @p load,
     * whose weights sum to 1; the response at the point is the same
     * weighted sum of radial displacements, so g_ij = g_ji.
     *
     * PointLoad::node: one entry, a unit radial force on the point's node.
     * PointLoad::tributary_area: the point is the centre of its rectangle
     * dx x dy on the tread surface; a unit force is a uniform radial
     * traction of 1 / A over it (A its area), integrated onto the radial
     * DoFs of the tread faces it covers, and the response is the mean radial
     * displacement over the rectangle.
     */
    struct ContactPoint
    {
      double x;      ///< along the rolling direction from the patch centre [m]
      double y;      ///< across the tread, the tyre's axial coordinate [m]
      double radius; ///< of the tread surface under the point [m]
      double angle;  ///< theta of the point, the first contact cell starting at 0 [rad]
      std::vector<LoadEntry> load;
    };

    /**
     * @brief The grid of contact points, point p = i N_y + j (i along x,
     * j across), and what was achieved.
     */
    struct ContactPatch
    {
      std::vector<ContactPoint> points;
      unsigned int              points_along = 0, points_across = 0;
      PointLoad                 load = PointLoad::node;
      /// The spacing asked for, L_c / N_x and l_c / N_y [m].
      double asked_dx = 0., asked_dy = 0.;
      /// The spacing achieved along x (arc length on the tread) and across
      /// y [m]; with tributary areas, the size of every rectangle.
      double dx = 0., dy = 0.;
      /// With tributary areas, the angle of every rectangle along the
      /// ring, dx over the tread's outer radius [rad].
      double arc = 0.;
      /// Cells spanned by the points, N_c.
      unsigned int n_contact_cells = 0;

      /// A description for the report: positions and spacings.
      std::string
      describe() const;
    };

    /**
     * @brief The one selection point of the point loads: the points of
     * @p request, by place_on_nodes() or place_tributary_areas().
     */
    ContactPatch
    place_contact_points(const PeriodicCell &cell, const PatchRequest &request);

    /**
     * @brief PointLoad::node: the points on tread-surface nodes of the ring,
     * each a unit radial force on its node.
     *
     * Along x, the nodes are half a cell apart (the faces and mid-planes of
     * the quadratic cells); across, at the tread nodes of the section. On
     * each axis the points take a whole stride of nodes, the one closest to
     * the spacing asked for (patch size / number of points), so the grid is
     * regular; the achieved spacing is reported.
     * @throws InputError (naming the parameter) if the patch does not fit on
     * the tread or in the ring, or the nodes under it are not evenly spaced.
     */
    ContactPatch
    place_on_nodes(const PeriodicCell &cell, const PatchRequest &request);

    /**
     * @brief PointLoad::tributary_area: the points exactly on the grid asked for, on any mesh:
     * dx = L_c / N_x, dy = l_c / N_y, symmetric about the patch centre
     * (y = 0 and the bottom of the tyre), and give each its tributary-area
     * load.
     *
     * The patch centre sits on a cell face or mid-plane, the first one that
     * leaves the whole patch in the cells from 0 on. The loads are
     * integrated by 3 x 3 Gauss points on each piece of a rectangle that
     * lies in one tread face, with the face's own shape functions (linear
     * or quadratic, from the cell's nodes), so that each is exact.
     * @throws InputError (naming the parameter) if the patch does not fit on
     * the tread or in the ring.
     */
    ContactPatch
    place_tributary_areas(const PeriodicCell &cell, const PatchRequest &request);
  } // namespace periodic
} // namespace greentread

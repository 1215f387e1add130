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
    /// What the user asks for: the patch and its points.
    struct PatchRequest
    {
      double       length       = 0.06; ///< L_c along x [m]
      double       width        = 0.08; ///< l_c along y [m]
      unsigned int points_along = 10;   ///< N_x
      unsigned int points_across = 12;  ///< N_y
    };

    /**
     * @brief One contact point, on a tread-surface node of the ring.
     */
    struct ContactPoint
    {
      double       x;    ///< along the rolling direction from the patch centre [m]
      double       y;    ///< across the tread, the tyre's axial coordinate [m]
      double       radius; ///< of its node [m]
      double       angle; ///< theta of its node, the first contact cell starting at 0 [rad]
      unsigned int cell;  ///< the cell it is in, counted from the first contact cell
      unsigned int dof;   ///< its radial DoF in the reference cell's [L, I]
    };

    /**
     * @brief The grid of contact points, point p = i N_y + j (i along x,
     * j across), and what was achieved.
     */
    struct ContactPatch
    {
      std::vector<ContactPoint> points;
      unsigned int              points_along = 0, points_across = 0;
      /// The spacing achieved along x and across y [m].
      double dx = 0., dy = 0.;
      /// Cells spanned by the points, N_c.
      unsigned int n_contact_cells = 0;

      /// A description for the report: positions and spacings.
      std::string
      describe(const PatchRequest &request) const;
    };

    /**
     * @brief Place the points on tread-surface nodes of the ring.
     *
     * Along x, the nodes are half a cell apart (the faces and mid-planes of
     * the quadratic cells); across, at the tread nodes of the section. On
     * each axis the points take a whole stride of nodes, the one closest to
     * the spacing asked for (patch size / number of points), so the grid is
     * regular; the achieved spacing is reported.
     * @throws InputError (naming the parameter) if the patch does not fit on
     * the tread or in the ring.
     */
    ContactPatch
    place_contact_points(const PeriodicCell &cell, const PatchRequest &request);
  } // namespace periodic
} // namespace greentread

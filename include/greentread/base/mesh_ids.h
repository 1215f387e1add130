#pragma once

/**
 * @file
 * The ids that the tyre cell's mesh carries, shared by the stages that make
 * it (geometry/) and that use it (fe/, periodic/): material ids of the
 * layers and boundary ids of the faces. One header, so that geometry and fe
 * need not include each other.
 */

namespace greentread
{
  namespace fe
  {
    /// Material ids of the tyre's layers (the .geo physical surfaces).
    enum MaterialId : unsigned char
    {
      tread_id    = 1,
      belt_id     = 2,
      sidewall_id = 3,
      bead_id     = 4
    };
  } // namespace fe

  namespace geometry
  {
    /// Boundary ids of the cell.
    enum BoundaryId : unsigned char
    {
      free_surface    = 0, ///< every untagged outer face
      rim_seat        = 1, ///< clamped to the rim
      inner_surface   = 2, ///< carries the inflation pressure
      tread_surface   = 3, ///< touches the road
      periodic_first  = 4, ///< the section at theta = 0
      periodic_second = 5  ///< the section at theta = 2 pi / N
    };
  } // namespace geometry
} // namespace greentread

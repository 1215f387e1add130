#include <greentread/base/exceptions.h>
#include <greentread/base/mesh_ids.h>
#include <greentread/geometry/tyre_cell.h>

#include <deal.II/grid/grid_generator.h>
#include <deal.II/grid/grid_tools.h>
#include <deal.II/grid/manifold_lib.h>

#include <cmath>
#include <map>
#include <memory>
#include <string>
#include <utility>
#include <vector>

/**
 * @file
 * The whole ring from one periodic cell (make_ring() of tyre_cell.h), and
 * the cylindrical manifold both carry.
 */

namespace greentread
{
  namespace geometry
  {
    void
    attach_cylindrical_manifold(dealii::Triangulation<3> &triangulation)
    {
      triangulation.set_all_manifold_ids(0);
      triangulation.set_manifold(0, dealii::CylindricalManifold<3>(2));
    }



    void
    make_ring(const dealii::Triangulation<3> &cell,
              const double                    angle,
              const unsigned int              n_cells,
              dealii::Triangulation<3>       &ring)
    {
      std::vector<std::unique_ptr<dealii::Triangulation<3>>> copies;
      std::vector<const dealii::Triangulation<3> *>          pointers;
      for (unsigned int k = 0; k < n_cells; ++k)
        {
          copies.push_back(std::make_unique<dealii::Triangulation<3>>());
          copies.back()->copy_triangulation(cell);
          dealii::GridTools::rotate(k * angle, 2, *copies.back());
          pointers.push_back(copies.back().get());
        }
      double size = 0.;
      for (const auto &v : cell.get_vertices())
        size = std::max(size, v.norm());
      dealii::GridGenerator::merge_triangulations(pointers, ring, 1e-9 * size, false);

      // merge_triangulations drops boundary ids. A face of the ring is a
      // rotated face of the cell: the radius and axial position of its
      // vertex average identify it.
      const auto key = [size](const dealii::TriaAccessor<2, 3, 3> &face) {
        dealii::Point<3> c;
        for (unsigned int v = 0; v < 4; ++v)
          c += face.vertex(v) / 4.;
        const double scale = 1e-9 * size;
        return std::make_pair(std::llround(std::hypot(c[0], c[1]) / scale),
                              std::llround(c[2] / scale));
      };
      std::map<std::pair<long long, long long>, dealii::types::boundary_id> ids;
      std::size_t outer_faces = 0, ring_faces = 0;
      for (const auto &cell_iterator : cell.active_cell_iterators())
        for (const auto &face : cell_iterator->face_iterators())
          if (face->at_boundary() && face->boundary_id() != periodic_first &&
              face->boundary_id() != periodic_second)
            {
              ids[key(*face)] = face->boundary_id();
              ++outer_faces;
            }
      for (const auto &cell_iterator : ring.active_cell_iterators())
        for (const auto &face : cell_iterator->face_iterators())
          ring_faces += face->at_boundary();
      // Every seam closed: a vertex left unmerged would leave a slit.
      if (ring_faces != n_cells * outer_faces)
        throw NumericalError("the ring of " + std::to_string(n_cells) + " cells has " +
                             std::to_string(ring_faces) + " boundary faces, not " +
                             std::to_string(n_cells * outer_faces) +
                             ": the periodic faces of the cell do not match when rotated");
      for (const auto &cell_iterator : ring.active_cell_iterators())
        for (const auto &face : cell_iterator->face_iterators())
          if (face->at_boundary())
            {
              const auto found = ids.find(key(*face));
              face->set_boundary_id(found == ids.end() ? dealii::types::boundary_id(free_surface) :
                                                         found->second);
            }
      attach_cylindrical_manifold(ring);
    }
  } // namespace geometry
} // namespace greentread

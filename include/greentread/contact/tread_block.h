#pragma once

#include <greentread/contact/elastic_layer.h>

#include <deal.II/grid/tria.h>

#include <Eigen/Core>

#include <memory>
#include <vector>

/**
 * @file
 * The normal compliance of one tread block by a 3D finite-element model
 * (deal.II): the reference for the finite blocks of a tread pattern
 * (greentread/contact/tread_pattern.h), whose contact grid otherwise sees an
 * endless tread layer (greentread/contact/elastic_layer.h). Implemented in
 * source/contact/tread_block.cc.
 *
 * **The block.** An isotropic rubber prism, @p length along the road by
 * @p width across and @p height high (the grooves' depth), standing on the
 * undertread, a slab @p base thick that reaches @p margin beyond the block's
 * four sides (half the grooves' width) and is bonded to the belt (rigid: it
 * is a hundred times stiffer than the rubber). The slab's own sides slide
 * (no normal displacement): it goes on under the next block, taken as this
 * one's mirror image. The block's sides and the top are free: the block's
 * sides bulge. With @p margin 0 the block's sides slide too, and the block
 * is one period of an endless layer under a periodic load: what the
 * contact grid's layer kernel (elastic_layer.h) gives in closed form. Coordinates: x along from the
 * block's corner, y across from it, z up from the belt; the top at z = base + height.
 *
 * **What it gives.** Rectangles of the top are loaded one at a time by a
 * unit force spread uniformly over each; C(i, j) is the mean displacement
 * into the block of rectangle j under the force on rectangle i, the
 * tributary-area convention of the contact grid's layer kernel, so the two
 * compare entry by entry. C is symmetric (the load and the response are the
 * same functional) and positive definite.
 *
 * **The discretisation.** Hexahedra of degree 2 (27 nodes; rubber at
 * nu = 0.49 does not lock them), about @p cell_size on a side; the mesh's
 * lines pass through every rectangle's edges, so each rectangle is a union of
 * faces and its load is integrated exactly. One sparse LU factorisation
 * (UMFPACK), one back substitution per rectangle.
 */

namespace greentread
{
  namespace contact
  {
    /// Boundary ids of the block's mesh beside geometry::rim_seat (the belt)
    /// and geometry::free_surface: the undertread's sides, which slide.
    constexpr unsigned int tread_block_side_x = 6, tread_block_side_y = 7;

    /// The block's shape [m]; the file documentation.
    struct TreadBlockGeometry
    {
      double length = 0.025;
      double width  = 0.042;
      double height = 0.006;
      double base   = 0.002;
      double margin = 0.0025;
    };

    /// A rectangle of the block's top, [x0, x1] x [y0, y1] from its corner [m].
    struct TopRectangle
    {
      double x0 = 0., x1 = 0., y0 = 0., y1 = 0.;
    };

    /**
     * @brief The block's finite-element model and its compliance between
     * rectangles of its top (file documentation).
     */
    class TreadBlock
    {
    public:
      /**
       * @param[in] shape The block.
       * @param[in] rubber Young's modulus and Poisson's ratio (its thickness
       *            is not used).
       * @param[in] rectangles On the top, inside the block; each at least
       *            one hundredth of a cell across.
       * @param[in] cell_size The cells' largest side [m].
       * @throws InputError if a size is not positive and finite, a rectangle
       *            is empty or leaves the top, or the mesh would exceed
       *            200,000 cells.
       */
      TreadBlock(const TreadBlockGeometry        &shape,
                 const ElasticLayer              &rubber,
                 const std::vector<TopRectangle> &rectangles,
                 double                           cell_size);

      ~TreadBlock();

      /// C [m/N] of the file documentation, rectangles in the given order.
      Eigen::MatrixXd
      compliance() const;

      /// The mesh: material id fe::tread_id; the faces on the belt carry
      /// boundary id geometry::rim_seat, the undertread's sides
      /// tread_block_side_x and _y, the rest geometry::free_surface.
      const dealii::Triangulation<3> &
      triangulation() const;

      unsigned int
      n_dofs() const;

    private:
      struct Model;
      std::unique_ptr<Model> model;
    };
  } // namespace contact
} // namespace greentread

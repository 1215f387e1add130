#pragma once

#include <greentread/contact/elastic_layer.h>
#include <greentread/contact/tread_pattern.h>

#include <deal.II/grid/tria.h>

#include <Eigen/Core>

#include <array>
#include <functional>
#include <memory>
#include <string>
#include <vector>

/**
 * @file
 * The normal compliance of one tread block by a 3D finite-element model
 * (deal.II): the reference for the finite blocks of a tread pattern
 * (greentread/contact/tread_pattern.h), whose contact grid otherwise sees an
 * endless tread layer (greentread/contact/elastic_layer.h). Implemented in
 * source/contact/tread_block.cc (the block) and block_compliance.cc (the
 * blocks in the contact).
 *
 * **The block.** An isotropic rubber prism, @p length along the road by
 * @p width across and @p height high (the grooves' depth), standing on the
 * undertread, a slab @p base thick that reaches @p margin_along beyond the
 * block's ends and @p margin_across beyond its sides, bonded to the belt
 * (rigid: it is a hundred times stiffer than the rubber). The slab's own
 * sides slide (no normal displacement): a mirror plane. The block's sides
 * and the top are free: the block's sides bulge. Without the grooves
 * (@p grooves false, or margins 0), the box is one period of an endless
 * layer under a periodic load: what the contact grid's layer kernel
 * (elastic_layer.h) gives in closed form. Coordinates: x along from the
 * block's corner, y across from it, z up from the belt; the top at
 * z = base + height.
 *
 * **What it gives.** Rectangles of the top are loaded one at a time by a
 * unit force spread uniformly over each; C(i, j) is the mean displacement
 * into the block of rectangle j under the force on rectangle i, the
 * tributary-area convention of the contact grid's layer kernel, so the two
 * compare entry by entry. C is symmetric (the load and the response are the
 * same functional) and positive definite.
 *
 * **The discretisation.** Hexahedra of degree 2 (27 nodes; rubber at
 * nu = 0.49 does not lock them), about @p cell_size on a side (twice that in
 * the margins); the mesh's lines pass through every rectangle's edges, so
 * each rectangle is a union of faces and its load is integrated exactly.
 * One sparse Cholesky factor (CHOLMOD, supernodal), the loads solved 64 at
 * a time.
 *
 * **The finite blocks in the contact** (BlockCompliance). The contact grid's
 * local term is the endless layer's (contact_grid.h). A `blocks` pattern
 * adds, between the contact points on one block, what the block adds to
 * it: \f$\Delta C = C_{block} - C_{layer}\f$, both by this model on one
 * mesh (the grooves' cells removed, or kept), between the rectangles of a
 * table over the block's top (about @p mesh_size each, one cell each). The
 * block stands alone on an undertread that reaches twice the tread's
 * thickness beyond it: with margins of half a groove, the ungrooved
 * model's mirror images at its walls lowered its compliance (a nearly
 * incompressible layer rises around a load) by 8% of the endless layer's,
 * an error the difference did not cancel. The mesh's own error largely
 * cancels in the difference, and removing cells can only soften a
 * finite-element model, so \f$\Delta C\f$ is symmetric positive
 * semidefinite and the contact points' compliance stays positive definite.
 * A contact point takes the table rectangle its centre lies in, in the
 * block under it at the pattern's position (the blocks move with the road,
 * tread_pattern.h), so contact points i, j on one block get
 * \f$\Delta C_{IJ}\f$ of their rectangles I, J: the table spread piecewise
 * constant over the contact points, as the Green's functions' compliance is
 * over the coarse cells. One table per block shape (pitch length and rib
 * width); a rib at the tread's edge is a block there too. Left out: the
 * blocks' coupling to each other stays the endless layer's (through the
 * rubber under a groove).
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
      double length        = 0.025;
      double width         = 0.042;
      double height        = 0.006;
      double base          = 0.002; ///< 0: the block stands on the belt
      double margin_along  = 0.0025;
      double margin_across = 0.004;
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
       * @param[in] grooves false: the grooves filled (the same mesh, no
       *            cell removed): the endless layer on the block's mesh.
       * @throws InputError if a size is not positive and finite, a rectangle
       *            is empty or leaves the top, or the mesh would exceed
       *            200,000 cells.
       */
      TreadBlock(const TreadBlockGeometry        &shape,
                 const ElasticLayer              &rubber,
                 const std::vector<TopRectangle> &rectangles,
                 double                           cell_size,
                 bool                             grooves = true);

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

    /**
     * @brief The finite blocks of a `blocks` pattern in the contact grid
     * (file documentation): \f$\Delta C\f$ of each block shape; per run,
     * BlockState applies it to the contact points as the pattern moves.
     */
    class BlockCompliance
    {
    public:
      /**
       * @param[in] pattern The pattern's pitches round the tyre.
       * @param[in] parameters Its grooves (`blocks`).
       * @param[in] tread The tread rubber and its thickness (the grooves'
       *            depth is the blocks' height, the rest the undertread).
       * @param[in] tread_width The tread's width [m]: the outer ribs' edges.
       * @param[in] mesh_size The table's rectangles and the mesh's cells [m].
       * @param[in] n_threads The shapes computed side by side.
       * @param[in] progress Whether to print a line per block shape.
       * @throws InputError if a size is not positive; std::logic_error if
       *         the pattern is not `blocks` (its parameters refuse that).
       */
      BlockCompliance(const TreadPattern           &pattern,
                      const TreadPatternParameters &parameters,
                      const ElasticLayer           &tread,
                      double                        tread_width,
                      double                        mesh_size,
                      unsigned int                  n_threads = 1,
                      bool                          progress  = false);

      /// One line for the log: the shapes, their tables, the softening.
      std::string
      summary() const;

      /// A block shape and its table.
      struct Shape
      {
        double          length = 0., width = 0.;
        unsigned int    nx = 0, ny = 0; ///< the table's rectangles along, across
        Eigen::MatrixXd delta;          ///< \f$\Delta C\f$ [m/N], I = i_x ny + i_y
        /// delta in single precision, which BlockState's products read:
        /// half the memory traffic, which matters most when a second run
        /// shares the caches (the scene's runs go side by side). delta is
        /// this table in double, so that every product is with the same
        /// operator; the rounding, 6e-8 relative, is far below the blocks'
        /// mesh error.
        Eigen::MatrixXf single;
        double          norm = 0.; ///< \f$\|\Delta C\|_2\f$ [m/N]
        /// The block's and the layer's compliance under the whole top
        /// uniformly loaded, and at its corner rectangle [m/N].
        double top_block = 0., top_layer = 0., corner_block = 0., corner_layer = 0.;
      };

      const std::vector<Shape> &
      shapes() const
      {
        return shape_list;
      }

    private:
      friend class BlockState;
      const TreadPattern                &pattern;
      double                             lateral = 0.;
      std::vector<std::array<double, 2>> ribs;     ///< [y0, y1] across [m]
      std::vector<std::vector<unsigned>> shape_of; ///< [pitch][rib]
      std::vector<Shape>                 shape_list;
    };

    /**
     * @brief The blocks of a BlockCompliance under a set of contact points
     * at the pattern's position: one per run (not shared between threads).
     */
    class BlockState
    {
    public:
      BlockState(const BlockCompliance &blocks, const std::vector<std::array<double, 3>> &points);

      /// The patch position s [m] (tread_pattern.h): which block and
      /// table rectangle each point is on.
      void
      set_position(double s);

      /// y += \f$\Delta C\f$ x over the points.
      void
      add_product(const Eigen::VectorXd &x, Eigen::VectorXd &y) const;

      /// out(k, l) += \f$\Delta C\f$ between points rows[k] and columns[l].
      void
      add_block(const std::vector<unsigned int> &rows,
                const std::vector<unsigned int> &columns,
                Eigen::MatrixXd                 &out) const;

      /// A bound on the norm of \f$\Delta C\f$ over the points at any
      /// position: the largest shape's norm times the most points a table
      /// rectangle can hold (\f$\|A^T \Delta C A\|_2 \le \max_I n_I
      /// \|\Delta C\|_2\f$, A the points' sums per rectangle). (The
      /// largest row sum of \f$|D^{1/2} \Delta C D^{1/2}|\f$, D the counts,
      /// over every way the blocks can lie on the points, gave no faster
      /// solve: 9.6 against 9.3 ms per step.)
      double
      norm_bound() const
      {
        return bound;
      }

      /**
       * The norm of W plus \f$\Delta C\f$ over the points, largest over
       * @p n_positions positions spread round the pattern, for the step
       * length of a solve on the whole grid. norm_bound() added to W's norm
       * over-estimates it (1.6 times on the dense asphalt of
       * prm/tyre_pattern.prm on a coarse ring, 1.8 times in
       * unit/tread_block), and the solve slows down with it. Each
       * position's norm is a power iteration's, as without blocks
       * (contact/projected_cg.h); the positions follow a low-discrepancy
       * sequence (the golden ratio's), so that they spread evenly over the
       * blocks and their offsets from the points (64 samples cannot take
       * every one); and the largest gets a margin of 5%
       * for the positions between. The solve's step, 1.9 over it, stays below
       * the 2 over the true norm while that is within 10% of the largest
       * sampled one; unit/tread_block checks it against dense eigenvalues at
       * other positions. Leaves this state's position as it was.
       *
       * @param[in] W The rest of the operator (y = W x), symmetric positive
       *            definite.
       * @param[in] n_positions The positions sampled.
       */
      double
      largest_norm(const std::function<void(const Eigen::VectorXd &, Eigen::VectorXd &)> &W,
                   unsigned int n_positions = 64) const;

    private:
      const BlockCompliance                    &blocks;
      const std::vector<std::array<double, 3>> &points;
      /// Per point: its slot (a block in the patch; -1 in a groove) and
      /// its table rectangle.
      std::vector<int>          slot;
      std::vector<unsigned int> cell;
      /// Per slot: the block (pitch times the ribs' number plus rib) and
      /// its shape.
      std::vector<std::size_t>             slot_block;
      std::vector<unsigned int>            slot_shape;
      mutable std::vector<Eigen::VectorXd> load, response;
      mutable std::vector<bool>            loaded;
      double                               bound = 0.;
    };
  } // namespace contact
} // namespace greentread

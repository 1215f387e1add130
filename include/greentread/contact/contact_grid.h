#pragma once

#include <greentread/contact/contact_grid_parameters.h>
#include <greentread/contact/elastic_layer.h>
#include <greentread/contact/rolling.h>
#include <greentread/convolution/lattice_convolution.h>
#include <greentread/convolution/patch_convolution.h>

#include <Eigen/Core>

#include <array>
#include <memory>
#include <string>
#include <vector>

/**
 * @file
 * A contact grid finer than the Green's functions' points, by a split of
 * scales. Implemented in source/contact/contact_grid.cc.
 *
 * Each of the Green's functions' rectangles (dx x dy, the "coarse" cells) is
 * split into s x s contact rectangles. The finite-element model resolves the
 * tread's compliance at the coarse cells' scale, not below it; an elastic
 * layer (greentread/contact/elastic_layer.h: the tread's rubber, its
 * thickness, bonded to the belt) carries what lies below. With P the mean
 * over each coarse cell spread back over its contact points, the
 * displacement of the contact points under their forces f is
 * \f[
 *   u = A^T G\,A f + (I - P)\,L_f\,(I - P)\,f,
 * \f]
 * A the sum of the forces of each coarse cell (q = A f), G the Green's
 * functions between the coarse cells (the patch model, with its dynamics) and
 * L_f the layer's compliance between the contact rectangles. Nothing is
 * counted twice: the coarse cells' mean displacements are exactly G's response
 * to the cells' total forces, whatever the forces' distribution within the
 * cells; the layer adds only the displacement's variation within each cell,
 * and only in response to the force's variation within the cells. The local
 * term is symmetric positive semidefinite (L_f is), so the contact points'
 * instantaneous compliance stays positive definite whatever G's split
 * between its instantaneous and its modal parts. Left out: how a force's
 * distribution within one cell moves the mean of another (the layer's cross
 * terms \f$P L_f (I - P)\f$; the coarse model cannot represent them, and
 * with them the local term \f$L_f - A^T L_c A\f$ is indefinite, measured:
 * the contact points' compliance then lost its positivity against the
 * patch model's instantaneous part G_r). The local term is quasi-static and
 * elastic: its inertia and the rubber's loss factor are left out (the
 * variation it carries is shorter than a coarse cell, and the rubber's shear
 * wavelength is longer than 6 mm up to about 5 kHz; the tread's inertia at
 * the cells' scale is in G's modes). With s = 1 the grid is the Green's
 * functions' points and adds nothing.
 *
 * **Two solvers of the contact** (`Contact grid/Solver`, chosen in one
 * place, ContactGridParameters::matrix_free()):
 * - `pivoting`: the N x N compliances are formed, and each step's LCP is
 *   solved by block principal pivoting (greentread/contact/lcp.h), warm-
 *   started from the last step's active set. Exact to round-off; memory
 *   8 N^2 bytes per matrix (several are held), so up to 10,000 points
 *   (refused above).
 * - `projected CG`: no N x N matrix. The compliance is applied as
 *   $A^T (G (A f)) + (I - P) L_f (I - P) f$, L_f by FFT on the lattice
 *   (greentread/convolution/lattice_convolution.h), and each step's LCP is the
 *   bound-constrained quadratic programme solved by MPRGP
 *   (greentread/contact/projected_cg.h), warm-started from the last step's
 *   forces. O(N log N) per product; it needs a reciprocal (symmetric) patch
 *   model, which the ring's own modes are. MPRGP runs on the candidate
 *   points alone (greentread/contact/candidate_set.h), on their dense block
 *   of the compliance (ContactGrid::block()), and the answer is checked on
 *   the whole grid by one FFT product per round.
 * - `projected CG on the whole grid`: the same MPRGP on every point, each
 *   product by FFT; the reference of the candidate set.
 * - `auto` (the default): `projected CG` with the ring's own modes,
 *   `pivoting` with the identified (non-reciprocal) model.
 */

namespace greentread
{
  namespace contact
  {
    class BlockState;

    /**
     * @brief The contact points of a subdivided patch and the split of the
     * file documentation.
     */
    class ContactGrid
    {
    public:
      /**
       * @param[in] coarse_points The Green's functions' points, a lattice
       *            (any order); their third coordinate, the tread's radius,
       *            is kept.
       * @param[in] subdivisions s >= 1.
       * @param[in] layer The tread as a layer (used when s > 1).
       * @param[in] matrix_free The `projected CG` solver: the local term only
       *            as its FFT product, ContactGrid::local stays empty.
       * @param[in] candidate_set With @p matrix_free: the solve on the
       *            candidate set (ContactGrid::candidate_set).
       * @param[in] tolerance With @p matrix_free: the solve's tolerance
       *            (ContactGrid::tolerance).
       * @throws InputError if the points are not a lattice or s is 0.
       */
      ContactGrid(const std::vector<std::array<double, 3>> &coarse_points,
                  unsigned int                              subdivisions,
                  const ElasticLayer                       &layer,
                  bool                                      matrix_free   = false,
                  bool                                      candidate_set = true,
                  double                                    tolerance     = 1e-6);

      unsigned int
      n_points() const
      {
        return points.size();
      }

      /// \f$A^T M A\f$: a coarse matrix seen by the contact points.
      Eigen::MatrixXd
      expand(const Eigen::MatrixXd &coarse) const;

      /// \f$A^T v\f$: a coarse cell's value at each of its contact points.
      Eigen::VectorXd
      expand(const Eigen::VectorXd &coarse) const;

      /// \f$A f\f$: the sum over each coarse cell.
      Eigen::VectorXd
      gather(const Eigen::VectorXd &fine) const;

      /// The same into @p coarse (resized), without an allocation once sized.
      void
      gather(const Eigen::VectorXd &fine, Eigen::VectorXd &coarse) const;

      /// The static compliance between the contact points, \f$A^T G_0 A\f$
      /// plus the local term.
      Eigen::MatrixXd
      compliance(const Eigen::MatrixXd &coarse_static) const;

      /// y += the local term times x, \f$(I - P) L_f (I - P) x\f$, by FFT (0 when s = 1).
      void
      add_local(const Eigen::VectorXd &x, Eigen::VectorXd &y) const;

      /// y = \f$A^T M A x\f$ + the local term times x, without the N x N matrix.
      void
      apply(const Eigen::MatrixXd &coarse, const Eigen::VectorXd &x, Eigen::VectorXd &y) const;

      /// y += \f$A^T M A x\f$ (none when @p coarse is null) + the local
      /// term times x: apply() without clearing y, each cell sum taken once.
      void
      add_product(const Eigen::MatrixXd *coarse,
                  const Eigen::VectorXd &x,
                  Eigen::VectorXd       &y) const;

      /**
       * @brief A block of apply()'s operator, entry by entry: out(k, l) =
       * \f$(A^T M A)_{ij}\f$ + \f$((I - P) L_f (I - P))_{ij}\f$ for i =
       * rows[k], j = columns[l], from the layer's kernel and its sums over
       * the coarse cells (tabulated once), in O(rows x columns) without the
       * N x N matrix or an FFT. What the candidate-set solve
       * (candidate_set.h) iterates on.
       */
      void
      block(const Eigen::MatrixXd           &coarse,
            const std::vector<unsigned int> &rows,
            const std::vector<unsigned int> &columns,
            Eigen::MatrixXd                 &out) const;

      /**
       * @brief The weights of the reporting cell, @p along x @p across [m]
       * centred at the patch centre (x0 = 0, y0 = 0), whatever the grid; 0
       * for either: a coarse cell's size (the Green's-function rectangle).
       * The stress there is \f$\sum_p w_p \sigma_p\f$, the mean of the
       * piecewise constant stress over the cell (each w_p is the area of the
       * cell that contact rectangle p covers, over the cell's area).
       * @throws InputError naming 'Spectra/Reporting cell along' or
       * 'across' if the cell is not inside the grid.
       */
      Eigen::VectorXd
      reporting_weights(double along = 0., double across = 0.) const;

      unsigned int subdivisions = 1;
      /// The contact points, a lattice p = i_x ny + i_y, x and y increasing.
      std::vector<std::array<double, 3>> points;
      unsigned int                       nx = 0, ny = 0;
      /// The contact rectangle and the coarse cell [m].
      double dx = 0., dy = 0., coarse_dx = 0., coarse_dy = 0.;
      /// The coarse point (index into the constructor's points) of each contact point.
      std::vector<unsigned int> coarse_of;
      /// \f$(I - P) L_f (I - P)\f$ [m/N]; empty when s = 1 or matrix-free.
      Eigen::MatrixXd local;
      /// The solver: `projected CG` (true) or `pivoting`.
      bool matrix_free = false;
      /// Whether the matrix-free solve works on the candidate set
      /// (candidate_set.h; `projected CG`) or on the whole grid (`projected
      /// CG on the whole grid`).
      bool candidate_set = true;
      /// The matrix-free solve's tolerance (`Contact grid/Tolerance`).
      double tolerance = 1e-6;
      /// \f$L_f\f$ on the lattice, by FFT; empty when s = 1.
      std::shared_ptr<const convolution::LatticeConvolution> layer_product;

    private:
      void
      tabulate_cell_sums();

      unsigned int n_coarse = 0, cnx = 0, cny = 0;
      /// The coarse point of coarse cell (c_x, c_y), at c_x cny + c_y.
      std::vector<unsigned int> coarse_at;
      /// For block(): the layer's kernel summed over a coarse cell's s x s
      /// offsets, over s^2 (offset (dx, dy) at (dx + nx - 1, dy + ny - 1)),
      /// and over two cells' offsets, over s^4 (cell offset (cx, cy) at
      /// (cx + cnx - 1, cy + cny - 1)). Empty unless matrix-free with s > 1.
      Eigen::MatrixXd cell_sums, cell_pair_sums;
    };

    /**
     * @brief The convolution of the contact points: the patch model's
     * convolution @p coarse driven by the forces gathered per coarse cell,
     * its history seen by each contact point, plus the local term at the end
     * of each step. With s = 1 and no @p blocks, @p coarse itself.
     * @param[in] blocks A tread pattern's finite blocks at the run's patch
     *            position (the road's heights set it before each step's
     *            solve), added to the local term; nullptr: none.
     * @throws std::logic_error if @p blocks is given with the `pivoting`
     *         solver (the scene refuses that).
     */
    std::unique_ptr<convolution::PatchConvolution>
    make_grid_convolution(std::unique_ptr<convolution::PatchConvolution> coarse,
                          const ContactGrid                             &grid,
                          const BlockState                              *blocks = nullptr);

    /**
     * @brief contact::start_contact() on the grid: the static compliance
     * \f$A^T G_0 A\f$ + the local term (+ the finite @p blocks' at the start),
     * by the grid's solver.
     * @throws std::logic_error if @p blocks is given with the `pivoting`
     *         solver.
     */
    StaticContact
    start_grid_contact(const ContactGrid      &grid,
                       const Eigen::MatrixXd  &coarse_static,
                       const Eigen::VectorXd  &tread,
                       const PatchRoadHeights &road,
                       const RollingSetup     &setup,
                       const BlockState       *blocks = nullptr);
  } // namespace contact
} // namespace greentread

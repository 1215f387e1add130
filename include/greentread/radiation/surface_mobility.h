#pragma once

#include <greentread/fe/harmonic_section.h>
#include <greentread/periodic/contact_patch.h>
#include <greentread/radiation/tyre_surface.h>

#include <Eigen/Dense>

#include <complex>
#include <vector>

/**
 * @file
 * The tyre's surface mobility: the normal velocity of every cell of the
 * radiating surface per unit force at each contact point, from the section's
 * modes harmonic by harmonic.
 *
 * The ring is axisymmetric, so harmonic n of its response to point q's load
 * (the strip w_j / W_j of its row j across the tread, its box of angle a
 * along the ring, as periodic/harmonic_ring.h loads it) is the section's response
 * D_n(w)^{-1} w_j / W_j. Averaged over a surface cell, which spans segment s
 * of the section's outer line (fe::HarmonicSection::surface_segments()) and
 * the angle a_c round the axle, it gives the cell's mean normal
 * displacement; summed over the harmonics,
 *
 *   Y_cq(w) = j w sum_{n < N} e_n / (2 pi) sinc(n a_c / 2) sinc(n a / 2)
 *             cos(n (theta_c - theta_q)) H_n(w)_{s j},
 *
 * e_0 = 1, e_n = 2, theta measured from the patch centre, and
 * H_n(w) = (w_s / W_s)^T D_n(w)^{-1} (w_j / W_j), the section's transfer from
 * the tread's strips to the line's segments. H_n is synthesised from the
 * modes of harmonic n below a cut-off (synthesis/harmonic_modes.h), with the
 * damping's coupling among them (synthesis::coupled_point_modes()), plus
 * their static residual: H_n(0) by a direct static solve less the modes'
 * part at 0 Hz, so that the modes above the cut-off enter as a spring.
 *
 * The sum stops at N harmonics. A cell's box factor sinc(n a_c / 2) falls
 * to zero at n = 2 pi / a_c, the number of cells round the tyre: the mesh
 * cannot hold more, and N is chosen from it (and checked by the mesh's
 * refinement). The section's load and its velocity are those of the unloaded
 * ring: the flattening of the tyre by its load moves where the surface is
 * (radiation/tyre_surface.h), not how it moves. The wheel's discs are held
 * still (a rigid rim).
 */

namespace greentread
{
  namespace radiation
  {
    class SurfaceMobility
    {
    public:
      /**
       * @param[in] section     The inflated section of the ring.
       * @param[in] patch       The contact points, with tributary areas:
       *                        their rows' strips across the tread, their
       *                        box along it, and their angle from the patch
       *                        centre (x over the tread's radius).
       * @param[in] surface     The radiating surface, built on the outer line
       *                        of the same section.
       * @param[in] cutoff      The modes' cut-off [rad/s].
       * @param[in] n_harmonics The harmonics 0 .. N - 1 summed.
       * @param[in] couple_damping Keep the damping's coupling among the
       *                        modes of a harmonic.
       * @throws InputError if the patch's points are nodes, not tributary
       *         areas (their series round the ring does not converge).
       * @throws NumericalError if a harmonic's modes or static solve fail.
       */
      SurfaceMobility(const fe::HarmonicSection    &section,
                      const periodic::ContactPatch &patch,
                      const TyreSurface            &surface,
                      double                        cutoff,
                      unsigned int                  n_harmonics,
                      bool                          couple_damping = true);

      /**
       * @brief The cells' normal velocity [m/s] at @p omega for the forces
       * @p forces at the points [N] (rows: points; columns: cases), Y(w) F,
       * without forming Y: per harmonic the forces' harmonic content along
       * the patch, sum_i F_i e^{-+j n theta_i} per strip, goes through H_n
       * to the segments and round the tyre to the cells, N (P + S J + C)
       * operations per case for P points, S segments, J strips and C cells.
       */
      Eigen::MatrixXcd
      velocity(double omega, const Eigen::MatrixXcd &forces) const;

      /**
       * @brief The points' own velocity [m/s] (each over its rectangle) for
       * the forces @p forces, by the same sum over the harmonics as
       * velocity() with the strips in place of the segments. Its power
       * 1/2 Re F^H v is what the forces put into the tyre, less what the
       * harmonics from N on and the modes above the cut-off would add: each
       * harmonic's and each mode's share is dissipated, so none is
       * negative, and the sum is a lower bound of the whole.
       */
      Eigen::MatrixXcd
      point_velocity(double omega, const Eigen::MatrixXcd &forces) const;

      /// Y(w) [m / (s N)]: cells (rows) by points (columns), velocity() of
      /// unit forces.
      Eigen::MatrixXcd
      at(double omega) const;

      unsigned int
      n_cells() const
      {
        return static_cast<unsigned int>(cell_segment.size());
      }

      unsigned int
      n_points() const
      {
        return static_cast<unsigned int>(point_angle.size());
      }

      /// The section's transfer H_n(w) of harmonic @p n, segments (rows) by
      /// strips (columns) [m / N per unit of the ring's box].
      Eigen::MatrixXcd
      section_transfer(unsigned int n, double omega) const;

      /// The same from the strips to the strips.
      Eigen::MatrixXcd
      strip_transfer(unsigned int n, double omega) const;

      unsigned int
      n_harmonics() const
      {
        return static_cast<unsigned int>(harmonics.size());
      }

      /// The modes kept, over all harmonics.
      unsigned int
      n_modes() const;

      /// The same mobility summed over its first @p n harmonics only (the
      /// harmonics' error bar). @throws InputError if @p n exceeds them.
      SurfaceMobility
      truncated(unsigned int n) const;

      /// The mobility as flat arrays, for a saved stage: per harmonic its
      /// modes' count, coupling, frequencies, damping ratios and shapes
      /// (row-major, mode by segment and mode by strip) and its residuals
      /// (row-major), one after the other; the cells' and points' places.
      struct Saved
      {
        std::vector<int>                  modes, coupled, cell_segment, point_strip;
        std::vector<double>               omega, damping_ratio, cell_angle, point_angle;
        std::vector<std::complex<double>> at_segments, at_strips;
        std::vector<double>               residual, strip_residual;
        /// The strips J, the segments S, the cells' arc and the points' arc.
        std::vector<double> sizes;
      };

      Saved
      saved() const;

      /// The mobility that saved() gave. @throws InputError if the arrays'
      /// sizes do not fit together.
      explicit SurfaceMobility(const Saved &saved);

    private:
      /// One harmonic's modes at the segments and strips, and its residual.
      struct Harmonic
      {
        Eigen::VectorXd omega, damping_ratio;
        /// Shapes [mode][segment] and [mode][strip]; complex with the
        /// damping's coupling, else real (imaginary parts zero).
        Eigen::MatrixXcd at_segments, at_strips;
        bool             coupled = false;
        /// H_n(0) less the modes' part at 0 Hz, segments by strips, and
        /// strips by strips.
        Eigen::MatrixXd residual, strip_residual;
      };

      /// The modes' part of H_n(w) from the strips to @p left, the modes'
      /// values at the segments or the strips.
      static Eigen::MatrixXcd
      modal_part(const Harmonic &h, const Eigen::MatrixXcd &left, double omega);

      /// velocity() (to the cells) or point_velocity() (@p to_points).
      Eigen::MatrixXcd
      spread(double omega, const Eigen::MatrixXcd &forces, bool to_points) const;

      std::vector<Harmonic> harmonics;
      /// Per cell its segment (-1: held still), cos and sin of n theta come
      /// from its angle; per point its strip and angle.
      std::vector<int>    cell_segment;
      std::vector<double> cell_angle, point_angle;
      std::vector<int>    point_strip;
      unsigned int        n_strips = 0;
      double              cell_arc = 0., point_arc = 0.;
    };
  } // namespace radiation
} // namespace greentread

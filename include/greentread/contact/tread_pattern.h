#pragma once

#include <greentread/contact/tread_pattern_parameters.h>

#include <Eigen/Core>

#include <array>
#include <string>
#include <vector>

/**
 * @file
 * A tread pattern in the contact: grooves cut into the tread layer, pitch
 * after pitch round the circumference. Implemented in
 * source/contact/tread_pattern.cc; its parameters (subsection "Tread
 * pattern") in greentread/contact/tread_pattern_parameters.h.
 *
 * **The pattern moves with the road.** The contact grid is fixed in the
 * non-rotating frame of the wheel centre. A rolling tyre's tread in the
 * patch moves backwards at the speed V, as the road does: the tread point
 * under contact point x at patch position s (the distance rolled) is the
 * one at arc length \f$\sigma = s + x\f$ round the tyre, just as the road
 * point under it is at s + x. So the pattern is a recess of the tread's
 * surface at \f$(\sigma, y)\f$, and the demand of contact point p becomes
 * \f$d_p = \delta + z_p(s) - t_p - h\,\chi(s + x_p, y_p)\f$, with h the
 * groove depth and \f$\chi\f$ 1 in a groove, 0 on a block: a groove is the
 * road lowered by h under that point. A groove deeper than the tread's
 * indentation and the road's relief there carries no force; nothing else of
 * the contact changes, and the carcass (the Green's functions, the modes)
 * stays the axisymmetric ring.
 *
 * **The blocks' own compliance** is in greentread/contact/tread_block.h
 * (BlockCompliance, `Block compliance`): what a finite block adds to the
 * endless tread layer of the contact grid, for `blocks`. With `image` the
 * blocks are as stiff as the endless layer.
 *
 * **What it leaves out.** A groove's sides carry no shear; the grooves' air
 * (pumping, pipe resonances). A point is in a groove
 * when its centre is (no partial cover), so a groove's edges are resolved to
 * a contact rectangle: the study's contact-grid error bar measures that.
 *
 * **Pitches.** The pitch lengths of the sequence, repeated round the
 * circumference \f$2\pi r\f$ (r: the contact points' radius) as many whole
 * times as fit best, are scaled by one factor so that they fill it exactly:
 * the pattern is then periodic in \f$\sigma\f$ with the circumference, and a
 * uniform pitch p gives lines at exactly \f$kV/p\f$.
 */

namespace greentread
{
  namespace contact
  {
    /// The grooves of one pitch, as a footprint stretched over the pitch.
    struct PitchFootprint
    {
      /// `blocks`: a lateral groove at the pitch's start [m along, not
      /// stretched], circumferential grooves (centre, width) across.
      double                             lateral_groove_width = 0.;
      std::vector<std::array<double, 2>> circumferential;
      /// `image`: rows along the pitch (first row at its start), columns
      /// across 'Footprint width' centred on the tread; true: groove.
      std::vector<std::vector<unsigned char>> image;
      double                                  image_width = 0.;
    };

    class TreadPattern
    {
    public:
      /**
       * @param[in] parameters Subsection "Tread pattern" (not slick).
       * @param[in] radius The contact points' radius r [m].
       * @throws InputError if a footprint image cannot be read (naming the
       *         file) or the sequence does not fit round the tyre once.
       */
      TreadPattern(const TreadPatternParameters &parameters, double radius);

      /// A tread point's pitch and its distance from the pitch's start [m].
      struct Place
      {
        std::size_t pitch = 0;
        double      along = 0.;
      };

      /// The place of the tread point at arc length @p sigma [m] (any
      /// sign: the pattern repeats round the circumference).
      Place
      locate(double sigma) const;

      /// Whether the tread point at arc length @p sigma [m] and @p y [m]
      /// across lies in a groove.
      bool
      in_groove(double sigma, double y) const;

      /// z_p -= depth for every point of @p points in a groove at patch
      /// position @p s [m] (the file documentation).
      void
      recess(const std::vector<std::array<double, 3>> &points, double s, Eigen::VectorXd &z) const;

      /// The pitches round the tyre, after scaling [m].
      const std::vector<double> &
      pitches() const
      {
        return lengths;
      }

      /// Where each pitch starts [m]; the lateral groove is there.
      const std::vector<double> &
      pitch_starts() const
      {
        return starts;
      }

      double
      circumference() const
      {
        return total;
      }

      /// The factor the given lengths were scaled by.
      double
      scale() const
      {
        return factor;
      }

      double
      depth() const
      {
        return groove_depth;
      }

      /// One line for the log: pitches, sequence, scaling.
      std::string
      summary() const;

    private:
      PitchFootprint      footprint;
      std::vector<double> lengths, starts;
      double              total = 0., factor = 1., groove_depth = 0.;
      unsigned int        repeats = 1, sequence_length = 1;
    };

    /**
     * @brief Check a pattern against the tread and the contact grid: nothing
     * wider than the tread, no groove narrower than a contact rectangle
     * (@p dx along, @p dy across) and no block shorter than one, the grooves
     * no deeper than the tread layer.
     * @throws InputError naming the parameter, its value and what is allowed.
     */
    void
    check_pattern(const TreadPatternParameters &parameters,
                  const TreadPattern           &pattern,
                  double                        tread_width,
                  double                        tread_thickness,
                  double                        dx,
                  double                        dy,
                  unsigned int                  subdivisions);
  } // namespace contact
} // namespace greentread

#pragma once

#include <Eigen/Core>

#include <functional>
#include <vector>

/**
 * @file
 * The local normal compliance of the tread as an elastic layer bonded to a
 * rigid base (the steel belt is a hundred times stiffer than the rubber):
 * its surface response to a normal pressure of any wavenumber, and from it
 * the compliance between the rectangles of a contact lattice. The contact
 * grid finer than the Green's functions' (greentread/contact/
 * contact_grid.h) takes from it the part of the compliance below the
 * Green's functions' rectangles. Implemented in source/contact/elastic_layer.cc.
 *
 * **The layer.** Isotropic, Young's modulus E, Poisson's ratio nu, thickness
 * h, its base z = h fixed, its surface z = 0 free of shear. A pressure
 * \f$p\cos(kx)\f$ on the surface moves it by \f$C(k)\,p\cos(kx)\f$ into the
 * layer. The problem is plane strain along the wavevector; its displacement
 * is a sum of four Papkovich-Neuber fields (\f$\nabla e^{\pm kz}\cos kx\f$
 * and \f$4(1-\nu)\psi - \nabla(z\psi)\f$, \f$\psi = e^{\pm kz}\cos kx\f$),
 * whose four amplitudes the two conditions at each face fix: a 4 x 4 solve
 * per k, with the growing exponentials written from the base so that nothing
 * overflows. Limits: \f$C \to 2(1-\nu^2)/(E k)\f$ (half-space) for
 * \f$kh \gg 1\f$, \f$C(0) = h/(\lambda + 2\mu)\f$ (a laterally constrained
 * column).
 *
 * **A lattice of rectangles.** Rectangles a x b tile the plane; a unit force
 * spread uniformly over rectangle (0, 0) moves rectangle (m, n) on average by
 * \f[
 *   T(m, n) = \frac{1}{P_x P_y} \sum_{\kappa} C(|\kappa|)\,
 *   \mathrm{sinc}^2\frac{\kappa_x a}{2}\,\mathrm{sinc}^2\frac{\kappa_y b}{2}\,
 *   \cos(\kappa_x m a)\cos(\kappa_y n b),
 * \f]
 * the Fourier series over a period \f$P_x \times P_y\f$ (whole numbers of
 * rectangles, large enough that the layer's response to its images, which
 * decays over a few h, does not count), \f$\kappa = 2\pi(j_x / P_x, j_y /
 * P_y)\f$. The sinc^2 is the rectangle's load and its averaging; the series
 * converges as \f$|\kappa|^{-5}\f$ and is cut at @p harmonics rectangles'
 * worth of wavenumbers per direction. The load and the response are the same
 * functional, so T is symmetric: the tributary-area convention of the
 * Green's functions.
 */

namespace greentread
{
  namespace contact
  {
    /// An isotropic elastic layer bonded to a rigid base.
    struct ElasticLayer
    {
      double youngs_modulus = 7e6;   ///< E [Pa]
      double poissons_ratio = 0.49;  ///< nu, below 0.5
      double thickness      = 0.008; ///< h [m]
    };

    /**
     * @brief C(k) [m/Pa] of the file documentation by the 4 x 4 solve.
     * @throws InputError if E <= 0, nu is outside (-1, 0.5), h <= 0 or k < 0.
     */
    double
    layer_compliance(const ElasticLayer &layer, double k);

    /**
     * @brief C(k) tabulated once over kh, for the many evaluations of a
     * lattice: 20,000 points, log-spaced from kh = 1e-3 to 40, linear in log kh
     * (relative error below 1e-6 against layer_compliance()); below the
     * table quadratic in k from C(0), above it the half-space's value (the
     * two differ there by e^-80).
     */
    class LayerComplianceTable
    {
    public:
      explicit LayerComplianceTable(const ElasticLayer &layer);

      double
      operator()(double k) const;

    private:
      ElasticLayer        layer;
      double              c0 = 0., log_x0 = 0., dlog = 0.;
      std::vector<double> s; ///< C(k) E k / (2 (1 - nu^2)) at the table's kh
    };

    /**
     * @brief T(m, n) of the file documentation for m = 0 .. @p mx,
     * n = 0 .. @p my (T is even in m and in n), as a (mx + 1) x (my + 1)
     * matrix [m/N].
     * @param[in] compliance C(k) [m/Pa]; C(0) may be +inf (a half-space): then
     *            the mean term is left out and T is known up to a constant.
     * @param[in] a, b The rectangle [m].
     * @param[in] nx, ny The period in rectangles, P_x = nx a, P_y = ny b;
     *            at least 2 mx + 1 and 2 my + 1.
     * @param[in] harmonics The series is cut at |kappa_x| <= 2 pi harmonics / a
     *            (likewise y).
     * @throws InputError if a period is too short for the offsets asked.
     */
    Eigen::MatrixXd
    rectangle_lattice_compliance(const std::function<double(double)> &compliance,
                                 double                               a,
                                 double                               b,
                                 unsigned int                         mx,
                                 unsigned int                         my,
                                 unsigned int                         nx,
                                 unsigned int                         ny,
                                 unsigned int                         harmonics = 24);

    /**
     * @brief The kernel of the compliance between the rectangles of an
     * nx x ny patch of a x b rectangles of @p layer: T(m, n) of the file
     * documentation for the offsets m < nx, n < ny, on a period that adds
     * @p margin [m] on each side of the patch (at least the patch's own size).
     */
    Eigen::MatrixXd
    layer_lattice_kernel(const ElasticLayer &layer,
                         double              a,
                         double              b,
                         unsigned int        nx,
                         unsigned int        ny,
                         double              margin);

    /**
     * @brief The compliance [m/N] between all rectangles of an nx x ny patch
     * (point p = i_x ny + i_y) of a x b rectangles of @p layer, on a period
     * that adds @p margin [m] on each side of the patch.
     */
    Eigen::MatrixXd
    layer_patch_compliance(const ElasticLayer &layer,
                           double              a,
                           double              b,
                           unsigned int        nx,
                           unsigned int        ny,
                           double              margin);
  } // namespace contact
} // namespace greentread

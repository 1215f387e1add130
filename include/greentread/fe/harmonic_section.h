#pragma once

#include <greentread/fe/material.h>

#include <deal.II/base/symmetric_tensor.h>
#include <deal.II/dofs/dof_handler.h>
#include <deal.II/fe/fe_system.h>
#include <deal.II/fe/mapping_q.h>
#include <deal.II/grid/tria.h>

#include <Eigen/Dense>
#include <Eigen/Sparse>

#include <algorithm>
#include <array>
#include <complex>
#include <map>
#include <vector>

/**
 * @file
 * The semi-analytical (harmonic) finite element of a body of revolution: the
 * ring's matrices for one circumferential harmonic n, on the 2D section.
 *
 * With materials orthotropic in (r, theta, z), the ring's motion splits
 * exactly into harmonics. The symmetric family is
 *   u_r = U_r(r, z) cos(n theta), u_z = U_z(r, z) cos(n theta),
 *   u_theta = U_t(r, z) sin(n theta),
 * and the antisymmetric one (cos and sin swapped) has the same matrices. Each
 * d/dtheta becomes +-n, so the strains of the amplitudes (U_r, U_z, U_t) are
 * B_n = B_0 + n B_1 and the stiffness is
 *   K_n = int (B_0 + n B_1)^T C (B_0 + n B_1) r dr dz = K_a + n K_b + n^2 K_c,
 * three matrices assembled once. The mass does not depend on n. The damping
 * is each layer's alpha M + beta K, and the prestress stiffness Kp_n of the
 * axisymmetric inflation is quadratic in n in the same way (the cylindrical
 * displacement gradient, whose theta column carries the curvature terms).
 *
 * These are the section integrals: the ring's energy of harmonic n is c_n / 2
 * U^T K_n U, with c_n = pi for n >= 1 and 2 pi for n = 0. The factor cancels
 * in every use here (the load of a harmonic carries it too). For n = 0 the
 * third unknown is the torsion u_theta = U_t, which does not couple to the
 * other two. Implemented in source/fe/harmonic_section.cc.
 */

namespace greentread
{
  namespace fe
  {
    /// A matrix of the harmonic n: a + n b + n^2 c (HarmonicSection's
    /// sums form it).
    struct QuadraticInN
    {
      Eigen::SparseMatrix<double> a, b, c;
    };

    /// Whether two compressed sparse matrices have the same pattern: the
    /// section's matrices do (they are assembled from the same pairs of
    /// unknowns), and their sums are then one pass over the values.
    template <typename Scalar>
    bool
    same_pattern(const Eigen::SparseMatrix<Scalar> &x, const Eigen::SparseMatrix<Scalar> &y)
    {
      return x.isCompressed() && y.isCompressed() && x.rows() == y.rows() && x.cols() == y.cols() &&
             x.nonZeros() == y.nonZeros() &&
             std::equal(x.outerIndexPtr(), x.outerIndexPtr() + x.outerSize() + 1,
                        y.outerIndexPtr()) &&
             std::equal(x.innerIndexPtr(), x.innerIndexPtr() + x.nonZeros(), y.innerIndexPtr());
    }

    /**
     * @brief The section of a tyre as a ring of harmonics: its matrices over
     * the free unknowns (the rim seat held, if the section has one: a free
     * ring has its rigid motions in harmonics 0 and 1), its inflation, and
     * the load of a traction on a strip of its tread.
     */
    class HarmonicSection
    {
    public:
      /**
       * @param[in] section    The section in the (radius, axial) plane, with
       *                       the material ids of @p materials and the boundary
       *                       ids of geometry::BoundaryId (it must outlive
       *                       this object).
       * @param[in] materials  A material for every material id used.
       * @param[in] degree     The Lagrange degree of the elements, 1 to 4.
       * @throws InputError for a degree out of range, naming
       *         'Geometry/Element degree'.
       */
      HarmonicSection(const dealii::Triangulation<2>         &section,
                      const std::map<unsigned int, Material> &materials,
                      unsigned int                            degree);

      /**
       * @brief The static inflation (n = 0) under @p pressure [Pa] on the
       * inner surface, and the prestress stiffness of its stress, which
       * stiffness() adds from then on.
       * @throws NumericalError if the static system cannot be solved.
       */
      void
      inflate(double pressure);

      /// K_n + Kp_n (Kp after inflate()).
      Eigen::SparseMatrix<double>
      stiffness(unsigned int n) const;

      /// K_n + Kp_n - s M, in one pass over the shared pattern.
      Eigen::SparseMatrix<double>
      shifted_stiffness(unsigned int n, double s) const;

      /// C_n: each layer's alpha M + beta K_n.
      Eigen::SparseMatrix<double>
      damping(unsigned int n) const;

      /// D_n(w) = K_n + Kp_n + j w C_n - w^2 M by its parts in n, {a, b, c}
      /// with D_n = a + n b + n^2 c.
      std::array<Eigen::SparseMatrix<std::complex<double>>, 3>
      dynamic_stiffness(double omega) const;

      const Eigen::SparseMatrix<double> &
      mass() const
      {
        return M;
      }

      /// The free unknowns (three per node off the rim seat).
      unsigned int
      size() const
      {
        return static_cast<unsigned int>(M.rows());
      }

      unsigned int
      degree() const
      {
        return fe.degree;
      }

      /**
       * @brief A radial traction of 1 on the tread surface between the
       * axial positions @p z_low and @p z_high: its consistent load w (the
       * integral of each radial shape function times r ds) and the strip's
       * int r ds [m^2], so that a unit force over the strip and an arc of
       * angle a loads w / (a W), and w^T U / W is the mean radial amplitude
       * over the strip.
       * @throws NumericalError if the strip covers no tread surface.
       */
      std::pair<Eigen::VectorXd, double>
      tread_strip(double z_low, double z_high) const;

      /**
       * @brief The normal displacement averaged over each segment of a line
       * along the section's outer faces (the tread surface and the untagged
       * faces in the air), as functionals: for segment s, column s of the
       * first matrix holds w_s / W_s with w_s the integral of each shape
       * function's component along the faces' outward normal times r ds,
       * and W_s = int r ds, so that (w_s / W_s)^T U is the mean outward
       * displacement of amplitude U over the segment's part of the faces.
       * The faces are chained into one line by arc length, each point of
       * @p line placed where the nearest face puts it, and each face
       * integrated by Gauss over its overlap with each segment's arc.
       * @param[in] line Points in the (radius, axial) plane on the outer
       *                 faces, e.g. radiation::TyreSurface::section_line.
       * @throws NumericalError if the faces are not one line, or a segment
       *         covers none of them.
       */
      std::pair<Eigen::MatrixXd, Eigen::VectorXd>
      surface_segments(const std::vector<std::array<double, 2>> &line) const;

      /// The inflated tread's largest radial growth [m] (0 before inflate()).
      double
      tread_growth() const
      {
        return growth;
      }

    private:
      const dealii::Triangulation<2>  &triangulation;
      std::map<unsigned int, Material> materials;
      dealii::FESystem<2>              fe;
      dealii::MappingQ<2>              mapping;
      dealii::DoFHandler<2>            dofs;
      /// The free unknown of each DoF, or -1 for a held one.
      std::vector<long>           free;
      QuadraticInN                K, Kp, C_beta;
      Eigen::SparseMatrix<double> M, C_alpha;
      double                      growth = 0.;

      void
      assemble();
    };
  } // namespace fe
} // namespace greentread

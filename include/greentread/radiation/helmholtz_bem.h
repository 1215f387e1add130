#pragma once

#include <deal.II/base/point.h>
#include <deal.II/base/tensor.h>
#include <deal.II/fe/mapping.h>
#include <deal.II/grid/tria.h>

#include <Eigen/Dense>

#include <complex>
#include <vector>

namespace greentread
{
  namespace radiation
  {
    /**
     * @brief The air around a vibrating body, and the ground under it.
     *
     * The time convention is the rest of GreenTread's, \f$e^{j\omega t}\f$: a
     * wave leaving the body is \f$e^{-jkr}/r\f$, and the momentum equation
     * gives \f$\partial p/\partial n = -j\omega\rho\,v_n\f$.
     */
    struct Air
    {
      /// Density rho [kg/m^3].
      double density = 1.204;
      /// Speed of sound c [m/s].
      double sound_speed = 343.;
      /// Whether a rigid plane z = ground_height bounds the air (the road):
      /// the Green's function then adds the image source, and the plane
      /// needs no mesh.
      bool ground = false;
      /// The plane's height [m]; the body lies above it.
      double ground_height = 0.;
    };

    /**
     * @brief The free-field Green's function of the Helmholtz equation,
     * \f$G = e^{-jkr}/(4\pi r)\f$, and with a rigid plane its image added,
     * \f$G_h(x, y) = G(x, y) + G(x', y)\f$ where \f$x'\f$ is x mirrored in the
     * plane.
     */
    class HalfSpaceKernel
    {
    public:
      HalfSpaceKernel(const Air &air, double wavenumber);

      /// G(x, y) and its derivative along n at y, \f$\partial G/\partial n_y\f$.
      void
      evaluate(const dealii::Point<3>     &x,
               const dealii::Point<3>     &y,
               const dealii::Tensor<1, 3> &n,
               std::complex<double>       &g,
               std::complex<double>       &dg_dn) const;

    private:
      double k;
      bool   ground;
      double ground_height;
    };

    /**
     * @brief The exterior Neumann problem of the Helmholtz equation by a
     * boundary element method: from the normal velocity on a closed surface,
     * the pressure on it, in the air around it and the power it radiates.
     *
     * The direct (Kirchhoff-Helmholtz) integral equation is collocated at
     * the centre of each cell of the surface, with the pressure and the
     * velocity constant on a cell (Ciskowski & Brebbia 1991, Ch. 2):
     * \f[
     *   \tfrac12 p(x_i) = \int_S \left( p\,\frac{\partial G}{\partial n_y}
     *     + j\omega\rho\,v_n\,G \right) dS_y,
     * \f]
     * with n pointing into the air. Where the cell holds the collocation
     * point, its four triangles about the point are integrated by a Duffy
     * transform, which takes out the 1/r singularity; cells within
     * `near_distance` diameters get an iterated Gauss rule; the rest a
     * 4 x 4 Gauss rule. With the ground, the distance is the smaller of
     * the point's and its image's, so that a cell near the road, nearly
     * touching its own image, gets the finer rule. The surface is that of
     * the mapping, not the flat cells.
     *
     * At the eigenfrequencies of the body's interior with p = 0 on S, the
     * equation has no unique solution (the fictitious frequencies). The
     * CHIEF method (Schenck 1968) adds, for points inside the body, the
     * equation whose left side there is 0, and the system is solved in the
     * least-squares sense by a Householder QR. Without CHIEF points the
     * square system is factored by LU.
     *
     * The cells' normals must point into the air: `orient()` makes them
     * point away from a given inside point for star-shaped bodies, and
     * the CHIEF points check the whole surface (the solid angle seen from
     * inside is 4 pi; a wrong normal spoils it).
     */
    class HelmholtzBem
    {
    public:
      /**
       * @param[in] surface A closed surface mesh; it must outlive this object.
       * @param[in] mapping The surface's shape, e.g. MappingQ of degree 2-4.
       * @param[in] outward For each active cell in order, +1 if its normal
       * from the mapping points into the air, -1 if it points into the body.
       */
      HelmholtzBem(const dealii::Triangulation<2, 3> &surface,
                   const dealii::Mapping<2, 3>       &mapping,
                   const std::vector<int>            &outward);

      /// Signs for `outward` that make each cell's normal point away from
      /// `inside`: right for a body star-shaped about that point.
      static std::vector<int>
      orient(const dealii::Triangulation<2, 3> &surface,
             const dealii::Mapping<2, 3>       &mapping,
             const dealii::Point<3>            &inside);

      /// Number of cells, the unknowns.
      unsigned int
      n_cells() const
      {
        return static_cast<unsigned int>(panels.size());
      }

      /// The largest cell diameter [m].
      double
      largest_cell() const;

      /// The highest frequency [Hz] the mesh resolves, with six cells to a
      /// wavelength.
      double
      highest_frequency(const Air &air) const;

      /// Centre (collocation point) of cell i.
      const dealii::Point<3> &
      centre(unsigned int i) const
      {
        return panels[i].centre;
      }

      /// Unit normal into the air at the centre of cell i.
      const dealii::Tensor<1, 3> &
      normal(unsigned int i) const
      {
        return panels[i].normal;
      }

      /// Area of cell i [m^2].
      double
      area(unsigned int i) const
      {
        return panels[i].area;
      }

      /**
       * @brief Assemble and factor the system at one frequency.
       * @param[in] chief_points Points inside the body (none: the square
       * system).
       * @throws InputError if the frequency is beyond what the mesh
       * resolves, or a CHIEF point lies outside the body or on its surface.
       * @throws NumericalError if the system is singular.
       */
      void
      assemble(const Air                           &air,
               double                               frequency,
               const std::vector<dealii::Point<3>> &chief_points = {});

      /// The surface pressure [Pa] per cell from the normal velocity [m/s]
      /// per cell (positive into the air). Several columns, several cases.
      Eigen::MatrixXcd
      surface_pressure(const Eigen::MatrixXcd &normal_velocity) const;

      /// The pressure [Pa] at points in the air, one row per point, one
      /// column per case.
      Eigen::MatrixXcd
      field_pressure(const std::vector<dealii::Point<3>> &points,
                     const Eigen::MatrixXcd              &pressure,
                     const Eigen::MatrixXcd              &normal_velocity) const;

      /**
       * @brief The transfer T [Pa s/m] from the cells' normal velocities to
       * the pressure at @p points in the air (rows): p = T v, at the last
       * assemble()'s frequency, what field_pressure() gives for v through
       * surface_pressure(), by one adjoint solve per point instead of one
       * solve per cell. With S the system's solution operator (its inverse,
       * or with CHIEF points its least-squares inverse R^{-1} Q^H),
       * T = j w rho (H_x S G + G_x), the rows H_x S computed as
       * (S^H H_x^H)^H.
       */
      Eigen::MatrixXcd
      field_transfer(const std::vector<dealii::Point<3>> &points) const;

      /// The time-averaged power [W] that flows through the surface into the
      /// air, \f$\tfrac12 \mathrm{Re} \int_S p\,v_n^*\,dS\f$, per case.
      Eigen::VectorXd
      sound_power(const Eigen::MatrixXcd &pressure, const Eigen::MatrixXcd &normal_velocity) const;

      /**
       * @brief Scattering by the body held rigid: the pressure [Pa] at
       * `receivers` (rows) of unit monopoles at `sources` (columns), each
       * \f$G_h(x, s)\f$ in the air without the body, with the body there.
       *
       * The scattered field is the radiation of the normal velocity that
       * cancels the incident field's \f$\partial p/\partial n\f$ on the
       * surface, \f$v_n = \partial_n p_{inc} / (j\omega\rho)\f$, averaged
       * over each cell; the result is \f$p_{inc} + p_{sc}\f$. A source or a
       * receiver closer to the surface than a cell is not resolved.
       */
      Eigen::MatrixXcd
      rigid_scattering(const std::vector<dealii::Point<3>> &sources,
                       const std::vector<dealii::Point<3>> &receivers) const;

      /// The incident field alone: \f$G_h(x, s)\f$ at `receivers` (rows) for
      /// `sources` (columns), at the last assemble()'s frequency.
      Eigen::MatrixXcd
      incident_pressure(const std::vector<dealii::Point<3>> &sources,
                        const std::vector<dealii::Point<3>> &receivers) const;

    private:
      /// One cell: its centre and normal, and three quadrature rules on it
      /// (points, unit normals into the air, weights with the area element).
      struct Rule
      {
        std::vector<dealii::Point<3>>     points;
        std::vector<dealii::Tensor<1, 3>> normals;
        std::vector<double>               weights;
      };
      struct Panel
      {
        dealii::Point<3>     centre;
        dealii::Tensor<1, 3> normal;
        double               area     = 0.;
        double               diameter = 0.;
        Rule                 far, near, self;
      };

      /// The integrals of G and dG/dn_y over cell j seen from x; `self` when
      /// x is the cell's own centre.
      void
      integrate(const HalfSpaceKernel  &kernel,
                const dealii::Point<3> &x,
                unsigned int            j,
                bool                    self,
                std::complex<double>   &g,
                std::complex<double>   &dg_dn) const;

      /// Rows for points x of [H | G], the two integrals over every cell.
      void
      influence(const HalfSpaceKernel               &kernel,
                const std::vector<dealii::Point<3>> &x,
                bool                                 collocation,
                Eigen::MatrixXcd                    &h,
                Eigen::MatrixXcd                    &g) const;

      std::vector<Panel> panels;
      double             near_distance = 2.;

      // The factored system at the last assemble().
      Air                                    air;
      double                                 omega = 0.;
      Eigen::MatrixXcd                       g_matrix;
      bool                                   least_squares = false;
      Eigen::PartialPivLU<Eigen::MatrixXcd>  lu;
      Eigen::HouseholderQR<Eigen::MatrixXcd> qr;
    };
  } // namespace radiation
} // namespace greentread

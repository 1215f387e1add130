#include <greentread/base/exceptions.h>
#include <greentread/base/job_runner.h>
#include <greentread/radiation/helmholtz_bem.h>

#include <deal.II/base/multithread_info.h>
#include <deal.II/base/numbers.h>
#include <deal.II/base/quadrature_lib.h>
#include <deal.II/fe/fe_dgq.h>
#include <deal.II/fe/fe_values.h>

#include <cmath>

namespace greentread
{
  namespace radiation
  {
    using Complex = std::complex<double>;

    namespace
    {
      constexpr double pi = dealii::numbers::PI;

      /// A rule on the unit square for an integrand singular as 1/r at its
      /// centre: the square is cut into four triangles with the centre as
      /// a vertex, and each is mapped from [0, 1]^2 by the Duffy transform
      /// (s, t) -> c + s (a - c + t (b - a)), whose Jacobian s cancels 1/r.
      dealii::Quadrature<2>
      duffy_about_centre(const unsigned int n)
      {
        const dealii::QGauss<1>               gauss(n);
        const dealii::Point<2>                c(0.5, 0.5);
        const std::array<dealii::Point<2>, 4> corners{{{0., 0.}, {1., 0.}, {1., 1.}, {0., 1.}}};
        std::vector<dealii::Point<2>>         points;
        std::vector<double>                   weights;
        for (unsigned int side = 0; side < 4; ++side)
          {
            const dealii::Point<2> &a = corners[side];
            const dealii::Point<2> &b = corners[(side + 1) % 4];
            // |det(a - c, b - a)| is twice the triangle's area, 1/4.
            const double det = 0.5;
            for (unsigned int i = 0; i < n; ++i)
              for (unsigned int j = 0; j < n; ++j)
                {
                  const double s = gauss.point(i)[0], t = gauss.point(j)[0];
                  points.push_back(c + s * ((a - c) + t * (b - a)));
                  weights.push_back(gauss.weight(i) * gauss.weight(j) * s * det);
                }
          }
        return dealii::Quadrature<2>(points, weights);
      }
    } // namespace

    HalfSpaceKernel::HalfSpaceKernel(const Air &air, const double wavenumber)
        : k(wavenumber)
        , ground(air.ground)
        , ground_height(air.ground_height)
    {
    }

    void
    HalfSpaceKernel::evaluate(const dealii::Point<3>     &x,
                              const dealii::Point<3>     &y,
                              const dealii::Tensor<1, 3> &n,
                              Complex                    &g,
                              Complex                    &dg_dn) const
    {
      const auto add = [&](const dealii::Point<3> &source) {
        const dealii::Tensor<1, 3> d = y - source;
        const double               r = d.norm();
        const Complex              e = std::exp(Complex(0., -k * r)) / (4. * pi * r);
        g += e;
        // dG/dr = -e (1 + jkr) / r and dr/dn_y = (y - x).n / r.
        dg_dn += -e * Complex(1., k * r) * (d * n) / (r * r);
      };
      g = dg_dn = 0.;
      add(x);
      if (ground)
        add(dealii::Point<3>(x[0], x[1], 2. * ground_height - x[2]));
    }

    HelmholtzBem::HelmholtzBem(const dealii::Triangulation<2, 3> &surface,
                               const dealii::Mapping<2, 3>       &mapping,
                               const std::vector<int>            &outward)
    {
      if (outward.size() != surface.n_active_cells())
        throw InputError("HelmholtzBem: " + std::to_string(outward.size()) +
                         " orientation signs given for a surface of " +
                         std::to_string(surface.n_active_cells()) +
                         " cells; allowed: one per cell");
      const dealii::FE_DGQ<2, 3>  fe(0);
      const dealii::QMidpoint<2>  midpoint;
      const dealii::QGauss<2>     far(4);
      const dealii::QIterated<2>  near(dealii::QGauss<1>(4), 3);
      const dealii::Quadrature<2> self = duffy_about_centre(7);
      const auto flags = dealii::update_quadrature_points | dealii::update_normal_vectors |
                         dealii::update_JxW_values;
      dealii::FEValues<2, 3> at_centre(mapping, fe, midpoint, flags);
      dealii::FEValues<2, 3> on_far(mapping, fe, far, flags);
      dealii::FEValues<2, 3> on_near(mapping, fe, near, flags);
      dealii::FEValues<2, 3> on_self(mapping, fe, self, flags);
      const auto             fill = [](const dealii::FEValues<2, 3> &values, const double sign) {
        Rule rule;
        rule.points  = values.get_quadrature_points();
        rule.weights = values.get_JxW_values();
        for (const auto &n : values.get_normal_vectors())
          rule.normals.push_back(sign * n);
        return rule;
      };
      unsigned int index = 0;
      for (const auto &cell : surface.active_cell_iterators())
        {
          const double sign = outward[index++];
          Panel        panel;
          at_centre.reinit(cell);
          panel.centre = at_centre.quadrature_point(0);
          panel.normal = sign * at_centre.normal_vector(0);
          on_far.reinit(cell);
          panel.far = fill(on_far, sign);
          on_near.reinit(cell);
          panel.near = fill(on_near, sign);
          on_self.reinit(cell);
          panel.self = fill(on_self, sign);
          for (const double w : panel.near.weights)
            panel.area += w;
          panel.diameter = cell->diameter();
          panels.push_back(std::move(panel));
        }
    }

    std::vector<int>
    HelmholtzBem::orient(const dealii::Triangulation<2, 3> &surface,
                         const dealii::Mapping<2, 3>       &mapping,
                         const dealii::Point<3>            &inside)
    {
      const dealii::FE_DGQ<2, 3> fe(0);
      dealii::FEValues<2, 3>     at_centre(mapping, fe, dealii::QMidpoint<2>(),
                                           dealii::update_quadrature_points |
                                             dealii::update_normal_vectors);
      std::vector<int>           signs;
      for (const auto &cell : surface.active_cell_iterators())
        {
          at_centre.reinit(cell);
          signs.push_back(
            (at_centre.quadrature_point(0) - inside) * at_centre.normal_vector(0) > 0. ? 1 : -1);
        }
      return signs;
    }

    double
    HelmholtzBem::largest_cell() const
    {
      double h = 0.;
      for (const auto &panel : panels)
        h = std::max(h, panel.diameter);
      return h;
    }

    double
    HelmholtzBem::highest_frequency(const Air &air) const
    {
      return air.sound_speed / (6. * largest_cell());
    }

    void
    HelmholtzBem::integrate(const HalfSpaceKernel  &kernel,
                            const dealii::Point<3> &x,
                            const unsigned int      j,
                            const bool              self,
                            Complex                &g,
                            Complex                &dg_dn) const
    {
      const Panel &panel    = panels[j];
      double       distance = x.distance(panel.centre);
      if (air.ground)
        distance = std::min(
          distance,
          dealii::Point<3>(x[0], x[1], 2. * air.ground_height - x[2]).distance(panel.centre));
      const Rule &rule = self                                      ? panel.self :
                         distance < near_distance * panel.diameter ? panel.near :
                                                                     panel.far;
      g = dg_dn = 0.;
      for (std::size_t q = 0; q < rule.points.size(); ++q)
        {
          Complex gq, dq;
          kernel.evaluate(x, rule.points[q], rule.normals[q], gq, dq);
          g += rule.weights[q] * gq;
          dg_dn += rule.weights[q] * dq;
        }
    }

    void
    HelmholtzBem::influence(const HalfSpaceKernel               &kernel,
                            const std::vector<dealii::Point<3>> &x,
                            const bool                           collocation,
                            Eigen::MatrixXcd                    &h,
                            Eigen::MatrixXcd                    &g) const
    {
      const Eigen::Index rows = static_cast<Eigen::Index>(x.size());
      const Eigen::Index cols = static_cast<Eigen::Index>(panels.size());
      h.resize(rows, cols);
      g.resize(rows, cols);
      // Each entry is computed alone, so the bytes do not depend on the
      // number of threads.
      base::for_each_index(
        x.size(), dealii::MultithreadInfo::n_threads(), [&](const std::size_t i, unsigned int) {
          for (Eigen::Index j = 0; j < cols; ++j)
            integrate(kernel, x[i], static_cast<unsigned int>(j),
                      collocation && static_cast<Eigen::Index>(i) == j,
                      g(static_cast<Eigen::Index>(i), j), h(static_cast<Eigen::Index>(i), j));
        });
    }

    void
    HelmholtzBem::assemble(const Air                           &air_,
                           const double                         frequency,
                           const std::vector<dealii::Point<3>> &chief_points)
    {
      if (!(frequency > 0.) || frequency > highest_frequency(air_) * (1. + 1e-12))
        throw InputError("radiation frequency " + format_number(frequency) +
                         " Hz is beyond what the surface mesh resolves: its largest cell is " +
                         format_short(1e3 * largest_cell()) + " mm; allowed: (0, " +
                         format_short(highest_frequency(air_)) +
                         "] Hz (six cells to a wavelength)");
      air   = air_;
      omega = 2. * pi * frequency;
      const HalfSpaceKernel kernel(air, omega / air.sound_speed);

      std::vector<dealii::Point<3>> centres;
      for (const auto &panel : panels)
        centres.push_back(panel.centre);
      Eigen::MatrixXcd h;
      influence(kernel, centres, true, h, g_matrix);
      const Eigen::Index n = h.rows();
      // (1/2 I - H) p = j w rho G v.
      Eigen::MatrixXcd a = -h;
      a.diagonal().array() += 0.5;
      least_squares = !chief_points.empty();
      if (!least_squares)
        {
          lu.compute(a);
          const double rcond = lu.rcond();
          if (!(rcond > 1e-14))
            throw NumericalError("the boundary element system at " + format_number(frequency) +
                                 " Hz is singular (reciprocal condition " + format_short(rcond) +
                                 "): add CHIEF points inside the body");
          return;
        }

      // CHIEF: 0 = H_z p - j w rho G_z v at points z inside. The solid angle
      // seen from inside, minus the integral of dG0/dn over S, is 1 there:
      // a point outside, or a wrongly turned normal, shows in it.
      // The ground's image closes a surface that stands on it (the plane
      // takes the place of the cells it covers).
      const HalfSpaceKernel laplace(air, 0.);
      Eigen::MatrixXcd      h_z, g_z, h0, g0;
      influence(kernel, chief_points, false, h_z, g_z);
      influence(laplace, chief_points, false, h0, g0);
      for (std::size_t i = 0; i < chief_points.size(); ++i)
        {
          const double solid = -h0.row(static_cast<Eigen::Index>(i)).sum().real();
          if (std::abs(solid - 1.) > 0.05)
            throw InputError("CHIEF point (" + format_number(chief_points[i][0]) + ", " +
                             format_number(chief_points[i][1]) + ", " +
                             format_number(chief_points[i][2]) + ") sees a solid angle of " +
                             format_short(solid) +
                             " x 4 pi through the surface; allowed: a point inside the body "
                             "(1), with every normal pointing into the air");
        }
      const Eigen::Index m = static_cast<Eigen::Index>(chief_points.size());
      Eigen::MatrixXcd   stacked(n + m, n);
      stacked.topRows(n)    = a;
      stacked.bottomRows(m) = -h_z;
      g_matrix.conservativeResize(n + m, n);
      g_matrix.bottomRows(m) = g_z;
      qr.compute(stacked);
      const double smallest = qr.matrixQR().diagonal().cwiseAbs().minCoeff();
      if (!(smallest > 1e-14 * qr.matrixQR().diagonal().cwiseAbs().maxCoeff()))
        throw NumericalError("the boundary element system at " + format_number(frequency) +
                             " Hz is singular with its CHIEF points: move them off the "
                             "interior mode's nodes");
    }

    Eigen::MatrixXcd
    HelmholtzBem::surface_pressure(const Eigen::MatrixXcd &normal_velocity) const
    {
      const Eigen::MatrixXcd rhs = Complex(0., omega * air.density) * (g_matrix * normal_velocity);
      return least_squares ? Eigen::MatrixXcd(qr.solve(rhs)) : Eigen::MatrixXcd(lu.solve(rhs));
    }

    Eigen::MatrixXcd
    HelmholtzBem::field_pressure(const std::vector<dealii::Point<3>> &points,
                                 const Eigen::MatrixXcd              &pressure,
                                 const Eigen::MatrixXcd              &normal_velocity) const
    {
      const HalfSpaceKernel kernel(air, omega / air.sound_speed);
      Eigen::MatrixXcd      h, g;
      influence(kernel, points, false, h, g);
      return h * pressure + Complex(0., omega * air.density) * (g * normal_velocity);
    }

    Eigen::MatrixXcd
    HelmholtzBem::field_transfer(const std::vector<dealii::Point<3>> &points) const
    {
      const HalfSpaceKernel kernel(air, omega / air.sound_speed);
      Eigen::MatrixXcd      h, g;
      influence(kernel, points, false, h, g);
      const Eigen::Index n = h.cols();
      // x = H_x S as the adjoint solve S^H H_x^H.
      Eigen::MatrixXcd x;
      if (!least_squares)
        {
          // P A = L U: A^{-H} y = P^T L^{-H} U^{-H} y.
          Eigen::MatrixXcd z =
            lu.matrixLU().triangularView<Eigen::Upper>().adjoint().solve(h.adjoint());
          z = lu.matrixLU().triangularView<Eigen::UnitLower>().adjoint().solve(z);
          x = (lu.permutationP().transpose() * z).adjoint();
        }
      else
        {
          // S = R1^{-1} Q1^H, Q1 the first n columns of Q: S^H y =
          // Q [R1^{-H} y; 0].
          const Eigen::Index rows = qr.matrixQR().rows();
          Eigen::MatrixXcd   z    = Eigen::MatrixXcd::Zero(rows, h.rows());
          z.topRows(n) =
            qr.matrixQR().topLeftCorner(n, n).triangularView<Eigen::Upper>().adjoint().solve(
              h.adjoint());
          z = qr.householderQ() * z;
          x = z.adjoint();
        }
      return Complex(0., omega * air.density) * (x * g_matrix + g);
    }

    Eigen::VectorXd
    HelmholtzBem::sound_power(const Eigen::MatrixXcd &pressure,
                              const Eigen::MatrixXcd &normal_velocity) const
    {
      Eigen::VectorXd power = Eigen::VectorXd::Zero(pressure.cols());
      for (Eigen::Index c = 0; c < pressure.cols(); ++c)
        for (Eigen::Index i = 0; i < pressure.rows(); ++i)
          power[c] += 0.5 * panels[static_cast<std::size_t>(i)].area *
                      (pressure(i, c) * std::conj(normal_velocity(i, c))).real();
      return power;
    }

    Eigen::MatrixXcd
    HelmholtzBem::incident_pressure(const std::vector<dealii::Point<3>> &sources,
                                    const std::vector<dealii::Point<3>> &receivers) const
    {
      const HalfSpaceKernel kernel(air, omega / air.sound_speed);
      Eigen::MatrixXcd      p(receivers.size(), sources.size());
      Complex               dummy;
      for (std::size_t i = 0; i < receivers.size(); ++i)
        for (std::size_t s = 0; s < sources.size(); ++s)
          kernel.evaluate(sources[s], receivers[i], dealii::Tensor<1, 3>(),
                          p(static_cast<Eigen::Index>(i), static_cast<Eigen::Index>(s)), dummy);
      return p;
    }

    Eigen::MatrixXcd
    HelmholtzBem::rigid_scattering(const std::vector<dealii::Point<3>> &sources,
                                   const std::vector<dealii::Point<3>> &receivers) const
    {
      const HalfSpaceKernel kernel(air, omega / air.sound_speed);
      Eigen::MatrixXcd      velocity(panels.size(), sources.size());
      // G_h is symmetric, so dG_h(s, y)/dn_y is the incident field's normal
      // derivative at y.
      for (std::size_t i = 0; i < panels.size(); ++i)
        for (std::size_t s = 0; s < sources.size(); ++s)
          {
            Complex unused, dp_dn;
            integrate(kernel, sources[s], static_cast<unsigned int>(i), false, unused, dp_dn);
            velocity(static_cast<Eigen::Index>(i), static_cast<Eigen::Index>(s)) =
              dp_dn / (Complex(0., omega * air.density) * panels[i].area);
          }
      const Eigen::MatrixXcd pressure = surface_pressure(velocity);
      return incident_pressure(sources, receivers) + field_pressure(receivers, pressure, velocity);
    }
  } // namespace radiation
} // namespace greentread

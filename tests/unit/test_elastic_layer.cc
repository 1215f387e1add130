// The tread's local compliance as an elastic layer on a rigid base
// (contact/elastic_layer.h) against independent references: its limits (the
// half-space, the laterally constrained column), a deal.II finite-element
// solve of the same layer under a cosine pressure (plane strain, periodic,
// cubic elements), and Love's closed form for a uniformly loaded rectangle on
// a half-space (1929) for the lattice of rectangles.
#include <greentread/base/exceptions.h>
#include <greentread/contact/elastic_layer.h>

#include <deal.II/base/function.h>
#include <deal.II/base/quadrature_lib.h>
#include <deal.II/dofs/dof_handler.h>
#include <deal.II/dofs/dof_tools.h>
#include <deal.II/fe/fe_q.h>
#include <deal.II/fe/fe_system.h>
#include <deal.II/fe/fe_values.h>
#include <deal.II/grid/grid_generator.h>
#include <deal.II/grid/tria.h>
#include <deal.II/lac/affine_constraints.h>
#include <deal.II/lac/dynamic_sparsity_pattern.h>
#include <deal.II/lac/sparse_direct.h>
#include <deal.II/lac/sparse_matrix.h>
#include <deal.II/lac/vector.h>
#include <deal.II/numerics/vector_tools.h>

#include <Eigen/Dense>

#include <boost/test/unit_test.hpp>

#include <cmath>
#include <random>

using namespace greentread;

namespace
{
  /**
   * The layer 0 <= y <= 1 (unit thickness), base y = 0 clamped, periodic
   * over one wavelength in x, the pressure cos(k x) on its top: the top's
   * downward displacement at x = 0 per unit pressure amplitude, by deal.II
   * with Q3 elements in plane strain.
   */
  double
  fe_layer_compliance(const double E, const double nu, const double k)
  {
    using namespace dealii;
    Triangulation<2> tria;
    const double     width = 2. * M_PI / k;
    GridGenerator::subdivided_hyper_rectangle(tria, {24, 12}, Point<2>(0., 0.), Point<2>(width, 1.),
                                              true);
    const FESystem<2> fe(FE_Q<2>(3), 2);
    DoFHandler<2>     dof(tria);
    dof.distribute_dofs(fe);
    AffineConstraints<double> constraints;
    DoFTools::make_periodicity_constraints(dof, 0, 1, 0, constraints);
    VectorTools::interpolate_boundary_values(dof, 2, Functions::ZeroFunction<2>(2), constraints);
    constraints.close();
    DynamicSparsityPattern dsp(dof.n_dofs());
    DoFTools::make_sparsity_pattern(dof, dsp, constraints, false);
    SparsityPattern pattern;
    pattern.copy_from(dsp);
    SparseMatrix<double> K(pattern);
    Vector<double>       f(dof.n_dofs()), u(dof.n_dofs());

    const double    mu = E / (2. * (1. + nu)), lambda = 2. * mu * nu / (1. - 2. * nu);
    const QGauss<2> quadrature(5);
    const QGauss<1> face_quadrature(5);
    FEValues<2>     values(fe, quadrature, update_gradients | update_JxW_values);
    FEFaceValues<2> face(fe, face_quadrature,
                         update_values | update_quadrature_points | update_JxW_values);
    const FEValuesExtractors::Vector     disp(0);
    const unsigned int                   n = fe.n_dofs_per_cell();
    FullMatrix<double>                   Kc(n, n);
    Vector<double>                       fc(n);
    std::vector<types::global_dof_index> ids(n);
    for (const auto &cell : dof.active_cell_iterators())
      {
        values.reinit(cell);
        Kc = 0.;
        fc = 0.;
        for (unsigned int q = 0; q < quadrature.size(); ++q)
          for (unsigned int i = 0; i < n; ++i)
            for (unsigned int j = 0; j < n; ++j)
              Kc(i, j) += (lambda * values[disp].divergence(i, q) * values[disp].divergence(j, q) +
                           2. * mu *
                             scalar_product(values[disp].symmetric_gradient(i, q),
                                            values[disp].symmetric_gradient(j, q))) *
                          values.JxW(q);
        for (const auto fi : cell->face_indices())
          if (cell->face(fi)->at_boundary() && cell->face(fi)->boundary_id() == 3)
            {
              face.reinit(cell, fi);
              for (unsigned int q = 0; q < face_quadrature.size(); ++q)
                for (unsigned int i = 0; i < n; ++i)
                  fc[i] -= face[disp].value(i, q)[1] * std::cos(k * face.quadrature_point(q)[0]) *
                           face.JxW(q);
            }
        cell->get_dof_indices(ids);
        constraints.distribute_local_to_global(Kc, fc, ids, K, f);
      }
    SparseDirectUMFPACK solver;
    solver.initialize(K);
    solver.vmult(u, f);
    constraints.distribute(u);
    Vector<double> value(2);
    VectorTools::point_value(dof, u, Point<2>(0., 1.), value);
    return -value[1];
  }

  /// Love (1929): the integral of 1/r over the rectangle |xi| <= A, |eta| <= B seen from (x, y).
  double
  love_integral(const double x, const double y, const double A, const double B)
  {
    const auto F = [](const double xi, const double eta) {
      double v = 0.;
      if (xi != 0.)
        v += xi * std::asinh(eta / std::abs(xi));
      if (eta != 0.)
        v += eta * std::asinh(xi / std::abs(eta));
      return v;
    };
    return F(x + A, y + B) - F(x + A, y - B) - F(x - A, y + B) + F(x - A, y - B);
  }

  /// The mean displacement [m/N] of the a x b rectangle at (X, Y) under a
  /// unit force spread over the one at the origin, on a half-space: Love's
  /// field averaged by composite Gauss quadrature (its panels' edges on the
  /// loaded rectangle's, where the field's derivatives are singular).
  double
  love_mean(const double E,
            const double nu,
            const double a,
            const double b,
            const double X,
            const double Y)
  {
    const dealii::QGauss<1> gauss(8);
    const unsigned int      panels = 8;
    double                  sum    = 0.;
    for (unsigned int pi = 0; pi < panels; ++pi)
      for (unsigned int qi = 0; qi < gauss.size(); ++qi)
        for (unsigned int pj = 0; pj < panels; ++pj)
          for (unsigned int qj = 0; qj < gauss.size(); ++qj)
            {
              const double x = X - 0.5 * a + a * (pi + gauss.point(qi)[0]) / panels;
              const double y = Y - 0.5 * b + b * (pj + gauss.point(qj)[0]) / panels;
              sum += gauss.weight(qi) * gauss.weight(qj) / (panels * panels) *
                     love_integral(x, y, 0.5 * a, 0.5 * b);
            }
    return (1. - nu * nu) / (M_PI * E) * sum / (a * b);
  }
} // namespace

BOOST_AUTO_TEST_SUITE(elastic_layer)

BOOST_AUTO_TEST_CASE(limits_of_the_layer_compliance)
{
  // A thick layer is a half-space, 2 (1 - nu^2) / (E k); a long wave sees a
  // laterally constrained column, h / (lambda + 2 mu).
  for (const double nu : {0.0, 0.3, 0.49, 0.4999})
    {
      const contact::ElasticLayer layer{7e6, nu, 0.008};
      const double                k         = 30. / layer.thickness;
      const double                half      = 2. * (1. - nu * nu) / (layer.youngs_modulus * k);
      const double                thick     = contact::layer_compliance(layer, k);
      const double                mu        = 7e6 / (2. * (1. + nu));
      const double                column    = 0.008 / (2. * mu * nu / (1. - 2. * nu) + 2. * mu);
      const double                long_wave = contact::layer_compliance(layer, 1e-4 / 0.008);
      BOOST_TEST_MESSAGE("nu = " << nu << ": kh = 30 " << thick / half - 1.
                                 << " from the half-space; kh = 1e-4 " << long_wave / column - 1.
                                 << " from the column");
      BOOST_TEST(std::abs(thick / half - 1.) < 1e-15); // measured 2e-16: round-off
      // The next term is (kh)^2 / 3 (mu-dominated) over the column's; it
      // grows as the rubber nears incompressibility.
      BOOST_TEST(std::abs(long_wave / column - 1.) < (nu > 0.49 ? 2e-3 : 1e-6));
      BOOST_TEST(contact::layer_compliance(layer, 0.) == column,
                 boost::test_tools::tolerance(1e-14));
    }
  BOOST_CHECK_THROW(contact::layer_compliance({7e6, 0.5, 0.008}, 1.), InputError);
  BOOST_CHECK_THROW(contact::layer_compliance({7e6, 0.3, 0.}, 1.), InputError);
  BOOST_CHECK_THROW(contact::layer_compliance({7e6, 0.3, 0.008}, -1.), InputError);
}

BOOST_AUTO_TEST_CASE(layer_compliance_against_finite_elements)
{
  // Unit thickness and modulus: the cosine pressure of wavenumber k on the
  // deal.II layer against the 4 x 4 solve, for a compressible and the
  // tread's nearly incompressible rubber.
  for (const double nu : {0.3, 0.49})
    for (const double k : {0.5, 1., 3.})
      {
        const double fe    = fe_layer_compliance(1., nu, k);
        const double exact = contact::layer_compliance({1., nu, 1.}, k);
        BOOST_TEST_MESSAGE("nu = " << nu << ", kh = " << k << ": FE " << fe << ", layer " << exact
                                   << ", difference " << fe / exact - 1.);
        BOOST_TEST(std::abs(fe / exact - 1.) < 1.2e-5); // measured at most 4e-6
      }
}

BOOST_AUTO_TEST_CASE(table_against_the_direct_solve)
{
  const contact::ElasticLayer            layer{7e6, 0.49, 0.008};
  const contact::LayerComplianceTable    table(layer);
  std::mt19937                           rng(3);
  std::uniform_real_distribution<double> u(std::log(1e-2), std::log(1e5));
  double                                 worst = 0.;
  for (unsigned int i = 0; i < 500; ++i)
    {
      const double k = std::exp(u(rng));
      worst = std::max(worst, std::abs(table(k) / contact::layer_compliance(layer, k) - 1.));
    }
  BOOST_TEST_MESSAGE("table against the 4 x 4 solve, 500 wavenumbers: worst " << worst);
  BOOST_TEST(worst < 1e-6);
  BOOST_TEST(table(0.) == contact::layer_compliance(layer, 0.),
             boost::test_tools::tolerance(1e-14));
}

BOOST_AUTO_TEST_CASE(rectangle_lattice_against_love)
{
  // On a half-space the lattice's T is known up to a constant (its mean
  // term is infinite and left out): its differences T(0,0) - T(m,n) against
  // Love's rectangle averaged over the target, for the 1.5 x 1.667 mm
  // rectangles of the finest contact grid.
  const double E = 7e6, nu = 0.49, a = 1.5e-3, b = 1.6667e-3;
  const auto   half_space = [&](const double k) {
    return k == 0. ? std::numeric_limits<double>::infinity() : 2. * (1. - nu * nu) / (E * k);
  };
  const Eigen::MatrixXd T = contact::rectangle_lattice_compliance(half_space, a, b, 3, 3, 200, 200);
  const double          L0 = love_mean(E, nu, a, b, 0., 0.);
  for (const auto &[m, n] : std::vector<std::pair<int, int>>{{1, 0}, {0, 1}, {1, 1}, {3, 2}})
    {
      const double lattice = T(0, 0) - T(m, n);
      const double love    = L0 - love_mean(E, nu, a, b, m * a, n * b);
      BOOST_TEST_MESSAGE("T(0,0) - T(" << m << "," << n << "): lattice " << lattice << ", Love "
                                       << love << ", difference " << lattice / love - 1.);
      BOOST_TEST(std::abs(lattice / love - 1.) < 4e-4); // measured at most 1.2e-4
    }
  BOOST_CHECK_THROW(contact::rectangle_lattice_compliance(half_space, a, b, 3, 3, 6, 200),
                    InputError);
}

BOOST_AUTO_TEST_CASE(patch_compliance_is_symmetric_positive_definite)
{
  const contact::ElasticLayer layer{7e6, 0.49, 0.008};
  const Eigen::MatrixXd L = contact::layer_patch_compliance(layer, 1.5e-3, 1.6667e-3, 8, 6, 0.032);
  // Symmetric by construction (L(p, q) = T(abs(dx), abs(dy))), so only its
  // definiteness is asserted.
  const Eigen::SelfAdjointEigenSolver<Eigen::MatrixXd> eig(L);
  BOOST_TEST_MESSAGE("eigenvalues " << eig.eigenvalues().minCoeff() << " to "
                                    << eig.eigenvalues().maxCoeff() << " m/N");
  BOOST_TEST(eig.eigenvalues().minCoeff() > 0.);
  // The self term lies below the half-space's (the base stiffens the layer)
  // and above a quarter of it (the layer is five rectangles thick).
  const double self_half = love_mean(7e6, 0.49, 1.5e-3, 1.6667e-3, 0., 0.);
  BOOST_TEST_MESSAGE("self term " << L(0, 0) << " m/N, half-space " << self_half << " m/N");
  BOOST_TEST(L(0, 0) < self_half);
  BOOST_TEST(L(0, 0) > 0.25 * self_half);
}

BOOST_AUTO_TEST_SUITE_END()

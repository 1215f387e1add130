// The contact grid finer than the Green's functions' points
// (contact/contact_grid.h): its lattice and reporting cell, the split's
// properties (the coarse cells' means are the Green's functions' response,
// the local term is positive semidefinite), the split against the layer
// computed directly on the fine grid (what the left-out cross terms cost),
// the grid's convolution against the same model written out on every
// contact point, and the warm-started LCP of a fine grid against Siconos.
#include <greentread/base/exceptions.h>
#include <greentread/contact/contact_grid.h>
#include <greentread/contact/lcp.h>
#include <greentread/contact/patch_contact.h>
#include <greentread/contact/rolling.h>
#include <greentread/road/patch_road.h>
#include <greentread/road/texture.h>
#include <greentread/synthesis/mode_synthesis.h>

#include <Eigen/Dense>

#include <boost/test/unit_test.hpp>

#include "contact_grid_fixture.h"
#include "grid_roll.h"
#include "siconos_reference.h"

#include <cmath>
#include <random>

using namespace greentread;

using test::coarse_compliance;
using test::coarse_points;
using test::tread_layer;

BOOST_AUTO_TEST_SUITE(contact_grid)

BOOST_AUTO_TEST_CASE(lattice_and_reporting_cell)
{
  const auto coarse = coarse_points(10, 12);
  for (const unsigned int s : {1u, 2u, 3u, 4u})
    {
      const contact::ContactGrid grid(coarse, s, tread_layer);
      BOOST_TEST(grid.n_points() == 120 * s * s);
      BOOST_TEST(grid.dx == 6e-3 / s, boost::test_tools::tolerance(1e-12));
      // Each coarse point is the mean of its s x s contact points, and every
      // contact point lies on the lattice, x and y increasing.
      Eigen::MatrixXd sum = Eigen::MatrixXd::Zero(120, 2);
      for (unsigned int p = 0; p < grid.n_points(); ++p)
        {
          sum(grid.coarse_of[p], 0) += grid.points[p][0] / (s * s);
          sum(grid.coarse_of[p], 1) += grid.points[p][1] / (s * s);
          const unsigned int ix = p / grid.ny, iy = p % grid.ny;
          BOOST_TEST(std::abs(grid.points[p][0] - (-0.03 + (ix + 0.5) * grid.dx)) < 1e-12);
          BOOST_TEST(std::abs(grid.points[p][1] - (-0.04 + (iy + 0.5) * grid.dy)) < 1e-12);
        }
      for (unsigned int c = 0; c < 120; ++c)
        {
          BOOST_TEST(std::abs(sum(c, 0) - coarse[c][0]) < 1e-12);
          BOOST_TEST(std::abs(sum(c, 1) - coarse[c][1]) < 1e-12);
        }
      // The reporting cell: a coarse cell centred at the patch centre. Its
      // weights sum to 1; on the coarse grid the four central points share
      // it, on an even subdivision it is s x s whole contact rectangles.
      const Eigen::VectorXd w = grid.reporting_weights();
      BOOST_TEST(w.sum() == 1., boost::test_tools::tolerance(1e-12));
      unsigned int covered = 0;
      for (unsigned int p = 0; p < grid.n_points(); ++p)
        if (w[p] > 0.)
          {
            ++covered;
            BOOST_TEST(std::abs(grid.points[p][0]) < 0.5 * (grid.coarse_dx + grid.dx));
            BOOST_TEST(std::abs(grid.points[p][1]) < 0.5 * (grid.coarse_dy + grid.dy));
          }
      BOOST_TEST(covered == (s % 2 == 0 ? s * s : (s + 1) * (s + 1)));

      // A reporting cell of its own size ('Spectra/Reporting cell'): the
      // whole patch weighs every contact rectangle alike; a cell of 2 x 2
      // contact rectangles on an even subdivision covers those four; a cell
      // larger than the patch is refused.
      const Eigen::VectorXd all = grid.reporting_weights(0.06, 0.08);
      BOOST_TEST(all.minCoeff() == 1. / grid.n_points(), boost::test_tools::tolerance(1e-12));
      BOOST_TEST(all.maxCoeff() == 1. / grid.n_points(), boost::test_tools::tolerance(1e-12));
      if (s % 2 == 0)
        {
          const Eigen::VectorXd four = grid.reporting_weights(2. * grid.dx, 2. * grid.dy);
          BOOST_TEST(four.sum() == 1., boost::test_tools::tolerance(1e-12));
          BOOST_TEST((four.array() > 0.).count() == 4);
          BOOST_TEST(four.maxCoeff() == 0.25, boost::test_tools::tolerance(1e-12));
        }
      BOOST_CHECK_THROW(grid.reporting_weights(0.07, 0.), InputError);
      BOOST_CHECK_THROW(grid.reporting_weights(0., 0.09), InputError);
    }
  BOOST_CHECK_THROW(contact::ContactGrid(coarse, 0, tread_layer), InputError);
  auto not_a_lattice = coarse;
  not_a_lattice.pop_back();
  BOOST_CHECK_THROW(contact::ContactGrid(not_a_lattice, 2, tread_layer), InputError);
}

BOOST_AUTO_TEST_CASE(coarse_means_are_the_green_functions_response)
{
  // For any force on the contact points, the mean displacement of each
  // coarse cell is G times the cells' total forces; the local term is
  // symmetric positive semidefinite, and the compliance positive definite.
  const auto            coarse = coarse_points(5, 4);
  const Eigen::MatrixXd G      = coarse_compliance(coarse);
  for (const unsigned int s : {2u, 3u})
    {
      const contact::ContactGrid             grid(coarse, s, tread_layer);
      const Eigen::MatrixXd                  W = grid.compliance(G);
      std::mt19937                           rng(s);
      std::uniform_real_distribution<double> u(0., 1.);
      Eigen::VectorXd                        f(grid.n_points());
      for (auto &x : f)
        x = u(rng);
      const Eigen::VectorXd mean_u   = grid.gather(W * f) / (s * s);
      const Eigen::VectorXd coarse_u = G * grid.gather(f);
      BOOST_TEST((mean_u - coarse_u).cwiseAbs().maxCoeff() <
                 1e-13 * coarse_u.cwiseAbs().maxCoeff());
      BOOST_TEST((W - W.transpose()).cwiseAbs().maxCoeff() == 0.);
      const Eigen::SelfAdjointEigenSolver<Eigen::MatrixXd> local(grid.local), all(W);
      BOOST_TEST_MESSAGE("s = " << s << ": local term's eigenvalues "
                                << local.eigenvalues().minCoeff() << " to "
                                << local.eigenvalues().maxCoeff() << "; compliance's smallest "
                                << all.eigenvalues().minCoeff());
      BOOST_TEST(local.eigenvalues().minCoeff() > -1e-12 * local.eigenvalues().maxCoeff());
      BOOST_TEST(all.eigenvalues().minCoeff() > 0.);
    }
}

BOOST_AUTO_TEST_CASE(split_against_the_layer_on_the_fine_grid)
{
  // When the "finite-element" G is the layer itself on the coarse cells, the
  // split would ideally be the layer on the fine grid. It differs by the
  // left-out cross terms only (contact/contact_grid.h); measured here: the
  // driving points and the compliance in the energy norm of a force
  // concentrated in one contact rectangle, and of a uniform force.
  const auto      coarse = coarse_points(6, 6);
  const double    margin = 4. * tread_layer.thickness;
  Eigen::MatrixXd Lc_lattice =
    contact::layer_patch_compliance(tread_layer, 6e-3, 0.08 / 12, 6, 6, margin);
  for (const unsigned int s : {2u, 4u})
    {
      const contact::ContactGrid grid(coarse, s, tread_layer);
      // Lc in the coarse points' (shuffled) order.
      Eigen::MatrixXd Lc(36, 36);
      const auto      lattice_index = [&](const std::array<double, 3> &p) {
        const unsigned int ix = std::lround(p[0] / 6e-3 + 2.5),
                           iy = std::lround(p[1] / (0.08 / 12) + 2.5);
        return ix * 6 + iy;
      };
      for (unsigned int a = 0; a < 36; ++a)
        for (unsigned int b = 0; b < 36; ++b)
          Lc(a, b) = Lc_lattice(lattice_index(coarse[a]), lattice_index(coarse[b]));
      const Eigen::MatrixXd split = grid.compliance(Lc);
      const Eigen::MatrixXd direct =
        contact::layer_patch_compliance(tread_layer, grid.dx, grid.dy, grid.nx, grid.ny, margin);
      const double driving =
        ((split.diagonal() - direct.diagonal()).array() / direct.diagonal().array())
          .abs()
          .maxCoeff();
      const Eigen::VectorXd uniform = Eigen::VectorXd::Ones(grid.n_points());
      const double          energy_uniform =
        uniform.dot(split * uniform) / uniform.dot(direct * uniform) - 1.;
      BOOST_TEST_MESSAGE("s = " << s
                                << ": split against the layer on the fine grid, driving points "
                                << driving << ", uniform force's energy " << energy_uniform);
      // A uniform force has no variation within the cells: exact but for
      // the two layer series' own periods (whole numbers of their
      // rectangles) and cut-offs.
      // Measured 2e-4.
      BOOST_TEST(std::abs(energy_uniform) < 6e-4);
      // The cross terms, which the split leaves out: measured 3e-5 of a
      // driving point at s = 2 and 7.3% at s = 4.
      BOOST_TEST(driving < (s == 2 ? 1e-4 : 0.2));
    }
}

BOOST_AUTO_TEST_CASE(grid_convolution_equals_the_model_on_every_contact_point)
{
  // A synthetic modal model of 12 modes on 4 x 3 coarse cells, rolled on a
  // 2 x 2 grid by the grid's convolution, against the same model written
  // out on every contact point (shapes repeated over each cell's points,
  // G_r replaced by the grid's compliance of G_r) with the plain recursion.
  const auto                     coarse = coarse_points(4, 3);
  const unsigned int             n_c    = coarse.size();
  const synthesis::ModeSynthesis s      = test::synthetic_modes(coarse);
  const modal::PatchModel        coarse_model =
    synthesis::to_patch_model(s, Eigen::MatrixXd::Zero(n_c, n_c), 4000.);

  const contact::ContactGrid grid(coarse, 2, tread_layer);
  synthesis::ModeSynthesis   f = s;
  f.shapes.resize(s.shapes.rows(), grid.n_points());
  for (unsigned int p = 0; p < grid.n_points(); ++p)
    f.shapes.col(p) = s.shapes.col(grid.coarse_of[p]);
  f.instantaneous = grid.compliance(s.instantaneous);
  f.points        = grid.points;
  const modal::PatchModel fine_model =
    synthesis::to_patch_model(f, Eigen::MatrixXd::Zero(grid.n_points(), grid.n_points()), 4000.);
  BOOST_TEST((fine_model.static_compliance() - grid.compliance(coarse_model.static_compliance()))
               .cwiseAbs()
               .maxCoeff() < 1e-12 * fine_model.static_compliance().cwiseAbs().maxCoeff());

  const test::RoadARoll            roll(grid.points);
  const contact::PatchRoadHeights &heights = roll.heights;
  const contact::RollingSetup     &setup   = roll.setup;
  const Eigen::VectorXd           &tread   = roll.tread;
  const auto start = contact::start_contact(fine_model.static_compliance(), tread, heights, setup);
  BOOST_TEST(start.n_contact > 0u);

  std::vector<Eigen::VectorXd> reference, split;
  auto plain = contact::make_patch_convolution(setup.convolution, fine_model, setup.time_step,
                                               setup.n_steps, 0, 1);
  contact::roll_patch(*plain, tread, heights, start, setup, [&](const contact::RollingStep &step) {
    reference.push_back(step.force);
  });
  auto gridded = contact::make_grid_convolution(
    contact::make_patch_convolution(setup.convolution, coarse_model, setup.time_step, setup.n_steps,
                                    0, 1),
    grid);
  const auto summary = contact::roll_patch(*gridded, tread, heights, start, setup,
                                           [&](const contact::RollingStep &step) {
                                             split.push_back(step.force);
                                           });
  BOOST_TEST(summary.failed_steps == 0u);
  double peak = 0., worst = 0.;
  for (std::size_t k = 0; k < reference.size(); ++k)
    {
      peak  = std::max(peak, reference[k].cwiseAbs().maxCoeff());
      worst = std::max(worst, (reference[k] - split[k]).cwiseAbs().maxCoeff());
    }
  BOOST_TEST_MESSAGE("grid convolution against the model on every point: largest force difference "
                     << worst / peak << " of the peak " << peak << " N, contact "
                     << summary.min_contact_fraction << " to " << summary.max_contact_fraction);
  BOOST_TEST(summary.max_contact_fraction > summary.min_contact_fraction);
  // Measured 2.4e-16 of the peak: round-off, held within 10x.
  BOOST_TEST(worst < 2.5e-15 * peak);
}

BOOST_AUTO_TEST_CASE(warm_started_lcp_of_a_fine_grid_against_siconos)
{
  // The LCP of a 480-point grid (the coarse compliance of 10 x 12 cells, 2 x
  // 2 contact points each) for a rough demand, solved cold, then warm from a
  // nearby demand with the matrix norm given once, against Siconos' Lemke.
  const auto                       coarse = coarse_points(10, 12);
  const contact::ContactGrid       grid(coarse, 2, tread_layer);
  const Eigen::MatrixXd            W = grid.compliance(coarse_compliance(coarse));
  std::mt19937                     rng(1);
  std::normal_distribution<double> z(0., 1.);
  Eigen::VectorXd                  d(grid.n_points());
  for (auto &x : d)
    x = 3e-5 * z(rng) - 2e-5;
  const double      m = contact::lcp_matrix_norm(W);
  std::vector<bool> active;
  const auto        cold = contact::solve_lcp(W, -d, active);
  BOOST_TEST(cold.converged);
  Eigen::VectorXd d2 = d;
  for (auto &x : d2)
    x += 2e-6 * z(rng);
  contact::LcpOptions options;
  options.matrix_norm    = m;
  const auto        warm = contact::solve_lcp(W, -d2, active, options);
  std::vector<bool> none;
  const auto        plain     = contact::solve_lcp(W, -d2, none);
  const auto        reference = test::siconos_lemke(W, -d2);
  unsigned int      n_active  = 0;
  for (unsigned int i = 0; i < grid.n_points(); ++i)
    n_active += warm.z[i] > 0.;
  BOOST_TEST_MESSAGE("480 points, " << n_active << " in contact: cold " << cold.iterations
                                    << " iterations, warm " << warm.iterations << ", from nothing "
                                    << plain.iterations);
  BOOST_TEST(warm.converged);
  BOOST_TEST(n_active > 20u);
  BOOST_TEST(warm.iterations <= plain.iterations);
  BOOST_TEST(test::relative_difference(warm.z, reference.z, W, -d2) < 1e-8);
  BOOST_TEST(test::relative_difference(warm.z, plain.z, W, -d2) < 1e-12);
  BOOST_CHECK_THROW(contact::lcp_matrix_norm(W * std::nan("")), NumericalError);
}

BOOST_AUTO_TEST_SUITE_END()

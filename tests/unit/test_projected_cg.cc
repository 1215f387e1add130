// The contact grid's matrix-free solver ('Contact grid/Solver' = projected
// CG): the FFT product of the tread's layer against its dense matrix, the
// grid's products against its dense compliance, MPRGP against the dense
// block principal pivoting and Siconos' Lemke on the same LCPs (random SPD
// ones, and a 480-point grid's), its failures, and a rolling run and its
// static start by both solvers.
#include <greentread/base/exceptions.h>
#include <greentread/contact/contact_grid.h>
#include <greentread/contact/lcp.h>
#include <greentread/contact/projected_cg.h>
#include <greentread/contact/rolling.h>
#include <greentread/convolution/lattice_convolution.h>
#include <greentread/road/patch_road.h>
#include <greentread/road/texture.h>
#include <greentread/synthesis/mode_synthesis.h>

#include <Eigen/Dense>

#include <atomic>
#include <functional>
#include <thread>

#include <boost/test/unit_test.hpp>

#include "bounds.h"
#include "complementarity.h"
#include "contact_grid_fixture.h"
#include "grid_roll.h"
#include "siconos_reference.h"

#include <cmath>
#include <random>

using namespace greentread;

using test::coarse_compliance;
using test::random_vector;
using test::tread_layer;

namespace
{
  std::vector<std::array<double, 3>>
  coarse_points(const unsigned int nx, const unsigned int ny)
  {
    return test::coarse_points(nx, ny, false);
  }

  contact::SymmetricOperator
  dense_operator(const Eigen::MatrixXd &W)
  {
    return [&W](const Eigen::VectorXd &x, Eigen::VectorXd &y) {
      y = W * x;
    };
  }

} // namespace

BOOST_AUTO_TEST_SUITE(projected_cg)

BOOST_AUTO_TEST_CASE(lattice_convolution_equals_the_dense_product)
{
  // The layer's kernel on 7 x 9 and on 1 x 5 rectangles (a lattice one
  // rectangle wide), applied by FFT and as the dense matrix.
  for (const auto &[nx, ny] : {std::pair<unsigned int, unsigned int>{7, 9}, {1, 5}, {12, 3}})
    {
      const convolution::LatticeConvolution L(
        contact::layer_lattice_kernel(tread_layer, 1.5e-3, 1.67e-3, nx, ny, 0.032));
      const Eigen::VectorXd x = random_vector(nx * ny, nx + ny);
      Eigen::VectorXd       y;
      L.apply(x, y);
      const Eigen::VectorXd reference = L.dense() * x;
      BOOST_TEST_MESSAGE(nx << " x " << ny << ": FFT against dense "
                            << (y - reference).cwiseAbs().maxCoeff() /
                                 reference.cwiseAbs().maxCoeff());
      BOOST_TEST((y - reference).cwiseAbs().maxCoeff() < 1e-13 * reference.cwiseAbs().maxCoeff());
      Eigen::VectorXd in_place = x;
      L.apply(in_place, in_place);
      BOOST_TEST((in_place - y).cwiseAbs().maxCoeff() == 0.);

      // One convolution used by two threads at once (rolling runs side by
      // side): each thread's products equal the ones made alone, exactly
      // (the same plans on arrays of its own).
      const Eigen::VectorXd x2 = random_vector(nx * ny, 3 * nx + ny);
      Eigen::VectorXd       y2;
      L.apply(x2, y2);
      std::atomic<unsigned int> wrong{0};
      const auto                work = [&](const Eigen::VectorXd &in, const Eigen::VectorXd &out) {
        Eigen::VectorXd z;
        for (unsigned int k = 0; k < 500; ++k)
          {
            L.apply(in, z);
            wrong += (z - out).cwiseAbs().maxCoeff() == 0. ? 0u : 1u;
          }
      };
      std::thread other(work, std::cref(x2), std::cref(y2));
      work(x, y);
      other.join();
      BOOST_TEST(wrong.load() == 0u);
    }
  BOOST_CHECK_THROW(convolution::LatticeConvolution(Eigen::MatrixXd::Constant(2, 2, NAN)),
                    InputError);
  const convolution::LatticeConvolution L(Eigen::MatrixXd::Ones(2, 2));
  Eigen::VectorXd                       y;
  BOOST_CHECK_THROW(L.apply(Eigen::VectorXd::Ones(3), y), InputError);
}

BOOST_AUTO_TEST_CASE(matrix_free_grid_equals_its_dense_compliance)
{
  const auto                 coarse = coarse_points(4, 3);
  const Eigen::MatrixXd      G      = coarse_compliance(coarse);
  const contact::ContactGrid dense(coarse, 3, tread_layer), free(coarse, 3, tread_layer, true);
  BOOST_TEST(free.local.size() == 0);
  const Eigen::VectorXd x = random_vector(dense.n_points(), 3);
  Eigen::VectorXd       y = Eigen::VectorXd::Zero(x.size());
  free.add_local(x, y);
  const Eigen::VectorXd local = dense.local * x;
  BOOST_TEST((y - local).cwiseAbs().maxCoeff() < 1e-12 * local.cwiseAbs().maxCoeff());
  free.apply(G, x, y);
  const Eigen::VectorXd all = dense.compliance(G) * x;
  BOOST_TEST((y - all).cwiseAbs().maxCoeff() < 1e-12 * all.cwiseAbs().maxCoeff());
}

BOOST_AUTO_TEST_CASE(mprgp_against_pivoting_and_siconos)
{
  // Random SPD matrices (eigenvalues 1 to 1e3) and demands of every sign mix.
  for (unsigned int seed = 0; seed < 20; ++seed)
    {
      const unsigned int    n = 60;
      const Eigen::MatrixXd Q =
        Eigen::HouseholderQR<Eigen::MatrixXd>(Eigen::MatrixXd(n, n).setRandom()).householderQ();
      Eigen::VectorXd lambda(n);
      for (unsigned int i = 0; i < n; ++i)
        lambda[i] = std::pow(1e3, double(i) / (n - 1));
      const Eigen::MatrixXd W = Q * lambda.asDiagonal() * Q.transpose();
      const Eigen::VectorXd q =
        random_vector(n, seed) + Eigen::VectorXd::Constant(n, 0.1 * seed - 1.);
      std::vector<bool> active;
      const auto        reference = contact::solve_lcp(W, q, active);
      const auto        mprgp     = contact::solve_lcp_projected_cg(dense_operator(W), q, {});
      BOOST_TEST(reference.converged);
      BOOST_TEST(mprgp.converged);
      BOOST_TEST(test::relative_difference(mprgp.z, reference.z, W, q) < 1e-8);
      // The pair measured here from W, q and z, not from the solver's own
      // gradient: gap and complementarity within what the tolerance on the
      // projected gradient (1e-10 of |q|) allows, times cond(W) = 1e3 for the
      // gap of a point the iteration has not released.
      const test::Complementarity c = test::complementarity(W, q, mprgp.z);
      BOOST_TEST(c.gap >= -1e-9);
      BOOST_TEST(c.natural <= 1e-9);
      BOOST_TEST(c.product <= 1e-9);
      // mprgp.residual, the solver's own natural residual, is not asserted:
      // its stopping rule on the projected gradient holds it below 1e-10.
    }

  // The LCP of a 480-point grid (10 x 12 cells, 2 x 2 points each) for a
  // rough demand, cold and warm-started from a nearby demand's solution.
  const auto                       coarse = coarse_points(10, 12);
  const contact::ContactGrid       grid(coarse, 2, tread_layer);
  const Eigen::MatrixXd            G = coarse_compliance(coarse), W = grid.compliance(G);
  const contact::ContactGrid       free_grid(coarse, 2, tread_layer, true);
  const contact::SymmetricOperator product = [&](const Eigen::VectorXd &x, Eigen::VectorXd &y) {
    free_grid.apply(G, x, y);
  };
  const Eigen::VectorXd d =
    3e-5 * random_vector(grid.n_points(), 1) - Eigen::VectorXd::Constant(grid.n_points(), 2e-5);
  const Eigen::VectorXd       d2 = d + 2e-6 * random_vector(grid.n_points(), 2);
  contact::ProjectedCgOptions options;
  options.operator_norm   = contact::operator_norm(product, grid.n_points());
  const auto        cold  = contact::solve_lcp_projected_cg(product, -d, {}, options);
  const auto        warm  = contact::solve_lcp_projected_cg(product, -d2, cold.z, options);
  const auto        again = contact::solve_lcp_projected_cg(product, -d2, {}, options);
  std::vector<bool> none;
  const auto        pivoting  = contact::solve_lcp(W, -d2, none);
  const auto        reference = test::siconos_lemke(W, -d2);
  unsigned int      n_active  = 0;
  for (unsigned int i = 0; i < grid.n_points(); ++i)
    n_active += pivoting.z[i] > 0.;
  BOOST_TEST_MESSAGE("480 points, " << n_active << " in contact: MPRGP cold " << cold.iterations
                                    << " iterations, warm " << warm.iterations
                                    << " (from 0: " << again.iterations << "); against pivoting "
                                    << test::relative_difference(warm.z, pivoting.z, W, -d2)
                                    << ", against Siconos "
                                    << test::relative_difference(warm.z, reference.z, W, -d2));
  BOOST_TEST(cold.converged);
  BOOST_TEST(warm.converged);
  BOOST_TEST(n_active > 20u);
  BOOST_TEST(warm.iterations < again.iterations);
  BOOST_TEST(test::relative_difference(warm.z, pivoting.z, W, -d2) < 1e-8);
  BOOST_TEST(test::relative_difference(warm.z, reference.z, W, -d2) < 1e-8);
  // The returned forces measured here, w = W z + q formed from the dense
  // compliance (not the solver's FFT products): no point inside the road, no
  // force negative, none where the gap is open. Measured, relative to |q|:
  // the deepest penetration 3.9e-13, the natural residual 4.2e-13, the
  // largest z w 7.3e-14, far below the solver's stopping rule (its projected
  // gradient at 1e-10 of |q|): its last iterations converge fast. Bounds
  // about 5 times each, for another processor's round-off; a solver that
  // stopped at its tolerance would fail them.
  const test::Complementarity c = test::complementarity(W, -d2, warm.z);
  CHECK_BOUND(-c.gap, 2e-12);
  CHECK_BOUND(c.natural, 2e-12);
  CHECK_BOUND(c.product, 4e-13);
}

BOOST_AUTO_TEST_CASE(mprgp_edge_cases_and_failures)
{
  const Eigen::MatrixXd W = Eigen::MatrixXd::Identity(5, 5) * 2.;
  // No contact: z = 0 at once; every point pushed: z = -q / 2.
  const auto none =
    contact::solve_lcp_projected_cg(dense_operator(W), Eigen::VectorXd::Ones(5), {});
  BOOST_TEST(none.converged);
  BOOST_TEST(none.iterations == 0u);
  BOOST_TEST(none.z.cwiseAbs().maxCoeff() == 0.);
  const auto all =
    contact::solve_lcp_projected_cg(dense_operator(W), -Eigen::VectorXd::Ones(5), {});
  BOOST_TEST(all.converged);
  BOOST_TEST((all.z - Eigen::VectorXd::Constant(5, 0.5)).cwiseAbs().maxCoeff() < 1e-12);
  // q = 0: z = 0.
  BOOST_TEST(
    contact::solve_lcp_projected_cg(dense_operator(W), Eigen::VectorXd::Zero(5), {}).converged);
  // Not positive definite: reported, not a wrong answer.
  const Eigen::MatrixXd       indefinite = Eigen::Vector2d(1., -1.).asDiagonal();
  contact::ProjectedCgOptions options;
  options.operator_norm = 1.;
  const auto failed     = contact::solve_lcp_projected_cg(dense_operator(indefinite),
                                                          Eigen::Vector2d(1., -1.), {}, options);
  BOOST_TEST(!failed.converged);
  BOOST_TEST(failed.message.find("not positive") != std::string::npos);
  BOOST_CHECK_THROW(contact::operator_norm(dense_operator(-W), 5), NumericalError);
  BOOST_CHECK_THROW(
    contact::solve_lcp_projected_cg(dense_operator(W), Eigen::VectorXd::Constant(5, NAN), {}),
    NumericalError);
  BOOST_CHECK_THROW(contact::solve_lcp_projected_cg(dense_operator(W), Eigen::VectorXd::Ones(5),
                                                    Eigen::VectorXd::Ones(4)),
                    InputError);
  // The iteration limit, reported.
  options.max_iterations        = 1;
  const Eigen::MatrixXd hard    = Eigen::Vector3d(1., 10., 100.).asDiagonal();
  const auto            limited = contact::solve_lcp_projected_cg(dense_operator(hard),
                                                                  -Eigen::Vector3d(1., 1., 1.), {}, options);
  BOOST_TEST(!limited.converged);
  BOOST_TEST(limited.message.find("iterations") != std::string::npos);
}

BOOST_AUTO_TEST_CASE(rolling_by_both_solvers)
{
  // A synthetic modal model on 4 x 3 coarse cells, rolled on road-A on a 3 x
  // 3 grid from the static start: the matrix-free solver against pivoting,
  // at a tolerance of 1e-10 (here), and at the default (below).
  const auto                     coarse = coarse_points(4, 3);
  const unsigned int             n_c    = coarse.size();
  const synthesis::ModeSynthesis s      = test::synthetic_modes(coarse);
  const modal::PatchModel        model =
    synthesis::to_patch_model(s, Eigen::MatrixXd::Zero(n_c, n_c), 4000.);

  const contact::ContactGrid pivoting(coarse, 3, tread_layer),
    free(coarse, 3, tread_layer, true, true, 1e-10);
  const test::GridRolls r     = test::roll_on_two_grids(model, pivoting, free);
  const auto           &start = r.start[0], &start_free = r.start[1];
  const auto           &summary = r.summary;
  const double          peak = r.peak, worst = r.worst;
  BOOST_TEST(start.n_contact > 0u);
  BOOST_TEST(std::abs(start_free.delta / start.delta - 1.) < 1e-7);
  BOOST_TEST((start_free.q - start.q).cwiseAbs().maxCoeff() < 1e-7 * start.q.maxCoeff());
  BOOST_TEST_MESSAGE("rolling, projected CG against pivoting: largest force difference "
                     << worst / peak << " of the peak " << peak << " N; largest penetration "
                     << summary[1].max_penetration << " m against " << summary[0].max_penetration);
  BOOST_TEST(summary[0].failed_steps == 0u);
  BOOST_TEST(summary[1].failed_steps == 0u);
  BOOST_TEST(summary[1].max_contact_fraction > summary[1].min_contact_fraction);
  // Both solve to 1e-10: measured 1.3e-10 of the peak, the bound 3 times that.
  CHECK_BOUND(worst / peak, 4e-10);

  // The default 'Contact grid/Tolerance' (1e-6): each force within the
  // tolerance times the compliance's spread of the exact one. Measured
  // 1.45e-6 of the peak; the bound is 3 times that.
  const contact::ContactGrid loose(coarse, 3, tread_layer, true);
  BOOST_TEST(loose.tolerance == 1e-6);
  const test::GridRolls d = test::roll_on_two_grids(model, pivoting, loose);
  BOOST_TEST_MESSAGE("at the default tolerance: largest force difference "
                     << d.worst / d.peak << " of the peak; largest penetration "
                     << d.summary[1].max_penetration << " m");
  BOOST_TEST(d.summary[1].failed_steps == 0u);
  BOOST_TEST(d.worst < 4.4e-6 * d.peak);
  BOOST_TEST(d.worst > 1e-8 * d.peak); // the tolerance reaches the solve
}

BOOST_AUTO_TEST_CASE(the_solver_is_chosen_in_one_place_from_the_model_and_the_grid)
{
  // 'auto' is projected CG with a reciprocal model (the ring's modes) and
  // pivoting with the identified one; pivoting is refused above its size,
  // projected CG without reciprocity, each with the parameter named.
  contact::ContactGridParameters p;
  const unsigned int             n_coarse = 120;
  p.subdivisions                          = 8; // 7680 points
  BOOST_TEST(p.solver == "auto");
  BOOST_TEST(p.matrix_free(true, n_coarse));
  BOOST_TEST(!p.matrix_free(false, n_coarse));
  p.solver = "pivoting";
  BOOST_TEST(!p.matrix_free(true, n_coarse));
  p.subdivisions = 10; // 12,000 points
  BOOST_CHECK_EXCEPTION(p.matrix_free(true, n_coarse), InputError, [](const InputError &e) {
    return std::string(e.what()).find("'Contact grid/Subdivisions' = 10 gives 12000") !=
           std::string::npos;
  });
  p.solver = "auto";
  BOOST_CHECK_EXCEPTION(p.matrix_free(false, n_coarse), InputError, [](const InputError &e) {
    return std::string(e.what()).find("too many for the solver 'pivoting'") != std::string::npos;
  });
  BOOST_TEST(p.matrix_free(true, n_coarse));
  p.solver = "projected CG";
  BOOST_TEST(p.matrix_free(true, n_coarse));
  BOOST_CHECK_THROW(p.matrix_free(false, n_coarse), InputError);
}

BOOST_AUTO_TEST_SUITE_END()

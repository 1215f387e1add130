// The contact solve on the candidate set ('Contact grid/Solver' = projected
// CG): the grid's dense block against its dense compliance, the candidate-set
// solve against block principal pivoting and against MPRGP on the whole grid
// on the same LCPs, a point pulled into the road by its neighbours (the set
// must grow), its edge cases, and a rolling run against the whole-grid solve.
#include <greentread/base/exceptions.h>
#include <greentread/contact/candidate_set.h>
#include <greentread/contact/contact_grid.h>
#include <greentread/contact/lcp.h>

#include <Eigen/Dense>

#include <boost/test/unit_test.hpp>

#include "bounds.h"
#include "complementarity.h"
#include "contact_grid_fixture.h"
#include "grid_roll.h"
#include "siconos_reference.h"

#include <random>

using namespace greentread;

using test::coarse_compliance;
using test::random_vector;
using test::tread_layer;

namespace
{
  contact::OperatorBlock
  dense_block(const Eigen::MatrixXd &W)
  {
    return [&W](const std::vector<unsigned int> &rows, const std::vector<unsigned int> &columns,
                Eigen::MatrixXd &out) {
      out.resize(rows.size(), columns.size());
      for (std::size_t l = 0; l < columns.size(); ++l)
        for (std::size_t k = 0; k < rows.size(); ++k)
          out(k, l) = W(rows[k], columns[l]);
    };
  }
} // namespace

BOOST_AUTO_TEST_SUITE(candidate_set)

BOOST_AUTO_TEST_CASE(the_grid_block_is_its_dense_compliance)
{
  // 10 x 12 cells of 4 x 4 points (1920): ContactGrid::block() on 400 random
  // points, entry by entry from the layer's kernel and its cell sums, against
  // the dense compliance that the pivoting grid forms (the layer's dense
  // matrix with its cell means removed by products) and against the FFT
  // product. Measured 1.1e-16 and 6.7e-16 of the largest entry: round-off,
  // whose size differs between machines' FFTs, hence the bound 1e-13.
  const auto                 coarse = test::coarse_points(10, 12);
  const Eigen::MatrixXd      G      = coarse_compliance(coarse);
  const contact::ContactGrid dense(coarse, 4, tread_layer), free(coarse, 4, tread_layer, true);
  const Eigen::MatrixXd      W = dense.compliance(G);
  std::vector<unsigned int>  set;
  std::mt19937               rng(3);
  for (unsigned int i = 0; i < dense.n_points(); ++i)
    if (rng() % 5 == 0)
      set.push_back(i);
  Eigen::MatrixXd block;
  free.block(G, set, set, block);
  double worst = 0.;
  for (std::size_t l = 0; l < set.size(); ++l)
    for (std::size_t k = 0; k < set.size(); ++k)
      worst = std::max(worst, std::abs(block(k, l) - W(set[k], set[l])));
  const double scale = W.cwiseAbs().maxCoeff();
  // The product of the block with a force on the set, against the whole
  // grid's FFT product read on the set.
  const Eigen::VectorXd x_set = random_vector(set.size(), 4).cwiseAbs();
  Eigen::VectorXd       x     = Eigen::VectorXd::Zero(free.n_points()), y;
  for (std::size_t k = 0; k < set.size(); ++k)
    x[set[k]] = x_set[k];
  free.apply(G, x, y);
  const Eigen::VectorXd by_block = block * x_set;
  double                product  = 0.;
  for (std::size_t k = 0; k < set.size(); ++k)
    product = std::max(product, std::abs(by_block[k] - y[set[k]]));
  product /= y.cwiseAbs().maxCoeff();
  BOOST_TEST_MESSAGE(set.size() << " of " << free.n_points() << " points: block against the "
                                << "dense compliance " << worst / scale
                                << ", its product against the FFT's " << product);
  BOOST_TEST(set.size() > 300u);
  // Measured 1.1e-16 and 6.7e-16: round-off, held within 10x.
  BOOST_TEST(worst < 1.2e-15 * scale);
  BOOST_TEST(product < 7e-15);
}

BOOST_AUTO_TEST_CASE(the_candidate_set_solves_the_whole_grid_lcp)
{
  // The 480-point grid (10 x 12 cells, 2 x 2 points each) of
  // unit/projected_cg for a rough demand, cold and warm-started: the
  // candidate-set solve against block principal pivoting on the dense
  // compliance and MPRGP on the whole grid. Both solve to the same tolerance
  // on the projected gradient (1e-10 of |q|), so each may be that times
  // cond(W) from the exact answer: the bound 4.5e-11 is 2.6 times the
  // measured 1.7e-11 from pivoting; from the whole grid's MPRGP 3.2e-12 (the set's
  // step length comes from its own rows' sums, so the iterates differ), held
  // within 1e-11.
  const auto                 coarse = test::coarse_points(10, 12, false);
  const Eigen::MatrixXd      G      = coarse_compliance(coarse);
  const contact::ContactGrid dense(coarse, 2, tread_layer), free(coarse, 2, tread_layer, true);
  const Eigen::MatrixXd      W             = dense.compliance(G);
  const unsigned int         n             = free.n_points();
  const contact::SymmetricOperator product = [&](const Eigen::VectorXd &x, Eigen::VectorXd &y) {
    free.apply(G, x, y);
  };
  const contact::OperatorBlock block = [&](const std::vector<unsigned int> &rows,
                                           const std::vector<unsigned int> &columns,
                                           Eigen::MatrixXd                 &out) {
    free.block(G, rows, columns, out);
  };
  const Eigen::VectorXd       d  = 3e-5 * random_vector(n, 1) - Eigen::VectorXd::Constant(n, 2e-5);
  const Eigen::VectorXd       d2 = d + 2e-6 * random_vector(n, 2);
  contact::ProjectedCgOptions options;
  options.operator_norm = contact::operator_norm(product, n);
  contact::CandidateSetReport cold_set, warm_set;
  const auto cold = contact::solve_lcp_candidate_set(product, block, -d, {}, options, &cold_set);
  const auto warm =
    contact::solve_lcp_candidate_set(product, block, -d2, cold.z, options, &warm_set);
  const auto        whole = contact::solve_lcp_projected_cg(product, -d2, cold.z, options);
  std::vector<bool> none;
  const auto        pivoting = contact::solve_lcp(W, -d2, none);
  unsigned int      n_active = 0, n_demand = 0;
  for (unsigned int i = 0; i < n; ++i)
    {
      n_active += pivoting.z[i] > 0.;
      n_demand += d2[i] > 0.;
    }
  const double against_pivoting = test::relative_difference(warm.z, pivoting.z, W, -d2);
  const double against_whole    = test::relative_difference(warm.z, whole.z, W, -d2);
  BOOST_TEST_MESSAGE(n << " points, " << n_active << " in contact, " << n_demand
                       << " with the road above them: candidates " << cold_set.end << " cold, "
                       << warm_set.end << " warm; products " << cold.iterations << " cold, "
                       << warm.iterations << " warm (whole grid " << whole.iterations
                       << "); against pivoting " << against_pivoting << ", against the whole "
                       << "grid " << against_whole);
  BOOST_TEST(cold.converged);
  BOOST_TEST(warm.converged);
  BOOST_TEST(n_active > 20u);
  BOOST_TEST(warm_set.end < n / 2);
  BOOST_TEST(warm_set.end >= n_active);
  BOOST_TEST(!warm_set.whole_grid);
  // Measured 1.7e-11 (the pivoting solver's tolerance) and 3.2e-12 (MPRGP's
  // own tolerance, on other iterates).
  BOOST_TEST(against_pivoting < 4.5e-11);
  BOOST_TEST(against_whole < 1e-11);
  // The returned forces measured here, w = W z + q formed from the dense
  // compliance (not the solver's blocks and FFT products): no point inside the road, no
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

BOOST_AUTO_TEST_CASE(a_point_pulled_into_the_road_joins_the_set)
{
  // W = [1 -1/2; -1/2 1] (a load at one point lifts the other, as a nearly
  // incompressible tread bulges), q = (-1, 0.1): the candidates start as
  // point 0 alone, whose force pulls point 1 into the road (w_1 = -0.4); the
  // set grows and the answer is z = -W^-1 q = (19/15, 8/15), both in contact.
  Eigen::MatrixXd W(2, 2);
  W << 1., -0.5, -0.5, 1.;
  Eigen::VectorXd q(2);
  q << -1., 0.1;
  const contact::SymmetricOperator product = [&](const Eigen::VectorXd &x, Eigen::VectorXd &y) {
    y = W * x;
  };
  contact::CandidateSetReport set;
  const auto r = contact::solve_lcp_candidate_set(product, dense_block(W), q, {}, {}, &set);
  BOOST_TEST(r.converged);
  BOOST_TEST(set.start == 1u);
  BOOST_TEST(set.end == 2u);
  BOOST_TEST(set.whole_grid); // 2 of 2 points: more than half the grid
  BOOST_TEST(std::abs(r.z[0] - 19. / 15.) < 1e-9);
  BOOST_TEST(std::abs(r.z[1] - 8. / 15.) < 1e-9);
  BOOST_TEST(r.w.cwiseAbs().maxCoeff() < 1e-9);
}

BOOST_AUTO_TEST_CASE(a_point_pulled_in_just_past_the_tolerance_joins_the_set)
{
  // The same pair of points among four open ones (so that the set, 2 of 6,
  // stays below the whole-grid limit), q = (-1, 1/2 - 10 tau, 1, 1, 1, 1)
  // with tau = 1e-10 (the default tolerance, |q| = 1): point 0 alone pulls
  // point 1 into the road by 10 tau only, 10 times the join threshold. It
  // must join: the answer is z = (1 + 2/3 10 tau, 4/3 10 tau, 0, 0, 0, 0). A
  // threshold 1000 times too lax leaves z_1 = 0 with point 1 inside the road
  // by 10 tau. Measured: z_1 2.1e-25 from the closed form (1.6e-16 of it),
  // z_0 exact, no penetration at point 1: round-off, so the bounds are about
  // 10 times round-off, 2e-15 of z_1 and of |q|.
  Eigen::MatrixXd W = Eigen::MatrixXd::Identity(6, 6);
  W(0, 1) = W(1, 0)                        = -0.5;
  const double    tau                      = contact::ProjectedCgOptions().tolerance;
  Eigen::VectorXd q                        = Eigen::VectorXd::Ones(6);
  q[0]                                     = -1.;
  q[1]                                     = 0.5 - 10. * tau;
  const contact::SymmetricOperator product = [&](const Eigen::VectorXd &x, Eigen::VectorXd &y) {
    y = W * x;
  };
  contact::CandidateSetReport set;
  const auto r = contact::solve_lcp_candidate_set(product, dense_block(W), q, {}, {}, &set);
  const Eigen::VectorXd exact = -W.inverse() * q;
  BOOST_TEST_MESSAGE("z_1 " << r.z[1] << " against " << exact[1] << ": difference "
                            << std::abs(r.z[1] - exact[1]) << "; gap at point 1 "
                            << (W * r.z + q)[1]);
  BOOST_TEST(r.converged);
  BOOST_TEST(set.start == 1u);
  BOOST_TEST(set.end == 2u);
  BOOST_TEST(!set.whole_grid);
  CHECK_BOUND(std::abs(r.z[1] - exact[1]), 2e-15 * exact[1]);
  CHECK_BOUND(std::abs(r.z[0] - exact[0]), 2e-15 * exact[0]);
  CHECK_BOUND(-(W * r.z + q)[1], 2e-15);
}

BOOST_AUTO_TEST_CASE(edge_cases)
{
  const Eigen::MatrixXd            W       = 2. * Eigen::MatrixXd::Identity(6, 6);
  const contact::SymmetricOperator product = [&](const Eigen::VectorXd &x, Eigen::VectorXd &y) {
    y = W * x;
  };
  // No point below the road: no candidate, one product to check it, z = 0.
  contact::CandidateSetReport set{99, 99, true};
  const auto                  none = contact::solve_lcp_candidate_set(product, dense_block(W),
                                                                      Eigen::VectorXd::Ones(6), {}, {}, &set);
  BOOST_TEST(none.converged);
  BOOST_TEST(set.end == 0u);
  BOOST_TEST(!set.whole_grid);
  BOOST_TEST(none.iterations == 1u);
  BOOST_TEST(none.z.cwiseAbs().maxCoeff() == 0.);
  // Every point below it: more than half the grid, so the whole-grid solve,
  // z = -q / 2.
  const auto all = contact::solve_lcp_candidate_set(product, dense_block(W),
                                                    -Eigen::VectorXd::Ones(6), {}, {}, &set);
  BOOST_TEST(all.converged);
  BOOST_TEST(set.end == 6u);
  BOOST_TEST(set.whole_grid);
  BOOST_TEST((all.z - Eigen::VectorXd::Constant(6, 0.5)).cwiseAbs().maxCoeff() < 1e-12);
  // Bad input.
  BOOST_CHECK_THROW(contact::solve_lcp_candidate_set(product, dense_block(W),
                                                     Eigen::VectorXd::Constant(6, NAN), {}, {}),
                    NumericalError);
  BOOST_CHECK_THROW(contact::solve_lcp_candidate_set(product, dense_block(W),
                                                     Eigen::VectorXd::Ones(6),
                                                     Eigen::VectorXd::Ones(4), {}),
                    InputError);
  // Not positive definite on the set: reported, not a wrong answer.
  Eigen::VectorXd diagonal(3);
  diagonal << 1., -1., 1.;
  const Eigen::MatrixXd            indefinite = diagonal.asDiagonal();
  const contact::SymmetricOperator bad        = [&](const Eigen::VectorXd &x, Eigen::VectorXd &y) {
    y = indefinite * x;
  };
  contact::ProjectedCgOptions options;
  options.operator_norm = 1.;
  const auto failed =
    contact::solve_lcp_candidate_set(bad, dense_block(indefinite), diagonal, {}, options);
  BOOST_TEST(!failed.converged);
  BOOST_TEST(failed.message.find("not positive") != std::string::npos);
}

BOOST_AUTO_TEST_CASE(rolling_on_the_candidate_set_is_rolling_on_the_whole_grid)
{
  // A synthetic modal model on 4 x 3 coarse cells, rolled on road-A on a 4 x
  // 4 grid from the static start, by MPRGP on the candidate set and on the
  // whole grid. Both stop at the same tolerance (1e-10 of the step's |q|,
  // not the default 1e-6), so their forces may differ by about that times
  // the compliance's condition; measured 1.3e-10 of the peak, bound 3 times
  // that.
  const auto                     coarse = test::coarse_points(4, 3, false);
  const unsigned int             n_c    = coarse.size();
  const synthesis::ModeSynthesis s      = test::synthetic_modes(coarse);
  const modal::PatchModel        model =
    synthesis::to_patch_model(s, Eigen::MatrixXd::Zero(n_c, n_c), 4000.);
  const contact::ContactGrid candidates(coarse, 4, tread_layer, true, true, 1e-10),
    whole(coarse, 4, tread_layer, true, false, 1e-10);
  const test::GridRolls r       = test::roll_on_two_grids(model, whole, candidates);
  const auto           &summary = r.summary;
  const double          peak = r.peak, worst = r.worst;
  BOOST_TEST_MESSAGE("rolling on " << whole.n_points() << " points, candidate set against the "
                                   << "whole grid: largest force difference " << worst / peak
                                   << " of the peak " << peak << " N; points in contact "
                                   << summary[1].min_contact_fraction << " to "
                                   << summary[1].max_contact_fraction);
  BOOST_TEST(summary[0].failed_steps == 0u);
  BOOST_TEST(summary[1].failed_steps == 0u);
  BOOST_TEST(summary[1].max_contact_fraction < 0.5);
  BOOST_TEST(worst < 4e-10 * peak);
}

BOOST_AUTO_TEST_SUITE_END()

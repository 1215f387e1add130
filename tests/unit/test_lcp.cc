// The dense LCP solver against two independent references: Siconos
// numerics' lexicographic Lemke method (a complementary pivoting method,
// Debian libsiconos-numerics-dev) on random P-matrices up to n = 60, and an
// enumeration of all 2^n active sets for n <= 10; then the edge cases and
// the errors.
#include <greentread/base/exceptions.h>
#include <greentread/contact/lcp.h>

#include <Eigen/Dense>

#include <boost/test/unit_test.hpp>

#include "complementarity.h"
#include "siconos_reference.h"

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <limits>
#include <random>
#include <string>
#include <vector>

using namespace greentread;
using contact::LcpResult;
using contact::solve_lcp;
using test::relative_difference;
using test::siconos_lemke;
using test::SiconosSolution;

namespace
{
  /// The kinds of P-matrices the tests draw.
  enum class Family
  {
    diagonally_dominant,  ///< nonsymmetric, strictly row diagonally dominant
    symmetric_definite,   ///< B B^T / n + 0.05 I
    nonsymmetric_definite ///< B B^T / n + (S - S^T) + 0.05 I: not diagonally dominant
  };

  const char *
  name(const Family family)
  {
    switch (family)
      {
        case Family::diagonally_dominant:
          return "diagonally dominant";
        case Family::symmetric_definite:
          return "symmetric positive definite";
        case Family::nonsymmetric_definite:
          return "nonsymmetric positive definite";
      }
    return "";
  }

  /// A random n x n P-matrix of the given family, scaled by @p scale.
  Eigen::MatrixXd
  random_p_matrix(std::mt19937 &rng, const Family family, const int n, const double scale)
  {
    std::uniform_real_distribution<double> u(-1., 1.);
    const auto                             random = [&](const int rows, const int cols) {
      Eigen::MatrixXd A(rows, cols);
      for (int j = 0; j < cols; ++j)
        for (int i = 0; i < rows; ++i)
          A(i, j) = u(rng);
      return A;
    };
    Eigen::MatrixXd M;
    switch (family)
      {
        case Family::diagonally_dominant:
          {
            M = random(n, n);
            for (int i = 0; i < n; ++i)
              {
                const double off = M.row(i).cwiseAbs().sum() - std::abs(M(i, i));
                M(i, i)          = off * (1.05 + 0.5 * (u(rng) + 1.)) + 0.1;
              }
            break;
          }
        case Family::symmetric_definite:
          {
            const Eigen::MatrixXd B = random(n, n);
            M = B * B.transpose() / n + 0.05 * Eigen::MatrixXd::Identity(n, n);
            break;
          }
        case Family::nonsymmetric_definite:
          {
            const Eigen::MatrixXd B = random(n, n), S = random(n, n);
            M =
              B * B.transpose() / n + (S - S.transpose()) + 0.05 * Eigen::MatrixXd::Identity(n, n);
            break;
          }
      }
    return scale * M;
  }

  Eigen::VectorXd
  random_q(std::mt19937 &rng, const int n, const double scale)
  {
    std::uniform_real_distribution<double> u(-1., 1.);
    Eigen::VectorXd                        q(n);
    for (int i = 0; i < n; ++i)
      q[i] = scale * u(rng);
    return q;
  }

  /// Independent of the solver: try all 2^n active sets A, solve
  /// M_AA z_A = -q_A with a column-pivoting QR and keep the sets whose z_A
  /// and w_F = q_F + M_FA z_A are non-negative (to 1e-12 of the scale).
  std::vector<Eigen::VectorXd>
  enumerate_solutions(const Eigen::MatrixXd &M, const Eigen::VectorXd &q)
  {
    const int                    n = q.size();
    const double                 m = M.cwiseAbs().rowwise().sum().maxCoeff();
    std::vector<Eigen::VectorXd> solutions;
    for (unsigned long mask = 0; mask < (1ul << n); ++mask)
      {
        std::vector<int> A;
        for (int i = 0; i < n; ++i)
          if (mask & (1ul << i))
            A.push_back(i);
        const int       k = A.size();
        Eigen::MatrixXd M_AA(k, k);
        Eigen::VectorXd q_A(k);
        for (int a = 0; a < k; ++a)
          {
            q_A[a] = q[A[a]];
            for (int b = 0; b < k; ++b)
              M_AA(a, b) = M(A[a], A[b]);
          }
        Eigen::VectorXd z = Eigen::VectorXd::Zero(n);
        if (k > 0)
          {
            const Eigen::VectorXd z_A = M_AA.colPivHouseholderQr().solve(-q_A);
            for (int a = 0; a < k; ++a)
              z[A[a]] = z_A[a];
          }
        const Eigen::VectorXd w = M * z + q;
        const double scale = std::max(q.lpNorm<Eigen::Infinity>(), m * z.lpNorm<Eigen::Infinity>());
        bool         ok    = true;
        for (int i = 0; i < n; ++i)
          ok = ok && (mask & (1ul << i) ? m * z[i] >= -1e-12 * scale : w[i] >= -1e-12 * scale);
        if (ok)
          solutions.push_back(z);
      }
    return solutions;
  }

  std::vector<bool>
  positive(const Eigen::VectorXd &z)
  {
    std::vector<bool> p(z.size());
    for (Eigen::Index i = 0; i < z.size(); ++i)
      p[i] = z[i] > 0.;
    return p;
  }
} // namespace

BOOST_AUTO_TEST_SUITE(lcp)

BOOST_AUTO_TEST_CASE(random_p_matrices_against_siconos_lemke)
{
  std::mt19937                           rng(20240611);
  std::uniform_real_distribution<double> exponent(-3., 6.);
  for (const Family family :
       {Family::diagonally_dominant, Family::symmetric_definite, Family::nonsymmetric_definite})
    {
      // The strongly nonsymmetric family needs Murty's single exchanges,
      // many of them for n > 40: give it room (see below).
      contact::LcpOptions options;
      if (family == Family::nonsymmetric_definite)
        options.max_iterations = 100000;
      double       max_difference = 0., max_residual = 0., max_warm_difference = 0.;
      double       worst_gap = 0., worst_natural = 0.;
      unsigned int max_iterations = 0, total_iterations = 0, instances = 0;
      unsigned int max_warm_iterations = 0, total_active = 0, total_size = 0;
      for (int n = 1; n <= 60; ++n)
        for (int repeat = 0; repeat < 3; ++repeat)
          {
            // Stiffness-like and displacement-like scales far from 1.
            const double          M_scale = std::pow(10., exponent(rng));
            const double          q_scale = std::pow(10., exponent(rng) - 3.);
            const Eigen::MatrixXd M       = random_p_matrix(rng, family, n, M_scale);
            const Eigen::VectorXd q       = random_q(rng, n, q_scale);

            std::vector<bool> active;
            const LcpResult   r = solve_lcp(M, q, active, options);
            BOOST_TEST_REQUIRE(r.converged, r.message);
            BOOST_TEST(r.message.empty());
            // The returned pair measured here from M, q and z: the gap and
            // the complementarity within the solver's tolerance (tau =
            // 1e-10; measured: round-off, about 1e-16). What the projection
            // onto z >= 0 removed (r.projected) is not asserted: the
            // solver's own stopping rule holds it below tau; a projection
            // that removed a real force shows here in w and against Siconos.
            const test::Complementarity c = test::complementarity(M, q, r.z);
            BOOST_TEST(c.gap >= -2. * options.tolerance);
            BOOST_TEST(c.natural <= 2. * options.tolerance);
            BOOST_TEST(c.product <= 2. * options.tolerance);
            worst_gap     = std::min(worst_gap, c.gap);
            worst_natural = std::max(worst_natural, std::max(c.natural, c.product));
            // w is M z + q to round-off (the solver sums the active columns).
            const double w_scale =
              M.cwiseAbs().rowwise().sum().maxCoeff() * r.z.lpNorm<Eigen::Infinity>() +
              q.lpNorm<Eigen::Infinity>();
            BOOST_TEST((r.w - (M * r.z + q)).lpNorm<Eigen::Infinity>() <= 1e-14 * w_scale);
            BOOST_TEST(r.residual <= 1e-12);

            const SiconosSolution s = siconos_lemke(M, q);
            BOOST_TEST_REQUIRE(s.info == 0, "Siconos Lemke failed, n = " << n);
            const double difference = relative_difference(r.z, s.z, M, q);
            BOOST_TEST(difference <= 1e-8, name(family) << ", n = " << n);
            BOOST_TEST(active == positive(s.z), name(family) << ", n = " << n);
            BOOST_TEST(active == positive(r.z));

            // Warm start from the answer: no exchange, the same z.
            std::vector<bool> warm = active;
            const LcpResult   rw   = solve_lcp(M, q, warm, options);
            BOOST_TEST(rw.converged);
            BOOST_TEST(rw.iterations == 0u);
            BOOST_TEST(warm == active);
            BOOST_TEST(relative_difference(rw.z, r.z, M, q) <= 1e-14);

            // Warm start from the answer of a perturbed q (a time step later).
            const Eigen::VectorXd q_next = q + 0.1 * random_q(rng, n, q_scale);
            std::vector<bool>     next   = active;
            const LcpResult       rn     = solve_lcp(M, q_next, next, options);
            BOOST_TEST_REQUIRE(rn.converged, rn.message);
            const SiconosSolution sn = siconos_lemke(M, q_next);
            BOOST_TEST_REQUIRE(sn.info == 0);
            const double warm_difference = relative_difference(rn.z, sn.z, M, q_next);
            BOOST_TEST(warm_difference <= 1e-8);
            BOOST_TEST(next == positive(sn.z));

            max_difference      = std::max(max_difference, difference);
            max_warm_difference = std::max(max_warm_difference, warm_difference);
            max_residual        = std::max(max_residual, r.residual);
            max_iterations      = std::max(max_iterations, r.iterations);
            max_warm_iterations = std::max(max_warm_iterations, rn.iterations);
            total_iterations += r.iterations;
            total_active += std::count(active.begin(), active.end(), true);
            total_size += n;
            ++instances;
          }
      BOOST_TEST_MESSAGE(name(family)
                         << ": " << instances << " instances, n = 1..60, " << total_active << " of "
                         << total_size << " indices active; max |z - z_siconos| " << max_difference
                         << " (warm " << max_warm_difference << "), max residual " << max_residual
                         << "; measured here: gap down to " << worst_gap
                         << ", complementarity up to " << worst_natural << "; iterations max "
                         << max_iterations << ", mean " << double(total_iterations) / instances
                         << ", warm max " << max_warm_iterations);
      // Our use: block exchanges alone, a few of them.
      if (family != Family::nonsymmetric_definite)
        BOOST_TEST(max_iterations <= 10u);
    }
}

BOOST_AUTO_TEST_CASE(small_p_matrices_against_enumeration)
{
  std::mt19937 rng(7);
  for (const Family family :
       {Family::diagonally_dominant, Family::symmetric_definite, Family::nonsymmetric_definite})
    {
      double       max_difference = 0.;
      unsigned int max_iterations = 0, instances = 0;
      for (int n = 1; n <= 10; ++n)
        for (int repeat = 0; repeat < 20; ++repeat)
          {
            const Eigen::MatrixXd M = random_p_matrix(rng, family, n, 1.);
            const Eigen::VectorXd q = random_q(rng, n, 1.);

            const auto solutions = enumerate_solutions(M, q);
            BOOST_TEST_REQUIRE(solutions.size() == 1u); // P-matrix: exactly one

            // Cold, and from a random warm start.
            std::vector<bool> active, warm(n);
            for (int i = 0; i < n; ++i)
              warm[i] = rng() % 2;
            for (std::vector<bool> *set : {&active, &warm})
              {
                const LcpResult r = solve_lcp(M, q, *set);
                BOOST_TEST_REQUIRE(r.converged, r.message);
                const double difference = relative_difference(r.z, solutions[0], M, q);
                BOOST_TEST(difference <= 1e-12, name(family) << ", n = " << n);
                BOOST_TEST(*set == positive(solutions[0]));
                max_difference = std::max(max_difference, difference);
                max_iterations = std::max(max_iterations, r.iterations);
              }
            ++instances;
          }
      BOOST_TEST_MESSAGE(name(family)
                         << ": " << instances << " instances, n = 1..10, max |z - z_enumerated| "
                         << max_difference << ", max iterations " << max_iterations);
    }
}

BOOST_AUTO_TEST_CASE(edge_cases)
{
  // q >= 0 (with zeros): z = 0, w = q, nothing to exchange.
  {
    std::mt19937          rng(3);
    const Eigen::MatrixXd M = random_p_matrix(rng, Family::diagonally_dominant, 8, 1.);
    Eigen::VectorXd       q = random_q(rng, 8, 1.).cwiseAbs();
    q[2] = q[5] = 0.;
    std::vector<bool> active;
    const LcpResult   r = solve_lcp(M, q, active);
    BOOST_TEST(r.converged);
    BOOST_TEST(r.iterations == 0u);
    BOOST_TEST(r.z.lpNorm<Eigen::Infinity>() == 0.);
    BOOST_TEST((r.w - q).lpNorm<Eigen::Infinity>() == 0.);
    BOOST_TEST(r.residual == 0.);
    BOOST_TEST(active == std::vector<bool>(8, false));

    // The same from a wrong warm start: every index leaves.
    std::vector<bool> all(8, true);
    const LcpResult   ra = solve_lcp(M, q, all);
    BOOST_TEST(ra.converged);
    BOOST_TEST(ra.iterations >= 1u);
    BOOST_TEST(ra.z.lpNorm<Eigen::Infinity>() == 0.);
    BOOST_TEST(all == std::vector<bool>(8, false));
  }

  // q = 0 and M = 0: z = 0.
  {
    std::vector<bool> active;
    const LcpResult   r = solve_lcp(Eigen::MatrixXd::Zero(3, 3), Eigen::VectorXd::Zero(3), active);
    BOOST_TEST(r.converged);
    BOOST_TEST(r.z.lpNorm<Eigen::Infinity>() == 0.);
  }

  // n = 0.
  {
    std::vector<bool> active;
    const LcpResult   r = solve_lcp(Eigen::MatrixXd(0, 0), Eigen::VectorXd(0), active);
    BOOST_TEST(r.converged);
    BOOST_TEST(r.iterations == 0u);
    BOOST_TEST(r.z.size() == 0);
    BOOST_TEST(r.w.size() == 0);
    BOOST_TEST(active.empty());
  }

  // 1 x 1: z = max(0, -q/M), w = max(0, q).
  for (const double a : {1e-3, 1., 2.5e7})
    for (const double b : {-3., -1e-9, 0., 1e-9, 4.})
      {
        Eigen::MatrixXd M(1, 1);
        Eigen::VectorXd q(1);
        M(0, 0) = a;
        q[0]    = b;
        std::vector<bool> active;
        const LcpResult   r = solve_lcp(M, q, active);
        BOOST_TEST(r.converged);
        BOOST_TEST(r.z[0] == std::max(0., -b / a), boost::test_tools::tolerance(1e-15));
        BOOST_TEST(std::abs(r.w[0] - std::max(0., b)) <= 1e-15 * std::abs(b));
        BOOST_TEST(r.iterations == (b < 0. ? 1u : 0u));
        BOOST_TEST(active[0] == (b < 0.));
      }

  // Not P-matrices: failures are reported, not thrown.
  {
    Eigen::MatrixXd M(1, 1);
    Eigen::VectorXd q(1);
    M(0, 0) = 0.;
    q[0]    = -1.;
    std::vector<bool> active;
    const LcpResult   singular = solve_lcp(M, q, active);
    BOOST_TEST(!singular.converged);
    BOOST_TEST(singular.message.find("singular") != std::string::npos, singular.message);
    BOOST_TEST_MESSAGE(singular.message);

    M(0, 0) = -1.; // w = -z - 1 >= 0 has no solution with z >= 0
    active.clear();
    const LcpResult none = solve_lcp(M, q, active);
    BOOST_TEST(!none.converged);
    BOOST_TEST(none.iterations == 200u);
    BOOST_TEST(none.message.find("200") != std::string::npos, none.message);
    BOOST_TEST(none.residual > 0.1);
    BOOST_TEST_MESSAGE(none.message);
  }
}

BOOST_AUTO_TEST_CASE(bad_input_throws)
{
  std::mt19937          rng(5);
  const Eigen::MatrixXd M = random_p_matrix(rng, Family::diagonally_dominant, 4, 1.);
  const Eigen::VectorXd q = random_q(rng, 4, 1.);
  std::vector<bool>     active;

  Eigen::VectorXd q_nan = q;
  q_nan[1]              = std::numeric_limits<double>::quiet_NaN();
  BOOST_CHECK_THROW(solve_lcp(M, q_nan, active), NumericalError);

  Eigen::MatrixXd M_inf = M;
  M_inf(2, 3)           = std::numeric_limits<double>::infinity();
  BOOST_CHECK_THROW(solve_lcp(M_inf, q, active), NumericalError);

  BOOST_CHECK_THROW(solve_lcp(M, Eigen::VectorXd(3), active), InputError);
  BOOST_CHECK_THROW(solve_lcp(M.leftCols(3), q, active), InputError);
  std::vector<bool> wrong(3, false);
  BOOST_CHECK_THROW(solve_lcp(M, q, wrong), InputError);
  contact::LcpOptions options;
  options.tolerance = -1.;
  BOOST_CHECK_THROW(solve_lcp(M, q, active, options), InputError);
}

BOOST_AUTO_TEST_SUITE_END()

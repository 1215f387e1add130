#pragma once

// The independent reference of the LCP solver: Siconos numerics'
// lexicographic Lemke method (Debian libsiconos-numerics-dev), used by
// test_lcp.cc on random instances and by test_tyre_contact.cc on the
// instances of a rolling tyre.

#include <Eigen/Core>

#include <LCP_Solvers.h>
#include <LinearComplementarityProblem.h>
#include <NonSmoothDrivers.h>
#include <NumericsMatrix.h>
#include <SolverOptions.h>
#include <lcp_cst.h>

#include <algorithm>
#include <cstdlib>

namespace test
{
  /// Siconos numerics' lexicographic Lemke method through its LCP driver.
  struct SiconosSolution
  {
    Eigen::VectorXd z, w;
    int             info       = -1;
    int             iterations = 0;
  };

  inline SiconosSolution
  siconos_lemke(const Eigen::MatrixXd &M, const Eigen::VectorXd &q)
  {
    const int                    n      = q.size();
    Eigen::MatrixXd              M_copy = M; // column-major, as NM_DENSE expects
    Eigen::VectorXd              q_copy = q;
    NumericsMatrix              *matrix = NM_create_from_data(NM_DENSE, n, n, M_copy.data());
    LinearComplementarityProblem problem;
    problem.size = n;
    problem.M    = matrix;
    problem.q    = q_copy.data();

    SolverOptions *options                   = solver_options_create(SICONOS_LCP_LEMKE);
    options->iparam[SICONOS_IPARAM_MAX_ITER] = 100000;
    options->dparam[SICONOS_DPARAM_TOL]      = 1e-10;

    SiconosSolution s;
    s.z          = Eigen::VectorXd::Zero(n);
    s.w          = Eigen::VectorXd::Zero(n);
    s.info       = linearComplementarity_driver(&problem, s.z.data(), s.w.data(), options);
    s.iterations = options->iparam[SICONOS_IPARAM_ITER_DONE];
    solver_options_delete(options);
    NM_clear_not_dense(matrix); // the data is M_copy's
    std::free(matrix);
    return s;
  }

  /// max |z - z_ref| relative to the scale of z: max(|z_ref|, |q| / |M|).
  inline double
  relative_difference(const Eigen::VectorXd &z,
                      const Eigen::VectorXd &z_ref,
                      const Eigen::MatrixXd &M,
                      const Eigen::VectorXd &q)
  {
    const double m     = M.cwiseAbs().rowwise().sum().maxCoeff();
    const double scale = std::max(z_ref.lpNorm<Eigen::Infinity>(), q.lpNorm<Eigen::Infinity>() / m);
    return scale > 0. ? (z - z_ref).lpNorm<Eigen::Infinity>() / scale : 0.;
  }
} // namespace test

// The patch model (shared poles, residues of every pair): fitted to the
// frequency responses of a known modal system, it must give them back.

#include "bounds.h"
#include "scratch.h"
#include <greentread/base/exceptions.h>
#include <greentread/modal/passivity.h>
#include <greentread/modal/patch_model.h>

#include <Eigen/Eigenvalues>

#include <boost/test/unit_test.hpp>

#include <cmath>
#include <complex>
#include <filesystem>

namespace
{
  using namespace greentread;

  /**
   * Three points on a line and four lightly damped modes with real shapes
   * (residue R = phi_i phi_j / (2 j m omega_d), reciprocal), plus a local
   * compliance carried by a real pole at -2 pi f_r: a system the patch model
   * can represent exactly.
   */
  struct KnownSystem
  {
    static constexpr unsigned int      n = 3;
    std::vector<std::complex<double>>  lambda;
    std::vector<std::array<double, n>> shape;
    double                             f_r, local;
    /// The local compliance as a constant (true) or a real pole at f_r.
    bool constant;

    explicit KnownSystem(const double f_max, const bool constant_local = false)
        : f_r(3. * f_max)
        , local(2e-5)
        , constant(constant_local)
    {
      const double f[4]  = {180., 530., 1210., 2350.};
      const double xi[4] = {0.03, 0.02, 0.04, 0.05};
      for (unsigned int k = 0; k < 4; ++k)
        {
          const double w = 2. * M_PI * f[k];
          lambda.emplace_back(-xi[k] * w, w * std::sqrt(1. - xi[k] * xi[k]));
          shape.push_back({{std::cos(0.7 * k), std::sin(1.3 * k + 0.4), 0.5 + 0.2 * k}});
        }
    }

    std::complex<double>
    g(const unsigned int i, const unsigned int j, const double omega) const
    {
      const std::complex<double> jw(0., omega);
      std::complex<double>       sum = 0.;
      for (unsigned int k = 0; k < lambda.size(); ++k)
        {
          // A real mode, R = phi_i phi_j / (2 j m omega_d), with the modal
          // mass chosen so that every peak is about 1e-5 m/N.
          const double               damping = -lambda[k].real();
          const std::complex<double> R(0., -1e-5 * damping * shape[k][i] * shape[k][j]);
          sum += R / (jw - lambda[k]) + std::conj(R) / (jw - std::conj(lambda[k]));
        }
      // The local compliance: static value local (driving) or local / 4 (transfer).
      const double wr = 2. * M_PI * f_r;
      const double c  = (i == j ? local : 0.25 * local);
      return sum + (constant ? c : c * wr / (jw + wr));
    }

    base::FrequencyResponseMatrix
    sample(const double df, const unsigned int n_lines) const
    {
      base::FrequencyResponseMatrix m;
      m.df      = df;
      m.n_lines = n_lines;
      for (unsigned int i = 0; i < n; ++i)
        m.points.push_back({{0.01 * i, 0., 0.3}});
      for (unsigned int k = 0; k < n_lines; ++k)
        for (unsigned int i = 0; i < n; ++i)
          for (unsigned int j = 0; j < n; ++j)
            m.values.push_back(g(i, j, 2. * M_PI * k * df));
      return m;
    }
  };
} // namespace



BOOST_AUTO_TEST_SUITE(patch_model)

BOOST_AUTO_TEST_CASE(a_known_system_is_recovered_for_every_pair)
{
  const double                    f_max = 4000., df = 15.625;
  const KnownSystem               truth(f_max);
  const auto                      green = truth.sample(df, 257);
  modal::IdentificationParameters identification;
  modal::PatchModelParameters     parameters;
  parameters.instantaneous_residual = false; // a residual pole at 3 f_max, as the truth
  const auto model = modal::fit_patch_model(green, identification, parameters, false);

  // The four modes are found (plus the residual pole).
  BOOST_TEST(model.n_terms() >= 5u);
  unsigned int found = 0;
  for (const auto &l : truth.lambda)
    for (const auto &m : model.lambda)
      if (std::abs(m - l) < 1e-3 * std::abs(l))
        {
          ++found;
          break;
        }
  BOOST_TEST(found == 4u);

  // Every pair, at lines and between them: the model equals the system.
  double worst = 0., scale = 0.;
  for (unsigned int i = 0; i < KnownSystem::n; ++i)
    for (unsigned int j = 0; j < KnownSystem::n; ++j)
      {
        BOOST_TEST(model.errors(i, j) < 1e-4);
        for (double f = 0.; f <= f_max; f += 7.3)
          {
            const double w = 2. * M_PI * f;
            worst = std::max(worst, std::abs(model.frequency_response(i, j, w) - truth.g(i, j, w)));
            scale = std::max(scale, std::abs(truth.g(i, j, w)));
            // The one-pair model used by the one-point convolutions agrees.
            BOOST_TEST(std::abs(model.pair_model(i, j).frequency_response(w) -
                                model.frequency_response(i, j, w)) <= 1e-12 * scale);
          }
      }
  BOOST_TEST(worst < 1e-4 * scale);

  // The static compliance is the system's at 0 Hz.
  const auto G0 = model.static_compliance();
  for (unsigned int i = 0; i < KnownSystem::n; ++i)
    for (unsigned int j = 0; j < KnownSystem::n; ++j)
      BOOST_TEST(std::abs(G0(i, j) - truth.g(i, j, 0.).real()) < 1e-5 * std::abs(G0(0, 0)));
}

BOOST_AUTO_TEST_CASE(a_known_system_with_an_instantaneous_compliance_is_recovered)
{
  // The default residual: a constant G_r (here [1 1/4 1/4; ...] 2e-5 m/N,
  // positive definite) and modes with imaginary residues, as the truth.
  const double                    f_max = 4000., df = 15.625;
  const KnownSystem               truth(f_max, true);
  const auto                      green = truth.sample(df, 257);
  modal::IdentificationParameters identification;
  modal::PatchModelParameters     parameters;
  BOOST_TEST(parameters.instantaneous_residual);
  const auto model = modal::fit_patch_model(green, identification, parameters, false);
  BOOST_REQUIRE(model.instantaneous.rows() == KnownSystem::n);
  double worst = 0., scale = 0.;
  for (unsigned int i = 0; i < KnownSystem::n; ++i)
    for (unsigned int j = 0; j < KnownSystem::n; ++j)
      {
        BOOST_TEST(std::abs(model.instantaneous(i, j) - (i == j ? 1. : 0.25) * truth.local) <
                   1e-4 * truth.local);
        // That the modal part starts from rest (sum of 2 Re R_k = 0) is not
        // asserted: with an instantaneous residual the fit stores Re R_k = 0.
        for (double f = 0.; f <= f_max; f += 7.3)
          {
            const double w = 2. * M_PI * f;
            worst = std::max(worst, std::abs(model.frequency_response(i, j, w) - truth.g(i, j, w)));
            scale = std::max(scale, std::abs(truth.g(i, j, w)));
            // The one-pair model leaves G_r out.
            BOOST_TEST(std::abs(model.pair_model(i, j).frequency_response(w) +
                                model.instantaneous(i, j) - model.frequency_response(i, j, w)) <=
                       1e-12 * scale);
          }
      }
  BOOST_TEST_MESSAGE("instantaneous residual: worst |g_model - g| = " << worst << " of " << scale);
  // The system is one the model represents exactly: measured 3.8e-14 of the
  // scale; round-off, which differs between machines, so 10 times that.
  CHECK_BOUND(worst / scale, 4e-13);
}

BOOST_AUTO_TEST_CASE(an_identified_passive_system_passes_the_check_and_stays_passive_between_lines)
{
  // The identified route with 'Patch model/Allow non-passive' = false, on a
  // passive system: real shapes, positive damping and a positive definite
  // G_r, so -Im g is positive semidefinite at every frequency. The model the
  // scene's defaults identify must pass the scene's check at the lines, and
  // stay passive between them, where the scene does not look: on a grid 8
  // times finer than the lines, its smallest eigenvalue of -Im g over the
  // largest against the truth's, from the closed form on the same grid.
  // Measured: the truth's worst 2.6e-7 (at 2355 Hz, beside its 2350 Hz
  // mode), the model's 3.2e-17 from it (1.2e-10 of it): round-off, so the
  // bound is about 10 times, 1e-9 of it. The check at the lines alone
  // (2359 Hz) misses the worst frequency by 4 Hz.
  const double                    f_max = 4000., df = 15.625;
  const unsigned int              lines = 256, finer = 8;
  const KnownSystem               truth(f_max, true);
  const auto                      green = truth.sample(df, lines + 1);
  modal::IdentificationParameters identification;
  modal::PatchModelParameters     parameters;
  const auto             model = modal::fit_patch_model(green, identification, parameters, false);
  const modal::Passivity at_lines = modal::measure_passivity(model, df, lines);
  BOOST_CHECK_NO_THROW(modal::check_passivity(at_lines, false, "the identified patch model"));
  const modal::Passivity between     = modal::measure_passivity(model, df / finer, finer * lines);
  double                 truth_worst = 1., truth_frequency = 0.;
  for (unsigned int l = 1; l <= finer * lines; ++l)
    {
      const double    f = l * (df / finer);
      Eigen::MatrixXd loss(KnownSystem::n, KnownSystem::n);
      for (unsigned int i = 0; i < KnownSystem::n; ++i)
        for (unsigned int j = 0; j < KnownSystem::n; ++j)
          loss(i, j) = -truth.g(i, j, 2. * M_PI * f).imag();
      const Eigen::SelfAdjointEigenSolver<Eigen::MatrixXd> eigen(0.5 * (loss + loss.transpose()),
                                                                 Eigen::EigenvaluesOnly);
      const double                                         ratio =
        eigen.eigenvalues().minCoeff() / eigen.eigenvalues().cwiseAbs().maxCoeff();
      if (ratio < truth_worst)
        {
          truth_worst     = ratio;
          truth_frequency = f;
        }
    }
  BOOST_TEST_MESSAGE("passivity: the model's worst ratio "
                     << at_lines.worst << " at the lines (" << at_lines.frequency << " Hz), "
                     << between.worst << " between them (" << between.frequency
                     << " Hz); the truth's " << truth_worst << " (" << truth_frequency << " Hz)");
  BOOST_TEST(truth_worst > 0.);
  BOOST_TEST(between.frequency == truth_frequency, boost::test_tools::tolerance(1e-12));
  // Both ratios are a smallest eigenvalue over the largest, 2.6e-7: their
  // round-off is a few units of 2.2e-16 of the largest, whatever the
  // ratio, and differs between processors (4.4e-16 on an Intel Xeon, 2
  // units; less on an AMD EPYC). The bound is about 9 units.
  CHECK_BOUND(std::abs(between.worst - truth_worst), 2e-15);
}

BOOST_AUTO_TEST_CASE(the_model_file_round_trips_and_keeps_its_key)
{
  const KnownSystem               truth(2000.);
  const auto                      green = truth.sample(15.625, 129);
  modal::IdentificationParameters identification;
  modal::PatchModelParameters     parameters;
  const auto model = modal::fit_patch_model(green, identification, parameters, false);
  const std::filesystem::path file = test::scratch_directory("patch-model") / "gt_patch_model.h5";
  base::ParameterRecord       record;
  modal::write_patch_model(file, model, record, "key 1");
  BOOST_TEST(modal::read_patch_model_key(file.string()) == "key 1");
  const auto back = modal::read_patch_model(file.string());
  BOOST_TEST(back.n_terms() == model.n_terms());
  for (unsigned int t = 0; t < model.n_terms(); ++t)
    {
      BOOST_TEST(back.lambda[t] == model.lambda[t]);
      BOOST_TEST(back.real[t] == model.real[t]);
      BOOST_TEST((back.residues[t] - model.residues[t]).norm() == 0.);
    }
  BOOST_TEST((back.errors - model.errors).norm() == 0.);
  BOOST_TEST((back.instantaneous - model.instantaneous).norm() == 0.);
  std::filesystem::remove(file);
  // A missing file has no key and cannot be read.
  BOOST_TEST(modal::read_patch_model_key(file.string()).empty());
  BOOST_CHECK_THROW(modal::read_patch_model(file.string()), InputError);
}

BOOST_AUTO_TEST_SUITE_END()

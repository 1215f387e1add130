// The patch model from real modes (Patch model/Source = fe modes) in its
// rank-one form, against independent references:
// - its pole-residue form against the closed form
//   g = G_r + sum phi phi^T / (w_k^2 - w^2 + 2 j xi_k w_k w), over- and
//   under-critical modes alike;
// - its O(N_p N_m) recursion against the full-form recursion (every residue
//   a dense matrix) and the direct convolution sum, step by step, and its
//   time-blocked update against the step-by-step one;
// - modal_model.h5 read back bit for bit, and refused when incomplete.
// The paper's path, LSCE, on a synthesis of known modes is in
// test_lsce_on_synthesis.cc.
// Bounds: a comparison that is equal to round-off (1e-16 to 1e-14 measured)
// sits about 10x above what it measures, as round-off differs between
// machines and BLAS kernels; single-precision shapes (2.2e-7 to 2.4e-7) and
// the nudged critical damping (3.6e-8) about 3x.

#include "bounds.h"
#include "scratch.h"
#include <greentread/base/exceptions.h>
#include <greentread/convolution/mode_patch_convolution.h>
#include <greentread/convolution/patch_convolution.h>
#include <greentread/modal/identification.h>
#include <greentread/synthesis/mode_synthesis.h>

#include <deal.II/base/hdf5.h>

#include <boost/test/unit_test.hpp>

#include <algorithm>
#include <array>
#include <cmath>
#include <random>

using namespace greentread;

namespace
{
  /// 7 points, 9 modes from 120 Hz to 3 kHz (one over-critical, one
  /// undamped), shapes of mass-normalised size, a static residual of rank 2.
  synthesis::ModeSynthesis
  known_synthesis()
  {
    const unsigned int                     P = 7, m = 9;
    std::mt19937                           random(7);
    std::uniform_real_distribution<double> u(-1., 1.);
    synthesis::ModeSynthesis               s;
    s.frequency_hz.resize(m);
    s.damping_ratio.resize(m);
    const double f[m]  = {120., 310., 311., 640., 900., 1400., 1900., 2500., 3000.};
    const double xi[m] = {0.02, 0.05, 0.05, 0., 0.1, 1.7, 0.03, 1., 0.04};
    for (unsigned int k = 0; k < m; ++k)
      {
        s.frequency_hz(k)  = f[k];
        s.damping_ratio(k) = xi[k];
      }
    s.shapes.resize(m, P);
    for (unsigned int k = 0; k < m; ++k)
      for (unsigned int p = 0; p < P; ++p)
        s.shapes(k, p) = 0.3 * u(random);
    Eigen::MatrixXd B(P, 2);
    for (unsigned int p = 0; p < P; ++p)
      B.row(p) << 1e-6 * u(random), 1e-6 * u(random);
    s.instantaneous = B * B.transpose();
    for (unsigned int p = 0; p < P; ++p)
      s.points.push_back({{0.01 * p, 0.002 * p, 0.27}});
    s.wavenumber               = {0, 1, 1, 2, 3, 4, 5, 6, 7};
    s.dispersion.frequency_hz  = {Eigen::VectorXd::LinSpaced(2, 120., 640.)};
    s.dispersion.damping_ratio = {Eigen::VectorXd::Constant(2, 0.02)};
    return s;
  }

} // namespace

BOOST_AUTO_TEST_SUITE(mode_model)

namespace
{
  /// The largest difference of the pole-residue form from the closed form
  /// over a few lines, relative to the largest |g| at each line.
  double
  pole_residue_error(const synthesis::ModeSynthesis &s, const modal::PatchModel &model)
  {
    double worst = 0.;
    // 640 Hz is left out: the undamped mode is infinite there.
    for (const double f : {0., 50., 119., 120., 311., 1000., 2500., 2999., 5000.})
      {
        const Eigen::MatrixXcd g = s.at(2. * M_PI * f);
        for (unsigned int i = 0; i < 7; ++i)
          for (unsigned int j = 0; j < 7; ++j)
            worst =
              std::max(worst, std::abs(model.frequency_response(i, j, 2. * M_PI * f) - g(i, j)) /
                                g.cwiseAbs().maxCoeff());
      }
    return worst;
  }
} // namespace

BOOST_AUTO_TEST_CASE(poles_and_residues_give_the_closed_form)
{
  auto s             = known_synthesis();
  s.damping_ratio(7) = 1.3; // critical damping is the next case
  const auto model   = synthesis::to_patch_model(s, Eigen::MatrixXd(), 4000.);
  BOOST_TEST(model.is_rank_one());
  // Two real poles for each mode with xi >= 1, one pair for the others.
  BOOST_TEST(model.n_terms() == 11u);
  const double worst = pole_residue_error(s, model);
  BOOST_TEST_MESSAGE("pole-residue form against the closed form: " << worst);
  BOOST_TEST(worst < 3e-14);
  // Exactly critical damping is taken as xi = 1 + 1e-6 (two real poles
  // 2.8e-3 w apart): a relative change of order 1e-6 in that mode.
  const auto   s1 = known_synthesis();
  const double nudged =
    pole_residue_error(s1, synthesis::to_patch_model(s1, Eigen::MatrixXd(), 4000.));
  BOOST_TEST_MESSAGE("with a critically damped mode: " << nudged);
  BOOST_TEST(nudged < 1e-7);
  // The static compliance: G_r + sum phi phi^T / w^2.
  const Eigen::MatrixXd G0 = s.at(0.).real();
  CHECK_BOUND((model.static_compliance() - G0).cwiseAbs().maxCoeff() / G0.cwiseAbs().maxCoeff(),
              2e-15);
}

BOOST_AUTO_TEST_CASE(negative_damping_and_zero_frequency_are_refused)
{
  auto s             = known_synthesis();
  s.damping_ratio(2) = -0.01;
  BOOST_CHECK_THROW(synthesis::to_patch_model(s, Eigen::MatrixXd(), 4000.), NumericalError);
  s                 = known_synthesis();
  s.frequency_hz(0) = 0.;
  BOOST_CHECK_THROW(synthesis::to_patch_model(s, Eigen::MatrixXd(), 4000.), NumericalError);
}

namespace
{
  /// The rank-one recursion of @p model (shapes kept in @p precision)
  /// against its full form (every residue a dense matrix) and the direct
  /// convolution sum over 400 steps of loads linear over each step, some
  /// with impulses and some whose start is not the last step's end: the
  /// largest differences of the displacement histories over their size,
  /// and the one-step influences' against each other. Fourth: a second
  /// rank-one recursion asked for the displacement alone (history_u, which
  /// drops the velocity from its steps), its u against the first's, and its
  /// velocity at the end, summed again from its states, against the first's.
  std::array<double, 4>
  recursion_differences(
    const modal::PatchModel          &model,
    const convolution::ShapePrecision precision = convolution::ShapePrecision::double_precision)
  {
    const auto         full = synthesis::full_form(model);
    const double       dt   = 2e-5;
    const unsigned int n = 400, P = model.n_points();
    auto               fast   = convolution::make_modal_patch_convolution(model, dt, 2, precision);
    auto               fast_u = convolution::make_modal_patch_convolution(model, dt, 2, precision);
    auto               dense  = convolution::make_modal_patch_convolution(full, dt, 1);
    auto               direct = convolution::make_direct_patch_convolution(model, dt, n + 1);
    // The one-step influences, each against its own size. Without G_r the
    // displacement's response to the impulse at the step's end (u[3]) is zero:
    // exactly in the full form, to round-off in the rank-one form (2.5e-20
    // against u[0]'s 7e-6 with FMA), so a zero one is measured against the
    // largest of its kind.
    double                             influence = 0.;
    const convolution::PatchInfluence &a = fast->influence(), &b = dense->influence();
    const auto                         relative = [](const std::array<Eigen::MatrixXd, 4> &x,
                             const std::array<Eigen::MatrixXd, 4> &y, const unsigned int g) {
      double largest = 0.;
      for (const auto &m : y)
        largest = std::max(largest, m.cwiseAbs().maxCoeff());
      const double own = y[g].cwiseAbs().maxCoeff();
      return (x[g] - y[g]).cwiseAbs().maxCoeff() / (own > 0. ? own : largest);
    };
    for (unsigned int g = 0; g < 4; ++g)
      influence = std::max({influence, relative(a.u, b.u, g), relative(a.v, b.v, g)});
    BOOST_TEST(fast->influence().instantaneous);

    std::mt19937                           random(3);
    std::uniform_real_distribution<double> u(0., 100.);
    Eigen::VectorXd                        q0(P);
    for (unsigned int p = 0; p < P; ++p)
      q0(p) = u(random);
    for (auto *c : {fast.get(), fast_u.get(), dense.get(), direct.get()})
      c->preload(q0);
    double          worst_dense = 0., worst_direct = 0., worst_u = 0., size = 0.;
    Eigen::VectorXd previous = q0, u1(P), v1(P);
    for (unsigned int step = 0; step < n; ++step)
      {
        Eigen::VectorXd u2(P), v2(P), u3(P), v3(P), u4(P);
        fast->history(u1, v1);
        dense->history(u2, v2);
        direct->history(u3, v3);
        fast_u->history_u(u4);
        size         = std::max(size, u2.cwiseAbs().maxCoeff());
        worst_dense  = std::max(worst_dense, (u1 - u2).cwiseAbs().maxCoeff());
        worst_direct = std::max(worst_direct, (u1 - u3).cwiseAbs().maxCoeff());
        worst_u      = std::max(worst_u, (u1 - u4).cwiseAbs().maxCoeff());
        convolution::PatchLoad load(P);
        Eigen::VectorXd        next(P);
        for (unsigned int p = 0; p < P; ++p)
          next(p) = u(random);
        // The start is the last end (its modal forces reused), except every
        // 53rd step, and a load at rest (every 41st step) is zero.
        load.component[1] = step % 53 == 7 ? Eigen::VectorXd(0.5 * previous) : previous;
        load.component[2] = step % 41 == 11 ? Eigen::VectorXd::Zero(P) : next;
        if (step % 37 == 0)
          load.component[0] = 1e-4 * load.component[2];
        previous = load.component[2];
        for (auto *c : {fast.get(), fast_u.get(), dense.get(), direct.get()})
          c->advance(load);
      }
    Eigen::VectorXd u4(P), v4(P);
    fast->history(u1, v1);
    fast_u->history(u4, v4);
    const double velocity = (v1 - v4).cwiseAbs().maxCoeff() / v1.cwiseAbs().maxCoeff();
    return {
      {worst_dense / size, worst_direct / size, influence, std::max(worst_u / size, velocity)}};
  }
} // namespace

BOOST_AUTO_TEST_CASE(rank_one_recursion_equals_the_full_form_and_the_direct_sum)
{
  // The undamped mode cannot be convolved (Re lambda = 0): give it a little damping.
  auto s             = known_synthesis();
  s.damping_ratio(3) = 0.01;
  const auto d = recursion_differences(synthesis::to_patch_model(s, Eigen::MatrixXd(), 4000.));
  BOOST_TEST_MESSAGE("rank-one recursion against the full form "
                     << d[0] << ", against the direct sum " << d[1] << "; influences " << d[2]
                     << "; displacement alone, then the velocity " << d[3]);
  BOOST_TEST(d[0] < 2e-14);
  BOOST_TEST(d[1] < 7e-14);
  BOOST_TEST(d[2] < 2e-13);
  BOOST_TEST(d[3] < 1e-14);
}

BOOST_AUTO_TEST_CASE(time_blocks_equal_the_step_by_step_update)
{
  // The displacement of a continuous force is updated in time blocks
  // (convolution/mode_patch_convolution.h): free responses summed once per block
  // and lag kernels for the loads inside it. Against the step-by-step update
  // (block length 1) and the direct convolution sum, over 300 steps of a
  // force that is continuous, with points leaving and entering contact, the
  // velocity asked for once (the block is left and entered again) and one
  // load whose start is not the last end. 150 modes with complex shapes
  // (some over-critical: real poles) and a relaxing residual: 420 terms,
  // split over two threads.
  const unsigned int                     P = 12, m = 150, n = 300;
  std::mt19937                           random(5);
  std::uniform_real_distribution<double> u(0., 1.);
  synthesis::ModeSynthesis               s;
  s.frequency_hz.resize(m);
  s.damping_ratio.resize(m);
  s.shapes.resize(m, P);
  s.shapes_imag.resize(m, P);
  for (unsigned int k = 0; k < m; ++k)
    {
      s.frequency_hz(k)  = 100. + 7900. * u(random);
      s.damping_ratio(k) = k % 29 == 3 ? 1.4 : 0.005 + 0.1 * u(random);
      for (unsigned int p = 0; p < P; ++p)
        {
          s.shapes(k, p)      = 0.3 * (u(random) - 0.5);
          s.shapes_imag(k, p) = k % 29 == 3 ? 0. : 0.05 * (u(random) - 0.5);
        }
    }
  Eigen::MatrixXd B = Eigen::MatrixXd::Random(P, P);
  s.instantaneous   = 1e-7 * B * B.transpose();
  for (unsigned int p = 0; p < P; ++p)
    s.points.push_back({{0.01 * p, 0.002 * p, 0.27}});
  s.wavenumber          = std::vector<unsigned int>(m, 0);
  s.residual_relaxation = 5e-6;
  const auto   model    = synthesis::to_patch_model(s, Eigen::MatrixXd(), 1e4);
  const double dt       = 1.5e-5;
  using convolution::ShapePrecision;
  auto step =
    convolution::make_rank_one_patch_convolution(model, dt, 2, ShapePrecision::double_precision, 1);
  auto direct = convolution::make_direct_patch_convolution(model, dt, n + 1);
  std::vector<std::unique_ptr<convolution::PatchConvolution>> blocked;
  for (const unsigned int J : {4u, 8u, 16u})
    blocked.push_back(convolution::make_rank_one_patch_convolution(
      model, dt, 2, ShapePrecision::double_precision, J));
  auto            single = convolution::make_rank_one_patch_convolution(model, dt, 2,
                                                                        ShapePrecision::single_precision, 16);
  Eigen::VectorXd q0     = Eigen::VectorXd::Constant(P, 50.);
  for (auto *c : {step.get(), direct.get(), single.get()})
    c->preload(q0);
  for (auto &c : blocked)
    c->preload(q0);
  double          worst_block = 0., worst_direct = 0., worst_single = 0., worst_v = 0.;
  double          size     = 0.;
  Eigen::VectorXd previous = q0, u1(P), u2(P), v1(P), v2(P);
  for (unsigned int k = 0; k < n; ++k)
    {
      const bool velocity = k == 133;
      if (velocity)
        step->history(u1, v1);
      else
        step->history_u(u1);
      direct->history(u2, v2);
      size         = std::max(size, u1.cwiseAbs().maxCoeff());
      worst_direct = std::max(worst_direct, (u1 - u2).cwiseAbs().maxCoeff());
      for (auto &c : blocked)
        {
          if (velocity)
            {
              c->history(u2, v2);
              worst_v =
                std::max(worst_v, (v1 - v2).cwiseAbs().maxCoeff() / v1.cwiseAbs().maxCoeff());
            }
          else
            c->history_u(u2);
          worst_block = std::max(worst_block, (u1 - u2).cwiseAbs().maxCoeff());
        }
      single->history_u(u2);
      worst_single = std::max(worst_single, (u1 - u2).cwiseAbs().maxCoeff());
      convolution::PatchLoad load(P);
      load.component[1] = k == 201 ? Eigen::VectorXd(0.9 * previous) : previous;
      for (unsigned int p = 0; p < P; ++p)
        load.component[2](p) = (k / 20 + p) % 3 == 0 ? 0. : 100. * u(random);
      previous = load.component[2];
      for (auto *c : {step.get(), direct.get(), single.get()})
        c->advance(load);
      for (auto &c : blocked)
        c->advance(load);
    }
  BOOST_TEST_MESSAGE("time blocks of 4, 8 and 16 steps against step by step: "
                     << worst_block / size << " (the velocity once: " << worst_v
                     << "); step by step against the direct sum " << worst_direct / size
                     << "; blocks of 16 with single-precision shapes " << worst_single / size);
  BOOST_TEST(size > 0.);
  BOOST_TEST(worst_block / size < 1e-14);
  BOOST_TEST(worst_v < 5e-15);
  BOOST_TEST(worst_direct / size < 3e-14);
  BOOST_TEST(worst_single / size < 7e-7);
  BOOST_TEST(worst_single / size > 1e-12); // the shapes are rounded: not the double path
  BOOST_CHECK_THROW(
    convolution::make_rank_one_patch_convolution(model, dt, 2, ShapePrecision::double_precision, 5),
    std::logic_error);
}

BOOST_AUTO_TEST_CASE(single_precision_shapes_follow_the_full_form_to_float_rounding)
{
  // Convolution/Shape precision = single: the shapes rounded to float (6e-8
  // of each value) and the products formed in float over 7 points. The
  // history then differs from the full form (double) by about that rounding
  // times the modes' sum: bounded here by 1e-6, twenty times float's
  // epsilon, and far below the synthesis' own error (E of 1e-3).
  auto s             = known_synthesis();
  s.damping_ratio(3) = 0.01;
  const auto model   = synthesis::to_patch_model(s, Eigen::MatrixXd(), 4000.);
  const auto d       = recursion_differences(model, convolution::ShapePrecision::single_precision);
  BOOST_TEST_MESSAGE("single-precision shapes: against the full form "
                     << d[0] << ", against the direct sum " << d[1]
                     << "; displacement alone, then the "
                     << "velocity " << d[3]);
  BOOST_TEST(d[0] < 7e-7);
  BOOST_TEST(d[1] < 7e-7);
  BOOST_TEST(d[0] > 1e-12); // the shapes are rounded: not the double path
  BOOST_TEST(d[2] < 1e-12); // the one-step influences stay those of the double model
  BOOST_TEST(d[3] < 1e-14);
}

BOOST_AUTO_TEST_CASE(complex_shapes_give_the_closed_form_and_the_same_recursion)
{
  // Modes coupled by a damping that is not proportional have complex shapes
  // psi = a + j b (synthesis/ring_modes.h): mode k contributes
  //   psi psi^T / (2 j w_d (j w - l)) - conj(psi) conj(psi)^T / (2 j w_d (j w - conj(l))).
  // That sum written out here against the synthesis and its pole-residue
  // form, then the rank-one recursion with complex shapes against the full
  // form and the direct sum.
  auto s             = known_synthesis();
  s.damping_ratio(3) = 0.01;
  s.damping_ratio(5) = 0.3; // complex shapes need xi < 1
  s.damping_ratio(7) = 0.5;
  std::mt19937                           random(11);
  std::uniform_real_distribution<double> u(-0.1, 0.1);
  s.shapes_imag.resize(s.shapes.rows(), s.shapes.cols());
  for (Eigen::Index k = 0; k < s.shapes.rows(); ++k)
    for (Eigen::Index p = 0; p < s.shapes.cols(); ++p)
      s.shapes_imag(k, p) = u(random);
  const auto model = synthesis::to_patch_model(s, Eigen::MatrixXd(), 4000.);
  double     worst = 0., worst_model = 0.;
  for (const double f : {0., 50., 119., 311., 640., 1000., 2500., 5000.})
    {
      const double     w = 2. * M_PI * f;
      Eigen::MatrixXcd g = s.instantaneous.cast<std::complex<double>>();
      for (Eigen::Index k = 0; k < s.shapes.rows(); ++k)
        {
          const double               wk = 2. * M_PI * s.frequency_hz(k), xi = s.damping_ratio(k);
          const double               wd = wk * std::sqrt(1. - xi * xi);
          const std::complex<double> l(-xi * wk, wd), j(0., 1.);
          Eigen::VectorXcd           psi = s.shapes.row(k).transpose().cast<std::complex<double>>();
          psi.imag()                     = s.shapes_imag.row(k).transpose();
          g +=
            psi * psi.transpose() / (2. * j * wd * (j * w - l)) -
            psi.conjugate() * psi.conjugate().transpose() / (2. * j * wd * (j * w - std::conj(l)));
        }
      const double size = g.cwiseAbs().maxCoeff();
      worst             = std::max(worst, (s.at(w) - g).cwiseAbs().maxCoeff() / size);
      for (unsigned int i = 0; i < 7; ++i)
        for (unsigned int jj = 0; jj < 7; ++jj)
          worst_model =
            std::max(worst_model, std::abs(model.frequency_response(i, jj, w) - g(i, jj)) / size);
    }
  BOOST_TEST_MESSAGE("complex shapes: synthesis against the sum written out "
                     << worst << ", pole-residue form " << worst_model);
  BOOST_TEST(worst < 3e-14);
  BOOST_TEST(worst_model < 5e-15);
  CHECK_BOUND((model.static_compliance() - s.at(0.).real()).cwiseAbs().maxCoeff() /
                s.at(0.).cwiseAbs().maxCoeff(),
              2e-15);
  const auto d = recursion_differences(model);
  BOOST_TEST_MESSAGE("complex shapes: rank-one recursion against the full form "
                     << d[0] << ", against the direct sum " << d[1] << "; influences " << d[2]
                     << "; displacement alone, then the velocity " << d[3]);
  BOOST_TEST(d[0] < 2e-14);
  BOOST_TEST(d[1] < 4e-14);
  BOOST_TEST(d[2] < 5e-15);
  BOOST_TEST(d[3] < 1e-14);
  const auto single = recursion_differences(model, convolution::ShapePrecision::single_precision);
  BOOST_TEST_MESSAGE("complex shapes in single precision: against the full form " << single[0]);
  BOOST_TEST(single[0] < 7.5e-7);
  BOOST_TEST(single[3] < 1e-14);
  // A complex shape on an over-critical mode has no pole pair: refused.
  s.damping_ratio(2) = 1.5;
  BOOST_CHECK_THROW(synthesis::to_patch_model(s, Eigen::MatrixXd(), 4000.), NumericalError);
}

BOOST_AUTO_TEST_CASE(modes_beyond_the_band_interpolated_equal_the_sum_at_every_line)
{
  // modes_at_lines() interpolates the part of the modes whose poles lie
  // well beyond the highest line: 400 modes from 60 Hz to 20 kHz (half of
  // them above 1.25 times the highest line), real and then complex shapes,
  // among them an undamped mode and modes just below and above the split,
  // and over-critical modes high in w_k whose slow pole j w_k (xi -
  // sqrt(xi^2 - 1)) lies within the band (they must be summed, not
  // interpolated). Against modes_at() at each of the 257 lines.
  const unsigned int                     P = 6, m = 400, lines = 257;
  const double                           df = 15.625;
  std::mt19937                           random(19);
  std::uniform_real_distribution<double> u(-1., 1.);
  synthesis::ModeSynthesis               s;
  s.frequency_hz       = Eigen::VectorXd::LinSpaced(m, 60., 20000.);
  s.damping_ratio      = Eigen::VectorXd::Constant(m, 0.02);
  s.frequency_hz(150)  = 4000. * 1.249; // just below the split, lightly damped
  s.frequency_hz(151)  = 4000. * 1.251; // just above it
  s.damping_ratio(200) = 0.;            // undamped, above the band
  s.damping_ratio(300) = 40.;           // 12 kHz, its slow pole at about 150 Hz
  s.damping_ratio(390) = 3.;            // over-critical, both poles beyond the band
  std::sort(s.frequency_hz.data(), s.frequency_hz.data() + m);
  s.shapes.resize(m, P);
  for (unsigned int k = 0; k < m; ++k)
    for (unsigned int p = 0; p < P; ++p)
      s.shapes(k, p) = 0.3 * u(random);
  for (const bool complex_shapes : {false, true})
    {
      if (complex_shapes)
        {
          s.damping_ratio(300) = 0.9; // complex shapes need xi < 1
          s.damping_ratio(390) = 0.5;
          s.shapes_imag        = 0.1 * Eigen::MatrixXd::NullaryExpr(m, P, [&] {
                            return u(random);
                          });
        }
      const auto interpolated = s.modes_at_lines(df, lines);
      BOOST_TEST_REQUIRE(interpolated.size() == lines);
      double worst = 0.;
      for (unsigned int l = 0; l < lines; ++l)
        {
          const Eigen::MatrixXcd g = s.modes_at(2. * M_PI * df * l);
          worst =
            std::max(worst, (interpolated[l] - g).cwiseAbs().maxCoeff() / g.cwiseAbs().maxCoeff());
        }
      BOOST_TEST_MESSAGE("modes beyond the band interpolated, "
                         << (complex_shapes ? "complex" : "real")
                         << " shapes: largest difference from the sum at each line " << worst);
      BOOST_TEST(worst < 1e-13);
    }
  // Too few lines to gain: every mode summed at every line, the same figures.
  const auto few = s.modes_at_lines(df * 64., 5);
  for (unsigned int l = 0; l < 5; ++l)
    BOOST_TEST((few[l] - s.modes_at(2. * M_PI * df * 64. * l)).cwiseAbs().maxCoeff() == 0.);
}

BOOST_AUTO_TEST_CASE(a_relaxing_residual_is_a_kelvin_voigt_solid)
{
  // With beta_r > 0 the residual is G_r / (1 + j w beta_r): n_p real poles
  // from G_r's eigenvectors. Against the closed form, and in time against
  // the exact solution of w + beta w' = q, u = G_r w, for the residual alone
  // under a ramp to a constant load (a step-wise linear load: exact).
  auto s                = known_synthesis();
  s.damping_ratio(7)    = 1.3;
  s.residual_relaxation = 7e-6;
  const auto model      = synthesis::to_patch_model(s, Eigen::MatrixXd(), 4000.);
  BOOST_TEST(model.n_terms() == 11u + 7u);
  BOOST_TEST(model.instantaneous.size() == 0);
  const double worst = pole_residue_error(s, model);
  BOOST_TEST_MESSAGE("relaxing residual, pole-residue form against the closed form: " << worst);
  BOOST_TEST(worst < 3e-14);

  synthesis::ModeSynthesis residual;
  residual.frequency_hz.resize(0);
  residual.damping_ratio.resize(0);
  residual.shapes.resize(0, 7);
  residual.instantaneous       = s.instantaneous;
  residual.points              = s.points;
  residual.residual_relaxation = s.residual_relaxation;
  const auto         alone     = synthesis::to_patch_model(residual, Eigen::MatrixXd(), 4000.);
  const double       dt = 4e-6, beta = residual.residual_relaxation, T = 5 * dt;
  const unsigned int P           = 7;
  auto               convolution = convolution::make_modal_patch_convolution(alone, dt, 1);
  BOOST_TEST(convolution->influence().instantaneous);
  Eigen::VectorXd Q(P);
  for (unsigned int p = 0; p < P; ++p)
    Q(p) = 100. * (p + 1);
  const auto load_at = [&](const double t) {
    return std::min(t / T, 1.) * Q;
  };
  const auto exact = [&](const double t) -> Eigen::VectorXd {
    if (t <= T)
      return residual.instantaneous * (t - beta * (1. - std::exp(-t / beta))) / T * Q;
    const Eigen::VectorXd wT = (T - beta * (1. - std::exp(-T / beta))) / T * Q;
    return residual.instantaneous * (Q + (wT - Q) * std::exp(-(t - T) / beta));
  };
  double difference = 0., size = 0.;
  for (unsigned int n = 0; n < 40; ++n)
    {
      Eigen::VectorXd uh(P), vh(P);
      convolution->history(uh, vh);
      convolution::PatchLoad load(P);
      load.component[1]         = load_at(n * dt);
      load.component[2]         = load_at((n + 1) * dt);
      const auto           &psi = convolution->influence();
      const Eigen::VectorXd u   = uh + psi.u[1] * load.component[1] + psi.u[2] * load.component[2];
      const Eigen::VectorXd ref = exact((n + 1) * dt);
      difference                = std::max(difference, (u - ref).cwiseAbs().maxCoeff());
      size                      = std::max(size, ref.cwiseAbs().maxCoeff());
      convolution->advance(load);
    }
  BOOST_TEST_MESSAGE("relaxing residual in time against the exact solution: " << difference / size);
  BOOST_TEST(difference < 1e-14 * size);
}

BOOST_AUTO_TEST_CASE(modal_model_file_round_trip)
{
  const auto dir        = test::scratch_directory("mode_model");
  const auto file       = dir / "modal_model.h5";
  auto       s          = known_synthesis();
  s.residual_relaxation = 3.5e-6;
  base::ParameterRecord record;
  synthesis::write_modal_model(file, s, record, "key 1");
  BOOST_TEST(synthesis::read_modal_model_key(file.string()) == "key 1");
  const auto r = synthesis::read_modal_model(file.string());
  BOOST_TEST((r.frequency_hz - s.frequency_hz).cwiseAbs().maxCoeff() == 0.);
  BOOST_TEST((r.damping_ratio - s.damping_ratio).cwiseAbs().maxCoeff() == 0.);
  BOOST_TEST((r.shapes - s.shapes).cwiseAbs().maxCoeff() == 0.);
  BOOST_TEST((r.instantaneous - s.instantaneous).cwiseAbs().maxCoeff() == 0.);
  BOOST_TEST(r.residual_relaxation == s.residual_relaxation);
  BOOST_TEST(r.wavenumber == s.wavenumber);
  BOOST_TEST(r.points == s.points);
  BOOST_REQUIRE(r.dispersion.frequency_hz.size() == 1u);
  BOOST_TEST((r.dispersion.frequency_hz[0] - s.dispersion.frequency_hz[0]).norm() == 0.);
  // A file without one of its datasets has no key, and reading it is refused by name.
  {
    dealii::HDF5::File h5((dir / "partial.h5").string(),
                          dealii::HDF5::File::FileAccessMode::create);
    h5.create_dataset<double>("frequency_hz", {1}).write(std::vector<double>{1.});
    h5.set_attribute("stage_key", std::string("key 1"));
  }
  BOOST_TEST(synthesis::read_modal_model_key((dir / "partial.h5").string()).empty());
  BOOST_CHECK_EXCEPTION(synthesis::read_modal_model((dir / "partial.h5").string()), InputError,
                        [](const InputError &e) {
                          return std::string(e.what()).find("partial.h5") != std::string::npos;
                        });
}

BOOST_AUTO_TEST_SUITE_END()

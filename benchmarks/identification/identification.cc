// Identification of a whole Green's matrix: 120 x 120 = 14,400 FRFs of 1001
// lines (0 to 4 kHz), up to N_m = 60 modes each, on all threads. Prints the
// total time and the statistics of E (Eq. 50), beside the error of the
// identified poles against the modes the FRFs were built from.
//
//   identification [--quick] [--output DIR]

#include <greentread/modal/identification.h>

#include <algorithm>
#include <chrono>
#include <cstdio>

#include "benchmark_options.h"
#include "synthetic_green.h"

using namespace greentread;

int
main(int argc, char **argv)
{
  dealii::Utilities::MPI::MPI_InitFinalize mpi(argc, argv, dealii::numbers::invalid_unsigned_int);
  const auto                               options = benchmark::parse(argc, argv, "identification");
  const benchmark::SyntheticGreen          green;
  const unsigned int                       n_points = options.quick ? 6 : green.points.size();
  const unsigned int                       n_frf    = n_points * n_points;

  modal::IdentificationParameters parameters; // defaults: N_max 60, eq7, bands auto
  parameters.compare_models = false;

  std::printf("Identification benchmark: %u x %u = %u FRFs, 1001 lines to 4 kHz, N_max = %u, "
              "%u threads.\nThe FRFs are sums of %zu known modes (%u below 4 kHz).\n",
              n_points, n_points, n_frf, parameters.max_modes, dealii::MultithreadInfo::n_threads(),
              green.frequency.size(),
              unsigned(std::count_if(green.frequency.begin(), green.frequency.end(), [](double f) {
                return f < 4000.;
              })));

  // The Green's matrix in memory, as the periodic stage would hand it over
  // (not timed).
  base::FrequencyResponseMatrix matrix;
  matrix.df      = 4.;
  matrix.n_lines = 1001;
  matrix.points.assign(green.points.begin(), green.points.begin() + n_points);
  matrix.values.resize(std::size_t(matrix.n_lines) * n_points * n_points);
  std::vector<std::pair<unsigned int, unsigned int>> pairs;
  for (unsigned int i = 0; i < n_points; ++i)
    for (unsigned int j = 0; j < n_points; ++j)
      {
        pairs.emplace_back(i, j);
        if (j < i)
          continue; // g_ji = g_ij: the model is symmetric
        const auto frf = green.frf(i, j, matrix.df, matrix.n_lines);
        for (unsigned int k = 0; k < matrix.n_lines; ++k)
          matrix.values[(std::size_t(k) * n_points + i) * n_points + j] =
            matrix.values[(std::size_t(k) * n_points + j) * n_points + i] = frf.values[k];
      }

  const auto   start   = std::chrono::steady_clock::now();
  std::size_t  reused  = 0;
  const auto   results = modal::identify_pairs(matrix, pairs, parameters, reused);
  const double seconds =
    std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  const std::size_t identified = n_frf - reused;

  // E statistics, and the poles against the true ones below 0.9 f_max.
  std::vector<double> errors, modes;
  unsigned int        zoomed = 0;
  for (const auto &r : results)
    {
      errors.push_back(r.error);
      modes.push_back(r.n_modes);
      zoomed += r.n_bands > 1;
    }
  // The largest relative error of an identified pole of the first @p count
  // FRFs' @p found models. A mode is identifiable in an FRF where it carries
  // weight: at least 1% of the FRF's L1 norm over the band.
  const auto pole_error_of = [&](const std::vector<modal::Identification> &found,
                                 const std::size_t                         count) {
    double largest = 0.;
    for (std::size_t n = 0; n < count; ++n)
      {
        const auto truth = green.model(n / n_points, n % n_points);
        const auto frf   = greentread::modal::sample(truth, 4., 1001);
        for (const auto &t : truth.terms())
          {
            if (t.lambda.imag() > 0.9 * 2. * M_PI * 4000.)
              continue;
            if (benchmark::SyntheticGreen::weight(t, frf) < 0.01)
              continue;
            double best = INFINITY;
            for (const auto &f : found[n].model.terms())
              best = std::min(best, std::abs(f.lambda - t.lambda) / std::abs(t.lambda));
            largest = std::max(largest, best);
          }
      }
    return largest;
  };
  const double pole_error = pole_error_of(results, std::min<std::size_t>(n_frf, 200));

  // Beside it, the optional refinement of the poles (Identification/Pole
  // refinement = least squares) on the first FRFs, one at a time.
  const std::size_t first  = std::min<std::size_t>(n_frf, options.quick ? 6 : 24);
  auto              refine = parameters;
  refine.polish_poles      = true;
  std::vector<modal::Identification> refined;
  const auto                         refine_start = std::chrono::steady_clock::now();
  for (std::size_t n = 0; n < first; ++n)
    refined.push_back(modal::identify(
      green.frf(pairs[n].first, pairs[n].second, matrix.df, matrix.n_lines), refine));
  const double refine_seconds =
    std::chrono::duration<double>(std::chrono::steady_clock::now() - refine_start).count();
  std::vector<modal::Identification> plain;
  const auto                         plain_start = std::chrono::steady_clock::now();
  for (std::size_t n = 0; n < first; ++n)
    plain.push_back(modal::identify(
      green.frf(pairs[n].first, pairs[n].second, matrix.df, matrix.n_lines), parameters));
  const double plain_seconds =
    std::chrono::duration<double>(std::chrono::steady_clock::now() - plain_start).count();
  const auto largest_error = [](const std::vector<modal::Identification> &found) {
    double e = 0.;
    for (const auto &r : found)
      e = std::max(e, r.error);
    return e;
  };
  const std::size_t worst = std::max_element(results.begin(), results.end(),
                                             [](const auto &a, const auto &b) {
                                               return a.error < b.error;
                                             }) -
                            results.begin();
  // The worst FRF again with an upper residual: how much of its E is the
  // stiffness left in the band by the modes above it.
  auto with_residual           = parameters;
  with_residual.upper_residual = true;
  const auto worst_again =
    modal::identify(green.frf(pairs[worst].first, pairs[worst].second, 4., 1001), with_residual);
  std::sort(errors.begin(), errors.end());
  std::sort(modes.begin(), modes.end());
  const auto pct = [&](double q) {
    return errors[std::size_t(q * (errors.size() - 1))];
  };
  std::printf(
    "\nTime: %.1f s for %u FRFs: %zu identified (%.2f ms of wall time each, %u threads), %zu the "
    "same as their reciprocal g_ji and reused.\nWithout reciprocity all %u would take "
    "about %.0f s.\n",
    seconds, n_frf, identified, 1e3 * seconds / identified, dealii::MultithreadInfo::n_threads(),
    reused, n_frf, seconds / identified * n_frf);
  std::printf("E (Eq. 50): min %.3g, median %.3g, 95%% %.3g, max %.3g\n", errors.front(), pct(0.5),
              pct(0.95), errors.back());
  std::printf("Worst: g_%u,%u with E = %.3g (%.3g with an upper residual term)\n",
              pairs[worst].first, pairs[worst].second, results[worst].error, worst_again.error);
  std::printf("N_m: min %.0f, median %.0f, max %.0f; zoom LSCE used for %u FRFs\n", modes.front(),
              modes[modes.size() / 2], modes.back(), zoomed);
  std::printf("Largest relative error of an identified pole, over the modes below 3.6 kHz that\n"
              "carry at least 1%% of an FRF (first 200 FRFs): %.3g\n",
              pole_error);
  std::printf("Target: under 60 s on 2 cores.\n");
  std::printf(
    "\nThe first %zu FRFs one at a time, LSCE alone against LSCE with the pole refinement:\n"
    "  LSCE alone:       %8.2f ms per FRF, largest E %.3g, largest pole error %.3g\n"
    "  with refinement:  %8.2f ms per FRF, largest E %.3g, largest pole error %.3g\n",
    first, 1e3 * plain_seconds / first, largest_error(plain), pole_error_of(plain, first),
    1e3 * refine_seconds / first, largest_error(refined), pole_error_of(refined, first));

  base::AtomicFile csv(options.output / "identification.csv");
  csv.stream()
    << "frfs,identified,seconds,ms_per_frf_identified,E_min,E_median,E_p95,E_max,max_pole_error\n"
    << n_frf << ',' << identified << ',' << seconds << ',' << 1e3 * seconds / identified << ','
    << errors.front() << ',' << pct(0.5) << ',' << pct(0.95) << ',' << errors.back() << ','
    << pole_error << '\n';
  csv.commit();
  // Against the known synthetic modes: the identified poles (2.44e-10 with
  // --quick, 4.2e-10 over the full matrix; bound 3x the quick figure) and
  // the median E (1.81% with --quick, 1.16% in full).
  benchmark::Checks checks("identification");
  checks.at_most("largest pole error against the known modes", pole_error, 7.5e-10);
  checks.at_most("median E against the synthetic FRFs", pct(0.5), 0.055);
  return checks.exit_code();
}

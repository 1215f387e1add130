// Is the main job's ring converged? The main job (the default scene: the
// section's circumferential harmonics on the quartic 8 mm section) against
// the same job on the section twice as fine ('Mesh size' 4 mm), the test of
// a converged default. Everything else (roads, speeds,
// contact grid, harmonic tolerance, cut-off) is the main job's; the finer
// section's direct lines are every 1 kHz (they fit nothing: with the ring's
// own modes they only check the synthesis).
//
// It prints, after both runs:
// - each run's time;
// - the Green's functions at the lines both sections have (0 to 4 kHz every
//   1 kHz): the centre driving point and its transfers to the next point
//   along x and across y, both and their difference (the static ones must be
//   within 2%), and E of Eq. (50) between the sections over every pair of the
//   patch (within 5%);
// - for every road and speed, the stress at the patch centre and the total
//   force: the highest one-third-octave band, the largest level difference
//   in the bands from 100 Hz to 5 kHz within 20 dB of the highest (within
//   1 dB), and the largest in the bands below that;
// and plots both sections' spectra of every run (converged_ring_<run>.png).
//
// The runs write to DIR/default and DIR/converged (DIR from --output) and,
// like the program, reuse their saved stages there when the inputs have not
// changed: copy a main job's output directory to DIR/default to skip its
// Green's functions and modes. --part 1 only runs them; --part 2 only
// compares what DIR/default and DIR/converged hold (the two runs made
// otherwise, for instance by build/greentread with the same settings and
// 'Output directory' set). --quick runs a quadratic 32 mm section against a
// 16 mm one on one road and speed (a smoke run).
//
//   converged_ring [--quick] [--output DIR] [--part 1|2]

#include <greentread/base/blas_kernels.h>
#include <greentread/base/exceptions.h>
#include <greentread/base/frequency_response.h>
#include <greentread/base/output.h>
#include <greentread/base/parameters.h>
#include <greentread/base/plot.h>
#include <greentread/base/revision.h>
#include <greentread/config.h>
#include <greentread/scenes/scene.h>

#include <algorithm>
#include <array>
#include <cctype>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <map>
#include <string>
#include <vector>

#include "benchmark_options.h"

using namespace greentread;

namespace
{
  struct Ring
  {
    std::string              name;
    std::string              title;
    std::vector<std::string> settings;
  };

  /// One run of the road scene with @p settings (and @p shared) writing to
  /// @p directory; its wall time [s].
  double
  run_scene(const std::filesystem::path    &directory,
            const std::vector<std::string> &settings,
            const std::vector<std::string> &shared)
  {
    dealii::ParameterHandler prm;
    scenes::declare_parameters(prm);
    base::apply_override(prm, "Output directory=" + directory.string());
    base::apply_override(prm, "Geometry/Geometry file=" GREENTREAD_SOURCE_DIR
                              "/geometry/tyre_165_65_r13.geo");
    for (const auto &s : shared)
      base::apply_override(prm, s);
    for (const auto &s : settings)
      base::apply_override(prm, s);
    const auto start = std::chrono::steady_clock::now();
    scenes::create_scene(prm)->run();
    return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  }

  /// band [Hz] -> level [dB] of a spectrum CSV of the road scene: the
  /// column its header names level_dB, whatever columns the file holds
  /// besides (standard errors, each band's run, the error bars).
  std::map<int, double>
  read_levels(const std::filesystem::path &file)
  {
    std::ifstream in(file);
    if (!in)
      throw InputError("cannot read '" + file.string() + "'");
    const auto fields_of = [](const std::string &line) {
      std::vector<std::string> fields;
      std::size_t              start = 0;
      for (std::size_t comma; (comma = line.find(',', start)) != std::string::npos;
           start = comma + 1)
        fields.push_back(line.substr(start, comma - start));
      fields.push_back(line.substr(start));
      return fields;
    };
    std::map<int, double>    levels;
    std::vector<std::string> header;
    std::size_t              level = 0;
    std::string              line;
    while (std::getline(in, line))
      if (header.empty() && line.rfind("nominal_Hz,", 0) == 0)
        {
          header = fields_of(line);
          level  = std::find(header.begin(), header.end(), "level_dB") - header.begin();
          if (level == header.size())
            throw InputError("'" + file.string() + "': its header has no level_dB column");
        }
      else if (!line.empty() && std::isdigit(static_cast<unsigned char>(line[0])))
        {
          const auto fields = fields_of(line);
          if (header.empty() || fields.size() != header.size())
            throw InputError("'" + file.string() + "': line '" + line + "' does not have the " +
                             std::to_string(header.size()) + " fields of its header");
          levels[std::stoi(fields[0])] = std::stod(fields[level]);
        }
    return levels;
  }

  /// The comparison of one spectrum on two sections: the highest band of the
  /// finer one, and the largest |a - b| over the bands from 100 Hz to 5 kHz
  /// within 20 dB of it ([0], the test) and over the other bands ([1]).
  struct SpectrumDifference
  {
    std::pair<int, double> highest    = {0, -1e300};
    std::array<double, 2>  worst      = {{0., 0.}};
    std::array<int, 2>     worst_band = {{0, 0}};
  };

  SpectrumDifference
  compare_levels(const std::map<int, double> &coarse, const std::map<int, double> &fine)
  {
    SpectrumDifference d;
    for (const auto &[band, level] : fine)
      if (level > d.highest.second)
        d.highest = {band, level};
    for (const auto &[band, level] : fine)
      {
        const auto other = coarse.find(band);
        if (other == coarse.end())
          continue;
        const unsigned int kind =
          band >= 100 && band <= 5000 && level >= d.highest.second - 20. ? 0 : 1;
        if (std::abs(level - other->second) > d.worst[kind])
          {
            d.worst[kind]      = std::abs(level - other->second);
            d.worst_band[kind] = band;
          }
      }
    return d;
  }

  /// The static centre functions' and E's largest differences [relative].
  struct GreenDifferences
  {
    double static_worst = 0., E_worst = 0.;
  };

  /// The Green's functions of both rings at the lines they share.
  GreenDifferences
  compare_green(const std::filesystem::path &coarse_file, const std::filesystem::path &fine_file)
  {
    const auto         coarse = base::read_green_hdf5(coarse_file.string());
    const auto         fine   = base::read_green_hdf5(fine_file.string());
    const unsigned int P      = fine.n_points();
    if (coarse.n_points() != P)
      throw InputError("'" + coarse_file.string() + "' has " + std::to_string(coarse.n_points()) +
                       " contact points, '" + fine_file.string() + "' " + std::to_string(P) +
                       "; allowed: the same patch on both rings");
    for (unsigned int p = 0; p < P; ++p)
      if (std::abs(coarse.points[p][0] - fine.points[p][0]) > 1e-9 ||
          std::abs(coarse.points[p][1] - fine.points[p][1]) > 1e-9)
        throw InputError("contact point " + std::to_string(p) + " of '" + coarse_file.string() +
                         "' is not where '" + fine_file.string() +
                         "' has it; allowed: the same patch on both rings");
    // Every line of the sparser grid must be a line of the other.
    const bool         fine_sparser = fine.df >= coarse.df;
    const double       df           = std::max(fine.df, coarse.df);
    const double       ratio        = df / std::min(fine.df, coarse.df);
    const unsigned int step         = static_cast<unsigned int>(std::lround(ratio));
    if (std::abs(ratio - step) > 1e-9)
      throw InputError("the frequency steps of '" + coarse_file.string() + "' and '" +
                       fine_file.string() + "' (" + std::to_string(coarse.df) + " and " +
                       std::to_string(fine.df) +
                       " Hz) share no lines; allowed: one a whole multiple of the other");
    const unsigned int n_lines =
      std::min(fine_sparser ? fine.n_lines : (fine.n_lines - 1) / step + 1,
               fine_sparser ? (coarse.n_lines - 1) / step + 1 : coarse.n_lines);
    const auto at = [&](const base::FrequencyResponseMatrix &g, const bool sparse,
                        const unsigned int l, const unsigned int i, const unsigned int j) {
      const unsigned int k = sparse ? l : l * step;
      return g.values[(std::size_t(k) * P + i) * P + j];
    };
    // The centre point and its neighbours, as the Green's stage's 'auto' pairs.
    unsigned int ny = 1;
    while (ny < P && std::abs(fine.points[ny][0] - fine.points[0][0]) < 1e-9)
      ++ny;
    const unsigned int                                         nx     = P / ny;
    const unsigned int                                         centre = (nx / 2) * ny + ny / 2;
    const std::array<std::pair<const char *, unsigned int>, 3> pairs  = {
       {{"driving point, centre", centre},
        {"transfer along x", centre + ny},
        {"transfer across y", centre + 1}}};
    std::printf("\nGreen's functions at the lines both sections have, |g| in um/N, and the "
                "default's difference from the finer section (relative to the finer):\n\n"
                "| function | f [Hz] | default | twice as fine | difference |\n"
                "| --- | --- | --- | --- | --- |\n");
    double static_worst = 0.;
    for (const auto &[label, j] : pairs)
      for (unsigned int l = 0; l < n_lines; ++l)
        {
          const auto   gc         = at(coarse, !fine_sparser, l, centre, j);
          const auto   gf         = at(fine, fine_sparser, l, centre, j);
          const double difference = std::abs(gc - gf) / std::abs(gf);
          if (l == 0)
            static_worst = std::max(static_worst, difference);
          std::printf("| %s | %.0f | %.4g | %.4g | %.2f%% |\n", l == 0 ? label : "", l * df,
                      1e6 * std::abs(gc), 1e6 * std::abs(gf), 100. * difference);
        }
    std::printf("\nStatic centre driving point and near transfers: largest difference %.2f%% "
                "(the test: within 2%%): %s\n",
                100. * static_worst, static_worst <= 0.02 ? "met" : "NOT met");
    // E of Eq. (50), the converged ring as the reference, trapezoidal over the lines.
    std::vector<double> E;
    E.reserve(std::size_t(P) * P);
    for (unsigned int i = 0; i < P; ++i)
      for (unsigned int j = 0; j < P; ++j)
        {
          double num = 0., den = 0.;
          for (unsigned int l = 0; l < n_lines; ++l)
            {
              const double w  = (l == 0 || l + 1 == n_lines) ? 0.5 : 1.;
              const auto   gf = at(fine, fine_sparser, l, i, j);
              num += w * std::abs(at(coarse, !fine_sparser, l, i, j) - gf);
              den += w * std::abs(gf);
            }
          E.push_back(den > 0. ? num / den : 0.);
        }
    std::sort(E.begin(), E.end());
    std::printf("\nE of Eq. (50) between the sections over the %u lines 0 to %.0f Hz, all %u "
                "pairs: median %.2f%%, 90th percentile %.2f%%, worst %.2f%% (the test: within "
                "5%%): %s\n",
                n_lines, (n_lines - 1) * df, P * P, 100. * E[E.size() / 2],
                100. * E[std::min(E.size() - 1, E.size() * 9 / 10)], 100. * E.back(),
                E.back() <= 0.05 ? "met" : "NOT met");
    return {static_worst, E.back()};
  }
} // namespace



int
main(int argc, char **argv)
{
  base::use_native_blas_kernels(argv);
  dealii::Utilities::MPI::MPI_InitFinalize mpi(argc, argv, dealii::numbers::invalid_unsigned_int);
  const auto                               options = benchmark::parse(argc, argv, "converged_ring");
  if (options.part > 2)
    {
      std::fprintf(stderr,
                   "converged_ring: --part %u is not allowed; allowed: 1 (the runs), 2 "
                   "(the comparison), 0 (both)\n",
                   options.part);
      return 2;
    }
  try
    {
      std::vector<Ring>        rings;
      std::vector<std::string> shared;
      if (options.quick)
        {
          rings  = {{"default",
                     "quadratic 32 mm section",
                     {"Geometry/Mesh size=0.032", "Geometry/Element degree=2"}},
                    {"converged",
                     "quadratic 16 mm section",
                     {"Geometry/Mesh size=0.016", "Geometry/Element degree=2"}}};
          shared = {"Green's functions/Maximum frequency=2000",
                    "Green's functions/Frequency step=500",
                    "Patch model/Mode cutoff=4000",
                    "Road texture/Roads=road-A",
                    "Rolling/Speeds (kph)=90",
                    "Rolling/Distance=1.1",
                    "Contact grid/Subdivisions=2",
                    "Time stepping/Time step=1e-4",
                    "Spectra/Extend runs=false"};
        }
      else
        {
          rings = {{"default", "default section (quartic, 8 mm)", {}},
                   {"converged",
                    "section twice as fine (quartic, 4 mm)",
                    {"Geometry/Mesh size=0.004", "Green's functions/Frequency step=1000"}}};
          // Both rings over the same records: no run extends to its own errors.
          shared = {"Spectra/Extend runs=false"};
        }

      if (options.part == 0 || options.part == 1)
        {
          std::vector<double> seconds;
          for (const auto &ring : rings)
            {
              std::printf("\n=== %s ===\n", ring.title.c_str());
              std::fflush(stdout);
              seconds.push_back(run_scene(options.output / ring.name, ring.settings, shared));
            }
          std::printf("\nRun times (saved stages found in %s are reused): %s %.0f s, %s %.0f s\n",
                      options.output.c_str(), rings[0].title.c_str(), seconds[0],
                      rings[1].title.c_str(), seconds[1]);
        }
      if (options.part == 1)
        return 0;
      const auto            &a = options.output / rings[0].name;
      const auto            &b = options.output / rings[1].name;
      const GreenDifferences green =
        compare_green(a / "green_functions.h5", b / "green_functions.h5");

      std::printf("\nSpectra: the finer section's highest band, and the largest band-level "
                  "difference between the sections in the bands from 100 Hz to 5 kHz within 20 dB "
                  "of it (the test: within 1 dB) and in the other bands (stress at the patch "
                  "centre, dB re 100 Pa; total force, dB re 1 N):\n\n"
                  "| run | stress: highest band | within 20 dB | more than 20 dB down | "
                  "force: highest band | within 20 dB | more than 20 dB down |\n"
                  "| --- | --- | --- | --- | --- | --- | --- |\n");
      std::vector<std::string> runs;
      for (const auto &entry : std::filesystem::directory_iterator(b))
        {
          const std::string file = entry.path().filename().string();
          if (file.rfind("spectrum_", 0) == 0 && file.rfind("spectrum_force_", 0) != 0 &&
              entry.path().extension() == ".csv")
            runs.push_back(file.substr(9, file.size() - 13));
        }
      std::sort(runs.begin(), runs.end());
      double spectra_worst = 0.;
      for (const auto &run : runs)
        {
          const auto kind = [&](const std::string &prefix) {
            const auto d     = compare_levels(read_levels(a / (prefix + run + ".csv")),
                                              read_levels(b / (prefix + run + ".csv")));
            spectra_worst    = std::max(spectra_worst, d.worst[0]);
            std::string text = std::to_string(d.highest.first) + " Hz, " +
                               format_printf("%.1f", d.highest.second) + " dB";
            for (unsigned int r = 0; r < 2; ++r)
              text += d.worst_band[r] == 0 ? std::string(" | none") :
                                             " | " + format_printf("%.2f", d.worst[r]) + " dB (" +
                                               std::to_string(d.worst_band[r]) + " Hz)";
            return text;
          };
          std::printf("| %s | %s | %s |\n", run.c_str(), kind("spectrum_").c_str(),
                      kind("spectrum_force_").c_str());
          const auto q = [&](const std::filesystem::path &d, const std::string &kind) {
            return base::gnuplot_quote(d / ("spectrum_" + kind + run + ".csv"));
          };
          base::plot_png(
            options.output / ("converged_ring_" + run + ".png"),
            "set datafile separator ','\nset datafile commentschars '#'\nset grid\n"
            "set logscale x\nset xlabel 'one-third-octave band [Hz]'\n"
            "set ylabel 'level [dB]'\nset key bottom right\nset title '" +
              run +
              ": the default section against the one twice as fine' noenhanced\n"
              "set xrange [80:6000]\nplot " +
              q(a, "") + " skip 2 using 1:6 with linespoints lw 2 title 'stress, " +
              rings[0].title + "', " + q(b, "") +
              " skip 2 using 1:6 with linespoints lw 2 title 'stress, " + rings[1].title + "', " +
              q(a, "force_") + " skip 2 using 1:6 with linespoints lw 2 title 'force, " +
              rings[0].title + "', " + q(b, "force_") +
              " skip 2 using 1:6 with linespoints lw 2 title 'force, " + rings[1].title + "'\n",
            base::ParameterRecord{std::string("greentread ") + GREENTREAD_VERSION + " (" +
                                    base::git_revision() + "), benchmark converged_ring" +
                                    (options.quick ? " (--quick)" : ""),
                                  {}});
        }
      std::printf("\nSpectra: largest difference in the bands within 20 dB of the highest, "
                  "100 Hz to 5 kHz, over every run: %.2f dB (the test: within 1 dB): %s\n",
                  spectra_worst, spectra_worst <= 1. ? "met" : "NOT met");
      // The full run asserts the three tests of a converged default (static
      // 2%, E 5%, spectra 1 dB; measured 1.36%, 3.65%, 0.31 dB). --quick
      // compares two coarse quadratic sections, which are not converged: its
      // figures (20.05%, 124%, 7.92 dB) are deterministic and bounded 1.25x
      // above, so that a change of either section's discretisation shows.
      benchmark::Checks checks("converged_ring");
      checks.at_most("static centre functions against the finer section", green.static_worst,
                     options.quick ? 0.25 : 0.02);
      checks.at_most("worst E against the finer section", green.E_worst,
                     options.quick ? 1.55 : 0.05);
      checks.at_most("band levels within 20 dB of the highest against the finer section [dB]",
                     spectra_worst, options.quick ? 9.7 : 1.);
      return checks.exit_code();
    }
  catch (const InputError &e)
    {
      std::fprintf(stderr, "converged_ring: error: %s\n", e.what());
      return 2;
    }
  catch (const NumericalError &e)
    {
      std::fprintf(stderr, "converged_ring: error: %s\n", e.what());
      return 3;
    }
  return 0;
}

// How far does the main job's answer move when its ring is converged? The
// main job (the default scene) on the default ring, and again on the ring that
// meets issue 14's static 2% (README, "A crown at a third of the mesh size":
// 'Mesh size' 4 mm, 512 cells, 'Crown refinement=3'), with the ring's own
// modes as the patch model in both. The converged ring's Green's functions
// are solved directly only every 1 kHz (its whole patch costs about 12
// core-minutes a line): those lines give the synthesis its static residual,
// fit its relaxation β_r and measure its E. Everything else (roads, speeds,
// contact grid, cut-off) is the main job's.
//
// It prints, after both runs:
// - each run's time;
// - the Green's functions at the lines both rings have (0 to 4 kHz every
//   1 kHz): the centre driving point and its transfers to the next point
//   along x and across y, both rings and their difference, and E of Eq. (50)
//   between the rings over every pair of the patch;
// - for every road and speed, the stress at the patch centre and the total
//   force: each ring's highest one-third-octave band and the largest level
//   difference between the rings in the bands to 2 kHz and in those above
//   (to 5 kHz);
// and plots both rings' spectra of every run (converged_ring_<run>.png).
//
// The runs write to DIR/default and DIR/converged (DIR from --output) and,
// like the program, reuse their saved stages there when the inputs have not
// changed: copy a main job's output directory to DIR/default to skip its
// Green's functions and modes. --part 1 only runs them; --part 2 only
// compares what DIR/default and DIR/converged hold (the two runs made
// otherwise, for instance by build/greentread with the same settings and
// 'Output directory' set). --quick runs a 32 mm, N = 64 ring against a
// 16 mm, N = 128 one on one road and speed (a smoke run).
//
//   converged_ring [--quick] [--output DIR] [--part 1|2]

#include <greentread/base/blas_kernels.h>
#include <greentread/base/exceptions.h>
#include <greentread/base/output.h>
#include <greentread/base/parameters.h>
#include <greentread/base/plot.h>
#include <greentread/base/frequency_response.h>
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

  /// band [Hz] -> level [dB] of a spectrum CSV of the road scene.
  std::map<int, double>
  read_levels(const std::filesystem::path &file)
  {
    std::ifstream in(file);
    if (!in)
      throw InputError("cannot read '" + file.string() + "'");
    std::map<int, double> levels;
    std::string           line;
    while (std::getline(in, line))
      if (!line.empty() && std::isdigit(static_cast<unsigned char>(line[0])))
        {
          std::vector<std::string> fields;
          std::size_t              start = 0;
          for (std::size_t comma; (comma = line.find(',', start)) != std::string::npos;
               start = comma + 1)
            fields.push_back(line.substr(start, comma - start));
          fields.push_back(line.substr(start));
          if (fields.size() != 6)
            throw InputError("'" + file.string() + "': line '" + line +
                             "' does not have the 6 fields of a band spectrum");
          levels[std::stoi(fields[0])] = std::stod(fields[5]);
        }
    return levels;
  }

  /// The largest |a - b| over the bands of both, and its band, up to 2 kHz
  /// ([0]) and above ([1]); each one's highest band and level.
  struct SpectrumDifference
  {
    std::array<double, 2>                 worst      = {{0., 0.}};
    std::array<int, 2>                    worst_band = {{0, 0}};
    std::array<std::pair<int, double>, 2> highest;
  };

  SpectrumDifference
  compare_levels(const std::map<int, double> &a, const std::map<int, double> &b)
  {
    SpectrumDifference d;
    d.highest = {{{0, -1e300}, {0, -1e300}}};
    for (const auto &[band, level] : a)
      {
        if (level > d.highest[0].second)
          d.highest[0] = {band, level};
        const auto         other = b.find(band);
        const unsigned int range = band > 2000 ? 1 : 0;
        if (other != b.end() && std::abs(level - other->second) > d.worst[range])
          {
            d.worst[range]      = std::abs(level - other->second);
            d.worst_band[range] = band;
          }
      }
    for (const auto &[band, level] : b)
      if (level > d.highest[1].second)
        d.highest[1] = {band, level};
    return d;
  }

  /// The Green's functions of both rings at the lines they share.
  void
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
    std::printf("\nGreen's functions at the lines both rings have, |g| in um/N, and the default "
                "ring's difference from the converged one (relative to the converged):\n\n"
                "| function | f [Hz] | default ring | converged ring | difference |\n"
                "| --- | --- | --- | --- | --- |\n");
    for (const auto &[label, j] : pairs)
      for (unsigned int l = 0; l < n_lines; ++l)
        {
          const auto gc = at(coarse, !fine_sparser, l, centre, j);
          const auto gf = at(fine, fine_sparser, l, centre, j);
          std::printf("| %s | %.0f | %.4g | %.4g | %.1f%% |\n", l == 0 ? label : "", l * df,
                      1e6 * std::abs(gc), 1e6 * std::abs(gf),
                      100. * std::abs(gc - gf) / std::abs(gf));
        }
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
    std::printf("\nE of Eq. (50) between the rings over the %u lines 0 to %.0f Hz, all %u pairs: "
                "median %.1f%%, 90th percentile %.1f%%, worst %.1f%%\n",
                n_lines, (n_lines - 1) * df, P * P, 100. * E[E.size() / 2],
                100. * E[std::min(E.size() - 1, E.size() * 9 / 10)], 100. * E.back());
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
                     "32 mm, N = 64",
                     {"Geometry/Mesh size=0.032", "Geometry/Number of cells=64"}},
                    {"converged",
                     "16 mm, N = 128",
                     {"Geometry/Mesh size=0.016", "Geometry/Number of cells=128"}}};
          shared = {"Green's functions/Maximum frequency=2000",
                    "Green's functions/Frequency step=500",
                    "Patch model/Mode cutoff=4000",
                    "Road texture/Roads=road-A",
                    "Rolling/Speeds (kph)=90",
                    "Rolling/Distance=1.1",
                    "Contact grid/Subdivisions=2",
                    "Time stepping/Time step=1e-4"};
        }
      else
        rings = {{"default", "default ring (8 mm, N = 256)", {}},
                 {"converged",
                  "converged ring (4 mm, N = 512, Crown refinement=3)",
                  {"Geometry/Mesh size=0.004", "Geometry/Number of cells=512",
                   "Geometry/Other constants=Crown refinement=3",
                   "Green's functions/Frequency step=1000"}}};

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
      const auto &a = options.output / rings[0].name;
      const auto &b = options.output / rings[1].name;
      compare_green(a / "green_functions.h5", b / "green_functions.h5");

      std::printf("\nSpectra, each ring's highest band and the largest band-level difference "
                  "between the rings, in the bands to 2 kHz and above (stress at the patch "
                  "centre, dB re 100 Pa; total force, dB re 1 N):\n\n"
                  "| run | stress: default | converged | largest difference to 2 kHz | above | "
                  "force: default | converged | largest difference to 2 kHz | above |\n"
                  "| --- | --- | --- | --- | --- | --- | --- | --- | --- |\n");
      std::vector<std::string> runs;
      for (const auto &entry : std::filesystem::directory_iterator(b))
        {
          const std::string file = entry.path().filename().string();
          if (file.rfind("spectrum_", 0) == 0 && file.rfind("spectrum_force_", 0) != 0 &&
              entry.path().extension() == ".csv")
            runs.push_back(file.substr(9, file.size() - 13));
        }
      std::sort(runs.begin(), runs.end());
      for (const auto &run : runs)
        {
          const auto cells = [](const SpectrumDifference &d) {
            std::string text;
            for (const auto &h : d.highest)
              text +=
                std::to_string(h.first) + " Hz, " + format_printf("%.1f", h.second) + " dB | ";
            for (unsigned int r = 0; r < 2; ++r)
              text += format_printf("%.1f", d.worst[r]) + " dB (" +
                      std::to_string(d.worst_band[r]) + " Hz)" + (r == 0 ? " | " : "");
            return text;
          };
          const auto kind = [&](const std::string &prefix) {
            return cells(compare_levels(read_levels(a / (prefix + run + ".csv")),
                                        read_levels(b / (prefix + run + ".csv"))));
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
              ": the default ring against the converged one' noenhanced\n"
              "set xrange [80:6000]\nplot " +
              q(a, "") + " skip 2 using 1:6 with linespoints lw 2 title 'stress, " +
              rings[0].title + "', " + q(b, "") +
              " skip 2 using 1:6 with linespoints lw 2 title 'stress, " + rings[1].title + "', " +
              q(a, "force_") + " skip 2 using 1:6 with linespoints lw 2 title 'force, " +
              rings[0].title + "', " + q(b, "force_") +
              " skip 2 using 1:6 with linespoints lw 2 title 'force, " + rings[1].title + "'\n",
            base::ParameterRecord{"converged_ring", {}});
        }
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

// The main job's scene (tyre-road-contact) as a user runs it: the program
// itself, on the main job's tyre (tests/tyre_road_contact/default_mesh.prm: the default
// mesh and 10 x 12 points, Green's functions every 50 Hz), reusing the
// stages tyre_road_contact/default_mesh saved. Each check compares the output files with what
// physics says, not with an earlier run:
// - a sinusoidal road of wavelength lambda at speed V puts the stress
//   spectrum's highest band at V / lambda;
// - where contact is sustained (3000 N, small heights) the contact is
//   linear: twice the heights (+6.02 dB of texture, on a sinusoid and on
//   road-A) give +6.02 dB of stress;
// - the spectral centroid rises with speed;
// - the mean contact force equals the static load;
// - the patch model's fit to this real tyre (E of Eq. 50) stays within its
//   stated bounds;
// - a saved stage whose key matches but whose data are corrupt is computed
//   again, and a changed identification parameter recomputes the patch
//   model only.

#include "csv_rows.h"
#include "run_lines.h"
#include "scratch.h"

#include <greentread/modal/patch_model.h>

#include <deal.II/base/hdf5.h>

#include <Eigen/Eigenvalues>

#include <boost/test/unit_test.hpp>

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <functional>
#include <limits>
#include <map>
#include <sstream>
#include <string>
#include <vector>

namespace fs = std::filesystem;

namespace
{
  using test::read_csv;

  /// The stress spectrum of one run: band centre [Hz] -> level [dB].
  struct Spectrum
  {
    std::vector<double> centre, level;

    double
    top_band() const
    {
      return centre[std::max_element(level.begin(), level.end()) - level.begin()];
    }

    /// Energy-weighted mean band centre.
    double
    centroid() const
    {
      double w = 0., wf = 0.;
      for (std::size_t b = 0; b < level.size(); ++b)
        {
          const double e = std::pow(10., level[b] / 10.);
          w += e;
          wf += e * centre[b];
        }
      return wf / w;
    }
  };

  /// One run of the program on the main job's tyre, in a scratch directory that
  /// starts with tyre_road_contact/default_mesh's saved stages.
  struct Run
  {
    Spectrum spectrum;
    double   mean_force = 0.;
  };

  /// The screen output and the output directory of the last run_scene().
  std::string screen_text;
  fs::path    last_directory;

  Run
  run_scene(const std::string                           &name,
            const std::string                           &road,
            const double                                 speed_kmh,
            const std::vector<std::string>              &settings,
            const std::function<void(const fs::path &)> &prepare = {})
  {
    const fs::path dir = test::scratch_directory("main-job-output-" + name);
    for (const std::string file : {"green_functions.h5", "patch_model.h5"})
      fs::copy_file(fs::path(GREENTREAD_DEFAULT_MESH_OUTPUT) / file, dir / file);
    if (prepare)
      prepare(dir);
    std::string command =
      std::string("\"") + GREENTREAD_PROGRAM + "\" \"" + GREENTREAD_SOURCE_DIR +
      "/tests/tyre_road_contact/default_mesh.prm\" --set \"Output directory=" + dir.string() +
      "\" --set \"Geometry/Geometry file=" + GREENTREAD_SOURCE_DIR +
      "/geometry/tyre_165_65_r13.geo\" --set \"Road texture/Roads=" + road +
      "\" --set \"Rolling/Speeds (kph)=" + std::to_string(speed_kmh) + "\"";
    for (const auto &s : settings)
      command += " --set \"" + s + "\"";
    command += " > \"" + (dir / "screen.txt").string() + "\" 2>&1";
    const int         status = std::system(command.c_str());
    std::ifstream     screen(dir / "screen.txt");
    const std::string text((std::istreambuf_iterator<char>(screen)),
                           std::istreambuf_iterator<char>());
    BOOST_TEST_REQUIRE(status == 0, name << ": the program failed:\n" << text);
    screen_text    = text;
    last_directory = dir;
    // The saved stages were reused: this checks the contact and analysis.
    if (!prepare)
      BOOST_TEST(text.find("Reusing") != std::string::npos, name << ":\n" << text);
    test::check_every_run_converged(text, name);

    char label[32];
    std::snprintf(label, sizeof label, "%g", speed_kmh);
    const std::string run = road + "_" + label + "kmh";
    Run               r;
    for (const auto &row : read_csv(dir / ("spectrum_" + run + ".csv")))
      {
        r.spectrum.centre.push_back(row[1]);
        r.spectrum.level.push_back(row[5]);
      }
    const auto history = read_csv(dir / ("history_" + run + ".csv"));
    for (const auto &row : history)
      r.mean_force += row[2];
    r.mean_force /= history.size();
    BOOST_TEST_MESSAGE(name << ": highest band " << r.spectrum.top_band() << " Hz, centroid "
                            << r.spectrum.centroid() << " Hz, mean force " << r.mean_force << " N");
    return r;
  }

  /// The band of the IEC 61260-1 base-10 series that holds @p f.
  double
  band_of(const double f)
  {
    const double k = std::round(10. * std::log10(f / 1000.));
    return 1000. * std::pow(10., k / 10.);
  }
} // namespace

BOOST_AUTO_TEST_SUITE(main_job_output)

BOOST_AUTO_TEST_CASE(a_sinusoidal_road_peaks_at_speed_over_wavelength)
{
  // 0.2 mm under 600 N: the patch's edges leave the road and harmonics
  // appear, but the highest band is the road's frequency V / lambda.
  for (const auto &[lambda, V] :
       std::vector<std::pair<double, double>>{{0.05, 90.}, {0.02, 90.}, {0.05, 50.}})
    BOOST_TEST_CONTEXT("lambda = " << lambda << " m, V = " << V << " km/h")
    {
      const double f   = V / 3.6 / lambda;
      const auto   run = run_scene(
          "sinusoid-" + std::to_string(int(1e3 * lambda)) + "-" + std::to_string(int(V)), "sinusoid",
          V,
          {"Road/Sinusoid/Amplitude=0.0002", "Road/Sinusoid/Wavelength=" + std::to_string(lambda)});
      BOOST_TEST(std::abs(run.spectrum.top_band() / band_of(f) - 1.) < 1e-9,
                 "road frequency " << f << " Hz");
    }
}

BOOST_AUTO_TEST_CASE(twice_the_heights_is_six_decibels_where_contact_is_sustained)
{
  // 3000 N keep 106 to 116 of the 120 points on the road: the contact is
  // linear, and twice the heights (+6.02 dB of texture, the spectrum's shape
  // kept) give +6.02 dB of stress.
  const double six = 20. * std::log10(2.);
  {
    // A 20 um sinusoid of 4 cm at 90 km/h: its band, 630 Hz.
    const std::vector<std::string> sinus   = {"Rolling/Static load=3000",
                                              "Road/Sinusoid/Amplitude=0.00002",
                                              "Road/Sinusoid/Wavelength=0.04"};
    auto                           doubled = sinus;
    doubled.push_back("Road texture/Height scale=2");
    const auto a = run_scene("sinusoid-1", "sinusoid", 90., sinus);
    const auto b = run_scene("sinusoid-2", "sinusoid", 90., doubled);
    const auto peak =
      std::max_element(a.spectrum.level.begin(), a.spectrum.level.end()) - a.spectrum.level.begin();
    BOOST_TEST(a.spectrum.top_band() == band_of(25. / 0.04), boost::test_tools::tolerance(1e-9));
    BOOST_TEST_MESSAGE("sinusoid, twice the heights: "
                       << b.spectrum.level[peak] - a.spectrum.level[peak]
                       << " dB more in its band");
    BOOST_TEST(std::abs(b.spectrum.level[peak] - a.spectrum.level[peak] - six) < 0.1);
    BOOST_TEST(std::abs(a.mean_force / 3000. - 1.) < 5e-3);
  }
  {
    // Road-A at a fortieth and a twentieth of its heights (a tenth and a
    // fifth gave 4.6 dB at 2 kHz, and a twentieth and a tenth 4.9 dB on the
    // road's realisation of 3750 samples: there the contact is not
    // sustained enough): every band from 160 Hz to 5 kHz within 0.5 dB of
    // +6.02 dB, and on average within 0.2 dB.
    const auto a    = run_scene("road-A-fortieth", "road-A", 90.,
                                {"Rolling/Static load=3000", "Road texture/Height scale=0.025"});
    const auto b    = run_scene("road-A-twentieth", "road-A", 90.,
                                {"Rolling/Static load=3000", "Road texture/Height scale=0.05"});
    double     mean = 0.;
    int        n    = 0;
    for (std::size_t k = 0; k < a.spectrum.level.size(); ++k)
      if (a.spectrum.centre[k] > 150.)
        {
          const double d = b.spectrum.level[k] - a.spectrum.level[k];
          BOOST_TEST(std::abs(d - six) < 0.5,
                     "band " << a.spectrum.centre[k] << " Hz: " << d << " dB");
          mean += d;
          ++n;
        }
    BOOST_TEST_MESSAGE("road-A in sustained contact, twice the heights: " << mean / n
                                                                          << " dB more on average");
    BOOST_TEST(std::abs(mean / n - six) < 0.2);
    BOOST_TEST(std::abs(a.mean_force / 3000. - 1.) < 5e-3);
  }
}

BOOST_AUTO_TEST_CASE(a_finer_contact_grid_carries_the_load_and_stays_linear)
{
  // The sustained sinusoid of the case above on 2 x 2 contact points per
  // Green's-function rectangle (480 points, the tread's layer below them):
  // the road's band, +6.02 dB for twice the heights, the mean force the
  // load, and the total force's spectrum written beside the stress's.
  const std::vector<std::string> sinus = {
    "Rolling/Static load=3000", "Road/Sinusoid/Amplitude=0.00002", "Road/Sinusoid/Wavelength=0.04",
    "Contact grid/Subdivisions=2"};
  auto doubled = sinus;
  doubled.push_back("Road texture/Height scale=2");
  const auto a = run_scene("grid-2-sinusoid-1", "sinusoid", 90., sinus);
  BOOST_TEST(screen_text.find("Contact grid: 20 x 24 = 480 points") != std::string::npos,
             screen_text);
  const auto force = read_csv(last_directory / "spectrum_force_sinusoid_90kmh.csv");
  BOOST_TEST(force.size() == a.spectrum.level.size());
  const auto b = run_scene("grid-2-sinusoid-2", "sinusoid", 90., doubled);
  const auto peak =
    std::max_element(a.spectrum.level.begin(), a.spectrum.level.end()) - a.spectrum.level.begin();
  BOOST_TEST(a.spectrum.top_band() == band_of(25. / 0.04), boost::test_tools::tolerance(1e-9));
  BOOST_TEST_MESSAGE("480 contact points, sinusoid, twice the heights: "
                     << b.spectrum.level[peak] - a.spectrum.level[peak] << " dB more in its band");
  BOOST_TEST(std::abs(b.spectrum.level[peak] - a.spectrum.level[peak] - 20. * std::log10(2.)) <
             0.1);
  BOOST_TEST(std::abs(a.mean_force / 3000. - 1.) < 5e-3);
}

BOOST_AUTO_TEST_CASE(the_centroid_rises_with_speed_and_the_mean_force_is_the_load)
{
  // The main job's case: road-A under 600 N, where points leave the road.
  std::vector<double> centroids;
  for (const double V : {50., 70., 90.})
    {
      const auto run = run_scene("road-A-" + std::to_string(int(V)), "road-A", V, {});
      centroids.push_back(run.spectrum.centroid());
      // The indentation is the one that carries 600 N at the start position
      // and is then held: as the texture under the patch changes, the mean
      // force drifts (measured 4-5% above the load on this road). A
      // load-controlled axle would remove it (README, 'Results').
      BOOST_TEST(std::abs(run.mean_force / 600. - 1.) < 0.07, "V = " << V << " km/h");
    }
  BOOST_TEST(centroids[1] > centroids[0]);
  BOOST_TEST(centroids[2] > centroids[1]);
}

BOOST_AUTO_TEST_CASE(the_patch_fit_to_the_tyre_stays_within_its_bounds)
{
  // E of Eq. (50) of every pair, as tyre_road_contact/default_mesh's patch model reports it
  // (modal_errors.csv: i, j, E). The bounds are those measured when this
  // test was written (median 23.4%, 90th percentile 44.0%, worst 56.3%,
  // driving points 6.8%) plus a margin; a worse fit fails here.
  const auto rows = read_csv(fs::path(GREENTREAD_DEFAULT_MESH_OUTPUT) / "modal_errors.csv");
  BOOST_TEST_REQUIRE(rows.size() == 14400u);
  std::vector<double> E, driving;
  for (const auto &row : rows)
    {
      E.push_back(row[2]);
      if (row[0] == row[1])
        driving.push_back(row[2]);
    }
  std::sort(E.begin(), E.end());
  const double median = E[E.size() / 2], p90 = E[E.size() * 9 / 10], worst = E.back();
  const double worst_driving = *std::max_element(driving.begin(), driving.end());
  BOOST_TEST_MESSAGE("main job's tyre (lines every 50 Hz), patch fit: E median "
                     << median << ", 90th percentile " << p90 << ", worst " << worst
                     << ", worst driving point " << worst_driving);
  BOOST_TEST(median <= 0.25);
  BOOST_TEST(p90 <= 0.46);
  BOOST_TEST(worst <= 0.6);
  BOOST_TEST(worst_driving <= 0.075);
}

BOOST_AUTO_TEST_CASE(a_corrupt_saved_stage_with_a_matching_key_is_computed_again)
{
  // A saved file whose key still matches but whose data do not (a value
  // overwritten with NaN, as a disk fault or an interrupted copy can leave
  // it) must not be used: the stage is computed again and the file
  // rewritten, and the next run reuses the new one.
  const auto poison = [](const fs::path &file, const std::string &dataset) {
    dealii::HDF5::File h5(file.string(), dealii::HDF5::File::FileAccessMode::open);
    auto               data   = h5.open_dataset(dataset);
    auto               values = data.read<std::vector<std::complex<double>>>();
    values[values.size() / 2] = std::numeric_limits<double>::quiet_NaN();
    data.write(values);
  };
  for (const auto &[file, dataset] : std::vector<std::pair<std::string, std::string>>{
         {"patch_model.h5", "residues"}, {"green_functions.h5", "green"}})
    BOOST_TEST_CONTEXT(file)
    {
      run_scene("corrupt-" + dataset, "road-A", 90., {}, [&](const fs::path &dir) {
        poison(dir / file, dataset);
      });
      BOOST_TEST(screen_text.find(file + ", although its key matches") != std::string::npos,
                 screen_text);
      BOOST_TEST(screen_text.find(file + ": same") == std::string::npos, screen_text);
      const std::string stage =
        dataset == "green" ? "Stages geometry -> fe -> periodic" : "Stage modal";
      BOOST_TEST(screen_text.find(stage) != std::string::npos, screen_text);
    }
}

BOOST_AUTO_TEST_CASE(a_changed_identification_parameter_recomputes_only_the_patch_model)
{
  run_scene("identification-changed", "road-A", 90., {"Identification/Maximum number of modes=28"},
            [](const fs::path &) {});
  BOOST_TEST(screen_text.find("green_functions.h5: same") != std::string::npos, screen_text);
  BOOST_TEST(screen_text.find("patch_model.h5: same") == std::string::npos, screen_text);
  BOOST_TEST(screen_text.find("Stage modal") != std::string::npos, screen_text);
}

BOOST_AUTO_TEST_CASE(passivity_of_the_tyre_patch_model)
{
  // A passive, reciprocal structure absorbs power at every frequency:
  // -Im G(omega) is positive semidefinite. The identified model is not
  // (its residues are fitted, doc/methods/modal.md), and the program says so
  // when it rolls it: tyre_road_contact/default_mesh kept the figure of its
  // warning (smallest eigenvalue over the largest, and its line). Here the
  // same figure from the model's pairs one by one (PatchModel::
  // frequency_response, not the program's term-by-term matrices), on the
  // Green's functions' lines (every 50 Hz up to f_max), and G_r positive
  // definite.
  const auto model = greentread::modal::read_patch_model(
    (fs::path(GREENTREAD_DEFAULT_MESH_OUTPUT) / "patch_model.h5").string());
  std::ifstream warned(fs::path(GREENTREAD_DEFAULT_MESH_OUTPUT) / "passivity.txt");
  double        warned_value = 0., warned_frequency = 0.;
  BOOST_TEST_REQUIRE(bool(warned >> warned_value >> warned_frequency));
  const unsigned int n     = model.n_points(),
                     lines = static_cast<unsigned int>(std::lround(model.f_max / 50.));
  double worst = 0., worst_frequency = 0.;
  for (unsigned int line = 1; line <= lines; ++line)
    {
      const double    omega = 2. * M_PI * 50. * line;
      Eigen::MatrixXd A(n, n);
      for (unsigned int i = 0; i < n; ++i)
        for (unsigned int j = 0; j < n; ++j)
          A(i, j) = -model.frequency_response(i, j, omega).imag();
      BOOST_TEST_REQUIRE((A - A.transpose()).cwiseAbs().maxCoeff() <=
                         1e-12 * A.cwiseAbs().maxCoeff());
      const Eigen::VectorXd e = Eigen::SelfAdjointEigenSolver<Eigen::MatrixXd>(A).eigenvalues();
      if (e.minCoeff() / e.cwiseAbs().maxCoeff() < worst)
        {
          worst           = e.minCoeff() / e.cwiseAbs().maxCoeff();
          worst_frequency = 50. * line;
        }
    }
  const Eigen::VectorXd r =
    Eigen::SelfAdjointEigenSolver<Eigen::MatrixXd>(model.instantaneous).eigenvalues();
  BOOST_TEST_MESSAGE(
    "main job's tyre (lines every 50 Hz), patch model: smallest eigenvalue of -Im G over the lines "
    << worst << " of the largest at " << worst_frequency
    << " Hz (the program's warning: " << warned_value << " at " << warned_frequency
    << " Hz); G_r's eigenvalues from " << r.minCoeff() << " to " << r.maxCoeff() << " m/N");
  BOOST_TEST(r.minCoeff() > 0.);
  BOOST_TEST(worst < -1e-9); // not passive, and warned about
  // The warning prints 3 significant digits.
  BOOST_TEST(std::abs(warned_value - worst) <= 5e-3 * std::abs(worst));
  BOOST_TEST(warned_frequency == worst_frequency);
}

BOOST_AUTO_TEST_SUITE_END()

// The main job's own path, end to end, on the stages that
// tyre_road_contact/main_job saved: the program with every default of the
// main job (the harmonic ring on its quartic section, tributary areas, the
// ring's own modes, the contact grid at 8 subdivisions, projected CG), rolled
// on a 5 um sinusoid of 40 mm at 90 km/h under 3000 N, where the contact is
// sustained (60% of the 7680 points throughout). The fixture checks the
// route, the synthesis' E against its direct lines and the passivity
// (run_main_job.cmake); here, against physics and a second method:
// - the stress spectrum's highest band holds V / lambda, and the mean force
//   is the static load;
// - twice the heights give +6.02 dB in that band (the contact is linear while
//   it is sustained);
// - each band's error bars are written: the standard error, the
//   discretisations' estimates and their combination (the estimates
//   themselves are checked against refined runs in unit/error_bars);
// - the ring section's estimate is Richardson's factor times the level
//   difference from a run of the section twice as coarse, made here on its
//   own, whose stages are those the main job saved for it (in the
//   sinusoid's band: the others are at the contact solve's noise);
// - the same roll done here through the library, its forces convolved with
//   the patch model in the frequency domain (frequency_synthesis.h, nothing
//   shared with the time stepping), leaves no contact point inside the road
//   and every loaded point on it.
// tests/unit/test_main_job_output.cc keeps the paper's path (node loads, the
// identified model, the Green's functions' points as the contact grid).

#include "csv_rows.h"
#include "frequency_synthesis.h"
#include "run_lines.h"
#include "scratch.h"

#include <greentread/analysis/error_bars.h>
#include <greentread/base/frequency_response.h>
#include <greentread/contact/contact_grid.h>
#include <greentread/contact/rolling.h>
#include <greentread/fe/material.h>
#include <greentread/geometry/tyre_cell.h>
#include <greentread/road/patch_road.h>
#include <greentread/synthesis/mode_synthesis.h>

#include <boost/test/unit_test.hpp>

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

namespace fs = std::filesystem;
using namespace greentread;

namespace
{
  const fs::path stages = GREENTREAD_MAIN_JOB_OUTPUT;

  /// The fixture's road and load (run_main_job.cmake).
  constexpr double amplitude = 5e-6, wavelength = 0.04, speed_kmh = 90., static_load = 3000.;

  /// Column @p column of the data rows of a CSV file.
  std::vector<double>
  csv_column(const fs::path &file, const unsigned int column)
  {
    std::vector<double> values;
    for (const auto &row : test::read_csv(file))
      values.push_back(row.at(column));
    return values;
  }

  /// The band of the IEC 61260-1 base-10 series that holds @p f.
  double
  band_of(const double f)
  {
    return 1000. * std::pow(10., std::round(10. * std::log10(f / 1000.)) / 10.);
  }

  /// The stress band levels of a run's spectrum file: centres and levels.
  std::pair<std::vector<double>, std::vector<double>>
  stress_bands(const fs::path &directory)
  {
    const fs::path file = directory / "spectrum_sinusoid_90kmh.csv";
    return {csv_column(file, 1), csv_column(file, 5)};
  }

  /// The program on a copy of the stages in @p from (and of its
  /// coarser_section/, if there), on the fixture's road and load, with
  /// @p settings added: its output directory (a scratch directory named
  /// after @p name), what it printed, and how many saved stages it reused.
  struct Run
  {
    fs::path    dir;
    std::string screen;
    std::size_t reused = 0;
  };

  Run
  run_on_saved_stages(const std::string &name, const fs::path &from, const std::string &settings)
  {
    Run run{test::scratch_directory("main-job-path-" + name), {}, 0};
    for (const std::string file : {"green_functions.h5", "modal_model.h5"})
      fs::copy_file(from / file, run.dir / file);
    if (fs::exists(from / "coarser_section"))
      fs::copy(from / "coarser_section", run.dir / "coarser_section", fs::copy_options::recursive);
    const std::string command =
      std::string("\"") + GREENTREAD_PROGRAM + "\" --set \"Output directory=" + run.dir.string() +
      "\" --set \"Geometry/Geometry file=" + GREENTREAD_SOURCE_DIR +
      "/geometry/tyre_165_65_r13.geo\" --set \"Road texture/Roads=sinusoid\" --set "
      "\"Road/Sinusoid/Amplitude=0.000005\" --set \"Road/Sinusoid/Wavelength=0.04\" --set "
      "\"Rolling/Speeds (kph)=90\" --set \"Rolling/Static load=3000\" --set "
      "\"Rolling/Distance=1.1\" "
      "--set \"Spectra/Extend runs=false\" " +
      settings + " > \"" + (run.dir / "screen.txt").string() + "\" 2>&1";
    const int     status = std::system(command.c_str());
    std::ifstream screen(run.dir / "screen.txt");
    run.screen.assign(std::istreambuf_iterator<char>(screen), std::istreambuf_iterator<char>());
    BOOST_TEST_REQUIRE(status == 0, run.screen);
    for (std::size_t at = run.screen.find("Reusing"); at != std::string::npos;
         at             = run.screen.find("Reusing", at + 1))
      ++run.reused;
    return run;
  }
} // namespace

BOOST_AUTO_TEST_SUITE(main_job_path)

BOOST_AUTO_TEST_CASE(the_sinusoid_peaks_at_speed_over_wavelength_and_the_load_is_carried)
{
  const auto [centre, level] = stress_bands(stages);
  const double top           = centre[std::max_element(level.begin(), level.end()) - level.begin()];
  const double f             = speed_kmh / 3.6 / wavelength;
  BOOST_TEST_MESSAGE("main job's path: highest stress band " << top << " Hz, road " << f << " Hz");
  BOOST_TEST(top == band_of(f), boost::test_tools::tolerance(1e-9));

  // The mean of the total force over the record against the static load.
  const auto force = csv_column(stages / "history_sinusoid_90kmh.csv", 2);
  double     mean  = 0.;
  for (const double q : force)
    mean += q;
  mean /= force.size();
  BOOST_TEST_MESSAGE("mean total force " << mean << " N against the static " << static_load
                                         << " N: " << mean / static_load - 1.);
  BOOST_TEST(std::abs(mean / static_load - 1.) < 1e-3); // measured -3.5e-4
}

BOOST_AUTO_TEST_CASE(twice_the_heights_is_six_decibels_where_contact_is_sustained)
{
  // The program again, on a copy of the saved stages, with the heights doubled.
  const Run       run = run_on_saved_stages("doubled", stages,
                                            "--set \"Spectra/Standard error target=2\" --set \"Error "
                                                  "bars/Estimates=\" --set \"Road texture/Height scale=2\"");
  const fs::path &dir = run.dir;
  BOOST_TEST(run.reused == 2u, run.screen); // the Green's functions and the modes
  test::check_every_run_converged(run.screen, "doubled heights");

  const auto [centre, once] = stress_bands(stages);
  const auto [same, twice]  = stress_bands(dir);
  const auto   peak         = std::max_element(once.begin(), once.end()) - once.begin();
  const double six          = 20. * std::log10(2.);
  const double difference   = twice[peak] - once[peak];
  BOOST_TEST_MESSAGE("twice the heights: " << difference << " dB more in the " << centre[peak]
                                           << " Hz band (+" << six << " dB for a linear contact)");
  // Measured +6.11 dB at 5 and 10 um. The contact's edge moves with the
  // road, so the contact is linear only to first order: 20 and 40 um gave
  // +5.7 dB, 40 and 80 um +3.9 dB.
  BOOST_TEST(std::abs(difference - six) < 0.3);
}

BOOST_AUTO_TEST_CASE(each_band_has_its_error_bars)
{
  // The run's spectrum file: the standard error, each discretisation's
  // estimate and their combination, in the bands the estimates cover. The
  // low-rate run disagrees here (the fixture requires the warning), so the
  // bands to 1 kHz come from the 2 m run, whose coarser runs estimate from
  // its lowest own band, 1250 Hz, up: the bands below have none.
  const fs::path file = stages / "spectrum_sinusoid_90kmh.csv";
  std::ifstream  in(file);
  std::string    header;
  while (std::getline(in, header) && header.rfind("#", 0) == 0)
    ;
  BOOST_TEST(header.find(",total_error_dB,time_step_dB,contact_grid_dB,mode_cutoff_dB,"
                         "ring_section_dB") != std::string::npos,
             header);
  unsigned estimated = 0;
  for (const auto &row : test::read_csv(file))
    {
      BOOST_TEST_REQUIRE(row.size() == 16u);
      const double f = row[0], se = row[6], total = row[11];
      double       sum = se * se;
      for (unsigned c = 12; c < 16; ++c)
        {
          BOOST_TEST(std::isnan(row[c]) == (f < 1250.), f << " Hz, column " << c);
          // An estimate is factor |L_other - L_run|, not negative by
          // construction: what can go wrong is a level that is not finite.
          if (!std::isnan(row[c]))
            {
              BOOST_TEST(std::isfinite(row[c]), f << " Hz, column " << c);
              sum += row[c] * row[c];
            }
        }
      BOOST_TEST(total == std::sqrt(sum), boost::test_tools::tolerance(1e-9));
      estimated += f >= 1250. ? 1 : 0;
    }
  BOOST_TEST(estimated == 7u); // 1250 to 5000 Hz
}

BOOST_AUTO_TEST_CASE(the_ring_section_estimate_is_the_coarser_sections_scaled_difference)
{
  // Two runs of the fixture's road, one rate, 1.1 m (44 ms, within the
  // estimates' window of 69 ms, so each level is the whole record): the
  // default section with the ring section's estimate, and on its own the
  // section with 'Geometry/Mesh size' doubled (and its direct lines at 0
  // and 4 kHz only, as the error bar computes them), on the stages the main
  // job saved in coarser_section/ (which must be reused: they are what a
  // run of that section computes).
  const Run fine_run = run_on_saved_stages(
    "ring-section", stages,
    "--set \"Spectra/Low bands up to=0\" --set \"Error bars/Estimates=ring section\"");
  const Run coarse_run = run_on_saved_stages("coarser-section", stages / "coarser_section",
                                             "--set \"Spectra/Low bands up to=0\" --set \"Error "
                                             "bars/Estimates=\" --set \"Geometry/Mesh size=0.016\" "
                                             "--set \"Green's functions/Frequency step=4000\"");
  BOOST_TEST(fine_run.reused == 4u);   // both stages, and both of the coarser section
  BOOST_TEST(coarse_run.reused == 2u); // the coarser section's, as its own

  const auto fine_rows   = test::read_csv(fine_run.dir / "spectrum_sinusoid_90kmh.csv");
  const auto coarse_rows = test::read_csv(coarse_run.dir / "spectrum_sinusoid_90kmh.csv");
  BOOST_TEST_REQUIRE(fine_rows.size() == coarse_rows.size());
  // Richardson's factor for the section's mesh size doubled at order 1.5,
  // the order doc/methods/analysis.md gives the ring section (chosen from
  // error_bars.sh's three cases, observed 0.86 to 1.62), written here and not
  // taken from the program's constant, so that a change of it shows.
  const double factor  = 1. / (std::pow(2., 1.5) - 1.);
  double       highest = -1e300;
  for (const auto &row : fine_rows)
    highest = std::max(highest, row[5]);
  unsigned estimated = 0, compared = 0;
  for (std::size_t b = 0; b < fine_rows.size(); ++b)
    {
      // band, level, ..., ring_section_dB the last column (16 with every
      // estimate's; here the one estimate's column after total_error_dB).
      const double f = fine_rows[b][0], estimate = fine_rows[b].back();
      if (f < 250.)
        {
          BOOST_TEST(std::isnan(estimate), f << " Hz");
          continue;
        }
      ++estimated;
      // Present and finite (factor |L_coarse - L_fine| is not negative by
      // construction; its value is checked in the sinusoid's band below).
      BOOST_TEST(std::isfinite(estimate), f << " Hz");
      const double difference = std::abs(fine_rows[b][5] - coarse_rows[b][5]);
      BOOST_TEST_MESSAGE(f << " Hz (" << fine_rows[b][5] - highest
                           << " dB from the highest): estimate " << estimate << " dB, " << factor
                           << " x |" << fine_rows[b][5] << " - " << coarse_rows[b][5]
                           << "| = " << factor * difference << " dB");
      // The estimate is 'factor' x the difference of the two sections' runs,
      // and the test's run of the coarser section is the same computation
      // as the one inside the estimate: runs give the same bytes (the FFT
      // plans are estimated, the sums in a fixed order), so in every band
      // they agree to the CSV's printed digits (levels to about 1e-10 dB).
      // The bound, 1e-8 dB, is those digits with a margin; a regression
      // moves far more: order 2 instead of 1.5 moves the sinusoid's band's
      // estimate (0.0021 dB) by 8e-4 dB, the fine section's model in place
      // of the coarser one's by all of it.
      BOOST_TEST(std::abs(estimate - factor * difference) < 1e-8, f << " Hz");
      ++compared;
      if (fine_rows[b][5] >= highest - 20.)
        BOOST_TEST(estimate > 1e-3, f << " Hz"); // 0.0021 dB: the two sections do differ
    }
  BOOST_TEST(estimated == 14u); // 250 to 5000 Hz
  BOOST_TEST(compared == 14u);  // every one of them
}

BOOST_AUTO_TEST_CASE(no_point_enters_the_road_by_the_frequency_domain_synthesis)
{
  // The main job's patch model and contact grid, built here from the saved
  // stages and the defaults, as the scene builds them.
  const auto green = base::read_green_hdf5((stages / "green_functions.h5").string());
  const synthesis::ModeSynthesis modes =
    synthesis::read_modal_model((stages / "modal_model.h5").string());
  const unsigned int      n_c   = green.n_points();
  const modal::PatchModel model = synthesis::to_patch_model(modes, Eigen::MatrixXd::Zero(n_c, n_c),
                                                            green.df * (green.n_lines - 1));
  const fe::MaterialParameters       materials;
  const geometry::GeometryParameters geometry;
  // The solve at a tolerance of 1e-10, not the default 1e-6: this test
  // checks the convolution to 1e-6 of the displacement change (about 1e-11
  // m), far below what the default lets a point keep inside the road (a few
  // nm, checked in unit/projected_cg).
  const contact::ContactGrid grid(model.points, 8,
                                  {materials.tread_E, materials.tread_nu, geometry.tread_thickness},
                                  true, true, 1e-10);
  BOOST_TEST_REQUIRE(grid.n_points() == 7680u);

  road::RoadTextureParameters roads;
  roads.sinusoid.amplitude                = amplitude;
  roads.sinusoid.wavelength               = wavelength;
  const road::Texture             texture = roads.make("sinusoid", 0.08 + 0.03);
  const road::PatchRoad           road(texture, grid.points, roads.sampling, "sinusoid");
  const contact::PatchRoadHeights heights = [&](const double x, Eigen::VectorXd &z,
                                                Eigen::VectorXd &slope) {
    road.heights(x, z, slope);
  };
  contact::RollingSetup setup;
  setup.speed                 = speed_kmh / 3.6;
  setup.time_step             = texture.dx / setup.speed;
  setup.n_steps               = 100; // 3.84 cm: about one wavelength
  setup.static_load           = static_load;
  const Eigen::VectorXd tread = contact::tread_heights(grid.points);
  const auto            start =
    contact::start_grid_contact(grid, synthesis::static_line(green), tread, heights, setup);
  auto convolution = contact::make_grid_convolution(
    contact::make_patch_convolution(setup.convolution, model, setup.time_step, setup.n_steps, 0, 2),
    grid);
  std::vector<Eigen::VectorXd> f(1, start.q), d(1);
  const auto summary = contact::roll_patch(*convolution, tread, heights, start, setup,
                                           [&](const contact::RollingStep &step) {
                                             f.push_back(step.report.lcp_z);
                                             d.push_back(step.d);
                                           });
  BOOST_TEST_REQUIRE(summary.failed_steps == 0u, summary.first_failure);

  // u = A^T (g * A f) + (I - P) L_f (I - P) f (contact_grid.h), the
  // convolution in the frequency domain on the coarse cells' forces.
  std::vector<Eigen::VectorXd> q(f.size());
  for (std::size_t n = 0; n < f.size(); ++n)
    q[n] = grid.gather(f[n]);
  const auto                   coarse = test::synthesise_displacements(model, setup.time_step, q);
  double                       scale = 0., penetration = 0., gap = 0.;
  std::vector<Eigen::VectorXd> u(f.size());
  for (std::size_t n = 0; n < f.size(); ++n)
    {
      u[n] = grid.expand(coarse[n]);
      grid.add_local(f[n], u[n]);
      scale = std::max(scale, (u[n] - u[0]).cwiseAbs().maxCoeff());
    }
  for (std::size_t n = 1; n < f.size(); ++n)
    for (unsigned int p = 0; p < grid.n_points(); ++p)
      {
        penetration = std::max(penetration, (d[n][p] - u[n][p]) / scale);
        if (f[n][p] > 0.)
          gap = std::max(gap, std::abs(u[n][p] - d[n][p]) / scale);
      }
  BOOST_TEST_MESSAGE("main job's path, "
                     << setup.n_steps << " steps on " << grid.n_points()
                     << " points, points in contact " << 100. * summary.min_contact_fraction
                     << "% to " << 100. * summary.max_contact_fraction
                     << "%: by the frequency-domain synthesis, penetration " << penetration
                     << " and loaded points off the road " << gap << " of the displacement change "
                     << scale << " m");
  // Measured 1.5e-6 for both: the synthesis' own error (its replicas of
  // the Nyquist band), 1.5e-11 m here.
  BOOST_TEST(penetration <= 5e-6);
  BOOST_TEST(gap <= 5e-6);
}

BOOST_AUTO_TEST_SUITE_END()

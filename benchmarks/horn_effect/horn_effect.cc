// The horn effect of the main job's tyre on a rigid road: how much the tyre
// amplifies a point source on the road before its contact patch, heard at a
// microphone in the tyre's plane and out of it, against frequency, on two
// boundary element meshes (the second with its cells 1/sqrt(2) the size),
// with the run time of each; beside what Graf, Kuo, Dowling & Graham (2002)
// measured and Kropp, Becot & Barrelet (2000) computed. Writes
// horn_effect.csv and horn_effect.png.
//
// The amplification is 20 log10 |p| / |p0|: p with the tyre, p0 without it,
// both over the rigid road. It is computed the way Graf et al. measured it,
// by reciprocity: the source at the microphone, the receiver in the horn.
//
//   horn_effect [--quick] [--output DIR]

#include <greentread/base/exceptions.h>
#include <greentread/base/plot.h>
#include <greentread/base/revision.h>
#include <greentread/config.h>
#include <greentread/geometry/tyre_cell.h>
#include <greentread/radiation/helmholtz_bem.h>
#include <greentread/radiation/tyre_surface.h>

#include <deal.II/fe/mapping_q1.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <sstream>

#include "benchmark_options.h"

using namespace greentread;

int
main(int argc, char **argv)
{
  dealii::Utilities::MPI::MPI_InitFinalize mpi(argc, argv, dealii::numbers::invalid_unsigned_int);
  const auto                               options = benchmark::parse(argc, argv, "horn_effect");

  // The main job's tyre, the shipped 165/65 R13; its contour does not depend
  // on the ring's cell count.
  geometry::GeometryParameters geometry;
  geometry.geo_file  = GREENTREAD_SOURCE_DIR "/geometry/tyre_165_65_r13.geo";
  geometry.n_cells   = 64;
  const auto contour = radiation::outer_contour(geometry::TyreCell(geometry).section());
  // A loaded tyre: 10 mm of deflection, a patch about 15 cm long.
  const double deflection = 0.01;
  // The coarse mesh resolves the top band (six cells to a wavelength); the
  // fine one halves the cells' area.
  const double              coarse = options.quick ? 0.04 : 0.03;
  const std::vector<double> bands =
    options.quick ? std::vector<double>{250., 400., 630., 800.} :
                    std::vector<double>{250., 315., 400., 500., 630., 800., 1000., 1250.};
  const double sizes[2] = {coarse, coarse / std::sqrt(2.)};

  radiation::Air air;
  air.ground = true;
  // Receivers on the road before the patch's edge (Graf et al.'s
  // microphones in the road), 2, 4 and 8 cm from it; the microphones 1 m
  // from the patch's centre, 0.2 m high, at 0 (in the tyre's plane, ahead),
  // 45 and 90 degrees (beside the tyre).
  const std::vector<double>      gaps{0.02, 0.04, 0.08};
  const std::vector<std::string> directions{"0", "45", "90"};
  std::vector<dealii::Point<3>>  microphones;
  for (const double degrees : {0., 45., 90.})
    {
      const double t = degrees * dealii::numbers::PI / 180.;
      microphones.emplace_back(std::cos(t), std::sin(t), 0.2);
    }

  // amplification[mesh][band][gap][direction] [dB]
  std::vector<std::vector<std::vector<std::vector<double>>>> amplification(2);
  double                                                     run_time[2] = {0., 0.};
  unsigned int                                               n_cells[2]  = {0, 0};
  std::printf("Horn effect of the 165/65 R13 with %.0f mm of deflection on a rigid road:\n"
              "20 log10 |p with the tyre| / |p without it| [dB], a source on the road d before\n"
              "the patch's edge, a microphone 1 m away at 0.2 m height, at 0, 45, 90 degrees\n"
              "from the tyre's plane. Coarse | fine mesh.\n\n",
              1e3 * deflection);
  for (unsigned int mesh = 0; mesh < 2; ++mesh)
    {
      const auto                    start = std::chrono::steady_clock::now();
      const radiation::TyreSurface  surface(contour, sizes[mesh], deflection);
      const dealii::MappingQ1<2, 3> mapping;
      radiation::HelmholtzBem       bem(surface.mesh, mapping, surface.outward);
      n_cells[mesh] = bem.n_cells();
      std::vector<dealii::Point<3>> receivers;
      for (const double d : gaps)
        receivers.emplace_back(surface.patch_half_length + d, 0., 0.);
      for (const auto &p : receivers)
        if (surface.inside(p))
          throw std::logic_error("a receiver lies inside the tyre");
      for (const double f : bands)
        {
          bem.assemble(air, f, surface.interior_points);
          const Eigen::MatrixXcd p  = bem.rigid_scattering(microphones, receivers);
          const Eigen::MatrixXcd p0 = bem.incident_pressure(microphones, receivers);
          amplification[mesh].emplace_back();
          for (unsigned int g = 0; g < gaps.size(); ++g)
            {
              amplification[mesh].back().emplace_back();
              for (unsigned int m = 0; m < microphones.size(); ++m)
                amplification[mesh].back().back().push_back(
                  20. * std::log10(std::abs(p(g, m)) / std::abs(p0(g, m))));
            }
        }
      run_time[mesh] =
        std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
      std::printf("mesh %u: %u cells, largest %.1f mm, resolves to %.0f Hz; %.1f s for %zu bands\n",
                  mesh, n_cells[mesh], 1e3 * bem.largest_cell(), bem.highest_frequency(air),
                  run_time[mesh], bands.size());
      std::fflush(stdout);
    }

  std::printf("\n%-8s %-6s", "f [Hz]", "d [cm]");
  for (const auto &direction : directions)
    std::printf(" | %3s deg: coarse  fine ", direction.c_str());
  std::printf("\n");
  std::ostringstream csv;
  csv << "frequency,distance,direction,coarse,fine,difference\n";
  double largest_move = 0., in_plane_peak = -1e9, beside_peak = -1e9;
  for (unsigned int b = 0; b < bands.size(); ++b)
    for (unsigned int g = 0; g < gaps.size(); ++g)
      {
        std::printf("%-8.0f %-6.0f", bands[b], 1e2 * gaps[g]);
        for (unsigned int m = 0; m < microphones.size(); ++m)
          {
            const double a0 = amplification[0][b][g][m], a1 = amplification[1][b][g][m];
            std::printf(" |        %6.2f %6.2f ", a0, a1);
            largest_move = std::max(largest_move, std::abs(a1 - a0));
            if (m == 0)
              in_plane_peak = std::max(in_plane_peak, a1);
            if (m == 2)
              beside_peak = std::max(beside_peak, a1);
          }
        std::printf("\n");
      }
  std::printf("\nThe finer mesh moves the amplification by %.2f dB at most. Peak on the fine\n"
              "mesh: %.1f dB in the tyre's plane, %.1f dB beside the tyre. Graf et al. (2002)\n"
              "measured 10 to 20 dB near the contact; Kropp et al. (2000) about 20 dB in the\n"
              "tyre's plane and substantially less in other directions.\n",
              largest_move, in_plane_peak, beside_peak);

  // One curve (distance, direction) after another, so that each is one
  // contiguous block for the plot.
  for (unsigned int g = 0; g < gaps.size(); ++g)
    for (unsigned int m = 0; m < microphones.size(); ++m)
      for (unsigned int b = 0; b < bands.size(); ++b)
        csv << bands[b] << ',' << gaps[g] << ',' << directions[m] << ','
            << amplification[0][b][g][m] << ',' << amplification[1][b][g][m] << ','
            << amplification[1][b][g][m] - amplification[0][b][g][m] << '\n';

  benchmark::Checks checks("horn_effect");
  // The finer mesh moves the amplification by 0.26 dB at most in the
  // --quick run and 0.23 dB in the full one: a discretisation's difference,
  // bounded 1.25 times above it as the other benchmarks' are. The peaks are
  // compared with
  // measurements on another tyre (Graf et al.: 10 to 20 dB), so their
  // bounds are that range, widened, not 3x of a figure of this code: 13.0
  // dB (--quick, to 800 Hz) and 17.2 dB (full, to 1250 Hz) in the plane,
  // 3.0 and 3.5 dB beside the tyre.
  checks.at_most("largest change of the amplification with the mesh [dB]", largest_move, 0.33);
  checks.at_least("peak amplification in the tyre's plane [dB]", in_plane_peak, 10.);
  checks.at_most("peak amplification in the tyre's plane [dB]", in_plane_peak, 25.);
  checks.at_least("in-plane peak above the peak beside the tyre [dB]", in_plane_peak - beside_peak,
                  5.);

  {
    base::AtomicFile file(options.output / "horn_effect.csv");
    file.stream() << csv.str();
    file.commit();
  }
  const std::string data = base::gnuplot_quote(options.output / "horn_effect.csv");
  std::string       commands =
    "set datafile separator ','\nset logscale x\nset grid\n"
    "set xlabel 'one-third-octave band [Hz]'\nset ylabel 'amplification by the tyre [dB]'\n"
    "set xrange [200:" +
    std::to_string(static_cast<int>(1.25 * bands.back())) +
    "]\nset xtics (250, 400, 630, 1000, 1600, 2500)\n"
    "set key outside right\nset yrange [-10:30]\n"
    "set title 'GreenTread: horn effect, 165/65 R13, 10 mm deflection, source 2 cm before "
    "the patch'\n"
    "set object 1 rect from graph 0, first 10 to graph 1, first 20 fc rgb '#dddddd' "
    "fs solid 0.5 noborder behind\n"
    "set label 1 'Graf et al. 2002: 10-20 dB measured near the contact' at graph 0.03, "
    "first 21\nplot ";
  const std::string colours[] = {"#1f77b4", "#2ca02c", "#d62728"};
  for (unsigned int m = 0; m < directions.size(); ++m)
    for (unsigned int mesh = 0; mesh < 2; ++mesh)
      commands += std::string(m + mesh ? ", " : "") + data +
                  " skip 1 using 1:(($2 == 0.02 && stringcolumn(3) eq '" + directions[m] +
                  "') ? $" + (mesh ? "5" : "4") + " : NaN) with linespoints lw 2 " +
                  (mesh ? "pt 7" : "dt 2 pt 6") + " lc rgb '" + colours[m] + "' title '" +
                  directions[m] + " deg, " + (mesh ? "fine" : "coarse") + " mesh'";
  commands += "\n";
  base::ParameterRecord record;
  record.header = std::string("greentread ") + GREENTREAD_VERSION + " (" + base::git_revision() +
                  "), benchmark horn_effect (165/65 R13, 10 mm deflection" +
                  (options.quick ? ", --quick)" : ")");
  base::plot_png(options.output / "horn_effect.png", commands, record);
  std::printf("Wrote %s and horn_effect.png (coarse %u cells %.1f s, fine %u cells %.1f s)\n",
              (options.output / "horn_effect.csv").c_str(), n_cells[0], run_time[0], n_cells[1],
              run_time[1]);
  return checks.exit_code();
}

#include <greentread/analysis/green_output.h>
#include <greentread/base/exceptions.h>
#include <greentread/base/output.h>
#include <greentread/base/parameters.h>
#include <greentread/periodic/deflection_shape.h>
#include <greentread/periodic/green_stage.h>
#include <greentread/scenes/green_scene.h>

#include <deal.II/base/conditional_ostream.h>

#include <chrono>
#include <cmath>
#include <iostream>

namespace greentread
{
  namespace scenes
  {
    GreenScene::GreenScene(dealii::ParameterHandler &prm_, const GlobalParameters &global_)
        : prm(prm_)
        , global(global_)
    {
      geometry.parse_parameters(prm);
      materials.parse_parameters(prm);
      inflation.parse_parameters(prm);
      green.parse_parameters(prm);
    }



    void
    GreenScene::run()
    {
      namespace fs                    = std::filesystem;
      const MPI_Comm             comm = MPI_COMM_WORLD;
      const unsigned int         rank = dealii::Utilities::MPI::this_mpi_process(comm);
      dealii::ConditionalOStream out(std::cout, rank == 0);
      const auto                 start = std::chrono::steady_clock::now();

      // Check the output directory (rank 0) before any work.
      std::string directory_name;
      collectively(comm, [&]() {
        if (rank == 0)
          directory_name = base::prepare_output_directory(global.output_directory).string();
      });
      const fs::path directory = dealii::Utilities::MPI::broadcast(comm, directory_name, 0);
      const auto     record =
        base::ParameterRecord::from(prm, global.scene, recorded_sections(global.scene));

      // Every rank builds the tyre; a rank that fails (a file it cannot
      // read) must not leave the others waiting in the frequency loop.
      std::unique_ptr<periodic::InflatedTyre>            built;
      std::vector<std::pair<unsigned int, unsigned int>> pairs;
      std::string                                        key;
      collectively(comm, [&]() {
        built = std::make_unique<periodic::InflatedTyre>(geometry, materials, inflation,
                                                         green.patch, green.harmonic());
        pairs = green.csv_pairs(built->patch);
        key   = periodic::green_stage_key(prm, geometry.geo_file);
      });
      const auto &tyre = *built;
      out << "GreenTread: scene 'tyre-green', Green's functions of the inflated ring at the "
             "contact points (Meftah et al. 2013, Section 4.2)\n"
          << tyre.describe(inflation.pressure) << "  frequencies 0 to "
          << format_number(green.max_frequency) << " Hz every "
          << format_number(green.frequency_step) << " Hz (" << green.n_lines()
          << " lines), method '" << green.method << "'\n";

      const fs::path h5     = directory / "green_functions.h5";
      const auto     result = periodic::run_green_stage(tyre, green, key, h5, record, global.reuse,
                                                        global.print_timings, comm);
      out << periodic::describe(result, tyre, green, h5, global.print_timings);

      // The ring's deflection shape: one frequency, rank 0 alone.
      periodic::SolveDiagnostics deflection;
      const bool                 with_deflection = green.deflection_frequency >= 0.;
      const unsigned int         centre          = pairs.front().second;
      if (with_deflection && rank == 0)
        {
          const auto &q = tyre.patch.points[centre];
          const auto  u = periodic::ring_response(
             tyre.periodic_cell, 2. * M_PI * green.deflection_frequency, q.load, deflection);
          periodic::write_ring_deflection(directory / "ring_deflection.vtu", tyre.cell->cell(),
                                          tyre.periodic_cell, u);
        }
      if (rank != 0)
        return;

      analysis::write_contact_points(directory / "contact_points.csv", tyre.patch, record);
      const auto files = analysis::write_green_pairs(
        directory, result.green, pairs,
        "GreenTread: radial Green functions of the inflated ring (" +
          std::to_string(tyre.periodic_cell.n_cells) + " cells, " + green.method + ")",
        record);
      out << analysis::summarise_pairs(result.green, pairs);
      if (with_deflection)
        out << "Deflection shape at " << format_number(green.deflection_frequency)
            << " Hz under the unit load of point " << centre << ": largest backward error "
            << format_printf("%.2g", deflection.max_residual) << "\n";
      out << "Wrote green_functions.h5, contact_points.csv";
      for (const auto &n : files.csv)
        out << ", " << n;
      out << (files.plotted ? ", green_functions.png" : "")
          << (with_deflection ? ", ring_deflection.vtu" : "") << " in " << directory.string()
          << "\n";
      if (global.print_timings)
        out << "Total run time "
            << format_printf(
                 "%.4g",
                 std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count())
            << " s\n";
    }
  } // namespace scenes
} // namespace greentread

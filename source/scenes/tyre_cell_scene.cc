#include <greentread/analysis/tyre_cell_output.h>
#include <greentread/base/exceptions.h>
#include <greentread/base/output.h>
#include <greentread/base/parameters.h>
#include <greentread/fe/abaqus_export.h>
#include <greentread/fe/elastic_model.h>
#include <greentread/fe/inflation.h>
#include <greentread/scenes/tyre_cell_scene.h>

#include <chrono>
#include <cmath>
#include <cstdio>
#include <iostream>

namespace greentread
{
  namespace scenes
  {
    namespace
    {

      class Stopwatch
      {
      public:
        double
        lap()
        {
          const auto   now     = std::chrono::steady_clock::now();
          const double seconds = std::chrono::duration<double>(now - last).count();
          last                 = now;
          return seconds;
        }

      private:
        std::chrono::steady_clock::time_point last = std::chrono::steady_clock::now();
      };
    } // namespace



    TyreCellScene::TyreCellScene(dealii::ParameterHandler &prm_, const GlobalParameters &global_)
        : prm(prm_)
        , global(global_)
        , full(global_.scene == "tyre-cell")
    {
      geometry.parse_parameters(prm);
      materials.parse_parameters(prm);
      inflation.parse_parameters(prm);
    }



    void
    TyreCellScene::run()
    {
      namespace fs = std::filesystem;
      Stopwatch    clock;
      const auto   cell      = std::make_unique<geometry::TyreCell>(geometry);
      const double mesh_time = clock.lap();

      const fs::path directory = base::prepare_output_directory(global.output_directory);
      const auto     record =
        base::ParameterRecord::from(prm, global.scene, recorded_sections(global.scene));

      fe::ElasticModel model(cell->cell(), materials.materials());
      model.assemble();
      const double assembly_time = clock.lap();

      const auto   u              = fe::solve_inflation(model, cell->angle(), inflation.pressure);
      const double inflation_time = clock.lap();

      double kp_time = 0.;
      if (full)
        {
          model.assemble_geometric_stiffness(u);
          kp_time = clock.lap();
        }

      const auto [growth, crown] = fe::tread_growth(model, u, geometry.outer_radius());

      // Outputs.
      const std::string geo_name = fs::path(geometry.geo_file).filename().string();
      const bool        plotted  = analysis::write_section(directory, *cell, geo_name, record);
      analysis::write_inflated_cell(directory, model, u);
      const auto masses =
        analysis::write_mass_report(directory / "mass_report.csv", *cell, model, materials, record);
      if (full)
        fe::write_abaqus(directory / "tyre_cell.inp", cell->cell(), model.mapping(), materials,
                         record);

      std::cout << "GreenTread: scene '" << global.scene << "', the tyre's periodic cell "
                << "(Meftah et al. 2013, Section 4)\n"
                << "  section: " << geo_name << ", " << cell->section().n_active_cells()
                << " quadrilaterals; cell: 2 pi / " << cell->n_cells() << " = "
                << format_printf("%.4g", cell->angle() * 180. / M_PI) << " degrees, "
                << cell->cell().n_active_cells() << " hexahedra, " << model.dof_handler().n_dofs()
                << " DoFs (quadratic elements)\n"
                << "Masses of the layers in the cell (quadrature against Pappus):\n"
                << masses.lines << "  whole tyre "
                << format_printf("%.4f", masses.total * cell->n_cells()) << " kg\n"
                << "Inflation at " << format_number(inflation.pressure)
                << " Pa: radial growth of the tread " << format_printf("%.4g", 1e3 * growth)
                << " mm (crown " << format_printf("%.4g", 1e3 * crown)
                << " mm), largest von Mises stress "
                << format_printf("%.4g", 1e-6 * model.max_von_mises(u)) << " MPa\n";
      if (full)
        std::cout << "Matrices K, M, C (Rayleigh) and Kp (prestress of the inflation; the "
                     "pressure's load stiffness is not included): "
                  << model.stiffness().n_nonzero_elements() << " nonzeros each\n";
      if (global.print_timings)
        std::cout << "Run time: mesh " << format_printf("%.3g", mesh_time) << " s, assembly "
                  << format_printf("%.3g", assembly_time) << " s, inflation "
                  << format_printf("%.3g", inflation_time) << " s"
                  << (full ? ", Kp " + format_printf("%.3g", kp_time) + " s" : std::string())
                  << "\n";
      std::cout << "Wrote section.vtu" << (plotted ? ", section.png" : "")
                << ", inflated_cell.vtu, inflated_cell.pvd, mass_report.csv"
                << (full ? ", tyre_cell.inp" : "") << " in " << directory.string() << "\n";
    }
  } // namespace scenes
} // namespace greentread

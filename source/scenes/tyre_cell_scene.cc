#include <greentread/base/exceptions.h>
#include <greentread/base/output.h>
#include <greentread/base/parameters.h>
#include <greentread/base/plot.h>
#include <greentread/fe/abaqus_export.h>
#include <greentread/fe/cylindrical.h>
#include <greentread/fe/elastic_model.h>
#include <greentread/fe/inflation.h>
#include <greentread/scenes/tyre_cell_scene.h>

#include <deal.II/base/data_out_base.h>
#include <deal.II/numerics/data_out.h>

#include <chrono>
#include <cmath>
#include <cstdio>
#include <iostream>
#include <sstream>

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
      , full(global_.scene == "tire-cell")
    {
      geometry.parse_parameters(prm);
      materials.parse_parameters(prm);
      inflation.parse_parameters(prm);
    }



    void
    TyreCellScene::run()
    {
      namespace fs = std::filesystem;
      Stopwatch  clock;
      const auto cell = std::make_unique<geometry::TyreCell>(geometry);
      const double mesh_time = clock.lap();

      const fs::path directory = base::prepare_output_directory(global.output_directory);
      const auto     record    = base::ParameterRecord::from(prm, global.scene, recorded_sections(global.scene));

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
      {
        dealii::DataOut<2>    out;
        dealii::Vector<float> material(cell->section().n_active_cells());
        for (const auto &c : cell->section().active_cell_iterators())
          material[c->active_cell_index()] = c->material_id();
        out.attach_triangulation(cell->section());
        out.add_data_vector(material, "material_id");
        out.build_patches();
        base::AtomicFile vtu(directory / "section.vtu");
        out.write_vtu(vtu.stream());
        vtu.commit();
      }
      model.write_vtu(u, directory / "inflated_cell.vtu");
      {
        base::AtomicFile pvd(directory / "inflated_cell.pvd");
        dealii::DataOutBase::write_pvd_record(pvd.stream(), {{0., "inflated_cell.vtu"}});
        pvd.commit();
      }
      const auto             all         = materials.materials();
      const auto             fe_masses   = model.masses();
      double                 total       = 0., total_exact = 0.;
      std::ostringstream     mass_lines;
      {
        base::AtomicFile file(directory / "mass_report.csv");
        auto            &out = file.stream();
        out.precision(10);
        // A layer with curved edges has no closed-form volume: its columns
        // say "n/a" (so do the totals), never a NaN.
        out << "layer,fe_mass,analytic_mass,relative_difference\n";
        bool all_exact = true;
        for (const auto &[id, mass] : fe_masses)
          {
            const auto   volume = cell->analytic_volume(id);
            const double exact  = volume ? all.at(id).density * *volume : 0.;
            const std::string &name = all.at(id).name;
            out << name << ',' << mass << ',';
            mass_lines << "  " << name << std::string(10 - name.size(), ' ') << format_printf("%.6e", mass)
                       << " kg  ";
            if (volume)
              {
                out << exact << ',' << mass / exact - 1. << '\n';
                mass_lines << "Pappus " << format_printf("%.6e", exact) << " kg  relative difference "
                           << format_printf("%.1e", 100. * (mass / exact - 1.)) << " %\n";
              }
            else
              {
                out << "n/a,n/a\n";
                mass_lines << "Pappus n/a (the layer has curved edges)\n";
              }
            all_exact = all_exact && volume.has_value();
            total += mass;
            total_exact += exact;
          }
        out << "cell," << total << ',';
        if (all_exact)
          out << total_exact << ',' << total / total_exact - 1. << '\n';
        else
          out << "n/a,n/a\n";
        out << "tyre," << total * cell->n_cells() << ',';
        if (all_exact)
          out << total_exact * cell->n_cells() << ',' << total / total_exact - 1. << '\n';
        else
          out << "n/a,n/a\n";
        record.write_comments(out);
        file.commit();
      }
      if (full)
        fe::write_abaqus(directory / "tire_cell.inp", cell->cell(), model.mapping(), materials, record);

      // The section, coloured by material.
      std::ostringstream polygons;
      const char        *colour[5] = {"", "#303030", "#1f77b4", "#ff7f0e", "#b0b0b0"};
      const char        *name[5]   = {"", "tread", "belt", "sidewall", "bead"};
      std::string        plot;
      for (unsigned int id = 1; id <= 4; ++id)
        {
          polygons << "$M" << id << " << EOD\n";
          for (const auto &c : cell->section().active_cell_iterators())
            if (c->material_id() == id)
              {
                for (const unsigned int v : {0u, 1u, 3u, 2u, 0u})
                  polygons << 1e3 * c->vertex(v)[1] << ' ' << 1e3 * c->vertex(v)[0] << '\n';
                polygons << '\n';
              }
          polygons << "EOD\n";
          plot += std::string(plot.empty() ? "plot " : ", ") + "$M" + std::to_string(id) +
                  " with filledcurves closed fc rgb '" + colour[id] + "' fs solid 0.7 border "
                  "lc rgb 'white' title '" + name[id] + "'";
        }
      const bool plotted = base::plot_png(
        directory / "section.png",
        polygons.str() + "set size ratio -1\nset xlabel 'axial z [mm]'\nset ylabel 'radius [mm]'\n"
          "set key outside right\nset title noenhanced 'GreenTread tyre section: " +
          fs::path(geometry.geo_file).filename().string() + ", " +
          std::to_string(cell->section().n_active_cells()) + " quadrilaterals'\n" + plot + "\n",
        record, 1000, 800);

      std::cout << "GreenTread: scene '" << global.scene << "', the tyre's periodic cell "
                << "(Meftah et al. 2013, Section 4)\n"
                << "  section: " << fs::path(geometry.geo_file).filename().string() << ", "
                << cell->section().n_active_cells() << " quadrilaterals; cell: 2 pi / "
                << cell->n_cells() << " = " << format_printf("%.4g", cell->angle() * 180. / M_PI)
                << " degrees, " << cell->cell().n_active_cells() << " hexahedra, "
                << model.dof_handler().n_dofs() << " DoFs (quadratic elements)\n"
                << "Masses of the layers in the cell (quadrature against Pappus):\n"
                << mass_lines.str() << "  whole tyre " << format_printf("%.4f", total * cell->n_cells())
                << " kg\n"
                << "Inflation at " << format_number(inflation.pressure)
                << " Pa: radial growth of the tread " << format_printf("%.4g", 1e3 * growth) << " mm (crown "
                << format_printf("%.4g", 1e3 * crown) << " mm), largest von Mises stress "
                << format_printf("%.4g", 1e-6 * model.max_von_mises(u)) << " MPa\n";
      if (full)
        std::cout << "Matrices K, M, C (Rayleigh) and Kp (prestress of the inflation; the "
                     "pressure's load stiffness is not included): "
                  << model.stiffness().n_nonzero_elements() << " nonzeros each\n";
      if (global.print_timings)
        std::cout << "Run time: mesh " << format_printf("%.3g", mesh_time) << " s, assembly "
                  << format_printf("%.3g", assembly_time) << " s, inflation " << format_printf("%.3g", inflation_time)
                  << " s" << (full ? ", Kp " + format_printf("%.3g", kp_time) + " s" : std::string()) << "\n";
      std::cout << "Wrote section.vtu" << (plotted ? ", section.png" : "")
                << ", inflated_cell.vtu, inflated_cell.pvd, mass_report.csv"
                << (full ? ", tire_cell.inp" : "") << " in " << directory.string() << "\n";
    }
  } // namespace scenes
} // namespace greentread

#include <greentread/analysis/tyre_cell_output.h>
#include <greentread/base/exceptions.h>
#include <greentread/base/plot.h>

#include <deal.II/base/data_out_base.h>
#include <deal.II/numerics/data_out.h>

#include <sstream>

namespace greentread
{
  namespace analysis
  {
    bool
    write_section(const std::filesystem::path &directory,
                  const geometry::TyreCell    &cell,
                  const std::string           &geo_name,
                  const base::ParameterRecord &record)
    {
      {
        dealii::DataOut<2>    out;
        dealii::Vector<float> material(cell.section().n_active_cells());
        for (const auto &c : cell.section().active_cell_iterators())
          material[c->active_cell_index()] = c->material_id();
        out.attach_triangulation(cell.section());
        out.add_data_vector(material, "material_id");
        out.build_patches();
        out.set_flags(base::undated_vtk_flags());
        base::AtomicFile vtu(directory / "section.vtu");
        out.write_vtu(vtu.stream());
        vtu.commit();
      }
      // The section, coloured by material.
      std::ostringstream polygons;
      const char        *colour[5] = {"", "#303030", "#1f77b4", "#ff7f0e", "#b0b0b0"};
      const char        *name[5]   = {"", "tread", "belt", "sidewall", "bead"};
      std::string        plot;
      for (unsigned int id = 1; id <= 4; ++id)
        {
          polygons << "$M" << id << " << EOD\n";
          for (const auto &c : cell.section().active_cell_iterators())
            if (c->material_id() == id)
              {
                for (const unsigned int v : {0u, 1u, 3u, 2u, 0u})
                  polygons << 1e3 * c->vertex(v)[1] << ' ' << 1e3 * c->vertex(v)[0] << '\n';
                polygons << '\n';
              }
          polygons << "EOD\n";
          plot += std::string(plot.empty() ? "plot " : ", ") + "$M" + std::to_string(id) +
                  " with filledcurves closed fc rgb '" + colour[id] +
                  "' fs solid 0.7 border "
                  "lc rgb 'white' title '" +
                  name[id] + "'";
        }
      return base::plot_png(
        directory / "section.png",
        polygons.str() +
          "set size ratio -1\nset xlabel 'axial z [mm]'\nset ylabel 'radius [mm]'\n"
          "set key outside right\nset title noenhanced 'GreenTread tyre section: " +
          geo_name + ", " + std::to_string(cell.section().n_active_cells()) + " quadrilaterals'\n" +
          plot + "\n",
        record, 1000, 800);
    }



    void
    write_inflated_cell(const std::filesystem::path  &directory,
                        const fe::ElasticModel       &model,
                        const dealii::Vector<double> &u)
    {
      model.write_vtu(u, directory / "inflated_cell.vtu");
      base::AtomicFile pvd(directory / "inflated_cell.pvd");
      dealii::DataOutBase::write_pvd_record(pvd.stream(), {{0., "inflated_cell.vtu"}});
      pvd.commit();
    }



    MassReport
    write_mass_report(const std::filesystem::path  &file_name,
                      const geometry::TyreCell     &cell,
                      const fe::ElasticModel       &model,
                      const fe::MaterialParameters &materials,
                      const base::ParameterRecord  &record)
    {
      const auto         all       = materials.materials();
      const auto         fe_masses = model.masses();
      double             total = 0., total_exact = 0.;
      std::ostringstream lines;
      base::AtomicFile   file(file_name);
      auto              &out = file.stream();
      out.precision(10);
      out << "layer,fe_mass,analytic_mass,relative_difference\n";
      bool all_exact = true;
      for (const auto &[id, mass] : fe_masses)
        {
          const auto         volume = cell.analytic_volume(id);
          const double       exact  = volume ? all.at(id).density * *volume : 0.;
          const std::string &name   = all.at(id).name;
          out << name << ',' << mass << ',';
          lines << "  " << name << std::string(10 - name.size(), ' ') << format_printf("%.6e", mass)
                << " kg  ";
          if (volume)
            {
              out << exact << ',' << mass / exact - 1. << '\n';
              lines << "Pappus " << format_printf("%.6e", exact) << " kg  relative difference "
                    << format_printf("%.1e", 100. * (mass / exact - 1.)) << " %\n";
            }
          else
            {
              out << "n/a,n/a\n";
              lines << "Pappus n/a (the layer has curved edges)\n";
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
      out << "tyre," << total * cell.n_cells() << ',';
      if (all_exact)
        out << total_exact * cell.n_cells() << ',' << total / total_exact - 1. << '\n';
      else
        out << "n/a,n/a\n";
      record.write_comments(out);
      file.commit();
      return {lines.str(), total};
    }
  } // namespace analysis
} // namespace greentread

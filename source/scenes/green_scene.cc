#include <greentread/base/exceptions.h>
#include <greentread/base/output.h>
#include <greentread/base/parameters.h>
#include <greentread/base/plot.h>
#include <greentread/config.h>
#include <greentread/green_sources_digest.h>
#include <greentread/fe/cylindrical.h>
#include <greentread/periodic/deflection_shape.h>
#include <greentread/scenes/green_scene.h>

#include <deal.II/base/conditional_ostream.h>

#include <chrono>
#include <cmath>
#include <cstdint>
#include <fstream>
#include <iomanip>
#include <iostream>
#include <sstream>

namespace greentread
{
  namespace scenes
  {
    namespace
    {
      double
      seconds_since(const std::chrono::steady_clock::time_point start)
      {
        return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
      }

      /// FNV-1a of a file's bytes, as 16 hex digits: stable across runs and
      /// builds, unlike std::hash. An empty string if it cannot be read.
      std::string
      file_digest(const std::string &file)
      {
        std::ifstream in(file, std::ios::binary);
        if (!in)
          return {};
        std::uint64_t     hash = 1469598103934665603ull;
        std::vector<char> buffer(1 << 20);
        while (in)
          {
            in.read(buffer.data(), buffer.size());
            for (std::streamsize i = 0; i < in.gcount(); ++i)
              {
                hash ^= static_cast<unsigned char>(buffer[i]);
                hash *= 1099511628211ull;
              }
          }
        std::ostringstream hex;
        hex << std::hex << std::setw(16) << std::setfill('0') << hash;
        return hex.str();
      }

      /// Run @p work on every rank; an InputError or NumericalError on any
      /// rank is thrown on all of them (throw_if_any_rank_failed()).
      template <typename Work>
      void
      collectively(const MPI_Comm comm, Work &&work)
      {
        RankFailure failure = RankFailure::none;
        std::string message;
        try
          {
            work();
          }
        catch (const InputError &e)
          {
            failure = RankFailure::input;
            message = e.what();
          }
        catch (const NumericalError &e)
          {
            failure = RankFailure::numerical;
            message = e.what();
          }
        throw_if_any_rank_failed(comm, failure, message);
      }
    } // namespace



    InflatedTyre::InflatedTyre(const geometry::GeometryParameters &geometry,
                               const fe::MaterialParameters       &materials,
                               const fe::InflationParameters          &inflation,
                               const periodic::PatchRequest       &patch_request)
    {
      auto start   = std::chrono::steady_clock::now();
      cell         = std::make_unique<geometry::TyreCell>(geometry);
      mesh_seconds = seconds_since(start);

      start = std::chrono::steady_clock::now();
      model = std::make_unique<fe::ElasticModel>(cell->cell(), materials.materials());
      model->assemble();
      assembly_seconds = seconds_since(start);

      start        = std::chrono::steady_clock::now();
      const auto u = fe::solve_inflation(*model, cell->angle(), inflation.pressure);
      model->assemble_geometric_stiffness(u);
      inflation_seconds = seconds_since(start);

      tread_growth = fe::tread_growth(*model, u, geometry.outer_radius()).first;
      periodic_cell = periodic::make_periodic_cell(
        *model, cell->angle(), cell->n_cells(), geometry::rim_seat, geometry::tread_surface, true);
      patch = periodic::place_contact_points(periodic_cell, patch_request);
    }



    std::string
    green_stage_key(const dealii::ParameterHandler &prm, const std::string &geo_file)
    {
      std::ostringstream key;
      // What the Green's functions depend on, and nothing else: the digest
      // of the sources that compute them (taken when building, so it sees
      // uncommitted edits and ignores commits that touch other code), the
      // .geo file's content (not its path, which depends on the working
      // directory) and the parameters. Not the git revision: a commit to
      // the README would throw away five minutes of solves.
      const std::string geo_digest = file_digest(geo_file);
      if (geo_digest.empty())
        throw InputError("parameter 'Geometry/Geometry file' = " + geo_file +
                         ": the file cannot be read");
      key << "greentread " << GREENTREAD_VERSION << '\n'
          << "sources digest " << GREENTREAD_GREEN_SOURCES_DIGEST << '\n'
          << "geo file digest " << geo_digest << '\n';
      const auto record = base::ParameterRecord::from(
        prm, "", {"Geometry", "Materials", "Inflation", "Green's functions"});
      for (const auto &[path, value] : record.entries)
        if (path != "Green's functions/Pairs" &&
            path != "Green's functions/Deflection shape frequency" &&
            path != "Geometry/Geometry file")
          key << path << " = " << value << '\n';
      return key.str();
    }



    GreenStageResult
    run_green_stage(const InflatedTyre              &tyre,
                    const periodic::GreenParameters &parameters,
                    const std::string               &key,
                    const std::filesystem::path     &h5,
                    const base::ParameterRecord     &record,
                    const bool                       reuse_saved,
                    const bool                       show_progress,
                    const MPI_Comm                   comm)
    {
      const unsigned int rank = dealii::Utilities::MPI::this_mpi_process(comm);
      GreenStageResult   result;
      // Rank 0 decides, every rank follows.
      int reuse = 0;
      if (rank == 0 && reuse_saved)
        reuse = modal::read_green_stage_key(h5.string()) == key;
      MPI_Bcast(&reuse, 1, MPI_INT, 0, comm);
      if (reuse)
        {
          result.reused = true;
          if (rank == 0)
            result.green = modal::read_green_hdf5(h5.string());
          return result;
        }
      result.green = periodic::compute_green_functions(
        tyre.periodic_cell, tyre.patch, periodic::parse_method(parameters.method),
        parameters.frequency_step, parameters.n_lines(), comm, show_progress, result.report);
      if (rank == 0)
        modal::write_green_hdf5(h5, result.green, record, key);
      return result;
    }



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
      const auto     record    = base::ParameterRecord::from(prm, global.scene, recorded_sections(global.scene));

      // Every rank builds the tyre; a rank that fails (a file it cannot
      // read) must not leave the others waiting in the frequency loop.
      std::unique_ptr<InflatedTyre>                      built;
      std::vector<std::pair<unsigned int, unsigned int>> pairs;
      std::string                                        key;
      collectively(comm, [&]() {
        built = std::make_unique<InflatedTyre>(geometry, materials, inflation, green.patch);
        pairs = green.csv_pairs(built->patch);
        key   = green_stage_key(prm, geometry.geo_file);
      });
      const InflatedTyre &tyre = *built;
      const auto        &pc    = tyre.periodic_cell;
      out << "GreenTread: scene 'tire-green', Green's functions of the inflated ring at the "
             "contact points (Meftah et al. 2013, Section 4.2)\n"
          << "  ring: N = " << pc.n_cells << " cells of " << tyre.model->dof_handler().n_dofs()
          << " DoFs; reference cell " << pc.size() << " free DoFs (faces " << pc.n_face
          << " each, interior " << pc.n_interior << "), inflated at "
          << format_number(inflation.pressure) << " Pa (tread growth "
          << format_printf("%.4g", 1e3 * tyre.tread_growth) << " mm)\n"
          << "  " << tyre.patch.describe(green.patch) << '\n'
          << "  frequencies 0 to " << format_number(green.max_frequency) << " Hz every "
          << format_number(green.frequency_step) << " Hz (" << green.n_lines()
          << " lines), method '" << green.method << "'\n";

      const fs::path h5 = directory / "green_functions.h5";
      const auto result = run_green_stage(tyre, green, key, h5,
                                          record, global.reuse, global.print_timings, comm);
      if (result.reused)
        out << "Reusing " << h5.string()
            << ": it was computed with the same geometry, materials, inflation and "
               "Green's-function parameters\n";
      else
        {
          out << "Every solve checked: largest backward error "
              << format_printf("%.2g", result.report.diagnostics.max_residual)
              << ", largest condition estimate "
              << format_printf("%.2g", result.report.diagnostics.max_condition) << "\n";
          if (global.print_timings)
            out << "Run time on " << result.report.ranks << " MPI rank(s) x "
                << result.report.threads << " thread(s): mesh "
                << format_printf("%.3g", tyre.mesh_seconds) << " s, assembly "
                << format_printf("%.3g", tyre.assembly_seconds) << " s, inflation and Kp "
                << format_printf("%.3g", tyre.inflation_seconds) << " s, Green's functions "
                << format_printf("%.4g", result.report.seconds) << " s ("
                << format_printf("%.3g", result.report.seconds * result.report.ranks *
                                           result.report.threads / green.n_lines())
                << " core-seconds per frequency)\n";
        }

      // The ring's deflection shape: one frequency, rank 0 alone.
      periodic::SolveDiagnostics deflection;
      const bool                 with_deflection = green.deflection_frequency >= 0.;
      const unsigned int         centre          = pairs.front().second;
      if (with_deflection && rank == 0)
        {
          const auto &q = tyre.patch.points[centre];
          const auto u = periodic::ring_response(pc, 2. * M_PI * green.deflection_frequency, q.cell,
                                                 q.dof, deflection);
          periodic::write_ring_deflection(directory / "ring_deflection.vtu", tyre.cell->cell(), pc,
                                          u);
        }
      if (rank != 0)
        return;

      // The contact points.
      {
        base::AtomicFile file(directory / "contact_points.csv");
        auto            &o = file.stream();
        o.precision(10);
        o << "point,i_x,i_y,x,y,radius,cell\n";
        for (unsigned int p = 0; p < tyre.patch.points.size(); ++p)
          {
            const auto &c = tyre.patch.points[p];
            o << p << ',' << p / tyre.patch.points_across << ',' << p % tyre.patch.points_across
              << ',' << c.x << ',' << c.y << ',' << c.radius << ',' << c.cell << '\n';
          }
        record.write_comments(o);
        file.commit();
      }

      // The chosen pairs as CSV, the format 'identify' reads, and plotted.
      std::vector<std::string> names;
      std::string              magnitude, phase;
      const char *colours[] = {"black", "#d62728", "#1f77b4", "#2ca02c", "#9467bd", "#8c564b"};
      for (std::size_t n = 0; n < pairs.size(); ++n)
        {
          const auto [i, j]      = pairs[n];
          const std::string name = "green_" + std::to_string(i) + "_" + std::to_string(j) + ".csv";
          modal::write_frf_csv(directory / name, result.green.get(i, j), record);
          names.push_back(name);
          const std::string data  = base::gnuplot_quote(directory / name);
          const std::string style = "with lines lw 2 lc rgb '" + std::string(colours[n % 6]) +
                                    "' title 'g_{" + std::to_string(i) + "," + std::to_string(j) +
                                    "}'";
          magnitude += (n ? ", " : "plot ") + data + " skip 1 using 1:(sqrt($2**2+$3**2)) " + style;
          phase += (n ? ", " : "plot ") + data + " skip 1 using 1:(atan2($3,$2)*180/pi) " + style;
        }
      const bool plotted = base::plot_png(
        directory / "green_functions.png",
        "set datafile separator ','\nset datafile commentschars '#'\nset multiplot layout 2,1 "
        "title 'GreenTread: radial Green functions of the inflated ring (" +
          std::to_string(pc.n_cells) + " cells, " + green.method +
          ")'\nset grid\nset xlabel 'f [Hz]'\nset ylabel '|g| [m/N]'\nset logscale y\n"
          "set format y '10^{%L}'\n" +
          magnitude +
          "\nunset logscale y\nset format y '%g'\nset ylabel 'phase [deg]'\nset yrange "
          "[-180:180]\nset ytics 90\n" +
          phase + "\nunset multiplot\n",
        record, 1100, 800);

      // The driving point: resonance and passivity at a glance.
      const auto   driving = result.green.get(pairs.front().first, pairs.front().second);
      unsigned int peak    = 0;
      for (unsigned int k = 1; k < driving.values.size(); ++k)
        if (std::abs(driving.values[k]) > std::abs(driving.values[peak]))
          peak = k;
      // In um/N, so that the regression tests' absolute tolerance sees them.
      const auto transfer = result.green.get(pairs.back().first, pairs.back().second);
      out << "Driving point " << pairs.front().first << ": static receptance "
          << format_printf("%.6g", 1e6 * driving.values[0].real()) << " um/N, largest |g| "
          << format_printf("%.6g", 1e6 * std::abs(driving.values[peak])) << " um/N at "
          << format_number(peak * driving.df) << " Hz; g at f_max "
          << format_printf("%.6g", 1e6 * driving.values.back().real()) << " "
          << format_printf("%+.6g", 1e6 * driving.values.back().imag()) << "j um/N\n"
          << "Transfer g_" << pairs.back().first << "," << pairs.back().second << ": static "
          << format_printf("%.6g", 1e6 * transfer.values[0].real()) << " um/N, at f_max "
          << format_printf("%.6g", 1e6 * transfer.values.back().real()) << " "
          << format_printf("%+.6g", 1e6 * transfer.values.back().imag()) << "j um/N\n";
      if (with_deflection)
        out << "Deflection shape at " << format_number(green.deflection_frequency)
            << " Hz under a unit radial force at point " << centre << ": largest backward error "
            << format_printf("%.2g", deflection.max_residual) << "\n";
      out << "Wrote green_functions.h5, contact_points.csv";
      for (const auto &n : names)
        out << ", " << n;
      out << (plotted ? ", green_functions.png" : "")
          << (with_deflection ? ", ring_deflection.vtu" : "") << " in " << directory.string()
          << "\n";
      if (global.print_timings)
        out << "Total run time " << format_printf("%.4g", seconds_since(start)) << " s\n";
    }
  } // namespace scenes
} // namespace greentread

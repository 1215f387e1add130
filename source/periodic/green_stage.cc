#include <greentread/base/exceptions.h>
#include <greentread/base/parameters.h>
#include <greentread/base/progress.h>
#include <greentread/base/serial_deal_ii.h>
#include <greentread/config.h>
#include <greentread/green_sources_digest.h>
#include <greentread/periodic/green_stage.h>

#include <chrono>
#include <cstdint>
#include <fstream>
#include <iomanip>
#include <optional>
#include <sstream>
#include <vector>

namespace greentread
{
  namespace periodic
  {
    namespace
    {
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
    } // namespace



    InflatedTyre::InflatedTyre(const geometry::GeometryParameters   &geometry,
                               const fe::MaterialParameters         &materials,
                               const fe::InflationParameters        &inflation,
                               const PatchRequest                   &patch_request,
                               const std::optional<HarmonicOptions> &harmonic_options)
    {
      if (!harmonic_options && geometry.cell_degree() > 2)
        throw InputError(
          "parameter 'Geometry/Element degree' = " + std::to_string(geometry.cell_degree()) +
          " is not allowed with a 3D cell; allowed: 1 or 2 (up to 4 with "
          "'Green's functions/Method' = harmonic)");
      if (harmonic_options && materials.tread_surface_mass_inward)
        throw InputError("parameter 'Materials/Tread pattern/Surface mass' = inward is not "
                         "allowed with 'Green's functions/Method' = harmonic; allowed there: "
                         "consistent");
      // The finite-element set-up with deal.II on one thread (its round-off
      // then does not depend on the thread count), up to the harmonic ring,
      // whose harmonics go on GreenTread's threads.
      std::optional<base::SerialDealII> serial(std::in_place);
      auto                              start = std::chrono::steady_clock::now();
      cell                                    = std::make_unique<geometry::TyreCell>(geometry);
      mesh_seconds                            = base::seconds_since(start);

      // With the harmonic method the 3D cell only places the points: it
      // keeps quadratic elements whatever the section's degree.
      start = std::chrono::steady_clock::now();
      model = std::make_unique<fe::ElasticModel>(cell->cell(), materials.materials(),
                                                 std::min(geometry.cell_degree(), 2u));
      model->assemble();
      assembly_seconds = base::seconds_since(start);

      start        = std::chrono::steady_clock::now();
      const auto u = fe::solve_inflation(*model, cell->angle(), inflation.pressure);
      model->assemble_geometric_stiffness(u);
      inflation_seconds = base::seconds_since(start);

      tread_growth  = fe::tread_growth(*model, u, geometry.outer_radius()).first;
      periodic_cell = make_periodic_cell(*model, cell->angle(), cell->n_cells(), geometry::rim_seat,
                                         geometry::tread_surface, true);
      if (materials.tread_surface_mass_inward)
        moved_mass_fraction = move_tread_mass_inward(periodic_cell);
      patch = place_contact_points(periodic_cell, patch_request);

      if (harmonic_options)
        {
          start   = std::chrono::steady_clock::now();
          section = std::make_unique<fe::HarmonicSection>(cell->section(), materials.materials(),
                                                          geometry.section_degree());
          section->inflate(inflation.pressure);
          serial.reset();
          harmonic = std::make_unique<HarmonicRing>(*section, patch, harmonic_options->tolerance,
                                                    harmonic_options->max_omega);
          if (harmonic_options->mode_cutoff > 0.)
            check_mode_cutoff(*harmonic, harmonic_options->mode_cutoff);
          harmonic_seconds = base::seconds_since(start);
        }
    }



    std::string
    InflatedTyre::describe(const double pressure) const
    {
      const auto &pc = periodic_cell;
      return "  ring: N = " + std::to_string(pc.n_cells) + " cells of " +
             std::to_string(model->dof_handler().n_dofs()) + " DoFs; reference cell " +
             std::to_string(pc.size()) + " free DoFs (faces " + std::to_string(pc.n_face) +
             " each, interior " + std::to_string(pc.n_interior) + "), inflated at " +
             format_number(pressure) + " Pa (tread growth " +
             format_printf("%.4g", 1e3 * tread_growth) + " mm)" +
             (moved_mass_fraction > 0. ?
                "; the tread surface's mass (" + format_printf("%.3g", 100. * moved_mass_fraction) +
                  "% of the cell's) moved inward" :
                std::string()) +
             "\n  " + patch.describe() + '\n' + (harmonic ? harmonic->describe() : std::string());
    }



    std::string
    green_stage_key(const dealii::ParameterHandler           &prm,
                    const std::string                        &geo_file,
                    const std::map<std::string, std::string> &replaced)
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
          {
            const auto other = replaced.find(path);
            key << path << " = " << (other != replaced.end() ? other->second : value) << '\n';
          }
      return key.str();
    }



    GreenStageResult
    run_green_stage(const InflatedTyre          &tyre,
                    const GreenParameters       &parameters,
                    const std::string           &key,
                    const std::filesystem::path &h5,
                    const base::ParameterRecord &record,
                    const bool                   reuse_saved,
                    const bool                   show_progress,
                    const MPI_Comm               comm)
    {
      const unsigned int rank = dealii::Utilities::MPI::this_mpi_process(comm);
      GreenStageResult   result;
      // Rank 0 decides, every rank follows.
      int reuse = 0;
      if (rank == 0 && reuse_saved)
        reuse = base::read_green_stage_key(h5.string()) == key;
      MPI_Bcast(&reuse, 1, MPI_INT, 0, comm);
      if (reuse)
        {
          result.reused = true;
          if (rank == 0)
            result.green = base::read_green_hdf5(h5.string());
          return result;
        }
      result.green = compute_green_functions(
        tyre.periodic_cell, tyre.patch, parse_method(parameters.method), parameters.frequency_step,
        parameters.n_lines(), comm, show_progress, result.report, tyre.harmonic.get());
      if (rank == 0)
        base::write_green_hdf5(h5, result.green, record, key);
      return result;
    }



    std::string
    describe(const GreenStageResult      &result,
             const InflatedTyre          &tyre,
             const GreenParameters       &parameters,
             const std::filesystem::path &h5,
             const bool                   timings)
    {
      if (result.reused)
        return "Reusing " + h5.string() +
               ": it was computed with the same geometry, materials, inflation and "
               "Green's-function parameters\n";
      const auto &report = result.report;
      std::string text   = "Every solve checked: largest backward error " +
                         format_printf("%.2g", report.diagnostics.max_residual) +
                         ", largest condition estimate " +
                         format_printf("%.2g", report.diagnostics.max_condition) + "\n";
      if (timings)
        text +=
          "Run time on " + std::to_string(report.ranks) + " MPI rank(s) x " +
          std::to_string(report.threads) + " thread(s): mesh " +
          format_printf("%.3g", tyre.mesh_seconds) + " s, assembly " +
          format_printf("%.3g", tyre.assembly_seconds) + " s, inflation and Kp " +
          format_printf("%.3g", tyre.inflation_seconds) + " s, " +
          (tyre.harmonic ?
             "section and harmonics " + format_printf("%.3g", tyre.harmonic_seconds) + " s, " :
             std::string()) +
          "Green's functions " + format_printf("%.4g", report.seconds) + " s (" +
          format_printf("%.3g",
                        report.seconds * report.ranks * report.threads / parameters.n_lines()) +
          " core-seconds per frequency)\n";
      return text;
    }
  } // namespace periodic
} // namespace greentread

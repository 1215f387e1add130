#include <greentread/analysis/third_octave.h>
#include <greentread/base/exceptions.h>
#include <greentread/base/output.h>
#include <greentread/modal_sources_digest.h>
#include <greentread/base/parameters.h>
#include <greentread/base/plot.h>
#include <greentread/base/progress.h>
#include <greentread/contact/patch_contact.h>
#include <greentread/scenes/green_scene.h>
#include <greentread/scenes/road_scene.h>

#include <deal.II/base/multithread_info.h>
#include <deal.II/base/utilities.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <deque>
#include <filesystem>
#include <functional>
#include <iostream>
#include <sstream>

namespace greentread
{
  namespace scenes
  {
    namespace
    {
      /// A file name part for a road: its name without directories or dots.
      std::string
      road_label(const std::string &road)
      {
        std::string label = std::filesystem::path(road).stem().string();
        for (auto &c : label)
          if (!std::isalnum(static_cast<unsigned char>(c)) && c != '-')
            c = '_';
        return label;
      }

      std::string
      speed_label(const double v)
      {
        return format_printf("%g", v) + "kmh";
      }

      /**
       * Read a saved stage whose key matched by @p read. A file that cannot
       * be read in full (truncated, or holding a value that is not finite)
       * is not an error of the user's: say so and return false, so that the
       * stage is computed again and the file rewritten.
       */
      bool
      read_saved_stage(const std::filesystem::path &file, const std::function<void()> &read)
      {
        try
          {
            read();
            return true;
          }
        catch (const std::exception &e)
          {
            std::cout << "Not reusing " << file.string() << ", although its key matches: "
                      << e.what() << "; computing it again\n";
            return false;
          }
      }
    } // namespace



    void
    RollingParameters::declare_parameters(dealii::ParameterHandler &prm)
    {
      using base::RangePattern;
      prm.enter_subsection("Rolling");
      {
        prm.declare_entry("Speeds", "50, 70, 90", dealii::Patterns::List(dealii::Patterns::Double(1., 400.)),
                          "Rolling speeds V0 in km/h, a comma-separated list (1 to 400).");
        prm.declare_entry("Distance", "2", RangePattern::closed(0.01, 20., "m"),
                          "Distance rolled in each run (the paper: 2 m).");
        prm.declare_entry("Time step", "auto", dealii::Patterns::Anything(),
                          "'auto': the road's sampling interval divided by the speed (one road "
                          "sample per step, as the paper); or a time step in s (1e-8 to 1e-3).");
        prm.declare_entry("Static load", "600", RangePattern::closed(0., 1e5, "N"),
                          "Static load carried by the patch; the indentation that carries it is "
                          "found on the road where the run starts and then held (the rim does "
                          "not move). 0: use 'Indentation' instead.");
        prm.declare_entry("Indentation", "0", RangePattern::closed(-0.05, 0.05, "m"),
                          "Used when 'Static load' = 0: how far the road is pushed into the "
                          "tread, measured from the lowest tread point.");
        prm.declare_entry("Start from static equilibrium", "true", dealii::Patterns::Bool(),
                          "Start each run from the static contact (the loads applied for ever, "
                          "the tyre at rest) so that no impact transient pollutes the spectra; "
                          "'false' starts from an unloaded tyre suddenly indented.");
        prm.declare_entry("Convolution", "modal-recursive",
                          dealii::Patterns::Selection("modal-recursive|direct"),
                          "'modal-recursive': the exact modal recursion, O(N_m N_p^2) per step. "
                          "'direct': the convolution sum over every past step with the same "
                          "kernels (the reference; O(N_p^2 N_g) per step and memory).");
        prm.declare_entry("Direct kernel length", "0", dealii::Patterns::Integer(0),
                          "Steps kept by 'direct' (0: the whole run).");
        prm.declare_entry("Frames", "40", dealii::Patterns::Integer(1, 10000),
                          "Contact-stress maps written per run (VTU time series).");
        prm.declare_entry("Stress reference", "100", RangePattern::positive("Pa"),
                          "sigma0 of L_f = 20 log10(|sigma| / sigma0), Eq. (52): the paper "
                          "gives 10^2 (printed N/m; a stress is in N/m^2 = Pa).");
      }
      prm.leave_subsection();
    }



    void
    RollingParameters::parse_parameters(dealii::ParameterHandler &prm)
    {
      prm.enter_subsection("Rolling");
      {
        speeds.clear();
        for (const auto &s : base::split_list(prm.get("Speeds")))
          speeds.push_back(std::stod(s));
        if (speeds.empty())
          throw InputError("parameter 'Rolling/Speeds' is empty; allowed: a list of speeds in "
                           "km/h from 1 to 400");
        distance             = prm.get_double("Distance");
        const std::string ts = prm.get("Time step");
        if (ts == "auto")
          time_step = 0.;
        else
          {
            char  *end = nullptr;
            time_step  = std::strtod(ts.c_str(), &end);
            if (end == ts.c_str() || *end != '\0' || !(time_step >= 1e-8 && time_step <= 1e-3))
              throw InputError("parameter 'Rolling/Time step' = '" + ts +
                               "' is not allowed; allowed: 'auto' or a number from 1e-8 to "
                               "1e-3 (s)");
          }
        static_load      = prm.get_double("Static load");
        indentation      = prm.get_double("Indentation");
        static_start     = prm.get_bool("Start from static equilibrium");
        convolution      = prm.get("Convolution");
        direct_kernel    = prm.get_integer("Direct kernel length");
        frames           = prm.get_integer("Frames");
        stress_reference = prm.get_double("Stress reference");
      }
      prm.leave_subsection();
    }



    namespace
    {
      /**
       * The highest band of a run's spectrum: 5 kHz, or the highest band
       * below the Nyquist frequency 1 / (2 dt) of a coarser time step.
       * @throws InputError naming 'Rolling/Time step' if not even the 100 Hz
       * band fits.
       */
      double
      spectrum_top_band(const double dt)
      {
        double top = 0.;
        for (const auto &band : analysis::third_octave_bands(100., 5000.))
          if (band.upper <= 0.5 / dt)
            top = band.nominal;
        if (top == 0.)
          throw InputError("parameter 'Rolling/Time step' = " + format_short(dt) +
                           " s: the spectra need frequencies up to at least 112 Hz (the 100 Hz "
                           "band); allowed: a time step <= " +
                           format_short(0.5 / analysis::third_octave_bands(100., 100.)[0].upper) +
                           " s");
        return top;
      }
    } // namespace



    std::string
    patch_model_stage_key(const dealii::ParameterHandler &prm, const std::string &green_key)
    {
      // The record's entries only: its header names the git revision, which
      // must not throw the fit away (the sources' digest stands for it).
      std::ostringstream key;
      key << green_key << "\n--- modal ---\nsources digest " << GREENTREAD_MODAL_SOURCES_DIGEST
          << '\n';
      for (const auto &[path, value] :
           base::ParameterRecord::from(prm, "", {"Identification", "Patch model"}).entries)
        key << path << " = " << value << '\n';
      return key.str();
    }



    RoadContactScene::RoadContactScene(dealii::ParameterHandler &prm_,
                                       const GlobalParameters   &global_)
      : prm(prm_)
      , global(global_)
    {
      geometry.parse_parameters(prm);
      materials.parse_parameters(prm);
      inflation.parse_parameters(prm);
      green.parse_parameters(prm);
      identification.parse_parameters(prm);
      patch_model.parse_parameters(prm);
      roads.parse_parameters(prm);
      rolling.parse_parameters(prm);

      // A texture file is read now, not after the Green's functions (five
      // minutes): a malformed file, or one too narrow or too short for the
      // patch and the distance, is refused at once. The patch is the one
      // asked for; the points snap to tread nodes later, and PatchRoad
      // checks their exact extent again.
      for (const auto &name : roads.roads)
        if (!road::RoadTextureParameters::is_built_in(name) && texture_files.count(name) == 0)
          {
            road::Texture t = road::read_texture(name);
            const double  needed_width = green.patch.width + 2. * t.dy;
            if (t.ny > 1 && t.ny * t.dy < needed_width)
              throw InputError("texture file '" + name + "' is " + format_short(t.ny * t.dy) +
                               " m wide; the patch ('Green's functions/Patch width' = " +
                               format_short(green.patch.width) + " m) needs " +
                               format_short(needed_width) + " m");
            const double usable = t.length() - green.patch.length - 2. * t.dx;
            if (rolling.distance > usable)
              throw InputError("parameter 'Rolling/Distance' = " + format_short(rolling.distance) +
                               " m is longer than texture file '" + name + "' allows (" +
                               format_short(std::max(0., usable)) + " m: the file is " +
                               format_short(t.length()) + " m long, the patch " +
                               format_short(green.patch.length) + " m)");
            texture_files.emplace(name, std::move(t));
          }

      // The spectra of each run, checked now rather than after the run: the
      // time step must resolve the 100 Hz band, and the record must be long
      // enough for its Fourier lines to fall in that band.
      const auto   lowest = analysis::third_octave_bands(100., 100.)[0];
      const double needed = 1. / (lowest.upper - lowest.lower);
      for (const auto &name : roads.roads)
        {
          const auto   file    = texture_files.find(name);
          const double spacing = file != texture_files.end() ? file->second.dx : roads.spacing;
          for (const double speed_kmh : rolling.speeds)
            {
              const double V  = speed_kmh / 3.6;
              const double dt = rolling.time_step > 0. ? rolling.time_step : spacing / V;
              spectrum_top_band(dt);
              if (rolling.distance / V < needed)
                throw InputError("parameter 'Rolling/Distance' = " +
                                 format_short(rolling.distance) + " m lasts " +
                                 format_short(rolling.distance / V) + " s at " +
                                 format_number(speed_kmh) +
                                 " km/h; the 100 Hz band of the spectra needs a record of at "
                                 "least " + format_short(needed) + " s; allowed: a distance >= " +
                                 format_short(needed * V) + " m");
            }
        }
    }



    namespace
    {
      /// The results of one run that the summaries need.
      struct RunResult
      {
        std::string                 road;
        double                      speed = 0.;
        analysis::BandSpectrum      spectrum;
        double                      seconds = 0., mean_force = 0.;
        unsigned int                steps = 0, failed_steps = 0, fallback_points = 0;
        double                      max_contact_fraction = 0., min_contact_fraction = 1.;
      };

      void
      write_vtu_frame(const std::filesystem::path              &file,
                      const std::vector<std::array<double, 3>> &points,
                      unsigned int                              nx,
                      unsigned int                              ny,
                      const Eigen::VectorXd                    &stress,
                      const Eigen::VectorXd                    &displacement,
                      const Eigen::VectorXd                    &demand)
      {
        // Points on the lattice p = i_x ny + i_y, one quad between 4 neighbours.
        base::AtomicFile f(file);
        auto            &o = f.stream();
        o.precision(9);
        const unsigned int n_cells = (nx - 1) * (ny - 1);
        o << "<?xml version=\"1.0\"?>\n<VTKFile type=\"UnstructuredGrid\" version=\"0.1\" "
             "byte_order=\"LittleEndian\">\n<UnstructuredGrid>\n<Piece NumberOfPoints=\""
          << points.size() << "\" NumberOfCells=\"" << n_cells << "\">\n<Points>\n"
          << "<DataArray type=\"Float64\" NumberOfComponents=\"3\" format=\"ascii\">\n";
        for (const auto &p : points)
          o << p[0] << ' ' << p[1] << " 0\n";
        o << "</DataArray>\n</Points>\n<Cells>\n<DataArray type=\"Int32\" Name=\"connectivity\" "
             "format=\"ascii\">\n";
        for (unsigned int i = 0; i + 1 < nx; ++i)
          for (unsigned int j = 0; j + 1 < ny; ++j)
            o << i * ny + j << ' ' << (i + 1) * ny + j << ' ' << (i + 1) * ny + j + 1 << ' '
              << i * ny + j + 1 << '\n';
        o << "</DataArray>\n<DataArray type=\"Int32\" Name=\"offsets\" format=\"ascii\">\n";
        for (unsigned int c = 1; c <= n_cells; ++c)
          o << 4 * c << '\n';
        o << "</DataArray>\n<DataArray type=\"UInt8\" Name=\"types\" format=\"ascii\">\n";
        for (unsigned int c = 0; c < n_cells; ++c)
          o << "9\n";
        o << "</DataArray>\n</Cells>\n<PointData Scalars=\"contact_stress\">\n";
        const auto array = [&](const char *name, const Eigen::VectorXd &v) {
          o << "<DataArray type=\"Float64\" Name=\"" << name << "\" format=\"ascii\">\n";
          for (Eigen::Index k = 0; k < v.size(); ++k)
            o << v[k] << '\n';
          o << "</DataArray>\n";
        };
        array("contact_stress", stress);
        array("displacement", displacement);
        array("road_demand", demand);
        o << "</PointData>\n</Piece>\n</UnstructuredGrid>\n</VTKFile>\n";
        f.commit();
      }
    } // namespace



    void
    RoadContactScene::run()
    {
      namespace fs     = std::filesystem;
      const auto start = std::chrono::steady_clock::now();
      const auto since = [](const std::chrono::steady_clock::time_point t0) {
        return std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
      };
      const fs::path directory = base::prepare_output_directory(global.output_directory);
      const auto     record    = base::ParameterRecord::from(
        prm, global.scene,
        {"Scene", "Output directory", "Geometry", "Materials", "Inflation", "Green's functions",
         "Identification", "Patch model", "Road texture", "Rolling"});
      std::cout << "GreenTread: scene 'tire-road-contact', dynamic contact of the rolling tyre "
                   "on road textures (Meftah et al. 2013, Section 5)\n";

      // Stages 1-3: geometry, fe, periodic (cached Green's functions).
      const std::string green_key = green_stage_key(prm, geometry.geo_file);
      const fs::path    h5        = directory / "green_functions.h5";
      modal::FrequencyResponseMatrix G;
      const bool green_cached =
        global.reuse && modal::read_green_stage_key(h5.string()) == green_key &&
        read_saved_stage(h5, [&] { G = modal::read_green_hdf5(h5.string()); });
      if (green_cached)
        std::cout << "Reusing " << h5.string()
                  << ": same geometry, materials, inflation and Green's-function parameters\n";
      else
        {
          std::cout << "Stages geometry -> fe -> periodic: the Green's functions at "
                    << green.patch.points_along * green.patch.points_across << " points, 0 to "
                    << format_number(green.max_frequency) << " Hz (" << green.n_lines()
                    << " lines)\n";
          const InflatedTyre tyre(geometry, materials, inflation, green.patch);
          std::cout << "  " << tyre.patch.describe(green.patch) << '\n';
          const auto result = run_green_stage(tyre, green, green_key, h5, record, false,
                                              global.print_timings, MPI_COMM_WORLD);
          G                 = result.green;
          std::cout << "  every solve checked: largest backward error "
                    << format_printf("%.2g", result.report.diagnostics.max_residual) << '\n';
        }
      const unsigned int n_p = G.n_points();

      // Stage 4: modal, the patch model (cached too).
      const std::string modal_key = patch_model_stage_key(prm, green_key);
      const fs::path    modal_h5  = directory / "patch_model.h5";
      modal::PatchModel model;
      if (global.reuse && modal::read_patch_model_key(modal_h5.string()) == modal_key &&
          read_saved_stage(modal_h5, [&] { model = modal::read_patch_model(modal_h5.string()); }))
        {
          std::cout << "Reusing " << modal_h5.string()
                    << ": same Green's functions and identification parameters\n";
        }
      else
        {
          const auto t0 = std::chrono::steady_clock::now();
          std::cout << "Stage modal: LSCE poles and the residues of all " << n_p * n_p
                    << " pairs\n";
          model = modal::fit_patch_model(G, identification, patch_model, true);
          modal::write_patch_model(modal_h5, model, record, modal_key);
          if (global.print_timings)
            std::cout << "  modal stage: " << format_printf("%.3g", since(t0)) << " s\n";
        }
      {
        std::vector<double> e(model.errors.data(), model.errors.data() + model.errors.size());
        std::sort(e.begin(), e.end());
        double diagonal = 0.;
        for (unsigned int i = 0; i < n_p; ++i)
          diagonal = std::max(diagonal, model.errors(i, i));
        std::cout << "  modal fit, E of Eq. (50) over the " << e.size() << " pairs: median "
                  << format_printf("%.2f", 100. * e[e.size() / 2]) << "%, 90th percentile "
                  << format_printf("%.2f", 100. * e[e.size() * 9 / 10]) << "%, largest "
                  << format_printf("%.2f", 100. * e.back()) << "% (driving points at most "
                  << format_printf("%.2f", 100. * diagonal) << "%), " << model.n_terms()
                  << " poles\n";
        base::AtomicFile f(directory / "modal_errors.csv");
        f.stream() << "i,j,E\n";
        for (unsigned int i = 0; i < n_p; ++i)
          for (unsigned int j = 0; j < n_p; ++j)
            f.stream() << i << ',' << j << ',' << model.errors(i, j) << '\n';
        record.write_comments(f.stream());
        f.commit();
      }

      // The patch lattice and the tread's own height (its curvature along x).
      std::vector<double> xs, ys;
      for (const auto &p : model.points)
        {
          if (std::none_of(xs.begin(), xs.end(), [&](double x) { return std::abs(x - p[0]) < 1e-7; }))
            xs.push_back(p[0]);
          if (std::none_of(ys.begin(), ys.end(), [&](double y) { return std::abs(y - p[1]) < 1e-7; }))
            ys.push_back(p[1]);
        }
      const unsigned int nx = xs.size(), ny = ys.size();
      if (nx * ny != n_p)
        throw InputError("the contact points of " + h5.string() + " are not a lattice (" +
                         std::to_string(nx) + " x " + std::to_string(ny) + " != " +
                         std::to_string(n_p) + ")");
      Eigen::VectorXd tread(n_p);
      for (unsigned int p = 0; p < n_p; ++p)
        {
          const double r = model.points[p][2], x = model.points[p][0];
          tread[p]       = r - std::sqrt(r * r - x * x);
        }
      unsigned int centre = 0;
      for (unsigned int p = 0; p < n_p; ++p)
        if (std::hypot(model.points[p][0], model.points[p][1]) <
            std::hypot(model.points[centre][0], model.points[centre][1]))
          centre = p;
      std::vector<unsigned int> middle_row; // the points with x0 nearest 0
      for (unsigned int p = 0; p < n_p; ++p)
        if (std::abs(model.points[p][0] - model.points[centre][0]) < 1e-7)
          middle_row.push_back(p);
      Eigen::MatrixXd G0(n_p, n_p);
      for (unsigned int i = 0; i < n_p; ++i)
        for (unsigned int j = 0; j < n_p; ++j)
          G0(i, j) = G.values[std::size_t(i) * n_p + j].real();
      const double static_mismatch =
        (model.static_compliance() - G0).cwiseAbs().maxCoeff() / G0.cwiseAbs().maxCoeff();
      std::cout << "  the model's static compliance differs from the structure's by "
                << format_printf("%.2g", static_mismatch) << " (largest, relative)\n";

      std::vector<RunResult> results;
      const unsigned int     threads = dealii::MultithreadInfo::n_threads();
      for (const auto &road_name : roads.roads)
        {
          // The road stage: the texture, its MPD, spectrum and image.
          const auto        label = road_label(road_name);
          const double      width = (ys.size() > 1 ? ys.back() - ys.front() : 0.) + 0.03;
          std::cout << "Road '" << road_name << "'\n";
          const auto          file    = texture_files.find(road_name);
          const road::Texture texture =
            file != texture_files.end() ? file->second : roads.make(road_name, width);
          const road::PatchRoad patch_road(texture, model.points, roads.sampling, road_name);
          {
            const auto   bands    = road::wavelength_bands(std::max(2e-3, 4. * texture.dx),
                                                      std::min(0.1, 0.5 * texture.length()));
            const auto   spectrum = road::texture_spectrum(texture, bands);
            const double mpd      = texture.length() >= 0.1 ? road::mean_profile_depth(texture) : NAN;
            std::cout << "  " << texture.nx << " x " << texture.ny << " samples every "
                      << format_number(1e6 * texture.dx) << " um, MPD "
                      << format_printf("%.3f", 1e3 * mpd) << " mm (ISO 13473-1), ETD "
                      << format_printf("%.3f", 0.2 + 0.8 * 1e3 * mpd) << " mm\n";
            base::AtomicFile f(directory / ("road_" + label + "_spectrum.csv"));
            f.stream() << "# road " << road_name << ", MPD " << 1e3 * mpd
                       << " mm; texture level L = 20 log10(a_rms / 1 um) per one-third octave "
                          "of wavelength\nwavelength_nominal_mm,lower_mm,upper_mm,level_dB\n";
            for (std::size_t b = 0; b < bands.size(); ++b)
              f.stream() << 1e3 * bands[b].nominal << ',' << 1e3 * bands[b].lower << ','
                         << 1e3 * bands[b].upper << ',' << spectrum[b] << '\n';
            record.write_comments(f.stream());
            f.commit();
            base::plot_png(directory / ("road_" + label + "_spectrum.png"),
                           "set datafile separator ','\nset datafile commentschars '#'\nset grid\n"
                           "set logscale x\nset xrange [*:*] reverse\nset xlabel 'wavelength [mm]'\n"
                           "set ylabel 'texture level [dB re 1 um]'\nset title 'Road " +
                             road_name + ": texture spectrum, MPD " +
                             format_printf("%.2f", 1e3 * mpd) + " mm'\nplot " +
                             base::gnuplot_quote(directory / ("road_" + label + "_spectrum.csv")) +
                             " skip 2 using 1:4 with linespoints lw 2 notitle\n",
                           record);
            // A 0.1 m x 0.1 m sample as an image (Figure A.11).
            const unsigned int n_show_x = std::min<unsigned int>(texture.nx, std::ceil(0.1 / texture.dx));
            const unsigned int n_show_y = std::min<unsigned int>(texture.ny, std::ceil(0.1 / texture.dy));
            base::AtomicFile   img(directory / ("road_" + label + "_texture.dat"));
            for (unsigned int j = 0; j < n_show_y; ++j)
              {
                for (unsigned int i = 0; i < n_show_x; ++i)
                  img.stream() << 1e3 * i * texture.dx << ' ' << 1e3 * j * texture.dy << ' '
                               << 1e3 * texture(i, j) << '\n';
                img.stream() << '\n';
              }
            img.commit();
            base::plot_png(directory / ("road_" + label + "_texture.png"),
                           "set view map\nset size ratio -1\nset xlabel 'x [mm]'\nset ylabel 'y [mm]'\n"
                           "set cblabel 'z [mm]'\nset palette grey\nset title 'Road " + road_name +
                             " (sample)'\nplot " +
                             base::gnuplot_quote(directory / ("road_" + label + "_texture.dat")) +
                             " using 1:2:3 with image notitle\n",
                           record, 800, 700);
          }

          for (const double speed_kmh : rolling.speeds)
            {
              const double V  = speed_kmh / 3.6;
              const double dt = rolling.time_step > 0. ? rolling.time_step : texture.dx / V;
              const unsigned int n_steps =
                static_cast<unsigned int>(std::ceil(rolling.distance / (V * dt)));
              if (rolling.distance > patch_road.usable_length())
                throw InputError("parameter 'Rolling/Distance' = " +
                                 format_short(rolling.distance) + " m is longer than road '" +
                                 road_name + "' allows (" +
                                 format_short(patch_road.usable_length()) +
                                 " m once the patch is on it)");
              const std::string run = label + "_" + speed_label(speed_kmh);
              std::cout << "  run " << run << ": V0 = " << format_number(speed_kmh)
                        << " km/h, dt = " << format_printf("%.4g", 1e6 * dt) << " us, "
                        << n_steps << " steps, " << rolling.convolution << '\n';
              const auto t_run = std::chrono::steady_clock::now();

              // Road demand at patch position s: d = delta + road - tread.
              Eigen::VectorXd road_z(n_p), road_slope(n_p);
              const auto      sample = [&](const double s) {
                for (unsigned int p = 0; p < n_p; ++p)
                  patch_road.height(p, s, road_z[p], road_slope[p]);
              };
              sample(0.);
              const Eigen::VectorXd d0 = road_z - tread;
              const auto            equilibrium =
                contact::solve_static_contact(G0, d0, rolling.static_load, rolling.indentation);
              const double delta = equilibrium.delta;
              std::cout << "    static contact: indentation " << format_printf("%.4g", 1e3 * delta)
                        << " mm, load " << format_printf("%.4g", equilibrium.q.sum()) << " N, "
                        << equilibrium.n_contact << " of " << n_p << " points in contact\n";

              std::unique_ptr<contact::PatchConvolution> conv;
              if (rolling.convolution == "direct")
                {
                  const unsigned int n_kernel = rolling.direct_kernel > 0 ?
                                                  std::min(rolling.direct_kernel, n_steps + 1) :
                                                  n_steps + 1;
                  const double bytes = 8. * 8. * n_p * n_p * n_kernel;
                  if (bytes > 8e9)
                    throw InputError("'Rolling/Convolution' = direct would store " +
                                     format_short(bytes / 1e9) +
                                     " GB of kernels; shorten 'Rolling/Distance' or set "
                                     "'Rolling/Direct kernel length' (at most " +
                                     std::to_string(static_cast<unsigned int>(8e9 / (64. * n_p * n_p))) +
                                     " steps)");
                  conv = contact::make_direct_patch_convolution(model, dt, n_kernel);
                }
              else
                conv = contact::make_modal_patch_convolution(model, dt, threads);
              const double tributary = patch_road.dx_points * patch_road.dy_points;

              RunResult result;
              result.road  = road_name;
              result.speed = speed_kmh;
              result.steps = n_steps;
              std::vector<double> centre_stress(n_steps);
              base::AtomicFile    hist(directory / ("history_" + run + ".csv"));
              auto               &ho = hist.stream();
              ho.precision(8);
              ho << "# time histories at the points with x0 nearest 0 (i_x = " << centre / ny
                 << "): u inward displacement [m], sigma contact stress [Pa] = mean force over "
                    "the step / tributary area " << tributary << " m^2\ntime,x_road,total_force";
              for (const auto p : middle_row)
                ho << ",u_" << p << ",sigma_" << p;
              ho << '\n';
              fs::create_directories(directory / ("maps_" + run));
              std::vector<std::pair<double, std::string>> frames;
              const unsigned int frame_every = std::max(1u, n_steps / rolling.frames);
              base::Progress     progress("    " + run, n_steps);
              Eigen::VectorXd    stress(n_p);
              const auto demand = [&](const double t, Eigen::VectorXd &d, Eigen::VectorXd &dd) {
                sample(V * t);
                d  = (delta + road_z.array() - tread.array()).matrix();
                dd = V * road_slope;
              };
              const auto observe = [&](const contact::RollingStep &step) {
                const unsigned int n = step.step;
                const double       t = step.time;
                stress               = step.force / tributary;
                if (!step.report.converged && result.failed_steps < 5)
                  std::cout << "    step " << n << " (t = " << format_short(t)
                            << " s): the contact solve did not converge: " << step.report.message
                            << '\n';
                result.failed_steps += step.report.converged ? 0 : 1;
                centre_stress[n] = stress[centre];
                ho << t << ',' << V * t << ',' << step.force.sum();
                for (const auto p : middle_row)
                  ho << ',' << step.u[p] << ',' << stress[p];
                ho << '\n';
                if ((n + 1) % frame_every == 0 || n + 1 == n_steps)
                  {
                    const std::string name = "map_" + std::to_string(frames.size()) + ".vtu";
                    write_vtu_frame(directory / ("maps_" + run) / name, model.points, nx, ny,
                                    stress, step.u, step.d);
                    frames.emplace_back(t, "maps_" + run + "/" + name);
                  }
                if (global.print_timings)
                  progress.update(n + 1);
              };
              const auto summary =
                contact::roll(*conv, demand, n_steps,
                              rolling.static_start ? equilibrium.q : Eigen::VectorXd(), observe);
              result.fallback_points      = summary.fallback_points;
              result.min_contact_fraction = summary.min_contact_fraction;
              result.max_contact_fraction = summary.max_contact_fraction;
              const double impulse_total  = summary.impulse;
              progress.finish();
              record.write_comments(ho);
              hist.commit();
              {
                base::AtomicFile pvd(directory / ("contact_" + run + ".pvd"));
                pvd.stream() << "<?xml version=\"1.0\"?>\n<VTKFile type=\"Collection\" "
                                "version=\"0.1\">\n<Collection>\n";
                for (const auto &[t, name] : frames)
                  pvd.stream() << "<DataSet timestep=\"" << t << "\" file=\"" << name << "\"/>\n";
                pvd.stream() << "</Collection>\n</VTKFile>\n";
                pvd.commit();
              }
              result.seconds    = since(t_run);
              result.mean_force = impulse_total / (n_steps * dt);
              const double top_band = spectrum_top_band(dt);
              if (top_band < 5000.)
                std::cout << "    the spectrum ends at the " << format_number(top_band)
                          << " Hz band: dt = " << format_printf("%.4g", 1e6 * dt)
                          << " us resolves up to " << format_printf("%.0f", 0.5 / dt) << " Hz\n";
              result.spectrum = analysis::third_octave_spectrum(
                centre_stress, dt, rolling.stress_reference, 100., top_band);
              analysis::write_band_spectrum_csv(directory / ("spectrum_" + run + ".csv"),
                                                result.spectrum,
                                                "contact stress at the patch centre, Pa");
              std::cout << "    mean total force " << format_printf("%.4g", result.mean_force)
                        << " N (static " << format_printf("%.4g", equilibrium.q.sum())
                        << " N), points in contact " << format_printf("%.0f", 100. * result.min_contact_fraction)
                        << "% to " << format_printf("%.0f", 100. * result.max_contact_fraction)
                        << "%, largest penetration at a step's end "
                        << format_printf("%.2g", summary.max_penetration)
                        << " m, steps the contact solve did not converge: " << result.failed_steps
                        << ", point-steps on the fallback: " << result.fallback_points << '\n';
              if (global.print_timings)
                std::cout << "    " << format_printf("%.3g", result.seconds) << " s, "
                          << format_printf("%.3g", 1e3 * result.seconds / n_steps)
                          << " ms per step\n";

              // The time histories and a contact map, plotted.
              const std::string hq = base::gnuplot_quote(directory / ("history_" + run + ".csv"));
              std::string       u_plot, s_plot;
              for (std::size_t k = 0; k < middle_row.size(); k += std::max<std::size_t>(1, middle_row.size() / 4))
                {
                  const std::string col = std::to_string(4 + 2 * k);
                  const std::string tt  = "title 'point " + std::to_string(middle_row[k]) + "'";
                  u_plot += (u_plot.empty() ? "plot " : ", ") + hq + " skip 2 using 2:($" + col +
                            "*1e3) with lines " + tt;
                  s_plot += (s_plot.empty() ? "plot " : ", ") + hq + " skip 2 using 2:($" +
                            std::to_string(5 + 2 * k) + "/1e6) with lines " + tt;
                }
              base::plot_png(directory / ("history_" + run + ".png"),
                             "set datafile separator ','\nset datafile commentschars '#'\n"
                             "set multiplot layout 2,1 title 'Road " + road_name + ", " +
                               format_number(speed_kmh) + " km/h: points at x0 = 0 (Figures A.12-A.13)'\n"
                               "set grid\nset xlabel 'road position [m]'\nset ylabel 'u [mm]'\n" +
                               u_plot + "\nset ylabel 'contact stress [MPa]'\n" + s_plot +
                               "\nunset multiplot\n",
                             record, 1100, 800);
              {
                base::AtomicFile m(directory / ("map_" + run + ".dat"));
                for (unsigned int i = 0; i < nx; ++i)
                  {
                    for (unsigned int j = 0; j < ny; ++j)
                      m.stream() << 1e3 * model.points[i * ny + j][0] << ' '
                                 << 1e3 * model.points[i * ny + j][1] << ' '
                                 << stress[i * ny + j] / 1e6 << '\n';
                    m.stream() << '\n';
                  }
                m.commit();
                base::plot_png(directory / ("map_" + run + ".png"),
                               "set view map\nset size ratio -1\nset xlabel 'x [mm]'\nset ylabel "
                               "'y [mm]'\nset cblabel 'contact stress [MPa]'\nset palette "
                               "rgbformulae 33,13,10\nset title 'Road " + road_name + ", " +
                                 format_number(speed_kmh) + " km/h: contact stress at the last "
                                 "step'\nplot " + base::gnuplot_quote(directory / ("map_" + run + ".dat")) +
                                 " using 1:2:3 with image notitle\n",
                               record, 800, 700);
              }
              results.push_back(std::move(result));
            }
        }

      // Stage analysis: the spectra per road (speeds) and per speed (roads).
      {
        base::AtomicFile f(directory / "spectra.csv");
        auto            &o = f.stream();
        o << "# one-third-octave levels L_f = 20 log10(sigma_rms / sigma0) of the contact stress "
             "at the patch centre, sigma0 = " << rolling.stress_reference
          << " Pa; IEC 61260-1 base-10 bands; the Green's functions end at "
          << format_number(model.f_max) << " Hz\nroad,speed_kmh,band_Hz,level_dB\n";
        for (const auto &r : results)
          for (std::size_t b = 0; b < r.spectrum.bands.size(); ++b)
            o << r.road << ',' << r.speed << ',' << r.spectrum.bands[b].nominal << ','
              << r.spectrum.level[b] << '\n';
        record.write_comments(o);
        f.commit();
      }
      const auto plot_spectra = [&](const fs::path &png, const std::string &title,
                                    const std::function<bool(const RunResult &)> &take) {
        std::string plot;
        for (const auto &r : results)
          if (take(r))
            plot += (plot.empty() ? "plot " : ", ") +
                    base::gnuplot_quote(directory / ("spectrum_" + road_label(r.road) + "_" +
                                                     speed_label(r.speed) + ".csv")) +
                    " skip 2 using 1:6 with linespoints lw 2 title '" + road_label(r.road) + ", " +
                    format_number(r.speed) + " km/h'";
        base::plot_png(png,
                       "set datafile separator ','\nset datafile commentschars '#'\nset grid\n"
                       "set logscale x\nset xrange [90:5600]\nset xtics (100,200,500,1000,2000,5000)\n"
                       "set xlabel 'one-third-octave band [Hz]'\nset ylabel 'L_f [dB re " +
                         format_number(rolling.stress_reference) + " Pa]'\nset key left bottom\n"
                         "set title '" + title + "'\n" + plot + "\n",
                       record);
      };
      for (const auto &road_name : roads.roads)
        plot_spectra(directory / ("spectra_" + road_label(road_name) + ".png"),
                     "Contact stress at the patch centre, road " + road_name + " (Figure A.14)",
                     [&](const RunResult &r) { return r.road == road_name; });
      for (const double v : rolling.speeds)
        plot_spectra(directory / ("spectra_" + speed_label(v) + ".png"),
                     "Contact stress at the patch centre, " + format_number(v) +
                       " km/h (Figure A.15)",
                     [&](const RunResult &r) { return r.speed == v; });

      // The band of the highest level per run: does it rise with the speed?
      std::cout << "Spectra (one-third octaves of the contact stress at the patch centre, dB re "
                << format_number(rolling.stress_reference) << " Pa):\n";
      for (const auto &r : results)
        {
          std::size_t peak = 0;
          double      power = 0., moment = 0.;
          for (std::size_t b = 0; b < r.spectrum.bands.size(); ++b)
            {
              if (r.spectrum.level[b] > r.spectrum.level[peak])
                peak = b;
              const double p = r.spectrum.rms[b] * r.spectrum.rms[b];
              power += p;
              moment += p * std::log10(r.spectrum.bands[b].centre);
            }
          std::cout << "  " << road_label(r.road) << " at " << format_number(r.speed) << " km/h: ";
          if (power > 0.)
            std::cout << "highest band " << format_number(r.spectrum.bands[peak].nominal) << " Hz ("
                      << format_printf("%.1f", r.spectrum.level[peak]) << " dB), spectral centroid "
                      << format_printf("%.0f", std::pow(10., moment / power)) << " Hz\n";
          else
            std::cout << "no stress at the patch centre in any band (the point never touched "
                         "the road)\n";
        }
      if (global.print_timings)
        std::cout << "Total run time " << format_printf("%.3g", since(start)) << " s\n";
    }
  } // namespace scenes
} // namespace greentread

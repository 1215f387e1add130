#include <greentread/analysis/error_bars.h>
#include <greentread/analysis/rolling_output.h>
#include <greentread/base/exceptions.h>
#include <greentread/base/plot.h>

#include <algorithm>
#include <cctype>
#include <cmath>
#include <functional>
#include <iostream>
#include <limits>
#include <map>

namespace greentread
{
  namespace analysis
  {
    namespace
    {
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



    std::string
    slick_road(const std::string &road)
    {
      return road + " slick";
    }



    std::string
    texture_of_road(const std::string &road)
    {
      const std::string suffix = slick_road("");
      if (road.size() > suffix.size() &&
          road.compare(road.size() - suffix.size(), suffix.size(), suffix) == 0)
        return road.substr(0, road.size() - suffix.size());
      return road;
    }



    std::string
    road_label(const std::string &road)
    {
      const std::string texture = texture_of_road(road);
      if (texture != road)
        return road_label(texture) + "_slick";
      std::string label = std::filesystem::path(road).stem().string();
      for (auto &c : label)
        if (!std::isalnum(static_cast<unsigned char>(c)) && c != '-')
          c = '_';
      return label;
    }



    std::string
    speed_label(const double speed_kmh)
    {
      return format_printf("%g", speed_kmh) + "kmh";
    }



    PatchLattice::PatchLattice(const std::vector<std::array<double, 3>> &points_,
                               const std::string                        &source)
        : points(points_)
    {
      for (const auto &p : points)
        {
          if (std::none_of(xs.begin(), xs.end(), [&](double x) {
                return std::abs(x - p[0]) < 1e-7;
              }))
            xs.push_back(p[0]);
          if (std::none_of(ys.begin(), ys.end(), [&](double y) {
                return std::abs(y - p[1]) < 1e-7;
              }))
            ys.push_back(p[1]);
        }
      nx                     = xs.size();
      ny                     = ys.size();
      const unsigned int n_p = points.size();
      if (nx * ny != n_p)
        throw InputError("the contact points of " + source + " are not a lattice (" +
                         std::to_string(nx) + " x " + std::to_string(ny) +
                         " != " + std::to_string(n_p) + ")");
      for (unsigned int p = 0; p < n_p; ++p)
        if (std::hypot(points[p][0], points[p][1]) <
            std::hypot(points[centre][0], points[centre][1]))
          centre = p;
      for (unsigned int p = 0; p < n_p; ++p)
        if (std::abs(points[p][0] - points[centre][0]) < 1e-7)
          middle_row.push_back(p);
    }



    double
    write_road_report(const std::filesystem::path &directory,
                      const std::string           &road_name,
                      const road::Texture         &texture,
                      const base::ParameterRecord &record)
    {
      const std::string label    = road_label(road_name);
      const auto        bands    = road::wavelength_bands(std::max(2e-3, 4. * texture.dx),
                                                          std::min(0.1, 0.5 * texture.length()));
      const auto        spectrum = road::texture_spectrum(texture, bands);
      const double      mpd = texture.length() >= 0.1 ? road::mean_profile_depth(texture) : NAN;
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
                       road_name + ": texture spectrum, MPD " + format_printf("%.2f", 1e3 * mpd) +
                       " mm'\nplot " +
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
                     "set cblabel 'z [mm]'\nset palette grey\nset title 'Road " +
                       road_name + " (sample)'\nplot " +
                       base::gnuplot_quote(directory / ("road_" + label + "_texture.dat")) +
                       " using 1:2:3 with image notitle\n",
                     record, 800, 700);
      return mpd;
    }



    RunOutput::RunOutput(const std::filesystem::path &directory_,
                         const std::string           &run_,
                         const PatchLattice          &lattice_,
                         const double                 speed_,
                         const double                 tributary_,
                         const Eigen::VectorXd       &reporting_,
                         const unsigned int           n_steps_,
                         const unsigned int           n_frames,
                         const base::ParameterRecord &record_)
        : directory(directory_)
        , run(run_)
        , lattice(lattice_)
        , speed(speed_)
        , tributary(tributary_)
        , reporting(reporting_)
        , n_steps(n_steps_)
        , frame_every(std::max(1u, n_steps_ / n_frames))
        , record(record_)
        , history(directory_ / ("history_" + run_ + ".csv"))
    {
      if (static_cast<std::size_t>(reporting.size()) != lattice.points.size())
        throw InputError("rolling output: " + std::to_string(reporting.size()) +
                         " reporting weights for " + std::to_string(lattice.points.size()) +
                         " points");
      centre.reserve(n_steps);
      force.reserve(n_steps);
      auto &ho = history.stream();
      ho.precision(8);
      ho << "# time histories at the points with x0 nearest 0 (i_x = "
         << lattice.centre / lattice.ny
         << "): u inward displacement [m], sigma contact stress [Pa] = mean force over "
            "the step / tributary area "
         << tributary << " m^2\ntime,x_road,total_force";
      for (const auto p : lattice.middle_row)
        ho << ",u_" << p << ",sigma_" << p;
      ho << '\n';
      std::filesystem::create_directories(directory / ("maps_" + run));
    }



    void
    RunOutput::add(const contact::RollingStep &step)
    {
      const unsigned int n = step.step;
      const double       t = step.time;
      stress               = step.force / tributary;
      centre.push_back(reporting.dot(stress));
      force.push_back(step.force.sum());
      auto &ho = history.stream();
      ho << t << ',' << speed * t << ',' << step.force.sum();
      for (const auto p : lattice.middle_row)
        ho << ',' << step.u[p] << ',' << stress[p];
      ho << '\n';
      if ((n + 1) % frame_every == 0 || n + 1 == n_steps)
        {
          const std::string name = "map_" + std::to_string(frames.size()) + ".vtu";
          write_vtu_frame(directory / ("maps_" + run) / name, lattice.points, lattice.nx,
                          lattice.ny, stress, step.u, step.d);
          frames.emplace_back(t, "maps_" + run + "/" + name);
        }
    }



    void
    RunOutput::finish(const std::string &title)
    {
      record.write_comments(history.stream());
      history.commit();
      {
        base::AtomicFile pvd(directory / ("contact_" + run + ".pvd"));
        pvd.stream() << "<?xml version=\"1.0\"?>\n<VTKFile type=\"Collection\" "
                        "version=\"0.1\">\n<Collection>\n";
        for (const auto &[t, name] : frames)
          pvd.stream() << "<DataSet timestep=\"" << t << "\" file=\"" << name << "\"/>\n";
        pvd.stream() << "</Collection>\n</VTKFile>\n";
        pvd.commit();
      }
      // The time histories and a contact map, plotted.
      const std::string hq = base::gnuplot_quote(directory / ("history_" + run + ".csv"));
      std::string       u_plot, s_plot;
      for (std::size_t k = 0; k < lattice.middle_row.size();
           k += std::max<std::size_t>(1, lattice.middle_row.size() / 4))
        {
          const std::string col = std::to_string(4 + 2 * k);
          const std::string tt  = "title 'point " + std::to_string(lattice.middle_row[k]) + "'";
          u_plot += (u_plot.empty() ? "plot " : ", ") + hq + " skip 2 using 2:($" + col +
                    "*1e3) with lines " + tt;
          s_plot += (s_plot.empty() ? "plot " : ", ") + hq + " skip 2 using 2:($" +
                    std::to_string(5 + 2 * k) + "/1e6) with lines " + tt;
        }
      base::plot_png(directory / ("history_" + run + ".png"),
                     "set datafile separator ','\nset datafile commentschars '#'\n"
                     "set multiplot layout 2,1 title 'Road " +
                       title +
                       ": points at x0 = 0 (Figures A.12-A.13)'\n"
                       "set grid\nset xlabel 'road position [m]'\nset ylabel 'u [mm]'\n" +
                       u_plot + "\nset ylabel 'contact stress [MPa]'\n" + s_plot +
                       "\nunset multiplot\n",
                     record, 1100, 800);
      {
        base::AtomicFile m(directory / ("map_" + run + ".dat"));
        for (unsigned int i = 0; i < lattice.nx; ++i)
          {
            for (unsigned int j = 0; j < lattice.ny; ++j)
              m.stream() << 1e3 * lattice.points[i * lattice.ny + j][0] << ' '
                         << 1e3 * lattice.points[i * lattice.ny + j][1] << ' '
                         << stress[i * lattice.ny + j] / 1e6 << '\n';
            m.stream() << '\n';
          }
        m.commit();
        base::plot_png(directory / ("map_" + run + ".png"),
                       "set view map\nset size ratio -1\nset xlabel 'x [mm]'\nset ylabel "
                       "'y [mm]'\nset cblabel 'contact stress [MPa]'\nset palette "
                       "rgbformulae 33,13,10\nset title 'Road " +
                         title +
                         ": contact stress at the last "
                         "step'\nplot " +
                         base::gnuplot_quote(directory / ("map_" + run + ".dat")) +
                         " using 1:2:3 with image notitle\n",
                       record, 800, 700);
      }
    }
  } // namespace analysis
} // namespace greentread

#include <greentread/analysis/third_octave.h>
#include <greentread/base/exceptions.h>
#include <greentread/base/output.h>
#include <greentread/base/progress.h>
#include <greentread/contact/rolling.h>
#include <greentread/fe/inflation.h>
#include <greentread/fe/material.h>
#include <greentread/modal/identification.h>
#include <greentread/periodic/green_functions.h>
#include <greentread/periodic/green_stage.h>
#include <greentread/reference/newmark_ring.h>
#include <greentread/reference/transient_comparison.h>
#include <greentread/synthesis/mode_synthesis.h>
#include <greentread/synthesis/ring_modes.h>

#include <algorithm>
#include <chrono>
#include <cmath>

namespace greentread
{
  namespace reference
  {
    namespace
    {
      /// max |a - b| / max |b|.
      double
      relative_difference(const std::vector<double> &a, const std::vector<double> &b)
      {
        double diff = 0., peak = 0.;
        for (std::size_t n = 0; n < b.size(); ++n)
          {
            diff = std::max(diff, std::abs(a[n] - b[n]));
            peak = std::max(peak, std::abs(b[n]));
          }
        return peak > 0. ? diff / peak : diff;
      }

      /// rms(a - b) / rms(b - mean b): the difference against the reference's
      /// fluctuation, in the mean over the record; a force that jumps (a
      /// damped contact touching down) one step earlier in one run weighs
      /// one step in it, not the whole jump as in the largest difference.
      double
      rms_difference(const std::vector<double> &a, const std::vector<double> &b)
      {
        double mean = 0.;
        for (const double x : b)
          mean += x;
        mean /= b.size();
        double diff = 0., size = 0.;
        for (std::size_t n = 0; n < b.size(); ++n)
          {
            diff += (a[n] - b[n]) * (a[n] - b[n]);
            size += (b[n] - mean) * (b[n] - mean);
          }
        return size > 0. ? std::sqrt(diff / size) : std::sqrt(diff);
      }

      /// The largest band-level difference [dB], over the bands from 250 Hz
      /// (or the lowest with at least one Fourier line) to 5 kHz (or the
      /// highest below the Nyquist frequency); NaN if there is none.
      double
      band_difference(const std::vector<double> &a, const std::vector<double> &b, const double dt)
      {
        const double record = b.size() * dt;
        double       low = 0., high = 0.;
        for (const auto &band : analysis::third_octave_bands(250., 5000.))
          {
            if (low == 0. && (band.upper - band.lower) * record >= 1.)
              low = band.nominal;
            if (band.upper <= 0.5 / dt)
              high = band.nominal;
          }
        if (low == 0. || high < low)
          return NAN;
        const auto sa    = analysis::third_octave_spectrum(a, dt, 1., low, high);
        const auto sb    = analysis::third_octave_spectrum(b, dt, 1., low, high);
        double     worst = 0.;
        for (std::size_t k = 0; k < sa.level.size(); ++k)
          worst = std::max(worst, std::abs(sa.level[k] - sb.level[k]));
        return worst;
      }
    } // namespace



    TransientDifference
    compare(const TransientRun &run, const TransientRun &reference, const double dt)
    {
      if (run.force.size() != reference.force.size())
        throw InputError("compare: runs of " + std::to_string(run.force.size()) + " and " +
                         std::to_string(reference.force.size()) + " steps");
      TransientDifference d;
      d.force       = relative_difference(run.force, reference.force);
      d.force_rms   = rms_difference(run.force, reference.force);
      d.stress      = relative_difference(run.stress, reference.stress);
      d.force_band  = band_difference(run.force, reference.force, dt);
      d.stress_band = band_difference(run.stress, reference.stress, dt);
      return d;
    }



    TransientCase::TransientCase(const TransientCaseSetup &setup_)
        : setup(setup_)
    {
      geometry::GeometryParameters geometry;
      geometry.geo_file  = setup.geo_file;
      geometry.mesh_size = setup.mesh_size;
      geometry.n_cells   = setup.n_cells;
      fe::MaterialParameters  materials;
      fe::InflationParameters inflation;
      materials.tread_surface_mass_inward = setup.surface_mass_inward;
      if (setup.proportional_damping)
        {
          materials.tread_loss = materials.belt_loss = materials.sidewall_loss =
            materials.bead_loss                      = setup.loss_factor;
          inflation.pressure                         = 0.;
        }
      tyre = std::make_unique<periodic::InflatedTyre>(geometry, materials, inflation, setup.patch);
      const auto &patch = tyre->patch;

      periodic::GreenRunReport report;
      const unsigned int       n_lines =
        static_cast<unsigned int>(std::round(setup.max_frequency / setup.frequency_step)) + 1;
      green = periodic::compute_green_functions(tyre->periodic_cell, patch, periodic::Method::bloch,
                                                setup.frequency_step, n_lines, MPI_COMM_SELF, false,
                                                report);
      G0    = synthesis::static_line(green);
      for (const auto &p : patch.points)
        points.push_back({{p.x, p.y, p.radius}});
      tread  = contact::tread_heights(points);
      centre = (patch.points_along / 2) * patch.points_across + patch.points_across / 2;
      area   = patch.dx * patch.dy;

      road::RoadTextureParameters parameters;
      parameters.sampling            = setup.sampling;
      parameters.sinusoid.amplitude  = setup.sinusoid_amplitude;
      parameters.sinusoid.wavelength = setup.sinusoid_wavelength;
      spacing                        = parameters.spacing;
      double y_min = 0., y_max = 0.;
      for (const auto &p : points)
        {
          y_min = std::min(y_min, p[1]);
          y_max = std::max(y_max, p[1]);
        }
      for (const std::string name : {"sinusoid", "road-A", "road-B"})
        {
          roads.emplace(name, road::PatchRoad(parameters.make(name, y_max - y_min + 0.03), points,
                                              setup.sampling, name));
        }

      // The reference's static compliance against the Green's functions' 0 Hz line.
      const reference::NewmarkRing ring(tyre->periodic_cell, patch, road_time_step());
      static_difference =
        (ring.static_compliance() - G0).cwiseAbs().maxCoeff() / G0.cwiseAbs().maxCoeff();
      ring_dofs = ring.n_dofs();
    }



    TransientCase::~TransientCase() = default;



    const periodic::ContactPatch &
    TransientCase::patch() const
    {
      return tyre->patch;
    }



    std::string
    TransientCase::describe() const
    {
      const double pressure = setup.proportional_damping ? 0. : fe::InflationParameters().pressure;
      return tyre->describe(pressure) + "  full ring: " + std::to_string(ring_dofs) +
             " unknowns; its static compliance B^T K^-1 B equals the "
             "Green's functions' 0 Hz line to " +
             format_printf("%.2g", static_difference) +
             "\n  Green's functions: " + std::to_string(green.n_lines) + " lines every " +
             format_number(setup.frequency_step) + " Hz (Bloch); static load " +
             format_number(setup.static_load) + " N at " + format_number(setup.speed_kmh) + " km/h";
    }



    double
    TransientCase::road_time_step() const
    {
      return spacing / (setup.speed_kmh / 3.6);
    }



    unsigned int
    TransientCase::steps(const double dt) const
    {
      const double V = setup.speed_kmh / 3.6;
      return static_cast<unsigned int>(std::ceil(setup.distance / (V * dt) - 1e-9));
    }



    PathModel
    TransientCase::lsce_model() const
    {
      const auto                      start = std::chrono::steady_clock::now();
      modal::IdentificationParameters identification;
      identification.max_modes = setup.lsce_modes;
      PathModel path;
      path.name = "LSCE patch model";
      path.model =
        modal::fit_patch_model(green, identification, modal::PatchModelParameters(), false);
      path.seconds = base::seconds_since(start);
      return path;
    }



    PathModel
    TransientCase::mode_model(const double cutoff_hz) const
    {
      const auto            start = std::chrono::steady_clock::now();
      synthesis::ModeSearch search;
      search.cutoff = 2. * M_PI * cutoff_hz;
      const synthesis::RingModes modes =
        synthesis::ring_modes(tyre->periodic_cell, tyre->patch, search, MPI_COMM_SELF, false);
      const synthesis::ModeSynthesis synthesis = synthesis::synthesise(
        modes.omega, modes.damping_ratio, modes.shapes, modes.shapes_imag, green);
      PathModel path;
      path.name    = "modes to " + format_number(cutoff_hz / 1000.) + " kHz";
      path.model   = synthesis::to_patch_model(synthesis, Eigen::MatrixXd(), cutoff_hz);
      path.seconds = base::seconds_since(start);
      return path;
    }



    const road::PatchRoad &
    TransientCase::road_named(const std::string &name) const
    {
      const auto it = roads.find(name);
      if (it == roads.end())
        throw InputError("road '" + name + "' is not offered; allowed: sinusoid, road-A, road-B");
      return it->second;
    }



    TransientRun
    TransientCase::run(convolution::PatchConvolution &convolution,
                       const std::string             &name,
                       const double                   dt) const
    {
      const road::PatchRoad          &road    = road_named(name);
      const double                    run_in  = setup.run_in;
      const contact::PatchRoadHeights heights = [&road, run_in](const double s, Eigen::VectorXd &z,
                                                                Eigen::VectorXd &slope) {
        road.heights(s, z, slope);
        if (s >= run_in)
          return;
        // w(s) = sin^2(pi s / (2 L)): 0 with zero slope at the start.
        const double a = M_PI * s / (2. * run_in);
        const double w = std::sin(a) * std::sin(a), dw = M_PI / (2. * run_in) * std::sin(2. * a);
        slope = w * slope + dw * z;
        z *= w;
      };
      contact::RollingSetup rolling;
      rolling.speed            = setup.speed_kmh / 3.6;
      rolling.time_step        = dt;
      rolling.n_steps          = steps(dt);
      rolling.static_load      = setup.static_load;
      const auto start_contact = contact::start_contact(G0, tread, heights, rolling);

      TransientRun result;
      result.force.reserve(rolling.n_steps);
      result.stress.reserve(rolling.n_steps);
      const auto observe = [&](const contact::RollingStep &s) {
        result.force.push_back(s.force.sum());
        result.stress.push_back(s.force[centre] / area);
      };
      const auto start = std::chrono::steady_clock::now();
      const auto summary =
        contact::roll_patch(convolution, tread, heights, start_contact, rolling, observe);
      result.seconds              = base::seconds_since(start);
      result.step_compliance      = convolution.influence().u[2](centre, centre);
      result.failed_steps         = summary.failed_steps;
      result.static_contacts      = start_contact.n_contact;
      result.min_contact_fraction = summary.min_contact_fraction;
      result.max_contact_fraction = summary.max_contact_fraction;
      return result;
    }



    std::vector<double>
    TransientCase::driven_difference(const std::vector<const PathModel *> &models,
                                     const double                          dt,
                                     const double                          pulse) const
    {
      const unsigned int    n_steps = static_cast<unsigned int>(std::lround(3. * pulse / dt));
      const Eigen::VectorXd Q       = Eigen::VectorXd::LinSpaced(points.size(), 10., 60.);
      const auto            drive   = [&](convolution::PatchConvolution &c) {
        std::vector<Eigen::VectorXd> u;
        Eigen::VectorXd              uh, vh;
        convolution::PatchLoad       load(points.size());
        for (unsigned int k = 0; k < n_steps; ++k)
          {
            const double t = (k + 1) * dt;
            const double s = t < pulse ? std::pow(std::sin(M_PI * t / pulse), 2) : 0.;
            c.history(uh, vh);
            load.component[1] = load.component[2];
            load.component[2] = s * Q;
            for (unsigned int g = 0; g < 4; ++g)
              uh += c.influence().u[g] * load.component[g];
            c.advance(load);
            u.push_back(uh);
          }
        return u;
      };
      reference::NewmarkRing ring(tyre->periodic_cell, tyre->patch, dt);
      const auto             reference = drive(ring);
      double                 peak      = 0.;
      for (const auto &u : reference)
        peak = std::max(peak, u.cwiseAbs().maxCoeff());
      std::vector<double> differences;
      for (const PathModel *model : models)
        {
          const auto fast = contact::make_patch_convolution(convolution::Method::modal_recursive,
                                                            model->model, dt, n_steps, 0, 2);
          const auto u    = drive(*fast);
          double     diff = 0.;
          for (unsigned int k = 0; k < n_steps; ++k)
            diff = std::max(diff, (u[k] - reference[k]).cwiseAbs().maxCoeff());
          differences.push_back(diff / peak);
        }
      return differences;
    }



    TransientRun
    TransientCase::reference(const std::string &road, const double dt) const
    {
      const auto             start = std::chrono::steady_clock::now();
      reference::NewmarkRing ring(tyre->periodic_cell, tyre->patch, dt);
      const double           setup_seconds = base::seconds_since(start);
      TransientRun           result        = run(ring, road, dt);
      result.seconds += setup_seconds;
      return result;
    }



    TransientRun
    TransientCase::fast(const std::string        &road,
                        const double              dt,
                        const PathModel          &model,
                        const convolution::Method method) const
    {
      const auto start = std::chrono::steady_clock::now();
      const auto convolution =
        contact::make_patch_convolution(method, model.model, dt, steps(dt), 0, 2);
      const double setup_seconds = base::seconds_since(start);
      TransientRun result        = run(*convolution, road, dt);
      result.seconds += setup_seconds;
      return result;
    }
  } // namespace reference
} // namespace greentread

#include <greentread/analysis/error_bars.h>
#include <greentread/analysis/rolling_output.h>
#include <greentread/base/exceptions.h>
#include <greentread/base/output.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <tuple>

namespace greentread
{
  namespace analysis
  {
    namespace
    {
      /// The index of the band of nominal centre @p f in @p s, or its size.
      std::size_t
      find_band(const BandSpectrum &s, const double f)
      {
        for (std::size_t b = 0; b < s.bands.size(); ++b)
          if (std::abs(s.bands[b].nominal - f) <= 1e-9 * f)
            return b;
        return s.bands.size();
      }

      /// The lowest band a run's estimates cover, and the window that gives
      /// it @p lines Fourier lines [s] (0: the run gives no band from
      /// @p target_from up).
      std::pair<FrequencyBand, double>
      window_of(const BandRun &run, const double target_from, const unsigned int lines)
      {
        const double f_low = std::max(run.f_low, target_from);
        if (f_low > run.f_high * (1. + 1e-9))
          return {FrequencyBand{}, 0.};
        const FrequencyBand lowest = third_octave_bands(f_low, run.f_high).front();
        const double        whole  = run.steps * run.time_step;
        return {lowest, std::min(whole, lines / (lowest.upper - lowest.lower))};
      }
    } // namespace



    double
    richardson_factor(const double ratio, const double order)
    {
      if (!(ratio > 1.))
        throw NumericalError("richardson_factor: a coarsening ratio of " + format_number(ratio) +
                             ", not above 1");
      return 1. / (std::pow(ratio, order) - 1.);
    }



    std::vector<EstimateRun>
    plan_estimate_runs(const std::vector<BandRun> &plan,
                       const ErrorBarParameters   &parameters,
                       const double                target_from,
                       const double                speed,
                       const unsigned int          subdivisions)
    {
      std::vector<EstimateRun> estimates;
      for (std::size_t i = 0; i < plan.size(); ++i)
        {
          const auto [lowest, window] = window_of(plan[i], target_from, parameters.window_lines);
          if (window <= 0.)
            continue;
          for (const Discretisation d : parameters.estimates)
            {
              EstimateRun e;
              e.what     = d;
              e.of       = i;
              e.f_low    = lowest.nominal;
              e.f_high   = plan[i].f_high;
              e.run      = plan[i];
              e.run.name = (plan[i].name.empty() ? "" : plan[i].name + "_") + "coarser_" + label(d);
              e.run.target_out_of_reach = false;
              e.run.longest_steps       = 0; // a window of fixed length
              double step               = plan[i].time_step;
              if (d == Discretisation::time_step && i > 0)
                {
                  // The low-rate run against the run at the scene's step,
                  // over that run's record: no run of its own.
                  e.window    = plan[0].steps * plan[0].time_step;
                  e.ratio     = plan[i].time_step / plan[0].time_step;
                  e.factor    = 1. + richardson_factor(e.ratio, time_step_order);
                  e.run.steps = 0;
                  estimates.push_back(e);
                  continue;
                }
              if (d == Discretisation::time_step)
                {
                  // The step halved, not doubled: at one road sample per
                  // step a doubled step skips texture samples, which moves
                  // the low bands far more than the step's own error
                  // (doc/methods/analysis.md).
                  step     = 0.5 * plan[i].time_step;
                  e.ratio  = 2.;
                  e.factor = 1. + richardson_factor(e.ratio, time_step_order);
                  e.run.name =
                    (plan[i].name.empty() ? "" : plan[i].name + "_") + "finer_" + label(d);
                }
              else if (d == Discretisation::contact_grid)
                {
                  if (subdivisions < 2)
                    continue;
                  e.ratio  = double(subdivisions) / (subdivisions / 2);
                  e.factor = richardson_factor(e.ratio, contact_grid_order);
                }
              else if (d == Discretisation::ring_section)
                {
                  e.ratio  = 2.;
                  e.factor = richardson_factor(e.ratio, ring_section_order);
                }
              else if (d == Discretisation::block_mesh)
                {
                  e.ratio  = block_mesh_ratio;
                  e.factor = richardson_factor(e.ratio, block_mesh_order);
                }
              // Whole steps of the other level, both levels over the same
              // record (the window: the other run's duration, whole steps
              // of the run's own step too).
              const double       whole = std::max(step, plan[i].time_step);
              const unsigned int steps =
                unsigned(std::ceil(window / whole * (1. - 1e-9)) * std::lround(whole / step));
              e.run.time_step = step;
              e.run.steps =
                std::min(steps, unsigned(plan[i].steps * plan[i].time_step / step + 1e-9));
              e.run.distance = e.run.steps * step * speed;
              e.window       = e.run.steps * step;
              estimates.push_back(e);
            }
        }
      return estimates;
    }



    BandSpectrum
    window_spectrum(const std::vector<double> &x,
                    const double               dt,
                    const std::size_t          samples,
                    const double               reference,
                    const double               f_low,
                    const double               f_high,
                    const unsigned int         lines_per_segment)
    {
      const std::size_t n = std::min(samples, x.size());
      return welch_band_spectrum(std::vector<double>(x.begin(), x.begin() + n), dt, reference,
                                 f_low, f_high, lines_per_segment);
    }



    void
    add_estimate(BandSpectrum       &target,
                 const EstimateRun  &estimate,
                 const BandSpectrum &run,
                 const BandSpectrum &other)
    {
      const std::string name = label(estimate.what);
      auto it = std::find_if(target.discretisation_error.begin(), target.discretisation_error.end(),
                             [&](const auto &e) {
                               return e.first == name;
                             });
      if (it == target.discretisation_error.end())
        {
          target.discretisation_error.emplace_back(
            name,
            std::vector<double>(target.bands.size(), std::numeric_limits<double>::quiet_NaN()));
          it = target.discretisation_error.end() - 1;
        }
      for (std::size_t b = 0; b < target.bands.size(); ++b)
        {
          const double f = target.bands[b].nominal;
          if (f < estimate.f_low * (1. - 1e-9) || f > estimate.f_high * (1. + 1e-9) ||
              !std::isnan(it->second[b]))
            continue;
          const std::size_t i = find_band(run, f), j = find_band(other, f);
          if (i < run.bands.size() && j < other.bands.size())
            it->second[b] = estimate.factor * std::abs(other.level[j] - run.level[i]);
        }
    }



    void
    add_error_bars(RunSpectrum                                                   &merged,
                   const std::vector<EstimateRun>                                &estimates,
                   const std::vector<BandRun>                                    &plan,
                   const std::vector<bool>                                       &used,
                   const std::function<const RunSpectrum &(const std::string &)> &run_of,
                   const double                                                   stress_reference,
                   const unsigned int                                             lines_per_segment)
    {
      if (estimates.empty())
        return;
      for (const auto &e : estimates)
        {
          if (!used[e.of])
            continue;
          // The two levels: the run and its other level's run, or (the
          // low-rate run's time step) the low-rate run and the run at the
          // scene's step.
          const bool         low_rate_step = e.run.steps == 0;
          const RunSpectrum &run           = run_of(plan[e.of].name);
          const RunSpectrum &other         = run_of(low_rate_step ? plan[0].name : e.run.name);
          const auto         samples       = [&](const RunSpectrum &r) {
            return std::size_t(std::llround(e.window / r.time_step));
          };
          for (const auto &[history, reference, target] :
               {std::tuple<std::vector<double> RunSpectrum::*, double, BandSpectrum *>{
                  &RunSpectrum::stress_history, stress_reference, &merged.spectrum},
                {&RunSpectrum::force_history, 1., &merged.force_spectrum}})
            add_estimate(*target, e,
                         window_spectrum(run.*history, run.time_step, samples(run), reference,
                                         e.f_low, e.f_high, lines_per_segment),
                         window_spectrum(other.*history, other.time_step, samples(other), reference,
                                         e.f_low, e.f_high, lines_per_segment));
        }
      combine_errors(merged.spectrum);
      combine_errors(merged.force_spectrum);
    }



    void
    combine_errors(BandSpectrum &s)
    {
      s.total_error.assign(s.bands.size(), 0.);
      for (std::size_t b = 0; b < s.bands.size(); ++b)
        {
          double sum = s.standard_error.empty() ? 0. : s.standard_error[b] * s.standard_error[b];
          for (const auto &e : s.discretisation_error)
            if (!std::isnan(e.second[b]))
              sum += e.second[b] * e.second[b];
          s.total_error[b] = std::sqrt(sum);
        }
    }



    Contributor
    largest_contributor(const BandSpectrum &s, const double target_from, const double within_db)
    {
      double highest = -std::numeric_limits<double>::infinity();
      for (std::size_t b = 0; b < s.bands.size(); ++b)
        if (s.bands[b].nominal >= target_from * (1. - 1e-9))
          highest = std::max(highest, s.level[b]);
      const double fine_step =
        s.time_step.empty() ? 0. : *std::min_element(s.time_step.begin(), s.time_step.end());
      Contributor largest;
      const auto  consider = [&](const std::string &what, const std::string &parameter,
                                const double error, const double band) {
        if (error > largest.error)
          largest = {what, parameter, error, band};
      };
      for (std::size_t b = 0; b < s.bands.size(); ++b)
        {
          const double f = s.bands[b].nominal;
          if (f < target_from * (1. - 1e-9) || s.level[b] < highest - within_db)
            continue;
          if (!s.standard_error.empty())
            consider("statistics", "'Spectra/Standard error target'", s.standard_error[b], f);
          for (const auto &[name, error] : s.discretisation_error)
            {
              if (std::isnan(error[b]))
                continue;
              std::string parameter = "'Patch model/Mode cutoff'";
              if (name == label(Discretisation::time_step))
                parameter = !s.time_step.empty() && s.time_step[b] > fine_step * (1. + 1e-9) ?
                              "'Spectra/Low-band time step'" :
                              "'Time stepping/Time step'";
              else if (name == label(Discretisation::contact_grid))
                parameter = "'Contact grid/Subdivisions'";
              else if (name == label(Discretisation::ring_section))
                parameter = "'Geometry/Mesh size'";
              else if (name == label(Discretisation::block_mesh))
                parameter = "'Tread pattern/Block mesh size'";
              std::string what = name;
              std::replace(what.begin(), what.end(), '_', ' ');
              consider(what, parameter, error[b], f);
            }
        }
      return largest;
    }
  } // namespace analysis
} // namespace greentread

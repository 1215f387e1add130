#include <greentread/analysis/study.h>
#include <greentread/base/exceptions.h>
#include <greentread/base/output.h>

#include <algorithm>
#include <iostream>

namespace greentread
{
  namespace analysis
  {
    const RunLevel &
    RunLevels::of(const std::optional<Discretisation> &d) const
    {
      if (!d)
        return fine;
      const auto other_level = other.find(*d);
      return other_level == other.end() ? fine : other_level->second;
    }



    std::optional<Discretisation>
    Study::level_of(const std::size_t k) const
    {
      const StudyJob &job = jobs.at(k);
      if (job.estimate < 0)
        return std::nullopt;
      return cases[job.study_case].estimates[job.estimate].what;
    }



    bool
    Study::needs(const Discretisation d) const
    {
      for (std::size_t k = 0; k < jobs.size(); ++k)
        if (level_of(k) == d)
          return true;
      return false;
    }



    Study
    plan_study(const std::vector<StudyRoad>           &roads,
               const contact::RollingParameters       &rolling,
               const SpectraParameters                &spectra,
               const ErrorBarParameters               &error_bars,
               const unsigned int                      subdivisions,
               const std::map<Discretisation, double> &factors)
    {
      Study study;
      study.roads = roads;
      study.road_length.assign(roads.size(), 0.);
      for (std::size_t r = 0; r < roads.size(); ++r)
        {
          SpectraParameters limits = spectra;
          limits.longest_distance  = roads[r].longest_distance;
          for (std::size_t v = 0; v < rolling.speeds.size(); ++v)
            {
              const double V  = rolling.speeds[v] / 3.6;
              const double dt = rolling.time_step_for(roads[r].spacing, V);
              StudyCase    c{r, v, rolling.speeds[v], {}, {}};
              c.plan = plan_band_runs(limits, V, dt, rolling.distance, top_band_for_step(dt));
              const std::size_t index = study.cases.size();
              for (const auto &run : c.plan)
                {
                  if (run.target_out_of_reach)
                    std::cout << "  " << roads[r].name << " at " << format_number(rolling.speeds[v])
                              << " km/h: the low-rate run stops at " << format_short(run.distance)
                              << " m ('Spectra/Longest distance'"
                              << (roads[r].from_file ? ", or the texture file's length" : "")
                              << "), short of the standard error target\n";
                  study.jobs.push_back({index, run, -1});
                  // As long as the run may extend to ('Spectra/Extend runs').
                  study.road_length[r] = std::max(
                    {study.road_length[r], run.distance, run.longest_steps * V * run.time_step});
                }
              // The other levels the scene can roll, with their factors.
              for (auto &e :
                   plan_estimate_runs(c.plan, error_bars, spectra.target_from, V, subdivisions))
                {
                  const auto factor = factors.find(e.what);
                  const bool own_inputs =
                    e.what == Discretisation::time_step || e.what == Discretisation::contact_grid;
                  if (!own_inputs && factor == factors.end())
                    continue;
                  if (e.what == Discretisation::block_mesh && !roads[r].finite_blocks)
                    continue;
                  if (factor != factors.end())
                    e.factor = factor->second;
                  if (e.run.steps > 0)
                    study.jobs.push_back({index, e.run, int(c.estimates.size())});
                  c.estimates.push_back(std::move(e));
                }
              study.cases.push_back(std::move(c));
            }
        }
      std::stable_sort(study.jobs.begin(), study.jobs.end(),
                       [](const StudyJob &a, const StudyJob &b) {
                         return a.run.steps > b.run.steps;
                       });
      return study;
    }



    std::vector<RunSpectrum>
    Study::merge(const std::vector<RunSpectrum> &job_spectra,
                 const double                    stress_reference,
                 const unsigned int              lines_per_segment) const
    {
      if (job_spectra.size() != jobs.size())
        throw NumericalError("Study::merge: " + std::to_string(job_spectra.size()) +
                             " spectra for " + std::to_string(jobs.size()) + " runs");
      std::vector<RunSpectrum> merged_spectra;
      for (std::size_t c = 0; c < cases.size(); ++c)
        {
          const StudyCase &of_case = cases[c];
          // A run of this case, by its name (BandRun::name).
          const auto run_of = [&](const std::string &name) -> const RunSpectrum & {
            const auto job = std::find_if(jobs.begin(), jobs.end(), [&](const StudyJob &j) {
              return j.study_case == c && j.run.name == name;
            });
            if (job == jobs.end())
              throw NumericalError("Study::merge: no run '" + name + "' of " +
                                   roads[of_case.road].name);
            return job_spectra[job - jobs.begin()];
          };
          RunSpectrum       merged = run_of("");
          const auto       &plan   = of_case.plan;
          std::vector<bool> used(plan.size(), true);
          for (std::size_t i = 1; i < plan.size(); ++i)
            {
              const auto &low = run_of(plan[i].name);
              std::string disagreement =
                low_rate_disagreement(merged.spectrum, low.spectrum, plan[i]);
              if (disagreement.empty())
                disagreement =
                  low_rate_disagreement(merged.force_spectrum, low.force_spectrum, plan[i]);
              if (!disagreement.empty())
                {
                  std::cout << "Warning: " << roads[of_case.road].name << " at "
                            << format_number(of_case.speed_kmh) << " km/h: the low-rate run ("
                            << format_short(1e6 * plan[i].time_step)
                            << " us, 'Spectra/Low-band time step') disagrees with the run at "
                               "the scene's step in "
                            << disagreement
                            << "; its bands are not used (a smaller 'Spectra/Low-band time "
                               "step' may suit this contact)\n";
                  used[i] = false;
                  continue;
                }
              merged.spectrum = merge_band_spectra(merged.spectrum, low.spectrum, plan[i]);
              merged.force_spectrum =
                merge_band_spectra(merged.force_spectrum, low.force_spectrum, plan[i]);
            }
          add_error_bars(merged, of_case.estimates, plan, used, run_of, stress_reference,
                         lines_per_segment);
          merged_spectra.push_back(std::move(merged));
        }
      return merged_spectra;
    }



    std::vector<RunRollingResistance>
    Study::rolling_resistance(const std::vector<RunSpectrum> &job_spectra,
                              const std::vector<double>      &mpd) const
    {
      if (job_spectra.size() != jobs.size())
        throw NumericalError("Study::rolling_resistance: " + std::to_string(job_spectra.size()) +
                             " runs' results for " + std::to_string(jobs.size()) + " runs");
      std::vector<RunRollingResistance> runs;
      for (std::size_t k = 0; k < jobs.size(); ++k)
        {
          const StudyCase   &c = cases[jobs[k].study_case];
          const RunSpectrum &s = job_spectra[k];
          runs.push_back({s.road, s.run, jobs[k].estimate >= 0, c.speed_kmh, mpd.at(c.road),
                          s.time_step, s.time_step * s.force_history.size() * c.speed_kmh / 3.6,
                          s.rolling_resistance});
        }
      // The error bars: each other level against its run of the plan, over
      // the level's window.
      for (std::size_t k = 0; k < jobs.size(); ++k)
        {
          if (jobs[k].estimate < 0)
            continue;
          const StudyCase   &c        = cases[jobs[k].study_case];
          const EstimateRun &estimate = c.estimates[jobs[k].estimate];
          if (estimate.run.steps == 0)
            continue;
          const auto of = std::find_if(jobs.begin(), jobs.end(), [&](const StudyJob &j) {
            return j.study_case == jobs[k].study_case && j.estimate < 0 &&
                   j.run.name == c.plan[estimate.of].name;
          });
          if (of == jobs.end())
            throw NumericalError("Study::rolling_resistance: no run of the plan for the level '" +
                                 estimate.run.name + "'");
          const std::size_t  j   = of - jobs.begin();
          const RunSpectrum &run = job_spectra[j], &other = job_spectra[k];
          for (const PowerPart part : all_power_parts)
            {
              const double e = rolling_resistance_level_error(
                runs[j][part], part_work(part, run.step_work, run.tread_work), run.time_step,
                part_work(part, other.step_work, other.tread_work), other.time_step,
                estimate.window, rolling_resistance_factor(estimate));
              if (std::isfinite(e))
                runs[j][part].coefficient_errors[estimate.what] = e;
            }
        }
      return runs;
    }
  } // namespace analysis
} // namespace greentread

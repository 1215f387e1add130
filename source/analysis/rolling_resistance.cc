#include <greentread/analysis/rolling_resistance.h>
#include <greentread/base/exceptions.h>
#include <greentread/base/plot.h>

#include <algorithm>
#include <cmath>
#include <map>
#include <sstream>
#include <stdexcept>

namespace greentread
{
  namespace analysis
  {
    RollingPowerMeter::RollingPowerMeter(const Eigen::VectorXd &u_start, const double time_step)
        : u_last(u_start)
        , dt(time_step)
    {
    }



    std::string
    column_prefix(const PowerPart part)
    {
      switch (part)
        {
          case PowerPart::structure:
            return "";
          case PowerPart::tread:
            return "tread_";
          case PowerPart::sum:
            return "sum_";
        }
      return "";
    }



    void
    RollingPowerMeter::track_tread_losses(const double             loss_factor,
                                          const double             speed,
                                          const TreadLossGrid     &grid,
                                          const LocalDisplacement &local_displacement,
                                          const Eigen::VectorXd   &start_force)
    {
      local = local_displacement;
      local(start_force, w);
      tread.emplace(loss_factor, dt, speed, grid, start_force, w);
    }



    void
    RollingPowerMeter::add(const contact::RollingStep &step)
    {
      work.push_back(step.force.dot(step.u - u_last));
      load.push_back(step.force.sum());
      u_last = step.u;
      if (tread)
        {
          local(step.end_force, w);
          tread_work.push_back(tread->add(step.end_force, w));
        }
      else
        tread_work.push_back(0.);
    }



    std::vector<double>
    part_work(const PowerPart            part,
              const std::vector<double> &structure,
              const std::vector<double> &tread)
    {
      if (part == PowerPart::structure)
        return structure;
      if (part == PowerPart::tread)
        return tread;
      if (structure.size() != tread.size())
        throw NumericalError("rolling resistance: the structure's work has " +
                             std::to_string(structure.size()) + " steps, the tread's " +
                             std::to_string(tread.size()));
      std::vector<double> sum(structure.size());
      for (std::size_t k = 0; k < sum.size(); ++k)
        sum[k] = structure[k] + tread[k];
      return sum;
    }



    RollingResistance
    RollingPowerMeter::result(const double       speed,
                              const double       skip_fraction,
                              const unsigned int segments,
                              const PowerPart    part) const
    {
      RollingResistance         r;
      const std::vector<double> record = part_work(part, work, tread_work);
      const std::size_t         n      = record.size();
      const std::size_t         first  = static_cast<std::size_t>(std::ceil(skip_fraction * n));
      if (n < first + segments || segments < 2)
        {
          // Too short a record for a standard error: none.
          r.power = r.power_error = r.force = r.force_error = r.coefficient = r.coefficient_error =
            NAN;
          return r;
        }
      for (std::size_t k = 0; k < n; ++k)
        if (!std::isfinite(record[k]))
          throw NumericalError(
            std::string("rolling resistance: ") +
            (part == PowerPart::structure ? "the contact forces' work" : "the tread's losses") +
            " at step " + std::to_string(k) + " is not finite");
      // Batch means: the record after the skip in equal segments, the last
      // steps that do not fill one left out.
      const std::size_t   length = (n - first) / segments;
      std::vector<double> power(segments);
      double              load_sum = 0.;
      for (unsigned int s = 0; s < segments; ++s)
        {
          double w = 0.;
          for (std::size_t k = first + s * length; k < first + (s + 1) * length; ++k)
            {
              w += record[k];
              load_sum += load[k];
            }
          power[s] = w / (length * dt);
        }
      double mean = 0., scatter = 0.;
      for (const double p : power)
        mean += p / segments;
      for (const double p : power)
        scatter += (p - mean) * (p - mean) / (segments - 1);
      r.power             = mean;
      r.power_error       = std::sqrt(scatter / segments);
      r.load              = load_sum / (segments * length);
      r.force             = r.power / speed;
      r.force_error       = r.power_error / speed;
      r.coefficient       = r.load > 0. ? r.force / r.load : NAN;
      r.coefficient_error = r.load > 0. ? r.force_error / r.load : NAN;
      r.skipped           = first * dt;
      r.duration          = segments * length * dt;
      r.segments          = segments;
      return r;
    }



    double
    mean_power(const std::vector<double> &work, const double dt, const double from, const double to)
    {
      // The steps that start at or after from, and before to (within
      // round-off of a step's start).
      const double      eps   = 1e-9;
      const std::size_t first = static_cast<std::size_t>(std::max(0., std::ceil(from / dt - eps)));
      const std::size_t last =
        std::min(work.size(), static_cast<std::size_t>(std::max(0., std::ceil(to / dt - eps))));
      if (!(dt > 0.) || first >= last)
        throw std::invalid_argument("mean_power: no step of " + std::to_string(dt) +
                                    " s starts in [" + std::to_string(from) + ", " +
                                    std::to_string(to) + ") s of a record of " +
                                    std::to_string(work.size()) + " steps");
      double w = 0.;
      for (std::size_t k = first; k < last; ++k)
        w += work[k];
      return w / ((last - first) * dt);
    }



    double
    RollingResistance::coefficient_total_error() const
    {
      double sum = coefficient_error * coefficient_error;
      for (const auto &[d, e] : coefficient_errors)
        if (std::isfinite(e))
          sum += e * e;
      return std::sqrt(sum);
    }



    double
    rolling_resistance_factor(const EstimateRun &estimate)
    {
      switch (estimate.what)
        {
          case Discretisation::time_step:
            return 1. + richardson_factor(estimate.ratio, rolling_resistance_order);
          case Discretisation::mode_cutoff:
            return estimate.factor;
          case Discretisation::contact_grid:
          case Discretisation::ring_section:
          case Discretisation::block_mesh:
            return richardson_factor(estimate.ratio, rolling_resistance_order);
        }
      return NAN;
    }



    double
    rolling_resistance_level_error(const RollingResistance   &run,
                                   const std::vector<double> &work,
                                   const double               dt,
                                   const std::vector<double> &other_work,
                                   const double               other_dt,
                                   const double               window,
                                   const double               factor,
                                   const double               skip_fraction)
    {
      if (!std::isfinite(run.coefficient))
        return NAN;
      const double from  = skip_fraction * window;
      const double own   = mean_power(work, dt, from, window);
      const double other = mean_power(other_work, other_dt, from, window);
      if (own == 0.)
        return NAN;
      return std::abs(other / own - 1.) * factor * std::abs(run.coefficient);
    }



    void
    print_rolling_resistance_errors(std::ostream                            &out,
                                    const std::vector<RunRollingResistance> &runs)
    {
      bool header = false;
      for (const auto &r : runs)
        {
          if (r[PowerPart::sum].coefficient_errors.empty())
            continue;
          if (!header)
            out << "Rolling resistance the texture adds, with the standard error and the "
                   "discretisations' error bars (each from its other level over the error bars' "
                   "window, order "
                << format_number(rolling_resistance_order)
                << " but the mode cut-off's), in 1e-3, into the structure, in the tread's "
                   "losses and together:\n";
          header = true;
          for (const PowerPart part : all_power_parts)
            {
              const RollingResistance &v = r[part];
              out << "    " << r.run << " "
                  << (part == PowerPart::structure ? "structure" :
                      part == PowerPart::tread     ? "tread" :
                                                     "together")
                  << ": C_RR " << format_printf("%.3g", 1e3 * v.coefficient) << " +- "
                  << format_printf("%.2g", 1e3 * v.coefficient_error) << " (standard error)";
              for (const auto &[d, e] : v.coefficient_errors)
                out << " +- " << format_printf("%.2g", 1e3 * e) << " (" << describe(d) << ")";
              out << ", in all +- " << format_printf("%.2g", 1e3 * v.coefficient_total_error())
                  << '\n';
            }
        }
    }



    void
    write_rolling_resistance(const std::filesystem::path             &directory,
                             const std::vector<RunRollingResistance> &runs,
                             const base::ParameterRecord             &record)
    {
      {
        base::AtomicFile f(directory / "rolling_resistance.csv");
        f.stream().precision(6);
        f.stream()
          << "# The rolling resistance the texture adds (doc/methods/analysis.md), in three "
             "parts: the mean power the contact forces put into the tyre's structure after the "
             "start (unprefixed columns), the tread's small-scale losses (tread_: the rubber's "
             "loss factor below the Green's functions' scale, in its own frame, beyond each "
             "row's mean passage) and the two together (sum_): P, "
             "F_RR = P / V, C_RR = F_RR / F_z, each with its standard error (se, from 10 "
             "segments); coefficient_<discretisation>_error: that discretisation's error bar on "
             "C_RR (from its other level over the error bars' window, at order 1 but the mode "
             "cut-off's; empty where none was rolled), coefficient_total_error: the standard "
             "error and the error bars in quadrature; level: a run of the plan, or of an error "
             "bar's other level (its short window); the hysteresis of a turning tyre is not in "
             "it.\n"
             "road,mpd_mm,speed_kmh,run,level,dt_us,distance_m,skipped_m,load_N";
        for (const PowerPart part : all_power_parts)
          {
            const std::string p = column_prefix(part);
            f.stream() << ',' << p << "power_W," << p << "power_se_W," << p << "force_N," << p
                       << "force_se_N," << p << "coefficient," << p << "coefficient_se";
            for (const Discretisation d : all_discretisations)
              f.stream() << ',' << p << "coefficient_" << label(d) << "_error";
            f.stream() << ',' << p << "coefficient_total_error";
          }
        f.stream() << '\n';
        for (const auto &r : runs)
          {
            const double V = r.speed_kmh / 3.6;
            f.stream() << r.road << ',' << 1e3 * r.mpd << ',' << r.speed_kmh << ',' << r.run << ','
                       << (r.error_bar ? "error bar" : "plan") << ',' << 1e6 * r.time_step << ','
                       << r.distance << ',' << r[PowerPart::structure].skipped * V << ','
                       << r[PowerPart::structure].load;
            for (const PowerPart part : all_power_parts)
              {
                const RollingResistance &v = r[part];
                f.stream() << ',' << v.power << ',' << v.power_error << ',' << v.force << ','
                           << v.force_error << ',' << v.coefficient << ',' << v.coefficient_error;
                for (const Discretisation d : all_discretisations)
                  {
                    f.stream() << ',';
                    const auto e = v.coefficient_errors.find(d);
                    if (e != v.coefficient_errors.end() && std::isfinite(e->second))
                      f.stream() << e->second;
                  }
                f.stream() << ',';
                if (std::isfinite(v.coefficient))
                  f.stream() << v.coefficient_total_error();
              }
            f.stream() << '\n';
          }
        record.write_comments(f.stream());
        f.commit();
      }

      // The sum's coefficient against the MPD, one line per speed, with the
      // structure's part dashed in the same colour, from each case's run of
      // the plan at the finest step (the longest of those).
      std::map<double, std::map<std::string, const RunRollingResistance *>> longest;
      for (const auto &r : runs)
        {
          if (r.error_bar || !std::isfinite(r[PowerPart::sum].coefficient))
            continue;
          auto &best = longest[r.speed_kmh][r.road];
          if (best == nullptr || r.time_step < best->time_step ||
              (r.time_step == best->time_step && r.distance > best->distance))
            best = &r;
        }
      std::ostringstream data, plot;
      data.precision(6);
      unsigned int block = 0;
      for (const auto &[speed, by_road] : longest)
        {
          std::vector<const RunRollingResistance *> sorted;
          for (const auto &[road, r] : by_road)
            if (std::isfinite(r->mpd))
              sorted.push_back(r);
          std::sort(sorted.begin(), sorted.end(), [](const auto *a, const auto *b) {
            return a->mpd < b->mpd;
          });
          if (sorted.empty())
            continue;
          for (const auto *r : sorted)
            {
              const RollingResistance &v = (*r)[PowerPart::sum];
              data << 1e3 * r->mpd << ' ' << 1e3 * v.coefficient << ' '
                   << 1e3 * v.coefficient_total_error() << '\n';
            }
          data << "e\n";
          for (const auto *r : sorted)
            data << 1e3 * r->mpd << ' ' << 1e3 * (*r)[PowerPart::structure].coefficient << '\n';
          data << "e\n";
          ++block;
          plot << (block > 1 ? ", " : "plot ") << "'-' using 1:2:3 with yerrorlines lw 2 pt 7 lc "
               << block << " title '" << format_number(speed)
               << " km/h', '-' using 1:2 with lines lw 1 dt 2 lc " << block << " title '"
               << format_number(speed) << " km/h, structure only'";
        }
      if (block == 0)
        return;
      base::plot_png(directory / "rolling_resistance.png",
                     "set grid\nset xlabel 'mean profile depth MPD [mm]'\n"
                     "set ylabel 'C_{RR} added by the texture [10^{-3}]'\nset key top left\n"
                     "set title \"GreenTread: rolling resistance the texture adds, structure "
                     "and tread\\n(dashed: the structure alone; bars: standard error and "
                     "discretisations)\"\n" +
                       plot.str() + "\n" + data.str(),
                     record);
    }
  } // namespace analysis
} // namespace greentread

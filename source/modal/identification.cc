#include <greentread/base/exceptions.h>
#include <greentread/base/parameters.h>
#include <greentread/base/progress.h>
#include <greentread/modal/identification.h>
#include <greentread/modal/lsce.h>
#include <greentread/modal/pole_polish.h>
#include <greentread/modal/residue_fit.h>

#include <deal.II/base/multithread_info.h>

#include <Eigen/Dense>

#include <algorithm>
#include <atomic>
#include <chrono>
#include <cmath>
#include <exception>
#include <map>
#include <mutex>
#include <numeric>
#include <thread>

namespace greentread
{
  namespace modal
  {
    using internal::Pole;
    using internal::ResidueFit;



    namespace
    {
      /**
       * Classify the roots of one band's polynomial and keep its physical
       * poles: stable, inside the band's core [core_low, core_high) (Hz), and
       * persistent (Newton on the polynomial of order p - 2 finds them
       * again within the stabilisation tolerances).
       */
      template <typename Number>
      void
      band_poles(const ImpulseResponse<Number>  &h,
                 const double                    shift, // rad/s, the band's first line
                 const unsigned int              max_order,
                 const double                    core_low,
                 const double                    core_high,
                 const IdentificationParameters &parameters,
                 std::vector<Pole>              &poles,
                 Identification                 &result)
      {
        constexpr bool             real_band = std::is_same_v<Number, double>;
        const HankelSystem<Number> hankel(h, max_order);
        BandReport                 report;
        report.f_low  = core_low;
        report.f_high = core_high;
        // The numerical rank at the largest order tells how many exponentials
        // the band holds; solve with a quarter more roots than that (spare
        // roots absorb the ringing of the band's edges), not more: the cost
        // of the roots grows with the cube of the order.
        const unsigned int estimate = hankel.rank_estimate();
        const unsigned int order =
          std::min(max_order, std::max(4u, estimate + std::max(4u, estimate / 4)));
        report.order = order;
        const auto c = hankel.coefficients(order, report.rank, report.condition);
        typename HankelSystem<Number>::Vector c_low;
        if (order >= 4)
          c_low = hankel.coefficients_pivoted(order - 2);
        result.bands.push_back(report);

        // ln z / dt, with the angle in [0, 2 pi) for a shifted sub-band.
        const auto pole_of = [&](const std::complex<double> z) {
          if (real_band)
            return std::log(z) / h.dt;
          double angle = std::arg(z);
          if (angle < 0.)
            angle += 2. * M_PI;
          return std::complex<double>(std::log(std::abs(z)) / h.dt, shift + angle / h.dt);
        };

        for (const std::complex<double> z : companion_roots(c))
          {
            if (real_band && z.imag() < 0.)
              continue; // its conjugate stands for the pair
            ++result.poles.roots;
            if (real_band && z.imag() == 0. && z.real() <= 0.)
              {
                ++result.poles.out_of_band; // a real z <= 0: the Nyquist frequency, or no pole
                continue;
              }
            const std::complex<double> lambda = pole_of(z);
            const bool                 real   = real_band && z.imag() == 0.;
            const double               f      = lambda.imag() / (2. * M_PI);
            if (!(lambda.real() < 0.) || !std::isfinite(lambda.real()))
              {
                ++result.poles.unstable;
                continue;
              }
            if ((!real && (f < core_low || f >= core_high)) ||
                (real && -lambda.real() > 2. * M_PI * core_high))
              {
                ++result.poles.out_of_band;
                continue;
              }
            if (c_low.size() > 0)
              {
                std::complex<double> z_low = z;
                bool                 found = newton_root(c_low, z_low);
                if (found)
                  {
                    const std::complex<double> l      = pole_of(z_low);
                    const double               xi     = -lambda.real() / std::abs(lambda);
                    const double               xi_low = -l.real() / std::abs(l);
                    found =
                      std::abs(l - lambda) <= parameters.stability_frequency * std::abs(lambda) &&
                      std::abs(xi_low - xi) <= parameters.stability_damping * xi + 1e-12;
                  }
                if (!found)
                  {
                    ++result.poles.spurious;
                    continue;
                  }
              }
            poles.push_back({real ? std::complex<double>(lambda.real(), 0.) : lambda, real});
          }
      }
    } // namespace



    namespace
    {
      Identification
      identify_in_bands(const base::FrequencyResponse  &frf,
                        const IdentificationParameters &parameters,
                        const unsigned int              B)
      {
        Identification     result;
        std::vector<Pole>  poles;
        const double       f_max = frf.f_max();
        const unsigned int K     = frf.values.size() - 1;
        if (B == 1)
          // Appendix A: the whole band at once, 2 N_max real roots.
          band_poles(impulse_response(frf), 0., 2 * parameters.max_modes, 0.,
                     parameters.band_edge * f_max, parameters, poles, result);
        else
          {
            // Zoom LSCE: B cores tiling [0, band_edge f_max), each processed in a
            // band a quarter of a core wider on each side, at most 2 N_max roots.
            const double       width    = f_max / B;
            const unsigned int capacity = parameters.max_modes;
            for (unsigned int b = 0; b < B; ++b)
              {
                const double core_low = b * width;
                const double core_high =
                  b + 1 == B ? parameters.band_edge * f_max : (b + 1) * width;
                const unsigned int first =
                  b == 0 ?
                    0 :
                    static_cast<unsigned int>(std::floor((core_low - 0.25 * width) / frf.df));
                const unsigned int last = std::min<unsigned int>(
                  K, static_cast<unsigned int>(std::ceil((core_high + 0.25 * width) / frf.df)));
                if (b == 0)
                  {
                    const unsigned int order = std::min(2 * capacity, (2 * last - 2) / 2);
                    band_poles(impulse_response(frf, last), 0., order - order % 2, core_low,
                               core_high, parameters, poles, result);
                  }
                else
                  {
                    const unsigned int n_b   = last - first + 1;
                    const unsigned int order = std::min(2 * capacity, (n_b - 2) / 2);
                    band_poles(band_impulse_response(frf, first, last), 2. * M_PI * first * frf.df,
                               order, core_low, core_high, parameters, poles, result);
                  }
              }
          }
        for (const auto &band : result.bands)
          {
            result.order += band.order;
            result.rank += band.rank;
            result.condition = std::max(result.condition, band.condition);
          }
        result.poles.physical = poles.size();

        // Residues of all physical modes, then the order by contribution.
        const ResidueFit fit(frf, poles, parameters.residue_model, parameters.lower_residual,
                             parameters.upper_residual);
        if (!(fit.data_norm() > 0.))
          throw InputError("the FRF is zero at every line: there is nothing to identify");
        std::vector<unsigned int> ranking(poles.size());
        std::iota(ranking.begin(), ranking.end(), 0u);
        if (!poles.empty())
          {
            const Eigen::VectorXd x = fit.solve_all();
            std::vector<double>   importance(poles.size());
            for (unsigned int m = 0; m < poles.size(); ++m)
              importance[m] = fit.contribution(x, m);
            std::stable_sort(ranking.begin(), ranking.end(), [&](unsigned int a, unsigned int b) {
              return importance[a] > importance[b];
            });
          }
        const std::vector<double> errors = fit.prefix_errors(ranking);
        result.best_error                = *std::min_element(errors.begin(), errors.end());
        unsigned int n                   = 0;
        while (!(errors[n] <= result.best_error + parameters.order_tolerance))
          ++n;
        result.n_modes = n;
        std::vector<unsigned int> chosen(ranking.begin(), ranking.begin() + n);
        result.model = fit.model_of(fit.coefficients_of(n), chosen, result.lower_residual,
                                    result.upper_residual);
        result.error = modal_error(frf, result.model, result.lower_residual, result.upper_residual);
        if (parameters.polish_poles && n > 0)
          {
            // The chosen poles refined against every line (modal/pole_polish.h),
            // kept if E of Eq. (50) falls.
            std::vector<PolishPole> given;
            for (const unsigned int m : chosen)
              given.push_back({poles[m].lambda, poles[m].real});
            const auto        refined = polish_poles(frf, given, parameters.lower_residual,
                                                     parameters.upper_residual, result.polish);
            std::vector<Pole> moved;
            for (const auto &p : refined)
              moved.push_back({p.lambda, p.real});
            const ResidueFit again(frf, moved, parameters.residue_model, parameters.lower_residual,
                                   parameters.upper_residual);
            std::vector<unsigned int> all(moved.size());
            std::iota(all.begin(), all.end(), 0u);
            double       lower = 0., upper = 0.;
            const auto   model = again.model_of(again.solve_all(), all, lower, upper);
            const double e     = modal_error(frf, model, lower, upper);
            if (e < result.error)
              {
                result.model          = model;
                result.error          = e;
                result.lower_residual = lower;
                result.upper_residual = upper;
                poles                 = moved;
                chosen                = all;
              }
          }

        if (parameters.compare_models)
          {
            std::vector<Pole> kept;
            for (const unsigned int m : chosen)
              kept.push_back(poles[m]);
            const ResidueModel        other = parameters.residue_model == ResidueModel::eq7 ?
                                                ResidueModel::general :
                                                ResidueModel::eq7;
            const ResidueFit          alternative(frf, kept, other, parameters.lower_residual,
                                                  parameters.upper_residual);
            std::vector<unsigned int> all(kept.size());
            std::iota(all.begin(), all.end(), 0u);
            double     lower, upper;
            const auto model = alternative.model_of(alternative.solve_all(), all, lower, upper);
            result.other_model_error = modal_error(frf, model, lower, upper);
          }
        result.n_bands = B;
        return result;
      }
    } // namespace



    Identification
    identify(const base::FrequencyResponse &frf, const IdentificationParameters &parameters)
    {
      if (parameters.bands > 0)
        return identify_in_bands(frf, parameters, parameters.bands);
      Identification result = identify_in_bands(frf, parameters, 1);
      if (result.error > parameters.zoom_above_error)
        {
          // Zoom bands need room: a core of at least 16 lines.
          const unsigned int lines = frf.values.size() - 1;
          const unsigned int B     = std::min(8u, std::max(1u, lines / 16));
          if (B > 1)
            {
              Identification zoomed = identify_in_bands(frf, parameters, B);
              if (zoomed.error < result.error)
                result = std::move(zoomed);
            }
        }
      return result;
    }



    double
    modal_error(const base::FrequencyResponse &frf,
                const modal::ModalModel       &model,
                const double                   lower,
                const double                   upper)
    {
      const unsigned int first      = lower != 0. ? 1 : 0;
      const unsigned int last       = frf.values.size() - 1;
      double             difference = 0., norm = 0.;
      for (unsigned int k = first; k <= last; ++k)
        {
          const double         w     = (k == first || k == last) ? 0.5 : 1.;
          const double         omega = 2. * M_PI * k * frf.df;
          std::complex<double> fit   = model.frequency_response(omega) + upper;
          if (lower != 0.)
            fit += -lower / (omega * omega);
          difference += w * std::abs(frf.values[k] - fit);
          norm += w * std::abs(frf.values[k]);
        }
      return norm > 0. ? difference / norm : INFINITY;
    }



    std::vector<Identification>
    identify_all(const std::function<base::FrequencyResponse(std::size_t)> &get,
                 const std::size_t                                          count,
                 const IdentificationParameters                            &parameters,
                 const bool                                                 show_progress)
    {
      std::vector<Identification> results(count);
      std::atomic<std::size_t>    next{0}, done{0};
      std::atomic<bool>           stop{false};
      std::exception_ptr          failure;
      std::mutex                  failure_mutex;
      const auto                  work = [&]() {
        for (std::size_t n = next++; n < count && !stop; n = next++)
          {
            try
              {
                results[n] = identify(get(n), parameters);
              }
            catch (...)
              {
                std::lock_guard<std::mutex> lock(failure_mutex);
                if (!failure)
                  failure = std::current_exception();
                stop = true;
              }
            ++done;
          }
      };
      const unsigned int n_threads =
        std::max(1u, std::min<unsigned int>(dealii::MultithreadInfo::n_threads(), count));
      std::vector<std::thread> threads;
      for (unsigned int t = 0; t < n_threads; ++t)
        threads.emplace_back(work);
      // This thread only watches and reports.
      base::Progress progress("identification", count);
      while (done < count && !stop)
        {
          std::this_thread::sleep_for(std::chrono::milliseconds(50));
          if (show_progress)
            progress.update(done);
        }
      for (auto &t : threads)
        t.join();
      if (show_progress)
        progress.finish();
      if (failure)
        std::rethrow_exception(failure);
      return results;
    }



    std::vector<Identification>
    identify_pairs(const base::FrequencyResponseMatrix                      &green,
                   const std::vector<std::pair<unsigned int, unsigned int>> &pairs,
                   const IdentificationParameters                           &parameters,
                   std::size_t                                              &reused,
                   const bool                                                show_progress)
    {
      // For each pair, the index of an earlier pair with the same data by
      // reciprocity (g_ji for g_ij), or itself.
      std::map<std::pair<unsigned int, unsigned int>, std::size_t> index;
      for (std::size_t n = 0; n < pairs.size(); ++n)
        index.emplace(pairs[n], n);
      std::vector<std::size_t> source(pairs.size());
      std::vector<std::size_t> distinct;
      for (std::size_t n = 0; n < pairs.size(); ++n)
        {
          source[n]         = n;
          const auto [i, j] = pairs[n];
          const auto mirror = index.find({j, i});
          if (i != j && mirror != index.end() && mirror->second < n)
            {
              double             difference = 0., size = 0.;
              const auto        &values = green.values;
              const unsigned int np     = green.n_points();
              for (unsigned int k = 0; k < green.n_lines; ++k)
                {
                  const auto a = values[(std::size_t(k) * np + i) * np + j];
                  const auto b = values[(std::size_t(k) * np + j) * np + i];
                  difference   = std::max(difference, std::abs(a - b));
                  size         = std::max(size, std::abs(a));
                }
              if (difference <= 1e-12 * size)
                source[n] = mirror->second;
            }
          if (source[n] == n)
            distinct.push_back(n);
        }
      reused             = pairs.size() - distinct.size();
      const auto results = identify_all(
        [&](std::size_t d) {
          return green.get(pairs[distinct[d]].first, pairs[distinct[d]].second);
        },
        distinct.size(), parameters, show_progress);
      std::vector<Identification> all(pairs.size());
      std::vector<std::size_t>    slot(pairs.size());
      for (std::size_t d = 0; d < distinct.size(); ++d)
        slot[distinct[d]] = d;
      for (std::size_t n = 0; n < pairs.size(); ++n)
        all[n] = results[slot[source[n]]];
      return all;
    }
  } // namespace modal
} // namespace greentread

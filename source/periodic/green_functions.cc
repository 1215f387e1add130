#include <greentread/base/exceptions.h>
#include <greentread/base/parameters.h>
#include <greentread/base/progress.h>
#include <greentread/periodic/green_functions.h>

#include <deal.II/base/multithread_info.h>

#include <atomic>
#include <chrono>
#include <cmath>
#include <exception>
#include <mutex>
#include <thread>

namespace greentread
{
  namespace periodic
  {
    using base::RangePattern;

    void
    GreenParameters::declare_parameters(dealii::ParameterHandler &prm)
    {
      prm.enter_subsection("Green's functions");
      {
        prm.declare_entry("Maximum frequency", "4000", base::RangePattern::positive("Hz"),
                          "f_max, the last line of the grid. Unit: Hz. Paper, Section 5.1: "
                          "4000 Hz.");
        prm.declare_entry("Frequency step", "500", base::RangePattern::positive("Hz"),
                          "df, the line spacing: the grid is 0, df, ..., f_max, and f_max / df "
                          "must be a whole number. With 'Patch model/Source' = fe modes (the "
                          "default) the lines only check the modal synthesis (E of Eq. 50): "
                          "the default 500 Hz gives 9. With 'identified' the LSCE fit needs "
                          "long impulse responses (1 / df): use 15.625 Hz = 4000 / 256 (64 ms, "
                          "as prm/tyre_green.prm). Unit: Hz.");
        prm.declare_entry("Method", "harmonic",
                          dealii::Patterns::Selection("bloch|doubling|full-ring|harmonic"),
                          "'harmonic': the section's circumferential harmonics, for an "
                          "axisymmetric ring (no mesh along the ring; 'Number of cells' "
                          "then only places the points; the default). "
                          "'bloch': a discrete Fourier transform over the N identical cells, "
                          "N/2 + 1 sparse cell solves per frequency (exact). "
                          "'doubling': the paper's recursive doubling of the condensed cell "
                          "(Eqs. 46-49; exact, dense). 'full-ring': all N cells in one sparse "
                          "solve (the reference; coarse meshes only).");
        prm.declare_entry("Harmonic tolerance", "1e-3",
                          base::RangePattern::closed(1e-8, 0.1, ""),
                          "'Method' = harmonic: the harmonics 0 .. N - 1 are summed, N the "
                          "first for which a bound of the neglected static tail is below "
                          "this fraction of the smallest static driving point "
                          "(doc/methods/green-functions.md). Unit: 1.");
        prm.declare_entry("Patch length", "0.06", base::RangePattern::positive("m"),
                          "L_c, the contact patch along the rolling direction x. Unit: m. "
                          "Section 5.2: 6 cm.");
        prm.declare_entry("Patch width", "0.08", base::RangePattern::positive("m"),
                          "l_c, the contact patch across the tread (y). Unit: m. Section 5.2: "
                          "8 cm.");
        prm.declare_entry("Points along", "10", dealii::Patterns::Integer(1, 1000),
                          "N_x, contact points along x. Section 5.2: 10.");
        prm.declare_entry("Points across", "12", dealii::Patterns::Integer(1, 1000),
                          "N_y, contact points across y. Section 5.2: 12.");
        prm.declare_entry(
          "Point load", "tributary area", dealii::Patterns::Selection("node|tributary area"),
          "What a unit force at a contact point is. 'node': a radial force on one tread "
          "node, the points on a whole stride of nodes nearest the spacing asked (the "
          "paper's; singular in 3D elasticity, so the driving point grows as the mesh is "
          "refined). 'tributary area': a uniform radial traction 1 / A over the point's "
          "rectangle L_c / N_x x l_c / N_y, the response the mean radial displacement over "
          "it; the points exactly on the grid asked, on any mesh (the default).");
        prm.declare_entry("Pairs", "auto", dealii::Patterns::Anything(),
                          "The g_ij written as green_<i>_<j>.csv and plotted: 'auto' (the "
                          "driving point p = (N_x/2) N_y + N_y/2 nearest the patch centre, and "
                          "its transfers to the previous point along x and across y), or up "
                          "to 12 pairs 'i:j, i:j, ...' (0-based points, p = i_x N_y + i_y).");
        prm.declare_entry("Deflection shape frequency", "500", dealii::Patterns::Double(-1.),
                          "The frequency of the operating deflection shape of the ring "
                          "(ring_deflection.vtu) under a unit radial force at point j of the "
                          "first pair (with 'auto', the driving point); a negative value "
                          "writes none. Unit: Hz.");
      }
      prm.leave_subsection();
    }



    std::optional<HarmonicOptions>
    GreenParameters::harmonic() const
    {
      if (method != "harmonic")
        return std::nullopt;
      return HarmonicOptions{harmonic_tolerance, 2. * M_PI * max_frequency};
    }



    void
    GreenParameters::parse_parameters(dealii::ParameterHandler &prm)
    {
      prm.enter_subsection("Green's functions");
      {
        max_frequency        = prm.get_double("Maximum frequency");
        frequency_step       = prm.get_double("Frequency step");
        method               = prm.get("Method");
        harmonic_tolerance   = prm.get_double("Harmonic tolerance");
        patch.length         = prm.get_double("Patch length");
        patch.width          = prm.get_double("Patch width");
        patch.points_along   = prm.get_integer("Points along");
        patch.points_across  = prm.get_integer("Points across");
        patch.load = prm.get("Point load") == "node" ? PointLoad::node : PointLoad::tributary_area;
        pairs                = prm.get("Pairs");
        deflection_frequency = prm.get_double("Deflection shape frequency");
      }
      prm.leave_subsection();
      if (method == "harmonic" && patch.load == PointLoad::node)
        throw InputError("parameter 'Green's functions/Point load' = node is not allowed with "
                         "'Method' = harmonic: a point force's harmonic series does not "
                         "converge (its displacement is singular); allowed: tributary area");
      require_parameter(frequency_step <= max_frequency, "Green's functions/Frequency step",
                        frequency_step,
                        "at most 'Maximum frequency' = " + format_number(max_frequency) + " Hz");
      const double lines = max_frequency / frequency_step;
      require_parameter(std::abs(lines - std::round(lines)) < 1e-9 * lines,
                        "Green's functions/Frequency step", frequency_step,
                        "a whole fraction of 'Maximum frequency' = " +
                          format_number(max_frequency) + " Hz (f_max / df = " +
                          format_short(lines) + ")");
      require_parameter(lines <= 1e6, "Green's functions/Frequency step", frequency_step,
                        "at least f_max / 1e6");
      require_parameter(deflection_frequency <= max_frequency,
                        "Green's functions/Deflection shape frequency", deflection_frequency,
                        "at most 'Maximum frequency' = " + format_number(max_frequency) +
                          " Hz, or negative for none");
    }



    unsigned int
    GreenParameters::n_lines() const
    {
      return static_cast<unsigned int>(std::lround(max_frequency / frequency_step)) + 1;
    }



    std::vector<std::pair<unsigned int, unsigned int>>
    GreenParameters::csv_pairs(const ContactPatch &contact) const
    {
      const unsigned int n = contact.points.size();
      if (pairs != "auto")
        {
          // Each pair is a CSV file and a curve in one plot: a few, not all.
          const auto chosen = base::parse_point_pairs(pairs, n, "Green's functions/Pairs");
          require_parameter(chosen.size() <= 12, "Green's functions/Pairs", pairs,
                            "'auto' or at most 12 pairs i:j (this names " +
                              std::to_string(chosen.size()) +
                              "); the whole matrix is in green_functions.h5");
          return chosen;
        }
      const unsigned int nx = contact.points_along, ny = contact.points_across;
      const unsigned int centre = (nx / 2) * ny + ny / 2;
      std::vector<std::pair<unsigned int, unsigned int>> result = {{centre, centre}};
      if (nx > 1)
        result.emplace_back(centre, centre - ny);
      if (ny > 1)
        result.emplace_back(centre, centre - 1);
      return result;
    }



    base::FrequencyResponseMatrix
    compute_green_functions(const PeriodicCell &cell,
                            const ContactPatch &patch,
                            const Method        method,
                            const double        df,
                            const unsigned int  n_lines,
                            const MPI_Comm      comm,
                            const bool          show_progress,
                            GreenRunReport     &report,
                            const HarmonicRing *harmonic)
    {
      const auto         start   = std::chrono::steady_clock::now();
      const unsigned int rank    = dealii::Utilities::MPI::this_mpi_process(comm);
      const unsigned int n_ranks = dealii::Utilities::MPI::n_mpi_processes(comm);
      const unsigned int P       = patch.points.size();

      // This rank's lines: k = rank, rank + n_ranks, ...
      std::vector<unsigned int> lines;
      for (unsigned int k = rank; k < n_lines; k += n_ranks)
        lines.push_back(k);
      const unsigned int n_threads =
        std::max(1u, std::min<unsigned int>(dealii::MultithreadInfo::n_threads(), lines.size()));

      std::vector<double>       values(2 * std::size_t(n_lines) * P * P, 0.);
      std::atomic<unsigned int> next{0}, done{0};
      std::mutex                mutex;
      std::string               failure;
      SolveDiagnostics          diagnostics;
      base::Progress            progress(n_ranks == 1 ?
                                "Green's functions (" + std::to_string(n_lines) +
                                  " frequencies)" :
                                "Green's functions (rank 0's " + std::to_string(lines.size()) +
                                  " of " + std::to_string(n_lines) + " frequencies)",
                              lines.size());
      const auto work = [&]() {
        try
          {
            auto             solver = make_green_solver(method, cell, patch, harmonic);
            SolveDiagnostics mine;
            for (unsigned int l = next++; l < lines.size(); l = next++)
              {
                {
                  std::lock_guard<std::mutex> lock(mutex);
                  if (!failure.empty())
                    return;
                }
                const unsigned int k = lines[l];
                const auto         g = solver->solve(2. * M_PI * k * df, mine);
                double            *out = values.data() + 2 * std::size_t(k) * P * P;
                for (unsigned int i = 0; i < P; ++i)
                  for (unsigned int j = 0; j < P; ++j)
                    {
                      out[2 * (i * P + j)]     = g(i, j).real();
                      out[2 * (i * P + j) + 1] = g(i, j).imag();
                    }
                ++done;
              }
            std::lock_guard<std::mutex> lock(mutex);
            diagnostics.merge(mine);
          }
        catch (const std::exception &e)
          {
            std::lock_guard<std::mutex> lock(mutex);
            if (failure.empty())
              failure = e.what();
          }
      };
      base::run_on_threads(n_threads, work, done, lines.size(),
                           show_progress && rank == 0 ? &progress : nullptr, [&]() {
                                 std::lock_guard<std::mutex> lock(mutex);
                                 return !failure.empty();
                               });

      // Every rank learns whether any failed; the lowest failing rank's
      // message is the one reported.
      throw_if_any_rank_failed(comm, failure.empty() ? RankFailure::none : RankFailure::numerical,
                               "Green's functions: " + failure);

      base::FrequencyResponseMatrix green;
      green.df      = df;
      green.n_lines = n_lines;
      if (n_ranks > 1)
        {
          std::vector<double> sum(rank == 0 ? values.size() : 0);
          MPI_Reduce(values.data(), sum.data(), static_cast<int>(values.size()), MPI_DOUBLE,
                     MPI_SUM, 0, comm);
          values.swap(sum);
        }
      report.diagnostics.max_residual =
        dealii::Utilities::MPI::max(diagnostics.max_residual, comm);
      report.diagnostics.max_condition =
        dealii::Utilities::MPI::max(diagnostics.max_condition, comm);
      report.ranks   = n_ranks;
      report.threads = n_threads;
      report.seconds =
        std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
      if (rank == 0)
        {
          for (const auto &p : patch.points)
            green.points.push_back({{p.x, p.y, p.radius}});
          green.values.resize(std::size_t(n_lines) * P * P);
          for (std::size_t e = 0; e < green.values.size(); ++e)
            green.values[e] = {values[2 * e], values[2 * e + 1]};
        }
      return green;
    }
  } // namespace periodic
} // namespace greentread

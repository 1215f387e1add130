#pragma once

// Command line shared by the benchmarks: --quick (a smoke run with small
// sizes), --output DIR (where CSV and PNG files go), --model FILE (an
// input model, for the benchmarks that take one) and --part N (one part of
// a benchmark made of parts).

#include <greentread/base/output.h>

#include <deal.II/base/mpi.h>
#include <deal.II/base/multithread_info.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <string>
#include <utility>

namespace benchmark
{
  /**
   * The figures a benchmark asserts against its reference (the direct
   * method, an exact solution or the finer level of its own study), so that
   * its --quick smoke run in ctest fails on a number, not only on a crash.
   * Each check prints the figure beside its bound; exit_code() is 1 when one
   * failed. A figure that is not a number fails.
   */
  class Checks
  {
  public:
    explicit Checks(std::string name)
        : name(std::move(name))
    {
    }

    /// Asserts @p measured <= @p bound; @p what names the figure and its reference.
    void
    at_most(const std::string &what, const double measured, const double bound)
    {
      report(what, measured, "<=", bound, measured <= bound);
    }

    /// Asserts @p measured >= @p bound.
    void
    at_least(const std::string &what, const double measured, const double bound)
    {
      report(what, measured, ">=", bound, measured >= bound);
    }

    int
    exit_code() const
    {
      return failed == 0 ? 0 : 1;
    }

  private:
    void
    report(const std::string &what,
           const double       measured,
           const char        *relation,
           const double       bound,
           const bool         pass)
    {
      const bool ok = pass && std::isfinite(measured);
      std::printf("check %s: %.3g %s %.3g: %s\n", what.c_str(), measured, relation, bound,
                  ok ? "pass" : "FAIL");
      std::fflush(stdout);
      if (!ok)
        {
          std::fprintf(stderr, "%s: %s is %.6g, outside its bound %s %.6g\n", name.c_str(),
                       what.c_str(), measured, relation, bound);
          ++failed;
        }
    }

    std::string  name;
    unsigned int failed = 0;
  };

  struct Options
  {
    bool                  quick = false;
    std::filesystem::path output;
    /// --model FILE: an input model where a benchmark takes one (else empty).
    std::filesystem::path model;
    /// --part N: only part N of a benchmark made of parts (0: all of them).
    unsigned int part = 0;
  };

  inline Options
  parse(int argc, char **argv, const std::string &name)
  {
    Options options;
    // Default: <build directory>/benchmark-output/<name> (set by CMake), so
    // that a benchmark run does not write into the checkout.
    options.output = std::filesystem::path(GREENTREAD_BENCHMARK_OUTPUT) / name;
    for (int i = 1; i < argc; ++i)
      if (std::strcmp(argv[i], "--quick") == 0)
        options.quick = true;
      else if (std::strcmp(argv[i], "--output") == 0 && i + 1 < argc)
        options.output = argv[++i];
      else if (std::strcmp(argv[i], "--model") == 0 && i + 1 < argc)
        options.model = argv[++i];
      else if (std::strcmp(argv[i], "--part") == 0 && i + 1 < argc)
        {
          const std::string value = argv[++i];
          if (value.empty() || value.size() > 3 ||
              value.find_first_not_of("0123456789") != std::string::npos)
            {
              std::cerr << name << ": --part '" << value
                        << "' is not allowed; allowed: a part number (0: every part)\n";
              std::exit(2);
            }
          options.part = static_cast<unsigned int>(std::stoul(value));
        }
      else
        {
          std::cerr << "usage: " << name << " [--quick] [--output DIR] [--model FILE] [--part N]\n";
          std::exit(2);
        }
    options.output = greentread::base::prepare_output_directory(options.output.string());
    return options;
  }

  /// Peak double-precision rate of @p threads cores [FLOP/s]: clock x 16
  /// (two 4-wide FMA units), x 32 where the processor has AVX-512 (two
  /// 8-wide units, which the time-blocked update's products use:
  /// convolution/shape_kernels.h), the clock from /proc/cpuinfo.
  inline double
  peak_flops(const unsigned int threads)
  {
    std::ifstream cpuinfo("/proc/cpuinfo");
    std::string   line;
    double        mhz = 0.;
    while (std::getline(cpuinfo, line))
      if (line.rfind("cpu MHz", 0) == 0)
        mhz = std::max(mhz, std::stod(line.substr(line.find(':') + 1)));
    return threads * mhz * 1e6 * (__builtin_cpu_supports("avx512f") ? 32. : 16.);
  }
} // namespace benchmark

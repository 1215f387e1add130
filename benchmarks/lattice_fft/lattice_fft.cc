// The tread layer's lattice convolution (convolution/lattice_convolution.h),
// y = L x for a block Toeplitz kernel on the contact grid, by FFT: the cost of
// one product with the program's estimated plans (FFTW_ESTIMATE, every
// transform out of place), against the measured plans it had before
// (FFTW_MEASURE, the backward column transform in place), and each product's
// difference from the dense product L x, the reference. The contact solve
// applies L once per iteration, so this product is most of a rolling step.
//
// The estimated plans are the same in every run; the measured ones depend on
// the timings of the moment, so their round-off may change from run to run:
// the program uses the estimated ones (the same bytes with any thread count),
// and this benchmark says what that costs.
//
//   lattice_fft [--quick] [--output DIR]

#include "benchmark_options.h"

#include <greentread/base/exceptions.h>
#include <greentread/base/output.h>
#include <greentread/convolution/lattice_convolution.h>

#include <fftw3.h>

#include <chrono>
#include <cmath>
#include <cstdio>
#include <iostream>
#include <random>

using namespace greentread;

namespace
{
  /// printf-style formatting into a string.
  template <typename... Args>
  std::string
  text(const char *format, Args... args)
  {
    char buffer[256];
    std::snprintf(buffer, sizeof(buffer), format, args...);
    return buffer;
  }

  /// The earlier form of the product: measured plans, the backward column
  /// transform in place. Written here only to be timed against.
  class MeasuredProduct
  {
  public:
    MeasuredProduct(const Eigen::MatrixXd &T)
        : nx(T.rows())
        , ny(T.cols())
        , mx(2 * nx)
        , my(2 * ny)
        , my_c(ny + 1)
    {
      const std::size_t n_real = std::size_t(nx) * my, n_c = std::size_t(mx) * my_c;
      input            = fftw_alloc_real(n_real);
      output           = fftw_alloc_real(n_real);
      rows             = fftw_alloc_complex(n_c);
      spectrum         = fftw_alloc_complex(n_c);
      const int  n_row = my, n_column = mx;
      const auto t0 = std::chrono::steady_clock::now();
      forward_rows  = fftw_plan_many_dft_r2c(1, &n_row, nx, input, nullptr, 1, my, rows, nullptr, 1,
                                             my_c, FFTW_MEASURE);
      forward_columns = fftw_plan_many_dft(1, &n_column, my_c, rows, nullptr, my_c, 1, spectrum,
                                           nullptr, my_c, 1, FFTW_FORWARD, FFTW_MEASURE);
      backward_columns =
        fftw_plan_many_dft(1, &n_column, my_c, spectrum, nullptr, my_c, 1, spectrum, nullptr, my_c,
                           1, FFTW_BACKWARD, FFTW_MEASURE);
      backward_rows = fftw_plan_many_dft_c2r(1, &n_row, nx, spectrum, nullptr, 1, my_c, output,
                                             nullptr, 1, my, FFTW_MEASURE);
      plan_ms = 1e3 * std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
      // Measuring overwrote the arrays: zero the padding now.
      std::fill(input, input + n_real, 0.);
      std::fill(&rows[0][0], &rows[0][0] + 2 * n_c, 0.);
      // The kernel wrapped onto the period, transformed once.
      double       *field = fftw_alloc_real(std::size_t(mx) * my);
      fftw_complex *k     = fftw_alloc_complex(n_c);
      fftw_plan     whole = fftw_plan_dft_r2c_2d(mx, my, field, k, FFTW_ESTIMATE);
      for (unsigned int i = 0; i < mx; ++i)
        for (unsigned int j = 0; j < my; ++j)
          {
            const unsigned int m = i <= nx ? i : mx - i, n = j <= ny ? j : my - j;
            field[std::size_t(i) * my + j] = m < nx && n < ny ? T(m, n) : 0.;
          }
      fftw_execute(whole);
      kernel.resize(n_c);
      for (std::size_t q = 0; q < n_c; ++q)
        kernel[q] = k[q][0] / (double(mx) * my);
      fftw_destroy_plan(whole);
      fftw_free(field);
      fftw_free(k);
    }

    ~MeasuredProduct()
    {
      for (fftw_plan p : {forward_rows, forward_columns, backward_columns, backward_rows})
        fftw_destroy_plan(p);
      fftw_free(input);
      fftw_free(output);
      fftw_free(rows);
      fftw_free(spectrum);
    }

    void
    apply(const Eigen::VectorXd &x, Eigen::VectorXd &y)
    {
      for (unsigned int i = 0; i < nx; ++i)
        std::copy(x.data() + std::size_t(i) * ny, x.data() + std::size_t(i + 1) * ny,
                  input + std::size_t(i) * my);
      fftw_execute(forward_rows);
      fftw_execute(forward_columns);
      for (std::size_t q = 0; q < kernel.size(); ++q)
        {
          spectrum[q][0] *= kernel[q];
          spectrum[q][1] *= kernel[q];
        }
      fftw_execute(backward_columns);
      fftw_execute(backward_rows);
      y.resize(x.size());
      for (unsigned int i = 0; i < nx; ++i)
        std::copy(output + std::size_t(i) * my, output + std::size_t(i) * my + ny,
                  y.data() + std::size_t(i) * ny);
    }

    double plan_ms = 0.;

  private:
    unsigned int        nx, ny, mx, my, my_c;
    double             *input, *output;
    fftw_complex       *rows, *spectrum;
    fftw_plan           forward_rows, forward_columns, backward_columns, backward_rows;
    std::vector<double> kernel;
  };

  /// Microseconds per product of @p apply, over at least 0.2 s (0.05 s with
  /// @p quick).
  template <typename Apply>
  double
  time_product(const Apply &apply, const bool quick)
  {
    const double minimum = quick ? 0.05 : 0.2;
    unsigned int n       = 0;
    const auto   start   = std::chrono::steady_clock::now();
    double       elapsed = 0.;
    while (elapsed < minimum)
      {
        apply();
        ++n;
        elapsed = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
      }
    return 1e6 * elapsed / n;
  }
} // namespace

int
main(int argc, char **argv)
{
  dealii::Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  try
    {
      const auto options = benchmark::parse(argc, argv, "lattice_fft");
      // The contact grids: the main job's 80 x 96 points (6 x 8 cm) and its
      // refined level's 160 x 192; the dense reference up to 80 x 96
      // (7680^2 values, 0.5 GB).
      const std::vector<std::array<unsigned int, 2>> grids =
        options.quick ?
          std::vector<std::array<unsigned int, 2>>{{{20, 24}}, {{40, 48}}} :
          std::vector<std::array<unsigned int, 2>>{{{40, 48}}, {{80, 96}}, {{160, 192}}};
      base::AtomicFile csv_file(options.output / "lattice_fft.csv");
      auto            &csv = csv_file.stream();
      csv << "nx,ny,plans,plan_ms,us_per_product,difference_from_dense,same_bytes_twice\n";
      std::cout << "Lattice convolution y = L x by FFT, one thread\n"
                << "   nx   ny  plans                      plan [ms]  us per product  "
                   "max |y - L x| / max |L x|  same bytes twice\n";
      benchmark::Checks checks("lattice_fft");
      std::mt19937      random(7);
      for (const auto &[nx, ny] : grids)
        {
          // An even kernel that decays as a layer's does: 1 / (1 + r / h).
          Eigen::MatrixXd T(nx, ny);
          for (unsigned int m = 0; m < nx; ++m)
            for (unsigned int n = 0; n < ny; ++n)
              T(m, n) = 1. / (1. + std::hypot(double(m), 1.2 * n) / 3.);
          Eigen::VectorXd                        x(std::size_t(nx) * ny);
          std::uniform_real_distribution<double> uniform(0., 1.);
          for (Eigen::Index p = 0; p < x.size(); ++p)
            x(p) = uniform(random);

          const auto                      t0 = std::chrono::steady_clock::now();
          convolution::LatticeConvolution estimated(T);
          const double                    estimated_plan_ms =
            1e3 * std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
          MeasuredProduct measured(T);
          Eigen::VectorXd y_estimated, y_again, y_measured;
          estimated.apply(x, y_estimated);
          estimated.apply(x, y_again);
          measured.apply(x, y_measured);
          const double us_estimated = time_product(
            [&]() {
              estimated.apply(x, y_again);
            },
            options.quick);
          const double us_measured = time_product(
            [&]() {
              measured.apply(x, y_measured);
            },
            options.quick);
          const bool same        = y_again == y_estimated;
          double     d_estimated = NAN, d_measured = NAN;
          if (std::size_t(nx) * ny <= 7680)
            {
              const Eigen::VectorXd reference = estimated.dense() * x;
              const double          size      = reference.cwiseAbs().maxCoeff();
              d_estimated = (y_estimated - reference).cwiseAbs().maxCoeff() / size;
              d_measured  = (y_measured - reference).cwiseAbs().maxCoeff() / size;
            }
          const auto row = [&](const char *plans, const double plan_ms, const double us,
                               const double difference, const char *twice) {
            std::cout << text("%5u%5u  %-25s%10.1f%16.1f", nx, ny, plans, plan_ms, us)
                      << (std::isnan(difference) ? text("%27s", "-") : text("%27.2e", difference))
                      << "  " << twice << '\n';
            csv << nx << ',' << ny << ',' << plans << ',' << plan_ms << ',' << us << ','
                << (std::isnan(difference) ? std::string("none") : text("%.3e", difference)) << ','
                << twice << '\n';
          };
          row("estimated (the program's)", estimated_plan_ms, us_estimated, d_estimated,
              same ? "yes" : "no");
          row("measured (the earlier)", measured.plan_ms, us_measured, d_measured, "-");
          // Round-off of sums over nx ny terms of the size of the largest:
          // measured 1e-16 to 4e-16 here; 1e-14 is above it for any grid of
          // the program (the FFT's error grows as log n) and far below an
          // error of the method (an index off by one gives 1e-2).
          if (!std::isnan(d_estimated))
            checks.at_most(text("difference from the dense product, %u x %u", nx, ny), d_estimated,
                           1e-14);
          checks.at_least(text("the same bytes twice, %u x %u", nx, ny), same ? 1. : 0., 1.);
        }
      csv_file.commit();
      std::cout << "wrote " << (options.output / "lattice_fft.csv").string() << '\n';
      return checks.exit_code();
    }
  catch (const std::exception &e)
    {
      std::cerr << "lattice_fft: " << e.what() << '\n';
      return 1;
    }
}

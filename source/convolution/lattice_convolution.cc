#include <greentread/base/exceptions.h>
#include <greentread/convolution/lattice_convolution.h>

#include <fftw3.h>

#include <algorithm>
#include <array>
#include <cstdlib>
#include <vector>

namespace greentread
{
  namespace convolution
  {
    /**
     * The padded work arrays and FFTW's plans on them (row-major, 2 nx x
     * 2 ny). The 2D transform is done as its two passes, so that the rows
     * known to be zero are skipped: the padding rows i >= nx of the input
     * (their row transforms are zero) and of the output (never read). That
     * is half the row transforms each way. The plans are estimated
     * (FFTW_ESTIMATE), not measured: a measured plan depends on the timings
     * of the moment, so its round-off changed from run to run and with the
     * thread count. Every transform is out of place: FFTW_ESTIMATE's plan of
     * an in-place column transform buffers its data (its plan of the whole 2D
     * transform took 57% of a rolling run of the main job, much of it in
     * buffer copies, fftw_cpy2d); out of place, its plans cost what measured
     * ones do (benchmarks/lattice_fft).
     */
    namespace
    {
      /// A thread's work arrays: FFTW's new-array execute functions may run
      /// concurrently on arrays of their own (same sizes and alignment as
      /// at planning, which fftw_alloc gives), so that one convolution
      /// serves several threads (rolling runs side by side). The input's
      /// padding (the columns j >= ny of its rows) and the rows i >= nx of
      /// the row transforms' output are zeroed once, at allocation: no
      /// transform writes them (the column transform is out of place and
      /// keeps its input).
      struct Work
      {
        std::array<unsigned int, 4> shape{{0, 0, 0, 0}}; // nx, ny, mx, my
        double                     *input = nullptr, *output = nullptr;
        fftw_complex               *rows = nullptr, *spectrum = nullptr, *back = nullptr;

        void
        reserve(const unsigned int nx,
                const unsigned int ny,
                const unsigned int mx,
                const unsigned int my)
        {
          const std::array<unsigned int, 4> wanted{{nx, ny, mx, my}};
          if (wanted == shape)
            return;
          release();
          const std::size_t n_real    = std::size_t(nx) * my,
                            n_complex = std::size_t(mx) * (my / 2 + 1);
          input                       = fftw_alloc_real(n_real);
          output                      = fftw_alloc_real(n_real);
          rows                        = fftw_alloc_complex(n_complex);
          spectrum                    = fftw_alloc_complex(n_complex);
          back                        = fftw_alloc_complex(n_complex);
          if (!input || !output || !rows || !spectrum || !back)
            {
              release();
              throw NumericalError("lattice convolution: cannot allocate the FFT buffers of " +
                                   std::to_string(mx) + " x " + std::to_string(my) + " points");
            }
          std::fill(input, input + n_real, 0.);
          std::fill(&rows[0][0], &rows[0][0] + 2 * n_complex, 0.);
          shape = wanted;
        }

        void
        release()
        {
          fftw_free(input);
          fftw_free(output);
          fftw_free(rows);
          fftw_free(spectrum);
          fftw_free(back);
          input = output = nullptr;
          rows = spectrum = back = nullptr;
          shape                  = {{0, 0, 0, 0}};
        }

        ~Work()
        {
          release();
        }
      };
    } // namespace



    struct LatticeConvolution::Plans
    {
      unsigned int nx = 0, mx = 0, my = 0, my_c = 0; // the period, and ny's half spectrum
      /// Row r2c on the first nx rows (input to rows); column DFTs on all
      /// my_c columns, forward (rows to spectrum) and backward (spectrum to
      /// back); row c2r on the first nx rows (back to output).
      fftw_plan rows_forward = nullptr, columns_forward = nullptr, columns_backward = nullptr,
                rows_backward = nullptr;
      std::vector<double> kernel_spectrum; // real: the kernel is even

      Plans(const unsigned int nx_, const unsigned int ny)
          : nx(nx_)
          , mx(2 * nx_)
          , my(2 * ny)
          , my_c(ny + 1)
      {
        // Planned on a work set of their own, executed on each thread's.
        Work w;
        w.reserve(nx, ny, mx, my);
        const int      n_row = my, n_column = mx;
        const unsigned flags = FFTW_ESTIMATE;
        rows_forward     = fftw_plan_many_dft_r2c(1, &n_row, nx, w.input, nullptr, 1, my, w.rows,
                                                  nullptr, 1, my_c, flags);
        columns_forward  = fftw_plan_many_dft(1, &n_column, my_c, w.rows, nullptr, my_c, 1,
                                              w.spectrum, nullptr, my_c, 1, FFTW_FORWARD, flags);
        columns_backward = fftw_plan_many_dft(1, &n_column, my_c, w.spectrum, nullptr, my_c, 1,
                                              w.back, nullptr, my_c, 1, FFTW_BACKWARD, flags);
        rows_backward    = fftw_plan_many_dft_c2r(1, &n_row, nx, w.back, nullptr, 1, my_c, w.output,
                                                  nullptr, 1, my, flags);
        if (!rows_forward || !columns_forward || !columns_backward || !rows_backward)
          throw NumericalError("lattice convolution: FFTW could not plan the transforms of " +
                               std::to_string(mx) + " x " + std::to_string(my) + " points");
      }

      ~Plans()
      {
        for (fftw_plan p : {rows_forward, columns_forward, columns_backward, rows_backward})
          fftw_destroy_plan(p);
      }
    };



    LatticeConvolution::LatticeConvolution(const Eigen::MatrixXd &T)
        : nx(T.rows())
        , ny(T.cols())
        , kernel(T)
    {
      if (T.size() == 0 || !T.allFinite())
        throw InputError("lattice convolution: the kernel is empty or not finite (" +
                         std::to_string(T.rows()) + " x " + std::to_string(T.cols()) + ")");
      plans = std::make_unique<Plans>(nx, ny);
      // The kernel wrapped onto the period: offset m at m and at 2 nx - m.
      // Whole (its rows i >= nx are not zero): by a plan of its own, once.
      const unsigned int mx = plans->mx, my = plans->my;
      const std::size_t  n_c      = std::size_t(mx) * plans->my_c;
      double            *field    = fftw_alloc_real(std::size_t(mx) * my);
      fftw_complex      *spectrum = fftw_alloc_complex(n_c);
      if (field == nullptr || spectrum == nullptr)
        {
          fftw_free(field);
          fftw_free(spectrum);
          throw NumericalError("lattice convolution: cannot allocate the kernel's FFT buffers of " +
                               std::to_string(mx) + " x " + std::to_string(my) + " points");
        }
      fftw_plan whole = fftw_plan_dft_r2c_2d(mx, my, field, spectrum, FFTW_ESTIMATE);
      for (unsigned int i = 0; i < mx; ++i)
        for (unsigned int j = 0; j < my; ++j)
          {
            const unsigned int m = i <= nx ? i : mx - i, n = j <= ny ? j : my - j;
            field[std::size_t(i) * my + j] = m < nx && n < ny ? T(m, n) : 0.;
          }
      fftw_execute(whole);
      fftw_destroy_plan(whole);
      plans->kernel_spectrum.resize(n_c);
      // Normalised once: FFTW's backward transform is not.
      for (std::size_t k = 0; k < n_c; ++k)
        plans->kernel_spectrum[k] = spectrum[k][0] / (double(mx) * my);
      fftw_free(field);
      fftw_free(spectrum);
    }



    LatticeConvolution::~LatticeConvolution() = default;



    void
    LatticeConvolution::apply(const Eigen::VectorXd &x, Eigen::VectorXd &y) const
    {
      if (x.size() != Eigen::Index(nx) * ny)
        throw InputError("lattice convolution: a field of " + std::to_string(x.size()) +
                         " values on a lattice of " + std::to_string(nx * ny) + " points");
      const Plans      &p = *plans;
      thread_local Work w;
      w.reserve(nx, ny, p.mx, p.my);
      for (unsigned int i = 0; i < nx; ++i)
        std::copy(x.data() + std::size_t(i) * ny, x.data() + std::size_t(i + 1) * ny,
                  w.input + std::size_t(i) * p.my);
      fftw_execute_dft_r2c(p.rows_forward, w.input, w.rows);
      fftw_execute_dft(p.columns_forward, w.rows, w.spectrum);
      const std::size_t n_c = std::size_t(p.mx) * p.my_c;
      for (std::size_t k = 0; k < n_c; ++k)
        {
          w.spectrum[k][0] *= p.kernel_spectrum[k];
          w.spectrum[k][1] *= p.kernel_spectrum[k];
        }
      fftw_execute_dft(p.columns_backward, w.spectrum, w.back);
      fftw_execute_dft_c2r(p.rows_backward, w.back, w.output);
      y.resize(x.size());
      for (unsigned int i = 0; i < nx; ++i)
        std::copy(w.output + std::size_t(i) * p.my, w.output + std::size_t(i) * p.my + ny,
                  y.data() + std::size_t(i) * ny);
    }



    Eigen::MatrixXd
    LatticeConvolution::dense() const
    {
      const unsigned int n = nx * ny;
      Eigen::MatrixXd    L(n, n);
      for (unsigned int p = 0; p < n; ++p)
        for (unsigned int q = 0; q < n; ++q)
          L(p, q) =
            kernel(std::abs(int(p / ny) - int(q / ny)), std::abs(int(p % ny) - int(q % ny)));
      return L;
    }
  } // namespace convolution
} // namespace greentread

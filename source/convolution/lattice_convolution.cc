#include <greentread/base/exceptions.h>
#include <greentread/convolution/lattice_convolution.h>

#include <fftw3.h>

#include <algorithm>
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
     * is half the row transforms each way. The plans are measured once
     * (FFTW_MEASURE), not estimated: with FFTW_ESTIMATE's plan of the whole
     * 2D transform, FFTW took 57% of a rolling run of the main job, much of
     * it in its buffer copies (fftw_cpy2d).
     */
    namespace
    {
      /// A thread's work arrays: FFTW's new-array execute functions may run
      /// concurrently on arrays of their own (same sizes and alignment as
      /// at planning, which fftw_alloc gives), so that one convolution
      /// serves several threads (rolling runs side by side).
      struct Work
      {
        std::size_t   n_real = 0, n_complex = 0;
        double       *field    = nullptr;
        fftw_complex *spectrum = nullptr;

        void
        reserve(const std::size_t real, const std::size_t complex)
        {
          if (real == n_real && complex == n_complex)
            return;
          fftw_free(field);
          fftw_free(spectrum);
          field     = fftw_alloc_real(real);
          spectrum  = fftw_alloc_complex(complex);
          n_real    = real;
          n_complex = complex;
          if (field == nullptr || spectrum == nullptr)
            throw NumericalError("lattice convolution: cannot allocate the FFT buffers of " +
                                 std::to_string(real) + " points");
        }

        ~Work()
        {
          fftw_free(field);
          fftw_free(spectrum);
        }
      };
    } // namespace



    struct LatticeConvolution::Plans
    {
      unsigned int  nx = 0, mx = 0, my = 0, my_c = 0; // the period, and ny's half spectrum
      double       *field    = nullptr;
      fftw_complex *spectrum = nullptr;
      /// Row r2c on the first nx rows; column DFTs (both ways, in place) on
      /// all my_c columns; row c2r on the first nx rows.
      fftw_plan rows_forward = nullptr, columns_forward = nullptr, columns_backward = nullptr,
                rows_backward = nullptr;
      std::vector<double> kernel_spectrum; // real: the kernel is even

      Plans(const unsigned int nx_, const unsigned int ny)
        : nx(nx_)
        , mx(2 * nx_)
        , my(2 * ny)
        , my_c(ny + 1)
      {
        field    = fftw_alloc_real(std::size_t(mx) * my);
        spectrum = fftw_alloc_complex(std::size_t(mx) * my_c);
        if (field == nullptr || spectrum == nullptr)
          throw NumericalError("lattice convolution: cannot allocate the FFT buffers of " +
                               std::to_string(mx) + " x " + std::to_string(my) + " points");
        const int      n_row = my, n_column = mx;
        const unsigned flags = FFTW_MEASURE;
        rows_forward = fftw_plan_many_dft_r2c(1, &n_row, nx, field, nullptr, 1, my, spectrum,
                                              nullptr, 1, my_c, flags);
        columns_forward =
          fftw_plan_many_dft(1, &n_column, my_c, spectrum, nullptr, my_c, 1, spectrum, nullptr,
                             my_c, 1, FFTW_FORWARD, flags);
        columns_backward =
          fftw_plan_many_dft(1, &n_column, my_c, spectrum, nullptr, my_c, 1, spectrum, nullptr,
                             my_c, 1, FFTW_BACKWARD, flags);
        rows_backward = fftw_plan_many_dft_c2r(1, &n_row, nx, spectrum, nullptr, 1, my_c, field,
                                               nullptr, 1, my, flags);
        if (!rows_forward || !columns_forward || !columns_backward || !rows_backward)
          throw NumericalError("lattice convolution: FFTW could not plan the transforms of " +
                               std::to_string(mx) + " x " + std::to_string(my) + " points");
      }

      ~Plans()
      {
        for (fftw_plan p : {rows_forward, columns_forward, columns_backward, rows_backward})
          fftw_destroy_plan(p);
        fftw_free(field);
        fftw_free(spectrum);
      }

      /// The 2D forward transform of @p f's first nx rows (the others are
      /// zero) into @p c.
      void
      forward(double *f, fftw_complex *c) const
      {
        fftw_execute_dft_r2c(rows_forward, f, c);
        std::fill(&c[std::size_t(nx) * my_c][0], &c[std::size_t(mx) * my_c][0], 0.);
        fftw_execute_dft(columns_forward, c, c);
      }

      /// The 2D backward transform of @p c, its first nx rows into @p f.
      void
      backward(fftw_complex *c, double *f) const
      {
        fftw_execute_dft(columns_backward, c, c);
        fftw_execute_dft_c2r(rows_backward, c, f);
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
      fftw_plan          whole =
        fftw_plan_dft_r2c_2d(mx, my, plans->field, plans->spectrum, FFTW_ESTIMATE);
      for (unsigned int i = 0; i < mx; ++i)
        for (unsigned int j = 0; j < my; ++j)
          {
            const unsigned int m = i <= nx ? i : mx - i, n = j <= ny ? j : my - j;
            plans->field[std::size_t(i) * my + j] = m < nx && n < ny ? T(m, n) : 0.;
          }
      fftw_execute(whole);
      fftw_destroy_plan(whole);
      const std::size_t n_c = std::size_t(mx) * plans->my_c;
      plans->kernel_spectrum.resize(n_c);
      // Normalised once: FFTW's backward transform is not.
      for (std::size_t k = 0; k < n_c; ++k)
        plans->kernel_spectrum[k] = plans->spectrum[k][0] / (double(mx) * my);
    }



    LatticeConvolution::~LatticeConvolution() = default;



    void
    LatticeConvolution::apply(const Eigen::VectorXd &x, Eigen::VectorXd &y) const
    {
      if (x.size() != Eigen::Index(nx) * ny)
        throw InputError("lattice convolution: a field of " + std::to_string(x.size()) +
                         " values on a lattice of " + std::to_string(nx * ny) + " points");
      const Plans        &p = *plans;
      thread_local Work   w;
      const std::size_t   n_c = std::size_t(p.mx) * p.my_c;
      w.reserve(std::size_t(p.mx) * p.my, n_c);
      for (unsigned int i = 0; i < nx; ++i)
        {
          double *row = w.field + std::size_t(i) * p.my;
          std::copy(x.data() + std::size_t(i) * ny, x.data() + std::size_t(i + 1) * ny, row);
          std::fill(row + ny, row + p.my, 0.);
        }
      p.forward(w.field, w.spectrum);
      for (std::size_t k = 0; k < n_c; ++k)
        {
          w.spectrum[k][0] *= p.kernel_spectrum[k];
          w.spectrum[k][1] *= p.kernel_spectrum[k];
        }
      p.backward(w.spectrum, w.field);
      y.resize(x.size());
      for (unsigned int i = 0; i < nx; ++i)
        for (unsigned int j = 0; j < ny; ++j)
          y[i * ny + j] = w.field[std::size_t(i) * p.my + j];
    }



    Eigen::MatrixXd
    LatticeConvolution::dense() const
    {
      const unsigned int n = nx * ny;
      Eigen::MatrixXd    L(n, n);
      for (unsigned int p = 0; p < n; ++p)
        for (unsigned int q = 0; q < n; ++q)
          L(p, q) = kernel(std::abs(int(p / ny) - int(q / ny)), std::abs(int(p % ny) - int(q % ny)));
      return L;
    }
  } // namespace convolution
} // namespace greentread

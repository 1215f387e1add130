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
    /// The padded work arrays and FFTW's plans on them (row-major, 2 nx x 2 ny).
    struct LatticeConvolution::Plans
    {
      unsigned int  mx = 0, my = 0, my_c = 0; // the period, and ny's half spectrum
      double       *field    = nullptr;
      fftw_complex *spectrum = nullptr;
      fftw_plan     forward = nullptr, backward = nullptr;
      std::vector<double> kernel_spectrum; // real: the kernel is even

      Plans(const unsigned int nx, const unsigned int ny)
        : mx(2 * nx)
        , my(2 * ny)
        , my_c(ny + 1)
      {
        field    = fftw_alloc_real(std::size_t(mx) * my);
        spectrum = fftw_alloc_complex(std::size_t(mx) * my_c);
        if (field == nullptr || spectrum == nullptr)
          throw NumericalError("lattice convolution: cannot allocate the FFT buffers of " +
                               std::to_string(mx) + " x " + std::to_string(my) + " points");
        forward  = fftw_plan_dft_r2c_2d(mx, my, field, spectrum, FFTW_ESTIMATE);
        backward = fftw_plan_dft_c2r_2d(mx, my, spectrum, field, FFTW_ESTIMATE);
      }

      ~Plans()
      {
        fftw_destroy_plan(forward);
        fftw_destroy_plan(backward);
        fftw_free(field);
        fftw_free(spectrum);
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
      const unsigned int mx = plans->mx, my = plans->my;
      for (unsigned int i = 0; i < mx; ++i)
        for (unsigned int j = 0; j < my; ++j)
          {
            const unsigned int m = i <= nx ? i : mx - i, n = j <= ny ? j : my - j;
            plans->field[std::size_t(i) * my + j] = m < nx && n < ny ? T(m, n) : 0.;
          }
      fftw_execute(plans->forward);
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
      Plans &w = *plans;
      std::fill(w.field, w.field + std::size_t(w.mx) * w.my, 0.);
      for (unsigned int i = 0; i < nx; ++i)
        for (unsigned int j = 0; j < ny; ++j)
          w.field[std::size_t(i) * w.my + j] = x[i * ny + j];
      fftw_execute(w.forward);
      const std::size_t n_c = std::size_t(w.mx) * w.my_c;
      for (std::size_t k = 0; k < n_c; ++k)
        {
          w.spectrum[k][0] *= w.kernel_spectrum[k];
          w.spectrum[k][1] *= w.kernel_spectrum[k];
        }
      fftw_execute(w.backward);
      y.resize(x.size());
      for (unsigned int i = 0; i < nx; ++i)
        for (unsigned int j = 0; j < ny; ++j)
          y[i * ny + j] = w.field[std::size_t(i) * w.my + j];
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

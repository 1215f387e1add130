#include <greentread/base/exceptions.h>
#include <greentread/modal/lsce.h>

#include <Eigen/Dense>
#include <unsupported/Eigen/FFT>

#include <cmath>

namespace greentread
{
  namespace modal
  {
    ImpulseResponse<double>
    impulse_response(const base::FrequencyResponse &frf, const unsigned int last_line)
    {
      const std::size_t                 K = last_line > 0 ? last_line : frf.values.size() - 1;
      std::vector<std::complex<double>> half(frf.values.begin(), frf.values.begin() + K + 1);
      half[K] = {half[K].real(), 0.}; // the Nyquist line of a real sequence is real
      Eigen::FFT<double> fft;
      fft.SetFlag(Eigen::FFT<double>::HalfSpectrum);
      ImpulseResponse<double> g;
      fft.inv(g.values, half, 2 * K);
      // Eigen's inverse carries 1/N; the integral wants df per line.
      const double scale = frf.df * double(2 * K);
      for (double &x : g.values)
        x *= scale;
      g.dt = 1. / (2. * K * frf.df);
      return g;
    }



    ImpulseResponse<std::complex<double>>
    band_impulse_response(const base::FrequencyResponse &frf,
                          const unsigned int             first_line,
                          const unsigned int             last_line)
    {
      const std::vector<std::complex<double>> band(frf.values.begin() + first_line,
                                                   frf.values.begin() + last_line + 1);
      Eigen::FFT<double>                      fft;
      ImpulseResponse<std::complex<double>>   h;
      fft.inv(h.values, band);
      const double n_b = band.size();
      for (auto &x : h.values)
        x *= frf.df * n_b;
      h.dt = 1. / (n_b * frf.df);
      return h;
    }



    template <typename Number>
    HankelSystem<Number>::HankelSystem(const ImpulseResponse<Number> &h,
                                       const unsigned int             max_order)
    {
      const unsigned int first = 1; // skip h_0, see the class documentation
      const unsigned int n     = static_cast<unsigned int>(h.values.size());
      if (n < first + 2 * max_order + 1)
        throw InputError("LSCE: too few samples for the order asked: an order of " +
                         std::to_string(max_order) + " roots needs at least " +
                         std::to_string(first + 2 * max_order + 1) +
                         " impulse-response samples and the FRF gives " + std::to_string(n) +
                         ". Lower 'Identification/Maximum number of modes', use fewer "
                         "'Identification/Bands', or give more lines (a smaller 'Green's "
                         "functions/Frequency step': 15.625 Hz gives 257 lines to 4 kHz)");
      // Three equations per unknown at most: enough to average noise, few
      // enough to keep one QR cheap.
      const unsigned int rows = std::min(n - first - max_order, 3 * max_order);
      Matrix             A(rows, max_order + 1);
      for (unsigned int m = 0; m < rows; ++m)
        for (unsigned int i = 0; i <= max_order; ++i)
          A(m, i) = h.values[first + m + i];
      Eigen::HouseholderQR<Matrix> qr(A);
      triangle = qr.matrixQR().topRows(max_order + 1).template triangularView<Eigen::Upper>();
    }



    template <typename Number>
    typename HankelSystem<Number>::Vector
    HankelSystem<Number>::coefficients(const unsigned int order,
                                       unsigned int      &rank,
                                       double            &condition) const
    {
      const Matrix                                   R11 = triangle.topLeftCorner(order, order);
      const Vector                                   r   = triangle.col(order).head(order);
      Eigen::CompleteOrthogonalDecomposition<Matrix> cod;
      cod.setThreshold(1e-13);
      cod.compute(R11);
      rank              = static_cast<unsigned int>(cod.rank());
      const auto  &qr   = cod.matrixQTZ();
      const double top  = std::abs(qr(0, 0));
      const double last = rank > 0 ? std::abs(qr(rank - 1, rank - 1)) : 0.;
      condition         = last > 0. ? top / last : INFINITY;
      return cod.solve(-r);
    }



    template <typename Number>
    typename HankelSystem<Number>::Vector
    HankelSystem<Number>::coefficients_pivoted(const unsigned int order) const
    {
      Eigen::ColPivHouseholderQR<Matrix> qr(triangle.topLeftCorner(order, order));
      qr.setThreshold(1e-13);
      return qr.solve(-triangle.col(order).head(order));
    }



    template <typename Number>
    unsigned int
    HankelSystem<Number>::rank_estimate() const
    {
      const Eigen::Index p   = triangle.cols() - 1;
      double             top = 0.;
      for (Eigen::Index i = 0; i < p; ++i)
        top = std::max(top, std::abs(triangle(i, i)));
      unsigned int rank = 0;
      for (Eigen::Index i = 0; i < p; ++i)
        rank += std::abs(triangle(i, i)) > 1e-13 * top;
      return rank;
    }



    template <typename Number>
    std::vector<std::complex<double>>
    companion_roots(const Eigen::Matrix<Number, Eigen::Dynamic, 1> &c)
    {
      const Eigen::Index p = c.size();
      // Companion matrix in upper Hessenberg form: last column -c, ones below
      // the diagonal.
      Eigen::Matrix<Number, Eigen::Dynamic, Eigen::Dynamic> C =
        Eigen::Matrix<Number, Eigen::Dynamic, Eigen::Dynamic>::Zero(p, p);
      for (Eigen::Index i = 0; i < p; ++i)
        C(i, p - 1) = -c(i);
      for (Eigen::Index i = 1; i < p; ++i)
        C(i, i - 1) = 1.;
      std::vector<std::complex<double>> roots(p);
      bool                              converged;
      if constexpr (std::is_same_v<Number, double>)
        {
          Eigen::EigenSolver<Eigen::MatrixXd> solver(C, false);
          converged = solver.info() == Eigen::Success;
          for (Eigen::Index i = 0; i < p; ++i)
            roots[i] = solver.eigenvalues()(i);
        }
      else
        {
          Eigen::ComplexEigenSolver<Eigen::MatrixXcd> solver(C, false);
          converged = solver.info() == Eigen::Success;
          for (Eigen::Index i = 0; i < p; ++i)
            roots[i] = solver.eigenvalues()(i);
        }
      if (!converged)
        throw NumericalError("LSCE: the eigenvalues of the " + std::to_string(p) + "x" +
                             std::to_string(p) + " companion matrix did not converge");
      return roots;
    }



    template <typename Number>
    bool
    newton_root(const Eigen::Matrix<Number, Eigen::Dynamic, 1> &c, std::complex<double> &z)
    {
      const Eigen::Index p = c.size();
      for (unsigned int iteration = 0; iteration < 30; ++iteration)
        {
          // Horner for the polynomial and its derivative.
          std::complex<double> value = 1., derivative = 0.;
          for (Eigen::Index i = p - 1; i >= 0; --i)
            {
              derivative = derivative * z + value;
              value      = value * z + c(i);
            }
          if (derivative == 0.)
            return false;
          const std::complex<double> step = value / derivative;
          z -= step;
          if (!std::isfinite(z.real()) || !std::isfinite(z.imag()))
            return false;
          if (std::abs(step) <= 1e-12 * std::max(std::abs(z), 1e-300))
            return true;
        }
      return false;
    }



    template class HankelSystem<double>;
    template class HankelSystem<std::complex<double>>;
    template std::vector<std::complex<double>>
    companion_roots(const Eigen::Matrix<double, Eigen::Dynamic, 1> &);
    template std::vector<std::complex<double>>
    companion_roots(const Eigen::Matrix<std::complex<double>, Eigen::Dynamic, 1> &);
    template bool
    newton_root(const Eigen::Matrix<double, Eigen::Dynamic, 1> &, std::complex<double> &);
    template bool
    newton_root(const Eigen::Matrix<std::complex<double>, Eigen::Dynamic, 1> &,
                std::complex<double> &);
  } // namespace modal
} // namespace greentread

#include <greentread/base/exceptions.h>
#include <greentread/modal/modal_model.h>

#include <algorithm>
#include <cmath>
#include <limits>

namespace greentread
{
  namespace modal
  {
    void
    ModalModel::add_pair(const std::complex<double> lambda, const std::complex<double> residue)
    {
      if (!(lambda.imag() > 0.) || !std::isfinite(lambda.real()) ||
          !std::isfinite(std::abs(residue)))
        throw NumericalError("a complex pole pair needs a finite pole with Im(lambda) > 0");
      term_list.push_back({ModalTerm::Kind::complex_pair, lambda, residue, 0.});
    }



    void
    ModalModel::add_real(const double lambda, const double residue)
    {
      if (!std::isfinite(lambda) || !std::isfinite(residue))
        throw NumericalError("a real pole needs a finite pole and residue");
      term_list.push_back({ModalTerm::Kind::real_pole, lambda, residue, 0.});
    }



    void
    ModalModel::add_double(const double lambda, const double residue, const double residue_t)
    {
      if (!std::isfinite(lambda) || !std::isfinite(residue) || !std::isfinite(residue_t))
        throw NumericalError("a double pole needs a finite pole and residues");
      term_list.push_back({ModalTerm::Kind::double_pole, lambda, residue, residue_t});
    }



    double
    ModalModel::impulse_response(const double t) const
    {
      if (t < 0.)
        return 0.;
      double g = 0.;
      for (const auto &term : term_list)
        switch (term.kind)
          {
            case ModalTerm::Kind::complex_pair:
              g += 2. * std::real(term.residue * std::exp(term.lambda * t));
              break;
            case ModalTerm::Kind::real_pole:
              g += term.residue.real() * std::exp(term.lambda.real() * t);
              break;
            case ModalTerm::Kind::double_pole:
              g += (term.residue.real() + term.residue_t * t) * std::exp(term.lambda.real() * t);
              break;
          }
      return g;
    }



    double
    ModalModel::impulse_response_derivative(const double t) const
    {
      if (t < 0.)
        return 0.;
      double dg = 0.;
      for (const auto &term : term_list)
        switch (term.kind)
          {
            case ModalTerm::Kind::complex_pair:
              dg += 2. * std::real(term.residue * term.lambda * std::exp(term.lambda * t));
              break;
            case ModalTerm::Kind::real_pole:
              dg += term.residue.real() * term.lambda.real() * std::exp(term.lambda.real() * t);
              break;
            case ModalTerm::Kind::double_pole:
              {
                const double l = term.lambda.real();
                dg += (term.residue.real() * l + term.residue_t * (1. + l * t)) * std::exp(l * t);
                break;
              }
          }
      return dg;
    }



    std::complex<double>
    ModalModel::frequency_response(const double omega) const
    {
      const std::complex<double> jw(0., omega);
      std::complex<double>       g = 0.;
      for (const auto &term : term_list)
        switch (term.kind)
          {
            case ModalTerm::Kind::complex_pair:
              g += term.residue / (jw - term.lambda) +
                   std::conj(term.residue) / (jw - std::conj(term.lambda));
              break;
            case ModalTerm::Kind::real_pole:
              g += term.residue / (jw - term.lambda);
              break;
            case ModalTerm::Kind::double_pole:
              g += term.residue / (jw - term.lambda) +
                   term.residue_t / ((jw - term.lambda) * (jw - term.lambda));
              break;
          }
      return g;
    }



    double
    ModalModel::max_real_part() const
    {
      double r = -std::numeric_limits<double>::infinity();
      for (const auto &term : term_list)
        r = std::max(r, term.lambda.real());
      return r;
    }



    double
    ModalModel::max_modulus() const
    {
      double r = 0.;
      for (const auto &term : term_list)
        r = std::max(r, std::abs(term.lambda));
      return r;
    }


    base::FrequencyResponse
    sample(const ModalModel &model, const double df, const unsigned int n_lines)
    {
      base::FrequencyResponse frf;
      frf.df = df;
      frf.values.resize(n_lines);
      for (unsigned int k = 0; k < n_lines; ++k)
        frf.values[k] = model.frequency_response(2. * M_PI * k * df);
      return frf;
    }
  } // namespace modal
} // namespace greentread

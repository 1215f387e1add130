#include <greentread/base/exceptions.h>
#include <greentread/modal/passivity.h>

#include <Eigen/Eigenvalues>

#include <algorithm>
#include <cmath>
#include <complex>
#include <iostream>

namespace greentread
{
  namespace modal
  {
    Passivity
    measure_passivity(const PatchModel &model, const double df, const unsigned int n_lines)
    {
      const unsigned int n = model.n_points();
      Passivity          p;
      p.lines = n_lines;
      Eigen::MatrixXd loss(n, n);
      for (unsigned int l = 1; l <= n_lines; ++l)
        {
          // -Im g(w) term by term: G_r is real and adds nothing.
          const double               omega = 2. * M_PI * l * df;
          const std::complex<double> jw(0., omega);
          loss.setZero();
          for (unsigned int k = 0; k < model.n_terms(); ++k)
            {
              const std::complex<double> a = 1. / (jw - model.lambda[k]);
              const std::complex<double> b = 1. / (jw - std::conj(model.lambda[k]));
              if (!model.is_rank_one())
                {
                  const Eigen::MatrixXcd &R = model.residues[k];
                  if (model.real[k])
                    loss -= a.imag() * R.real();
                  else
                    loss -= (R * a + R.conjugate() * b).imag();
                  continue;
                }
              for (unsigned int j = 0; j < n; ++j)
                for (unsigned int i = 0; i < n; ++i)
                  {
                    const std::complex<double> r = model.residue(k, i, j);
                    loss(i, j) -=
                      model.real[k] ? (r.real() * a).imag() : (r * a + std::conj(r) * b).imag();
                  }
            }
          const Eigen::MatrixXd symmetric = 0.5 * (loss + loss.transpose());
          if (!symmetric.allFinite())
            throw NumericalError("passivity: the patch model's -Im g is not finite at " +
                                 format_short(l * df) + " Hz");
          const Eigen::SelfAdjointEigenSolver<Eigen::MatrixXd> eigen(symmetric,
                                                                     Eigen::EigenvaluesOnly);
          const double largest = eigen.eigenvalues().cwiseAbs().maxCoeff();
          if (!(largest > 0.))
            continue;
          const double ratio = eigen.eigenvalues().minCoeff() / largest;
          if (ratio < p.worst)
            {
              p.worst     = ratio;
              p.frequency = l * df;
            }
        }
      return p;
    }



    void
    print_passivity(const Passivity &passivity, const std::string &what)
    {
      std::cout << "  passivity of " << what
                << ": smallest eigenvalue of -Im g over its largest, over the " << passivity.lines
                << " lines, " << format_printf("%.3g", passivity.worst) << " (at "
                << format_printf("%.0f", passivity.frequency) << " Hz)\n";
    }



    void
    check_passivity(const Passivity &passivity, const bool allow, const std::string &what)
    {
      if (!std::isfinite(passivity.worst))
        throw NumericalError("passivity: the measure of " + what + " is not finite");
      if (!(passivity.worst < -passivity_tolerance))
        return;
      const std::string figure =
        what + " is not passive: the smallest eigenvalue of -Im g over its largest is " +
        format_printf("%.3g", passivity.worst) + " at " +
        format_printf("%.0f", passivity.frequency) + " Hz (a passive model has >= 0, to " +
        format_short(passivity_tolerance) + "), so it can put energy into the contact";
      if (!allow)
        throw InputError("parameter 'Patch model/Allow non-passive' = false: " + figure +
                         "; allowed: true, to roll it anyway with a warning, or 'Patch "
                         "model/Source' = fe modes, passive by construction");
      std::cerr << "greentread: warning: " << figure
                << "; rolled because 'Patch model/Allow non-passive' = true\n";
    }
  } // namespace modal
} // namespace greentread

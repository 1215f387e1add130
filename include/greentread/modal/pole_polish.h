#pragma once

#include <greentread/base/frequency_response.h>

#include <complex>
#include <vector>

/**
 * @file
 * The poles of an identification refined in the frequency domain: a
 * nonlinear least-squares fit of the poles to every FRF line, the residues
 * solved linearly for each trial set of poles (variable projection).
 *
 * LSCE (Appendix A) takes its poles from a linear prediction of the impulse
 * response. On noisy data that prediction is biased and, for modes closer
 * than their half-power bandwidth, can put one pole between two modes. The
 * polish starts from LSCE's poles and minimises
 *   sum_k w_k |g(w_k) - sum_r R_r / (j w_k - l_r) + conj(...) - U + L / w_k^2|^2
 * over the poles, with each trial's residues R_r (and the residual terms U,
 * L when asked) by linear least squares. The poles are parametrised as
 * log(-Re l) and log(Im l) (a real pole: log(-l)), so every trial pole is
 * stable and in the upper half plane. Levenberg-Marquardt (Eigen's
 * unsupported module) with the Jacobian of Kaufman's variable projection,
 * J = -(I - Q Q^T) (dA/dtheta) x, which costs one projection per parameter.
 */

namespace greentread
{
  namespace modal
  {
    /// A pole to polish: Im lambda > 0 for a pair, or a real pole.
    struct PolishPole
    {
      std::complex<double> lambda;
      bool                 real = false;
    };

    /// What the polish did.
    struct PolishReport
    {
      /// The least-squares misfit before and after, over |g|^2 summed.
      double misfit_before = 0., misfit_after = 0.;
      /// Levenberg-Marquardt iterations and function evaluations.
      unsigned int iterations = 0, evaluations = 0;
    };

    /**
     * @brief @p poles refined against every line of @p frf, with the lower
     * (-L / w^2, the 0 Hz line left out) and upper (a constant) residual
     * terms when asked. Returns the refined poles in the same order; if the
     * refinement does not lower the misfit, the poles as given.
     */
    std::vector<PolishPole>
    polish_poles(const base::FrequencyResponse &frf,
                 const std::vector<PolishPole> &poles,
                 bool                           lower,
                 bool                           upper,
                 PolishReport                  &report);
  } // namespace modal
} // namespace greentread

#pragma once

// A synthetic tyre-like Green's matrix with known modes, for the
// identification benchmark and the shipped example FRF
// (prm/example_frf.csv, written by make_example_frf).
//
// M global modes, k = 0..M-1, at f_k = 80 Hz + 85 Hz * (k + jitter) (about
// 46 in a 4 kHz band and the rest above it), damping ratios from 1% to 3%,
// mode shapes phi_k(x, y) = cos(2 pi a_k x / L + p_k) cos(2 pi b_k y / W + q_k)
// over an L x W patch of N_x x N_y points (the paper's 6 cm x 8 cm, 10 x 12),
// and g_ij(w) = sum_k A_k phi_k(i) phi_k(j) / (w_k^2 - w^2 + 2j xi_k w_k w):
// reciprocal (g_ij = g_ji) and passive (A_k > 0) like a real tyre's.

#include <greentread/base/frequency_response.h>
#include <greentread/modal/modal_model.h>

#include <cmath>
#include <random>
#include <vector>

namespace benchmark
{
  struct SyntheticGreen
  {
    std::vector<double>                frequency, damping, amplitude;
    std::vector<std::vector<double>>   shape; // shape[k][point]
    std::vector<std::array<double, 3>> points;

    SyntheticGreen(unsigned int n_modes = 60,
                   unsigned int nx      = 10,
                   unsigned int ny      = 12,
                   double       length  = 0.06,
                   double       width   = 0.08,
                   unsigned int seed    = 2013)
    {
      std::mt19937                           random(seed);
      std::uniform_real_distribution<double> unit(0., 1.);
      for (unsigned int ix = 0; ix < nx; ++ix)
        for (unsigned int iy = 0; iy < ny; ++iy)
          points.push_back({{length * (ix / (nx - 1.) - 0.5), width * (iy / (ny - 1.) - 0.5), 0.}});
      for (unsigned int k = 0; k < n_modes; ++k)
        {
          frequency.push_back(80. + 85. * (k + 0.8 * unit(random)));
          damping.push_back(0.01 + 0.02 * unit(random));
          // Residues of a unit modal mass spread over the patch: 1e3 m/N s^-2.
          amplitude.push_back(1e3 * (0.5 + unit(random)));
          const double        a = 3. * unit(random), b = 3. * unit(random);
          const double        p = 2. * M_PI * unit(random), q = 2. * M_PI * unit(random);
          std::vector<double> phi;
          for (const auto &x : points)
            phi.push_back(std::cos(2. * M_PI * a * x[0] / length + p) *
                          std::cos(2. * M_PI * b * x[1] / width + q));
          shape.push_back(phi);
        }
    }

    /// The exact modal model of g_ij.
    greentread::modal::ModalModel
    model(unsigned int i, unsigned int j) const
    {
      greentread::modal::ModalModel m;
      for (std::size_t k = 0; k < frequency.size(); ++k)
        {
          const double               w = 2. * M_PI * frequency[k], xi = damping[k];
          const std::complex<double> lambda(-xi * w, w * std::sqrt(1. - xi * xi));
          const double               A = amplitude[k] * shape[k][i] * shape[k][j];
          m.add_pair(lambda, A / std::complex<double>(0., 2. * lambda.imag()));
        }
      return m;
    }

    /**
     * The weight of mode @p term in @p frf, the FRF it is part of: the L1
     * norm of the mode's own response over the FRF's lines against the
     * FRF's (E of the data against 'data minus this mode'). A mode below
     * 1% is hardly held by the data, so identification is not judged on it.
     */
    static double
    weight(const greentread::modal::ModalTerm &term, const greentread::base::FrequencyResponse &frf)
    {
      greentread::modal::ModalModel alone;
      alone.add_pair(term.lambda, term.residue);
      const auto own =
        greentread::modal::sample(alone, frf.df, static_cast<unsigned int>(frf.values.size()));
      double mine = 0., norm = 0.;
      for (std::size_t k = 0; k < frf.values.size(); ++k)
        {
          mine += std::abs(own.values[k]);
          norm += std::abs(frf.values[k]);
        }
      return mine / norm;
    }

    /// The FRF g_ij on lines 0, df, ..., (n_lines - 1) df.
    greentread::base::FrequencyResponse
    frf(unsigned int i, unsigned int j, double df, unsigned int n_lines) const
    {
      return greentread::modal::sample(model(i, j), df, n_lines);
    }
  };
} // namespace benchmark

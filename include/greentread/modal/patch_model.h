#pragma once

#include <greentread/base/frequency_response.h>
#include <greentread/base/output.h>
#include <greentread/modal/identification.h>
#include <greentread/modal/modal_model.h>
#include <greentread/modal/patch_model_parameters.h>

#include <Eigen/Core>

#include <complex>
#include <filesystem>
#include <string>
#include <utility>
#include <vector>

/**
 * @file
 * The modal model of a whole contact patch: every Green's function
 * \f$g_{ij}\f$ between the patch's points, with poles shared by all pairs.
 *
 * The poles are those of the structure, so they are found once: by the LSCE
 * identification of Appendix A (greentread/modal/identification.h) applied
 * to a few reference functions that see the modes from different places (the
 * summed driving points \f$\sum_i g_{ii}\f$, the summed response to a
 * uniform pressure \f$\sum_{ij} g_{ij}\f$, and transfers from the point
 * nearest the centre), their poles merged when closer than a tolerance. The
 * residues of each pair then follow from one linear least-squares problem
 * with as many right-hand sides as pairs (one QR for all of them).
 *
 * **Residual flexibility.** A point force on one tread node meets a local
 * compliance of the rubber that is nearly flat up to the last line and beyond
 * (about 70% of the driving point's static compliance on the default tyre):
 * the modes above the band. Two ways to carry it:
 * - `instantaneous` (default): a constant term \f$G_r\f$,
 *   \f$\hat g(\omega) = G_r + \sum_k \ldots\f$, that is
 *   \f$u(t) = G_r\,q(t) + (g_m * q)(t)\f$, with purely imaginary residues
 *   \f$R_k = j\,b_k\f$ (the \f$\phi\phi^T/(2jm\omega_d)\f$ of a mode with
 *   proportional damping), so the modal part starts from rest,
 *   \f$g_m(0^+) = 0\f$, as a structure with mass does. Real poles and poles
 *   above the band are dropped (these would imitate the constant).
 *   \f$G_r\f$ is made symmetric positive definite (eigenvalues at least 1e-3
 *   of the largest). A contact force then acts through a positive definite
 *   spring at once, and the complementarity problem of a step is well posed
 *   (greentread/contact/patch_contact.h). Measured on the default tyre: with
 *   complex residues fitted freely (E 1.5% median) the contact of the patch
 *   grows without bound at every time step tried (10 us to 1 ms); with
 *   imaginary residues (E 6% median, driving points at most 0.8%) it is
 *   stable at all of them.
 * - `real pole`: a real pole at \f$-2\pi f_r\f$, with \f$f_r\f$ several times
 *   the highest line, whose residue is fitted with the others: a first-order
 *   lag that one-point impulse convolutions can carry.
 *
 * **The static line.** The 0 Hz line is weighted more than the others so
 * that the static compliance of the model equals the structure's, which the
 * static contact solve uses.
 */

namespace greentread
{
  namespace modal
  {
    /**
     * @brief With shapes psi_k = A.row(k) + j B.row(k) (B may be empty: real
     * shapes), A^T diag(w1) A - B^T diag(w1) B + A^T diag(w2) B + B^T diag(w2) A.
     * Re sum_k e_k psi_k psi_k^T is shape_sum(A, B, Re e, -Im e), and Im of
     * the same sum shape_sum(A, B, Im e, Re e).
     */
    Eigen::MatrixXd
    shape_sum(const Eigen::MatrixXd &A,
              const Eigen::MatrixXd &B,
              const Eigen::VectorXd &w1,
              const Eigen::VectorXd &w2);

    /// shape_sum() for several pairs of weights (w1, w2) at once, in one
    /// pass over the shapes: the real and imaginary parts of one sum.
    std::vector<Eigen::MatrixXd>
    shape_sums(const Eigen::MatrixXd                                          &A,
               const Eigen::MatrixXd                                          &B,
               const std::vector<std::pair<Eigen::VectorXd, Eigen::VectorXd>> &weights);

    /**
     * @brief Shared poles and the residue matrices of every pair.
     *
     * Term k is a complex pair (lambda[k] with Im > 0, contributing
     * \f$R/(j\omega-\lambda) + \bar R/(j\omega-\bar\lambda)\f$) or a real pole
     * (Im lambda = 0, \f$R/(j\omega-\lambda)\f$ with real R).
     *
     * The residues are stored in one of two forms, and every user goes
     * through residue() or is_rank_one():
     * - full (`identified`): residues[k] is the n x n matrix R_k;
     * - rank one (`fe modes`): residues is empty and
     *   \f$R_k = c_k\,\phi_k\phi_k^T\f$ with \f$\phi_k\f$ = shapes.row(k) and
     *   \f$c_k\f$ = factor[k], N_p values per term instead of N_p^2; the
     *   shape is complex, shapes.row(k) + j shapes_imag.row(k), when
     *   shapes_imag is not empty (modes coupled by the damping).
     */
    struct PatchModel
    {
      std::vector<std::complex<double>> lambda;
      std::vector<bool>                 real;
      /// residues[k](i, j): the residue of term k for the displacement at i
      /// due to a force at j (full form only).
      std::vector<Eigen::MatrixXcd> residues;
      /// Rank-one form: one shape per term, [term][point], and its factor.
      Eigen::MatrixXd                   shapes, shapes_imag;
      std::vector<std::complex<double>> factor;
      /// The instantaneous compliance G_r [m/N] (n x n, symmetric positive
      /// definite), or empty with a real residual pole.
      Eigen::MatrixXd instantaneous;
      /// > 0 when the residual G_r relaxes in this time [s] (modal/
      /// mode_synthesis.h): it is then the last n_p terms, real poles at
      /// -1/beta_r, and `instantaneous` is empty. The contact force is still
      /// taken continuous, as with an instantaneous G_r.
      double residual_relaxation = 0.;
      /// E of Eq. (50) of every pair.
      Eigen::MatrixXd errors;
      /// The points of the patch, as in the Green's function file.
      std::vector<std::array<double, 3>> points;
      /// The highest line of the fitted data [Hz].
      double f_max = 0.;
      /// Poles found by the identification, and its worst E on the reference functions.
      unsigned int identified_modes = 0;
      double       sum_error        = 0.;

      unsigned int
      n_points() const
      {
        return static_cast<unsigned int>(points.size());
      }

      unsigned int
      n_terms() const
      {
        return static_cast<unsigned int>(lambda.size());
      }

      bool
      is_rank_one() const
      {
        return residues.empty() && shapes.rows() > 0;
      }

      /// The residue of term @p k for the pair (i, j), in either form.
      std::complex<double>
      residue(unsigned int k, unsigned int i, unsigned int j) const
      {
        if (!is_rank_one())
          return residues[k](i, j);
        if (shapes_imag.size() == 0)
          return factor[k] * shapes(k, i) * shapes(k, j);
        return factor[k] * std::complex<double>(shapes(k, i), shapes_imag(k, i)) *
               std::complex<double>(shapes(k, j), shapes_imag(k, j));
      }

      /// The model of one pair, as used by the one-point convolutions
      /// (without G_r, which an impulse convolution cannot carry).
      modal::ModalModel
      pair_model(unsigned int i, unsigned int j) const;

      /// \f$\hat g_{ij}(\omega)\f$ of the model.
      std::complex<double>
      frequency_response(unsigned int i, unsigned int j, double omega) const;

      /// The static compliance matrix \f$\hat g(0)\f$ of the model.
      Eigen::MatrixXd
      static_compliance() const;
    };

    /**
     * @brief Fit the model to every pair of @p green.
     * @throws NumericalError if the identification finds no stable pole or
     * the least-squares problem is rank deficient.
     */
    PatchModel
    fit_patch_model(const base::FrequencyResponseMatrix &green,
                    const IdentificationParameters      &identification,
                    const PatchModelParameters          &parameters,
                    bool                                 show_progress);

    /// Write @p model as HDF5 (temporary name, then renamed) with its key.
    void
    write_patch_model(const std::filesystem::path &file,
                      const PatchModel            &model,
                      const base::ParameterRecord &record,
                      const std::string           &stage_key);

    /// Read a file written by write_patch_model().
    PatchModel
    read_patch_model(const std::string &file);

    /// The `stage_key` of a patch model file, empty if there is none.
    std::string
    read_patch_model_key(const std::string &file);
  } // namespace modal
} // namespace greentread

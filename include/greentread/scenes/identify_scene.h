#pragma once

#include <greentread/modal/identification.h>
#include <greentread/scenes/scene.h>

namespace greentread
{
  namespace scenes
  {
    /**
     * @brief Scene "identify": modal identification (LSCE, Appendix A) of one
     * FRF from a CSV file or of many from a Green's function file (HDF5).
     *
     * Stages used: Identification.
     *
     * Writes, in the output directory:
     * - modal_parameters.csv: i,j,lambda_re,lambda_im,R_re,R_im, one row per
     *   pole of g_ij(w) = sum [R/(jw - lambda) + conj(R)/(jw - conj(lambda))]
     *   (a real pole, lambda_im = 0, counts once);
     * - identification_report.csv: i,j,n_modes,error (E of Eq. 50);
     * - residual_terms.csv: i,j,lower,upper, when residual terms are fitted;
     * - worst_fit.csv and identification_worst.png: the FRF with the largest
     *   E against its fit (Figure A.10).
     */
    class IdentifyScene : public Scene
    {
    public:
      IdentifyScene(dealii::ParameterHandler &prm, const GlobalParameters &global);

      void
      run() override;

    private:
      dealii::ParameterHandler       &prm;
      GlobalParameters                global;
      modal::IdentificationParameters identification;
    };
  } // namespace scenes
} // namespace greentread

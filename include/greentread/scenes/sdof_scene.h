#pragma once

#include <greentread/contact/contact_parameters.h>
#include <greentread/convolution/convolution_parameters.h>
#include <greentread/modal/identification.h>
#include <greentread/road/road_profile.h>
#include <greentread/scenes/scene.h>
#include <greentread/sdof/oscillator.h>

namespace greentread
{
  namespace scenes
  {
    /**
     * @brief Scene "sdof": the paper's Section 3. A mass on a spring rolls over
     * a sinusoidal road; the contact force is found by kinematic or penalty
     * contact with one of three convolution methods, and every error is
     * measured against the exact piecewise-analytic solution.
     *
     * Stages used: Oscillator, Road, Contact, Time stepping, Convolution, and
     * Identification when the Green's function is identified.
     *
     * Writes, in the output directory:
     * - time_history.csv: t,u,v,F (F the mean contact force of the step
     *   ending at t, impulses included);
     * - reference.csv: t,u_road,u_exact,v_exact,F_exact;
     * - summary.csv: every error and statistic, quantity,value,unit;
     * - parameters.prm: the complete parameters of the run;
     * - time_history.png: displacement over the road, and contact force;
     * - with Oscillator/Green's function = identified, also frf.csv (the FRF
     *   identified) and modal_parameters.csv (the model used).
     */
    class SdofScene : public Scene
    {
    public:
      SdofScene(dealii::ParameterHandler &prm, const GlobalParameters &global);

      void
      run() override;

    private:
      dealii::ParameterHandler          &prm;
      GlobalParameters                   global;
      sdof::OscillatorParameters         oscillator;
      road::RoadParameters               road;
      contact::ContactParameters         contact;
      convolution::ConvolutionParameters convolution;
      modal::IdentificationParameters    identification;
    };
  } // namespace scenes
} // namespace greentread

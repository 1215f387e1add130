#pragma once

#include <greentread/base/frequency_response.h>
#include <greentread/contact/contact_parameters.h>
#include <greentread/contact/kinematic_contact.h>
#include <greentread/convolution/convolution.h>
#include <greentread/convolution/convolution_parameters.h>
#include <greentread/modal/identification.h>
#include <greentread/road/road_profile.h>
#include <greentread/sdof/exact_solution.h>
#include <greentread/sdof/oscillator.h>

#include <array>
#include <memory>
#include <vector>

/**
 * @file
 * Time stepping of the 1-DoF contact problem (Section 3) by convolution.
 */

namespace greentread
{
  namespace sdof
  {
    /**
     * @brief The result of one run.
     */
    struct SdofRun
    {
      double time_step = 0.;
      /// t_n = n dt, n = 0..N.
      std::vector<double> t;
      /// Displacement u(t_n) [m].
      std::vector<double> u;
      /// Velocity v(t_n^+), after any impulse at t_n [m/s].
      std::vector<double> v;
      /// Mean contact force over (t_{n-1}, t_n], impulses included [N]; F[0] = 0.
      std::vector<double> F;

      /// Per step n: u and v just after the step's start impulse, and v just
      /// before its end impulse (to interpolate inside the step).
      std::vector<double> u_start, v_start, v_end;

      /// Steps decided by each KinematicBranch (kinematic law).
      std::array<unsigned int, 5> branch_count{};
      /// Whether the law decides each step by a branch (the kinematic law).
      bool branches = false;
      /// Steps with a positive contact impulse.
      unsigned int contact_steps = 0;

      std::string  method;
      unsigned int size = 0; // N_g or N_m
      /// Wall time of the time loop alone [s].
      double run_time = 0.;
    };

    /**
     * @brief Errors of a run against the exact solution.
     */
    struct SdofErrors
    {
      double max_u_error     = 0.; ///< max_n |u_n - u(t_n)| [m]
      double max_v_error     = 0.; ///< max_n |v_n - v(t_n^+)| [m/s]
      double max_force_error = 0.; ///< max |mean F - exact mean F| over steps without an impact [N]
      double impulse_error   = 0.; ///< |total impulse - exact| / exact
      double max_penetration_grid   = 0.; ///< max_n (u_r - u_n)^+ [m]
      double max_penetration_step   = 0.; ///< the same inside steps (Hermite) [m]
      double contact_fraction       = 0.; ///< steps in contact / steps
      double exact_contact_fraction = 0.;
      double peak_contact_force     = 0.; ///< of the exact solution, impacts aside [N]
    };

    /**
     * @brief The oscillator's Green's function identified by LSCE from its
     * FRF (the round trip of the 1-DoF scene), with the relative error of
     * the nearest identified pole to the exact one.
     */
    struct IdentifiedGreen
    {
      base::FrequencyResponse frf;
      modal::Identification   identification;
      double                  pole_error = 0.;
    };

    IdentifiedGreen
    identify_green(const Oscillator                      &oscillator,
                   const OscillatorParameters            &parameters,
                   const modal::IdentificationParameters &identification);

    /**
     * @brief The convolution of the oscillator's Green's function by the
     * chosen method, for a run of @p n_steps steps of @p dt (through
     * convolution::create(), with the oscillator's closed-form g(t) for the
     * direct method).
     *
     * @param[in] model If given, a modal model used instead of the
     * oscillator's own (an identified one): the modal methods convolve with
     * it, and the direct method with its impulse response.
     */
    std::unique_ptr<convolution::Convolution>
    make_convolution(const Oscillator                         &oscillator,
                     const convolution::ConvolutionParameters &parameters,
                     double                                    dt,
                     unsigned int                              n_steps,
                     const modal::ModalModel                  *model = nullptr);

    /**
     * @brief Run the contact problem: gravity and contact load convolved with
     * g, from u(0) = u_r(0), v(0) = 0.
     *
     * @throws NumericalError if the run diverges (|u| beyond ten times the
     * largest physical swing: road amplitude + static deflection + peak road
     * speed / omega_0) or produces a non-finite value. Warns on standard
     * error when a penalty run has omega_c dt > 1.
     */
    SdofRun
    solve(const Oscillator                 &oscillator,
          const road::RoadTrack            &road,
          convolution::Convolution         &convolution,
          const contact::ContactParameters &contact,
          bool                              show_progress = true);

    /**
     * @brief Compare a run with the exact solution on its time grid.
     */
    SdofErrors
    compare(const SdofRun &run, const ExactSolution &exact, const road::RoadTrack &road);

    /**
     * @brief A run and its errors: what a test or a benchmark needs.
     */
    struct SdofOutcome
    {
      SdofRun      run;
      SdofErrors   errors;
      unsigned int exact_impacts = 0;
      /// max_n |u_n| [m]
      double max_abs_u = 0.;
    };

    /**
     * @brief Build the oscillator, the road track and the convolution, run,
     * and compare with the exact solution (the scene's pipeline without its
     * files).
     */
    SdofOutcome
    simulate(const OscillatorParameters               &oscillator,
             const road::RoadProfile                  &road,
             const contact::ContactParameters         &contact,
             const convolution::ConvolutionParameters &convolution,
             bool                                      show_progress = false,
             const modal::ModalModel                  *model         = nullptr);

    /**
     * @brief The oscillator's FRF (Eq. 3) on lines 0, df, ..., up to f_max.
     */
    base::FrequencyResponse
    frequency_response(const Oscillator &oscillator, double f_max, double df);
  } // namespace sdof
} // namespace greentread

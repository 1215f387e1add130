#pragma once

#include <greentread/base/output.h>
#include <greentread/modal/modal_model.h>
#include <greentread/road/road_profile.h>
#include <greentread/sdof/exact_solution.h>
#include <greentread/sdof/sdof_solver.h>

#include <filesystem>
#include <string>

/**
 * @file
 * The outputs of the 1-DoF scene (sdof): the computed and the exact time
 * histories, the summary of errors, the plot and the identified modal
 * parameters. Each file is written under a temporary name and renamed.
 */

namespace greentread
{
  namespace analysis
  {
    /// modal_parameters.csv: `i,j,lambda_re,lambda_im,R_re,R_im`, one row per pole.
    void
    write_modal_parameters(const std::filesystem::path &file,
                           const modal::ModalModel     &model,
                           const base::ParameterRecord &record);

    /// time_history.csv: `t,u,v,F` of @p run.
    void
    write_time_history(const std::filesystem::path &file,
                       const sdof::SdofRun         &run,
                       const base::ParameterRecord &record);

    /// reference.csv: `t,u_road,u_exact,v_exact,F_exact` on the run's time grid.
    void
    write_reference(const std::filesystem::path &file,
                    const sdof::SdofRun         &run,
                    const sdof::ExactSolution   &exact,
                    const road::RoadTrack       &track,
                    const base::ParameterRecord &record);

    /**
     * @brief summary.csv: `quantity,value,unit`, the errors @p e of @p run
     * against @p exact (relative ones to the road amplitude @p a0) and its
     * size, labelled @p size_name (N_g or N_m).
     */
    void
    write_summary(const std::filesystem::path &file,
                  const sdof::SdofRun         &run,
                  const sdof::SdofErrors      &e,
                  const sdof::ExactSolution   &exact,
                  double                       a0,
                  const std::string           &size_name,
                  const base::ParameterRecord &record);

    /**
     * @brief time_history.png in @p directory, from its time_history.csv and
     * reference.csv: displacement and contact force, computed and exact.
     * @return Whether it was plotted (gnuplot may be missing).
     */
    bool
    plot_time_history(const std::filesystem::path &directory,
                      const std::string           &label,
                      double                       peak_force,
                      const base::ParameterRecord &record);

    /**
     * @brief The errors on screen, small ones in nm, um/s and ppm: the
     * regression tests' numdiff passes any difference below 1e-6 in the
     * printed unit, which is then 1e-15 m, 1e-12 m/s and 1e-12.
     */
    std::string
    describe_errors(const sdof::SdofErrors &e, const sdof::ExactSolution &exact, double a0);
  } // namespace analysis
} // namespace greentread

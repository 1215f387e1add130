#pragma once

#include <greentread/analysis/rolling_resistance.h>
#include <greentread/analysis/spectra_parameters.h>
#include <greentread/analysis/third_octave.h>
#include <greentread/base/output.h>
#include <greentread/contact/patch_contact.h>
#include <greentread/road/texture.h>

#include <Eigen/Core>

#include <array>
#include <filesystem>
#include <string>
#include <utility>
#include <vector>

/**
 * @file
 * What the tyre-road-contact scene writes for people to look at: the report
 * of each road, the outputs of each rolling run (time histories, a VTU time
 * series of the contact stress for ParaView, plots) and the spectra of all
 * runs. Implemented in source/analysis/rolling_output.cc, and write_spectra()
 * in source/analysis/spectra_output.cc.
 */

namespace greentread
{
  namespace analysis
  {
    /// A file name part for a road: its name without directories or dots
    /// (a slick_road()'s: its texture's and "_slick").
    std::string
    road_label(const std::string &road);

    /// The name of the runs of the slick tyre on @p road when the scene
    /// rolls a tread pattern: "<road> slick".
    std::string
    slick_road(const std::string &road);

    /// The road a slick_road() rolls on (@p road itself if it is not one).
    std::string
    texture_of_road(const std::string &road);

    /// A file name part for a speed: "90kmh".
    std::string
    speed_label(double speed_kmh);

    /**
     * @brief The lattice of a patch's points, numbered p = i_x n_y + i_y as
     * the Green's stage numbers them.
     */
    struct PatchLattice
    {
      /// @throws InputError naming @p source if the points are not a lattice.
      PatchLattice(const std::vector<std::array<double, 3>> &points, const std::string &source);

      std::vector<std::array<double, 3>> points;
      std::vector<double>                xs, ys; ///< the distinct x and y [m]
      unsigned int                       nx = 0, ny = 0;
      unsigned int                       centre = 0; ///< the point nearest (0, 0)
      std::vector<unsigned int>          middle_row; ///< the points with x nearest 0
    };

    /**
     * @brief The road's report: its MPD on screen, its texture spectrum
     * (road_<label>_spectrum.csv and .png) and a 10 cm x 10 cm sample as an
     * image (road_<label>_texture.png, Figure A.11).
     * @return the MPD [m], NaN for a texture shorter than its 0.1 m segment.
     */
    double
    write_road_report(const std::filesystem::path &directory,
                      const std::string           &road,
                      const road::Texture         &texture,
                      const base::ParameterRecord &record);

    /**
     * @brief The outputs of one rolling run `<run>`, written step by step and
     * completed by finish(): history_<run>.csv/png (the points with x0
     * nearest 0, Figures A.12-A.13), maps_<run>/map_*.vtu with
     * contact_<run>.pvd (stress, displacement, road demand), and
     * map_<run>.png (the stress at the last step).
     */
    class RunOutput
    {
    public:
      /**
       * @param[in] speed V [m/s], for the road position of each step.
       * @param[in] tributary The area of one point [m^2]: stress = force / area.
       * @param[in] reporting The weight of each point's stress in the
       *            reporting cell's (contact::ContactGrid::reporting_weights()).
       * @param[in] frames VTU frames written over the run.
       */
      RunOutput(const std::filesystem::path &directory,
                const std::string           &run,
                const PatchLattice          &lattice,
                double                       speed,
                double                       tributary,
                const Eigen::VectorXd       &reporting,
                unsigned int                 n_steps,
                unsigned int                 frames,
                const base::ParameterRecord &record);

      /// Record one step.
      void
      add(const contact::RollingStep &step);

      /// The contact stress at the patch centre, the mean over the reporting
      /// cell, step by step [Pa].
      const std::vector<double> &
      centre_stress() const
      {
        return centre;
      }

      /// The total contact force, step by step [N].
      const std::vector<double> &
      total_force() const
      {
        return force;
      }

      /// Commit the history and the time series, and plot; @p title names the road and speed.
      void
      finish(const std::string &title);

    private:
      std::filesystem::path                       directory;
      std::string                                 run;
      const PatchLattice                         &lattice;
      double                                      speed, tributary;
      Eigen::VectorXd                             reporting;
      unsigned int                                n_steps, frame_every;
      const base::ParameterRecord                &record;
      base::AtomicFile                            history;
      std::vector<std::pair<double, std::string>> frames;
      std::vector<double>                         centre, force;
      Eigen::VectorXd                             stress;
    };

    /// One run's spectrum, for the summaries.
    struct RunSpectrum
    {
      std::string  road;
      double       speed_kmh = 0.;
      BandSpectrum spectrum;       ///< of the stress at the patch centre
      BandSpectrum force_spectrum; ///< of the total contact force, dB re 1 N
      /// The run's histories, step by step: the stress at the patch centre
      /// [Pa] and the total force [N], @p time_step [s] apart (the error
      /// bars' windows come from them).
      std::vector<double> stress_history, force_history;
      double              time_step = 0.;
      /// With RunSettings::point_forces, the contact forces summed over
      /// each Green's-function point's rectangle [N], one history per
      /// point (a run of the plan only: an error bar's level keeps none).
      std::vector<std::vector<double>> point_forces;
      /// The run's name (road_V[_low-rate]) and its rolling resistance, each
      /// part in the order of all_power_parts.
      std::string                      run;
      std::array<RollingResistance, 3> rolling_resistance;
      /// The contact forces' work on the structure and the tread's losses at
      /// each step (RollingPowerMeter::step_work(), tread_step_work()): the
      /// rolling resistance's error bars compare them between levels.
      std::vector<double> step_work, tread_work;
    };

    /**
     * @brief spectra.csv (all levels), spectra_<road>.png (Figure A.14) and
     * spectra_<V>kmh.png (Figure A.15), the total force's spectra_force.csv
     * and spectra_force_<road>.png, and on screen each run's highest band and
     * spectral centroid of both.
     * Each level comes with its standard error (welch_band_spectrum()):
     * a column of the CSV files, a shaded band of +- one standard error
     * around each curve, and on screen the bands from
     * @p spectra.target_from up whose error exceeds @p spectra.target_error,
     * with the distance of the run that gave them (BandSpectrum::duration)
     * that would meet it. Each run's spectra (each band from the run that
     * gave it) go to spectrum_<run>.csv and spectrum_force_<run>.csv.
     * @param[in] stress_reference sigma_0 of the levels [Pa].
     * @param[in] f_max The Green's functions' highest line [Hz].
     */
    void
    write_spectra(const std::filesystem::path    &directory,
                  const std::vector<RunSpectrum> &runs,
                  const std::vector<std::string> &roads,
                  const std::vector<double>      &speeds,
                  double                          stress_reference,
                  double                          f_max,
                  const SpectraParameters        &spectra,
                  const base::ParameterRecord    &record);
  } // namespace analysis
} // namespace greentread

#pragma once

#include <greentread/base/frequency_response.h>
#include <greentread/convolution/convolution_parameters.h>
#include <greentread/convolution/patch_convolution.h>
#include <greentread/modal/patch_model.h>
#include <greentread/periodic/contact_patch.h>
#include <greentread/road/patch_road.h>

#include <Eigen/Dense>

#include <map>
#include <memory>
#include <string>
#include <vector>

/**
 * @file
 * The fast pipeline against the finite-element transient: one
 * rolling case on a coarse ring, run by any fast path (a patch model and a
 * convolution) and by the reference reference::NewmarkRing, with the same
 * points, road, static start and contact law, and the difference of their
 * contact forces. Used by benchmarks/fe_transient and unit/fe_transient.
 * Implemented in source/reference/transient_comparison.cc.
 */

namespace greentread
{
  namespace periodic
  {
    struct InflatedTyre;
  }

  namespace reference
  {
    /// The case: ring, contact points, fast-path inputs, rolling.
    struct TransientCaseSetup
    {
      std::string  geo_file  = "geometry/tyre_165_65_r13.geo"; ///< 'Geometry/Geometry file'
      double       mesh_size = 0.04;                           ///< 'Geometry/Mesh size' [m]
      unsigned int n_cells   = 32;                             ///< 'Geometry/Number of cells'
      /// The contact points (default: the main job's 10 x 12 on 60 x 80 mm).
      periodic::PatchRequest patch;
      /// The Green's functions' lines, for the LSCE fit and the static start [Hz].
      double             frequency_step = 50., max_frequency = 5000.;
      unsigned int       lsce_modes  = 30; ///< 'modal::Identification/Maximum number of modes'
      double             speed_kmh   = 90.;
      double             distance    = 0.5;  ///< [m]
      double             static_load = 600.; ///< [N]
      road::RoadSampling sampling    = road::RoadSampling::envelope;
      /// The road's heights fade in over this distance from the start
      /// (\f$\sin^2\f$ ramp), so that both paths start at rest from the
      /// static contact on the flat road, with no impact at t = 0 [m].
      double run_in = 0.02;
      /// No inflation and one loss factor (loss_factor) for every layer, so that
      /// C = a M + b K and the modes diagonalise it: the fast path's only
      /// errors are then the time step's and the cut-off's.
      bool proportional_damping = false;
      /// With proportional_damping: the loss factor of every layer (0: no damping).
      double loss_factor = 0.05;
      /// 'Materials/Tread pattern/Surface mass = moved inward': the contact
      /// nodes carry no mass, only stiffness damping (periodic::move_tread_mass_inward),
      /// in the reference and in the fast path's Green's functions and modes alike.
      bool surface_mass_inward = false;
      /// 'Road texture/Sinusoid amplitude' and 'Sinusoid wavelength' [m].
      double sinusoid_amplitude = 1e-3, sinusoid_wavelength = 0.05;
    };

    /// A fast path's patch model and its label.
    struct PathModel
    {
      std::string       name;
      modal::PatchModel model;
      double            seconds = 0.; ///< to build it (fit or mode search) [s]
    };

    /// What one run gives: per step, the total force and the centre point's stress.
    struct TransientRun
    {
      double              seconds = 0.;
      std::vector<double> force, stress; ///< [N], [Pa]
      unsigned int        failed_steps = 0;
      /// The complementarity problem's matrix at the centre point: its
      /// displacement at a step's end per unit force at that end [m/N].
      double step_compliance = 0.;
      /// Points in contact at the start, and the least and most fraction over the run.
      unsigned int static_contacts      = 0;
      double       min_contact_fraction = 1., max_contact_fraction = 0.;
    };

    /**
     * @brief How far a run is from the reference: the largest difference
     * of the total force and of the centre stress over the reference's
     * largest value, the rms of the force difference over the reference's
     * rms fluctuation, and the largest band-level difference [dB] over the
     * one-third-octave bands from the lowest that the record resolves (or
     * 250 Hz) to 5 kHz (NaN if the record resolves none).
     */
    struct TransientDifference
    {
      double force = 0., stress = 0., force_band = 0., stress_band = 0.;
      /// rms of the force difference over the rms of the reference's
      /// fluctuation about its mean.
      double force_rms = 0.;
    };

    TransientDifference
    compare(const TransientRun &run, const TransientRun &reference, double dt);

    /**
     * @brief The case built once: the inflated ring, its points, the
     * Green's functions on the lines of @p setup (Bloch) and the static
     * contact; then runs of any path over "sinusoid", "road-A" or "road-B"
     * (the scene's built-in roads, default parameters).
     */
    class TransientCase
    {
    public:
      explicit TransientCase(const TransientCaseSetup &setup);
      ~TransientCase();

      /// The ring, the points, the static start and its check.
      std::string
      describe() const;

      /// One road sample per step: the texture's spacing over the speed [s].
      double
      road_time_step() const;

      unsigned int
      steps(double dt) const;

      /// The paper's path: LSCE on the Green's functions (patch model).
      PathModel
      lsce_model() const;

      /// The ring's own modes up to @p cutoff_hz with the static residual.
      PathModel
      mode_model(double cutoff_hz) const;

      /**
       * @brief The structure alone, with no contact: the points' displacement
       * under the loads \f$q_j(t) = Q_j \sin^2(\pi t / T)\f$ for t < T
       * (T = @p pulse, Q_j from 10 to 60 N over the points), then free, over
       * 3T, by the reference and by each of @p models' modal recursions at
       * @p dt: per model \f$\max_{n,i} |u_i - u_i^{ref}| / \max_{n,i}
       * |u_i^{ref}|\f$.
       */
      std::vector<double>
      driven_difference(const std::vector<const PathModel *> &models,
                        double                                dt,
                        double                                pulse) const;

      /// The reference: Newmark on the full ring.
      TransientRun
      reference(const std::string &road, double dt) const;

      /// A fast path: @p model with @p method.
      TransientRun
      fast(const std::string  &road,
           double              dt,
           const PathModel    &model,
           convolution::Method method) const;

      const periodic::ContactPatch &
      patch() const;

      /// max |B^T K^-1 B - G(0)| / max |G(0)|: the reference's static
      /// compliance against the Green's functions' 0 Hz line (Bloch).
      double
      static_mismatch() const
      {
        return static_difference;
      }

    private:
      TransientRun
      run(convolution::PatchConvolution &convolution, const std::string &road, double dt) const;

      const road::PatchRoad &
      road_named(const std::string &name) const;

      TransientCaseSetup                      setup;
      std::unique_ptr<periodic::InflatedTyre> tyre;
      base::FrequencyResponseMatrix           green;
      Eigen::MatrixXd                         G0;
      std::vector<std::array<double, 3>>      points;
      Eigen::VectorXd                         tread;
      unsigned int                            centre = 0;
      double                                  area = 0., spacing = 0.;
      double                                  static_difference = 0.;
      unsigned int                            ring_dofs         = 0;
      std::map<std::string, road::PatchRoad>  roads;
    };
  } // namespace reference
} // namespace greentread

#pragma once

#include <greentread/fe/elastic_model.h>
#include <greentread/fe/material.h>
#include <greentread/geometry/tyre_cell.h>
#include <greentread/modal/frequency_response.h>
#include <greentread/periodic/green_functions.h>
#include <greentread/scenes/scene.h>
#include <greentread/scenes/tyre_cell_scene.h>

#include <deal.II/base/mpi.h>

#include <filesystem>
#include <memory>
#include <string>

namespace greentread
{
  namespace scenes
  {
    /**
     * @brief The inflated tyre and its contact points: the stages geometry,
     * fe and the periodic cell, which every rank builds (they take a second).
     */
    struct InflatedTyre
    {
      std::unique_ptr<geometry::TyreCell> cell;
      std::unique_ptr<fe::ElasticModel>   model;
      periodic::PeriodicCell              periodic_cell;
      periodic::ContactPatch              patch;
      /// The largest radial growth of the tread under the inflation [m].
      double tread_growth = 0.;
      /// Run times of meshing, assembly, inflation with Kp [s].
      double mesh_seconds = 0., assembly_seconds = 0., inflation_seconds = 0.;

      InflatedTyre(const geometry::GeometryParameters &geometry,
                   const fe::MaterialParameters       &materials,
                   const fe::InflationParameters          &inflation,
                   const periodic::PatchRequest       &patch_request);
    };

    /**
     * @brief What the Green's functions depend on: the program's version,
     * a digest of the sources that compute them, the .geo file's contents
     * and every parameter of Geometry, Materials, Inflation and Green's
     * functions except those that only choose outputs ('Pairs', 'Deflection
     * shape frequency') or name the .geo file. Not the git revision, not the
     * file's path. Stored in green_functions.h5 as the attribute `stage_key`.
     */
    std::string
    green_stage_key(const dealii::ParameterHandler &prm, const std::string &geo_file);

    /**
     * @brief The Green's-function stage with its cache: if @p reuse, @p h5
     * exists and its `stage_key` equals @p key, it is read back (on rank 0) and
     * nothing is computed; otherwise the frequencies are computed over the
     * ranks of @p comm and written to @p h5 by rank 0, with progress on
     * rank 0 if @p show_progress.
     *
     * Ranks other than 0 return an empty matrix.
     */
    struct GreenStageResult
    {
      modal::FrequencyResponseMatrix green;
      bool                           reused = false;
      periodic::GreenRunReport       report;
    };

    GreenStageResult
    run_green_stage(const InflatedTyre              &tyre,
                    const periodic::GreenParameters &parameters,
                    const std::string               &key,
                    const std::filesystem::path     &h5,
                    const base::ParameterRecord     &record,
                    bool                             reuse,
                    bool                             show_progress,
                    MPI_Comm                         comm);

    /**
     * @brief Scene "tire-green": the Green's functions of the inflated ring
     * at the contact points (paper, Section 4.2, Eqs. 42-49), spread over
     * the MPI ranks.
     *
     * Writes green_functions.h5, green_<i>_<j>.csv for the chosen pairs,
     * green_functions.png (|g| and phase, as in Figure A.9),
     * contact_points.csv, and ring_deflection.vtu (the operating deflection
     * shape at one frequency).
     */
    class GreenScene : public Scene
    {
    public:
      GreenScene(dealii::ParameterHandler &prm, const GlobalParameters &global);

      void
      run() override;

    private:
      dealii::ParameterHandler    &prm;
      GlobalParameters             global;
      geometry::GeometryParameters geometry;
      fe::MaterialParameters       materials;
      fe::InflationParameters          inflation;
      periodic::GreenParameters    green;
    };
  } // namespace scenes
} // namespace greentread

#pragma once

#include <greentread/base/frequency_response.h>
#include <greentread/base/output.h>
#include <greentread/fe/elastic_model.h>
#include <greentread/fe/inflation.h>
#include <greentread/fe/material.h>
#include <greentread/geometry/tyre_cell.h>
#include <greentread/periodic/green_functions.h>

#include <deal.II/base/mpi.h>
#include <deal.II/base/parameter_handler.h>

#include <filesystem>
#include <map>
#include <memory>
#include <string>

/**
 * @file
 * The Green's-function stage with its cache: the inflated tyre (stages
 * geometry and fe), its periodic cell and contact points, and the Green's
 * functions, computed over the MPI ranks or read back from
 * green_functions.h5 when its key matches. Used by the scenes tyre-green
 * and tyre-road-contact.
 */

namespace greentread
{
  namespace periodic
  {
    /**
     * @brief The inflated tyre and its contact points: the stages geometry,
     * fe and the periodic cell, which every rank builds (they take a second).
     */
    struct InflatedTyre
    {
      std::unique_ptr<geometry::TyreCell> cell;
      std::unique_ptr<fe::ElasticModel>   model;
      /// The section's harmonics and their ring, with the `harmonic` method.
      std::unique_ptr<fe::HarmonicSection>    section;
      std::unique_ptr<periodic::HarmonicRing> harmonic;
      PeriodicCell                            periodic_cell;
      ContactPatch                            patch;
      /// The largest radial growth of the tread under the inflation [m].
      double tread_growth = 0.;
      /// With 'Surface mass = moved inward': the fraction of the cell's
      /// mass moved off the tread surface (0 otherwise).
      double moved_mass_fraction = 0.;
      /// Run times of meshing, assembly, inflation with Kp [s].
      double mesh_seconds = 0., assembly_seconds = 0., inflation_seconds = 0.;
      /// The section's assembly, inflation and choice of harmonics [s].
      double harmonic_seconds = 0.;

      InflatedTyre(const geometry::GeometryParameters   &geometry,
                   const fe::MaterialParameters         &materials,
                   const fe::InflationParameters        &inflation,
                   const PatchRequest                   &patch_request,
                   const std::optional<HarmonicOptions> &harmonic = std::nullopt);

      /// Two lines: the ring, its cell and inflation; the contact points.
      std::string
      describe(double pressure) const;
    };

    /**
     * @brief What the Green's functions depend on: the program's version,
     * a digest of the sources that compute them, the .geo file's contents
     * and every parameter of Geometry, Materials, Inflation and Green's
     * functions except those that only choose outputs ('Pairs', 'Deflection
     * shape frequency') or name the .geo file. Not the git revision, not the
     * file's path. Stored in green_functions.h5 as the attribute `stage_key`.
     * An entry of @p replaced ("Geometry/Mesh size" to its value, say) is
     * keyed with its value there instead of the parameter's: the key of
     * another level of a discretisation.
     */
    std::string
    green_stage_key(const dealii::ParameterHandler           &prm,
                    const std::string                        &geo_file,
                    const std::map<std::string, std::string> &replaced = {});

    /// The Green's functions of a stage run, and how they were obtained.
    struct GreenStageResult
    {
      base::FrequencyResponseMatrix green;
      bool                          reused = false;
      GreenRunReport                report;
    };

    /**
     * @brief The Green's-function stage with its cache: if @p reuse, @p h5
     * exists and its `stage_key` equals @p key, it is read back (on rank 0) and
     * nothing is computed; otherwise the frequencies are computed over the
     * ranks of @p comm and written to @p h5 by rank 0, with progress on
     * rank 0 if @p show_progress.
     *
     * Ranks other than 0 return an empty matrix.
     */
    GreenStageResult
    run_green_stage(const InflatedTyre          &tyre,
                    const GreenParameters       &parameters,
                    const std::string           &key,
                    const std::filesystem::path &h5,
                    const base::ParameterRecord &record,
                    bool                         reuse,
                    bool                         show_progress,
                    MPI_Comm                     comm);

    /**
     * @brief What a stage run did: reused, or the solves' checks and (with
     * @p timings) the run times of each stage of @p tyre.
     */
    std::string
    describe(const GreenStageResult      &result,
             const InflatedTyre          &tyre,
             const GreenParameters       &parameters,
             const std::filesystem::path &h5,
             bool                         timings);
  } // namespace periodic
} // namespace greentread

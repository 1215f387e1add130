#pragma once

#include <greentread/base/output.h>
#include <greentread/fe/elastic_model.h>
#include <greentread/fe/material.h>
#include <greentread/geometry/tyre_cell.h>

#include <deal.II/lac/vector.h>

#include <filesystem>
#include <string>

/**
 * @file
 * The outputs of the scenes geometry-study and tyre-cell: the section by
 * material, the inflated cell, and the masses of the layers against Pappus.
 */

namespace greentread
{
  namespace analysis
  {
    /**
     * @brief section.vtu (the section's material ids) and section.png (the
     * section coloured by layer, titled with @p geo_name).
     * @return Whether the PNG was plotted.
     */
    bool
    write_section(const std::filesystem::path &directory,
                  const geometry::TyreCell    &cell,
                  const std::string           &geo_name,
                  const base::ParameterRecord &record);

    /// inflated_cell.vtu (displacement @p u, von Mises stress) and its .pvd.
    void
    write_inflated_cell(const std::filesystem::path  &directory,
                        const fe::ElasticModel       &model,
                        const dealii::Vector<double> &u);

    /// The masses of the layers, as written by write_mass_report().
    struct MassReport
    {
      /// One line per layer for the screen: FE mass, Pappus mass, difference.
      std::string lines;
      /// The cell's mass [kg].
      double total = 0.;
    };

    /**
     * @brief mass_report.csv (`layer,fe_mass,analytic_mass,relative_difference`,
     * then the cell and the whole tyre). A layer with curved edges has no
     * closed-form volume: its columns say "n/a" (so do the totals), never a
     * NaN.
     */
    MassReport
    write_mass_report(const std::filesystem::path  &file,
                      const geometry::TyreCell     &cell,
                      const fe::ElasticModel       &model,
                      const fe::MaterialParameters &materials,
                      const base::ParameterRecord  &record);
  } // namespace analysis
} // namespace greentread

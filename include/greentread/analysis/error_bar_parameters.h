#pragma once

#include <deal.II/base/parameter_handler.h>

#include <iterator>
#include <string>
#include <vector>

/**
 * @file
 * The parameters of the discretisation error bars (subsection "Error bars"):
 * which discretisations get an estimate, how long the coarser runs roll and
 * how coarse the modes' level is (the ring section's coarser level is
 * 'Geometry/Mesh size' doubled, the finite tread blocks' 'Tread
 * pattern/Block mesh size' times 3/2). The method is in analysis/error_bars.h.
 */

namespace greentread
{
  namespace analysis
  {
    /// What one coarser level coarsens.
    enum class Discretisation
    {
      time_step,
      contact_grid,
      mode_cutoff,
      ring_section,
      block_mesh
    };

    /// Every discretisation, in the order of the enumeration.
    inline constexpr Discretisation all_discretisations[] = {
      Discretisation::time_step, Discretisation::contact_grid, Discretisation::mode_cutoff,
      Discretisation::ring_section, Discretisation::block_mesh};

    /// Subsection "Error bars".
    struct ErrorBarParameters
    {
      /// The discretisations estimated, in the order of 'Estimates'.
      std::vector<Discretisation> estimates = {std::begin(all_discretisations),
                                               std::end(all_discretisations)};
      /// The Fourier lines the lowest band of a coarser run's window holds.
      unsigned int window_lines = 4;
      /// The coarser level's mode cut-off over 'Patch model/Mode cutoff'.
      double cutoff_ratio = 0.75;

      bool
      estimates_any(Discretisation d) const;

      static void
      declare_parameters(dealii::ParameterHandler &prm);
      void
      parse_parameters(dealii::ParameterHandler &prm);
    };

    /// "time_step", "contact_grid", "mode_cutoff", "ring_section",
    /// "block_mesh": a column's name part.
    std::string
    label(Discretisation d);

    /// "time step", "contact grid", "mode cutoff", "ring section", "block
    /// mesh": as 'Estimates' names it.
    std::string
    describe(Discretisation d);
  } // namespace analysis
} // namespace greentread

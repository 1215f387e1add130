#pragma once

#include <deal.II/base/parameter_handler.h>

#include <cstddef>
#include <string>

/**
 * @file
 * Subsection "Contact grid": the subdivisions of the Green's functions'
 * rectangles and the contact's solver (contact::ContactGridParameters); the
 * grid and its solvers, "the file documentation" below, are in
 * greentread/contact/contact_grid.h. Implemented in
 * source/contact/contact_grid_parameters.cc.
 */

namespace greentread
{
  namespace contact
  {
    /// Subsection "Contact grid".
    struct ContactGridParameters
    {
      /// Contact rectangles per Green's-function rectangle along each direction.
      unsigned int subdivisions = 8;
      /// `Solver`: `auto`, `pivoting`, `projected CG` or `projected CG on
      /// the whole grid` (the file documentation).
      std::string solver = "auto";
      /// `Tolerance`: the matrix-free solve's projected gradient at its end,
      /// relative to the road's largest demand.
      double tolerance = 1e-6;

      /// The most contact points `pivoting` takes (its N x N matrices: 0.8 GB
      /// each at 10,000 points).
      static constexpr std::size_t max_pivoting_points = 10000;

      /**
       * @brief Whether the grid's solve is matrix-free (`projected CG`, on
       * the candidate set or on the whole grid: candidate_set()).
       * @param[in] reciprocal Whether the patch model is reciprocal (the
       * ring's own modes).
       * @param[in] n_coarse The Green's functions' points.
       * @throws InputError for `projected CG` with a model that is not
       * reciprocal, or `pivoting` on more than max_pivoting_points points,
       * naming the parameters.
       */
      bool
      matrix_free(bool reciprocal, unsigned int n_coarse) const;

      /// Whether a matrix-free solve works on the candidate set (all but
      /// `projected CG on the whole grid`).
      bool
      candidate_set() const
      {
        return solver != "projected CG on the whole grid";
      }

      static void
      declare_parameters(dealii::ParameterHandler &prm);
      void
      parse_parameters(dealii::ParameterHandler &prm);
    };
  } // namespace contact
} // namespace greentread

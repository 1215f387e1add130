#pragma once

#include <greentread/fe/elastic_model.h>
#include <greentread/fe/inflation_parameters.h>

#include <deal.II/lac/vector.h>

#include <utility>

/**
 * @file
 * The inflation of the tyre's cell: the static state whose stresses give the
 * prestress stiffness Kp (greentread/fe/elastic_model.h). Implemented in
 * source/fe/inflation.cc.
 */

namespace greentread
{
  namespace fe
  {
    /**
     * @brief The static inflation of the cell in the ring: rim seat clamped,
     * rotational periodicity over the cell's angle @p cell_angle [rad],
     * @p pressure [Pa] on the inner surface. Returns the displacement;
     * @p model must be assembled.
     * @throws NumericalError if the static system is singular.
     */
    dealii::Vector<double>
    solve_inflation(const ElasticModel &model, double cell_angle, double pressure);

    /**
     * @brief The inflated tread's radial growth [m]: the largest over the
     * nodes at the outer radius @p outer_radius [m], and at the crown (z = 0).
     */
    std::pair<double, double>
    tread_growth(const ElasticModel &model, const dealii::Vector<double> &u, double outer_radius);
  } // namespace fe
} // namespace greentread

#pragma once

#include <greentread/base/output.h>
#include <greentread/periodic/periodic_cell.h>

#include <deal.II/grid/tria.h>

#include <Eigen/Dense>

#include <filesystem>

/**
 * @file
 * The operating deflection shape of the whole ring, for ParaView.
 */

namespace greentread
{
  namespace periodic
  {
    /**
     * @brief Write the ring's complex displacement @p u (from ring_response())
     * on the ring of N rotated copies of @p cell_mesh, as VTU with the
     * Cartesian fields `displacement_real`, `displacement_imag` [m/N] and
     * `amplitude` [m/N] at the vertices.
     *
     * In ParaView, "Warp By Vector" on displacement_real shows the shape at
     * phase 0; the real part of u e^{j alpha} shows it at phase alpha.
     * @throws NumericalError if a vertex of the ring has no node in the
     * reference cell (the cell and @p cell_mesh disagree).
     */
    void
    write_ring_deflection(const std::filesystem::path    &file,
                          const dealii::Triangulation<3> &cell_mesh,
                          const PeriodicCell             &cell,
                          const Eigen::MatrixXcd         &u);
  } // namespace periodic
} // namespace greentread

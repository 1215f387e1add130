#include <greentread/base/exceptions.h>
#include <greentread/geometry/tyre_cell.h>
#include <greentread/periodic/deflection_shape.h>

#include <deal.II/dofs/dof_handler.h>
#include <deal.II/fe/fe_q.h>
#include <deal.II/fe/fe_system.h>
#include <deal.II/lac/vector.h>
#include <deal.II/numerics/data_component_interpretation.h>
#include <deal.II/numerics/data_out.h>

#include <array>
#include <cmath>
#include <map>
#include <tuple>

namespace greentread
{
  namespace periodic
  {
    namespace
    {
      /// A node of the reference cell's [L, I]: position and its DoF per
      /// cylindrical component (-1 where clamped).
      struct ReferenceNode
      {
        double             radius, axial, angle;
        std::array<int, 3> dof;
      };

      std::vector<ReferenceNode>
      reference_nodes(const PeriodicCell &cell)
      {
        // The components of a node have the same position: group them.
        std::map<std::tuple<long long, long long, long long>, std::size_t> index;
        std::vector<ReferenceNode>                                         nodes;
        const double                                                       scale = 1e-9;
        for (unsigned int i = 0; i < cell.n_face + cell.n_interior; ++i)
          {
            const auto &d = cell.dofs[i];
            const auto  key =
              std::make_tuple(std::llround(d.radius / scale), std::llround(d.axial / scale),
                              std::llround(d.angle / scale));
            auto at = index.find(key);
            if (at == index.end())
              {
                at = index.emplace(key, nodes.size()).first;
                nodes.push_back({d.radius, d.axial, d.angle, {{-1, -1, -1}}});
              }
            nodes[at->second].dof[d.component] = static_cast<int>(i);
          }
        for (const auto &h : cell.held_nodes)
          nodes.push_back({h[0], h[1], h[2], {{-1, -1, -1}}});
        return nodes;
      }
    } // namespace

    void
    write_ring_deflection(const std::filesystem::path    &file,
                          const dealii::Triangulation<3> &cell_mesh,
                          const PeriodicCell             &cell,
                          const Eigen::MatrixXcd         &u)
    {
      const unsigned int       N = cell.n_cells;
      dealii::Triangulation<3> ring;
      geometry::make_ring(cell_mesh, cell.angle, N, ring);
      const dealii::FESystem<3> fe(dealii::FE_Q<3>(1), 3);
      dealii::DoFHandler<3>     dof_handler(ring), scalar_handler(ring);
      dof_handler.distribute_dofs(fe);
      const dealii::FE_Q<3> fe_scalar(1);
      scalar_handler.distribute_dofs(fe_scalar);

      const auto nodes = reference_nodes(cell);
      double     size  = 0.;
      for (const auto &n : nodes)
        size = std::max(size, n.radius);
      const double           tolerance = 1e-7 * size;
      dealii::Vector<double> real(dof_handler.n_dofs()), imag(dof_handler.n_dofs()),
        amplitude(scalar_handler.n_dofs());
      std::vector<bool> done(dof_handler.n_dofs(), false);
      auto              scalar_cell = scalar_handler.begin_active();
      for (const auto &c : dof_handler.active_cell_iterators())
        {
          for (const unsigned int v : c->vertex_indices())
            {
              const auto first = c->vertex_dof_index(v, 0);
              if (done[first])
                continue;
              const dealii::Point<3> x     = c->vertex(v);
              const double           r     = std::hypot(x[0], x[1]);
              double                 theta = std::atan2(x[1], x[0]);
              if (theta < 0.)
                theta += 2. * M_PI;
              // The cell whose left face or interior holds the vertex.
              const unsigned int m =
                static_cast<unsigned int>(std::floor(theta / cell.angle + 1e-6)) % N;
              double local = theta - m * cell.angle;
              if (local > M_PI)
                local -= 2. * M_PI;
              const ReferenceNode *match = nullptr;
              for (const auto &n : nodes)
                if (std::abs(n.radius - r) + std::abs(n.axial - x[2]) +
                      r * std::abs(n.angle - local) <
                    tolerance)
                  {
                    match = &n;
                    break;
                  }
              if (match == nullptr)
                throw NumericalError(
                  "ring deflection shape: the ring vertex at r = " + format_short(r) +
                  " m, z = " + format_short(x[2]) + " m, theta = " + format_short(theta) +
                  " rad has no node in the reference cell");
              // Cylindrical (r, theta, z) components to Cartesian.
              const double                        cs = std::cos(theta), sn = std::sin(theta);
              std::array<std::complex<double>, 3> cyl;
              for (unsigned int d = 0; d < 3; ++d)
                cyl[d] = match->dof[d] >= 0 ? u(match->dof[d], m) : 0.;
              const std::array<std::complex<double>, 3> cart = {
                {cs * cyl[0] - sn * cyl[1], sn * cyl[0] + cs * cyl[1], cyl[2]}};
              double norm = 0.;
              for (unsigned int d = 0; d < 3; ++d)
                norm += std::norm(cart[d]);
              for (unsigned int d = 0; d < 3; ++d)
                {
                  const auto i = c->vertex_dof_index(v, d);
                  real[i]      = cart[d].real();
                  imag[i]      = cart[d].imag();
                  done[i]      = true;
                }
              amplitude[scalar_cell->vertex_dof_index(v, 0)] = std::sqrt(norm);
            }
          ++scalar_cell;
        }

      dealii::DataOut<3> out;
      out.attach_dof_handler(dof_handler);
      const std::vector<dealii::DataComponentInterpretation::DataComponentInterpretation> vector(
        3, dealii::DataComponentInterpretation::component_is_part_of_vector);
      out.add_data_vector(real, std::vector<std::string>(3, "displacement_real"),
                          dealii::DataOut<3>::type_dof_data, vector);
      out.add_data_vector(imag, std::vector<std::string>(3, "displacement_imag"),
                          dealii::DataOut<3>::type_dof_data, vector);
      out.add_data_vector(scalar_handler, amplitude, "amplitude");
      out.build_patches();
      out.set_flags(base::undated_vtk_flags());
      base::AtomicFile vtu(file);
      out.write_vtu(vtu.stream());
      vtu.commit();
    }
  } // namespace periodic
} // namespace greentread

#include <greentread/base/exceptions.h>
#include <greentread/base/mesh_ids.h>
#include <greentread/base/parameters.h>
#include <greentread/fe/harmonic_section.h>

#include <deal.II/base/geometry_info.h>
#include <deal.II/base/numbers.h>
#include <deal.II/base/quadrature_lib.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <map>

// The section's loads on its outer faces: the tread's strips under the
// contact points and the segments of the line that radiates.

namespace greentread
{
  namespace fe
  {
    namespace
    {
      /// The section's components: radial and axial (the third is theta).
      constexpr unsigned int section_radial = 0, section_axial = 1;
    } // namespace

    std::pair<Eigen::VectorXd, double>
    HarmonicSection::tread_strip(const double z_low, const double z_high) const
    {
      Eigen::VectorXd                              w        = Eigen::VectorXd::Zero(size());
      double                                       W        = 0.;
      const unsigned int                           per_cell = fe.n_dofs_per_cell();
      std::vector<dealii::types::global_dof_index> local(per_cell);
      const dealii::QGauss<1>                      gauss(fe.degree + 2);
      for (const auto &cell : dofs.active_cell_iterators())
        for (const unsigned int f : cell->face_indices())
          {
            if (!cell->face(f)->at_boundary() ||
                cell->face(f)->boundary_id() != geometry::tread_surface)
              continue;
            // The edge from the cell's face vertex 0 to 1; t in [0, 1] along
            // it. The section's edges are straight (MappingQ1).
            const unsigned int     v0 = dealii::GeometryInfo<2>::face_to_cell_vertices(f, 0);
            const unsigned int     v1 = dealii::GeometryInfo<2>::face_to_cell_vertices(f, 1);
            const dealii::Point<2> a = cell->vertex(v0), b = cell->vertex(v1);
            if (std::abs(b[1] - a[1]) <= 1e-12 * (a - b).norm())
              continue; // a radial edge has no extent across the tread
            const double t_low  = std::clamp((z_low - a[1]) / (b[1] - a[1]), 0., 1.);
            const double t_high = std::clamp((z_high - a[1]) / (b[1] - a[1]), 0., 1.);
            const double t0 = std::min(t_low, t_high), t1 = std::max(t_low, t_high);
            if (t1 - t0 < 1e-14)
              continue;
            const dealii::Point<2> u0 = dealii::GeometryInfo<2>::unit_cell_vertex(v0);
            const dealii::Point<2> u1 = dealii::GeometryInfo<2>::unit_cell_vertex(v1);
            cell->get_dof_indices(local);
            for (unsigned int q = 0; q < gauss.size(); ++q)
              {
                const double t    = t0 + (t1 - t0) * gauss.point(q)[0];
                const double ds   = (t1 - t0) * gauss.weight(q) * (b - a).norm();
                const double r    = a[0] + t * (b[0] - a[0]);
                const auto   unit = u0 + t * (u1 - u0);
                W += r * ds;
                for (unsigned int i = 0; i < per_cell; ++i)
                  if (fe.system_to_component_index(i).first == section_radial &&
                      free[local[i]] >= 0)
                    w(free[local[i]]) += fe.shape_value_component(i, unit, section_radial) * r * ds;
              }
          }
      if (!(W > 0.))
        throw NumericalError("the tread strip from z = " + format_short(z_low) + " to " +
                             format_short(z_high) + " m covers no tread surface of the section");
      return {w, W};
    }

    std::pair<Eigen::MatrixXd, Eigen::VectorXd>
    HarmonicSection::surface_segments(const std::vector<std::array<double, 2>> &line) const
    {
      const std::size_t n_segments = line.size() < 2 ? 0 : line.size() - 1;
      Eigen::MatrixXd   w          = Eigen::MatrixXd::Zero(size(), n_segments);
      Eigen::VectorXd   W          = Eigen::VectorXd::Zero(n_segments);

      // The outer faces, chained from one end of the line they form to the
      // other, each with the arc length at its start.
      struct Face
      {
        dealii::DoFHandler<2>::active_cell_iterator cell;
        unsigned int                                face;
        dealii::Point<2>                            a, b; // in the chain's direction
        double                                      start = 0.;
      };
      std::vector<Face>                             faces;
      std::map<unsigned int, std::vector<unsigned>> at;
      for (const auto &cell : dofs.active_cell_iterators())
        for (const unsigned int f : cell->face_indices())
          if (cell->face(f)->at_boundary() &&
              (cell->face(f)->boundary_id() == geometry::tread_surface ||
               cell->face(f)->boundary_id() == geometry::free_surface))
            {
              for (const unsigned int v : {0u, 1u})
                at[cell->face(f)->vertex_index(v)].push_back(static_cast<unsigned>(faces.size()));
              faces.push_back({cell, f, cell->face(f)->vertex(0), cell->face(f)->vertex(1), 0.});
            }
      std::vector<Face> chain;
      {
        unsigned int vertex = dealii::numbers::invalid_unsigned_int;
        for (const auto &[v, list] : at)
          if (list.size() == 1)
            vertex = v;
        std::vector<bool> used(faces.size(), false);
        double            length = 0.;
        while (vertex != dealii::numbers::invalid_unsigned_int)
          {
            unsigned int next = dealii::numbers::invalid_unsigned_int;
            for (const unsigned e : at[vertex])
              if (!used[e])
                {
                  used[e]   = true;
                  Face face = faces[e];
                  if (face.cell->face(face.face)->vertex_index(0) != vertex)
                    std::swap(face.a, face.b);
                  next       = face.cell->face(face.face)->vertex_index(0) == vertex ?
                                 face.cell->face(face.face)->vertex_index(1) :
                                 face.cell->face(face.face)->vertex_index(0);
                  face.start = length;
                  length += (face.b - face.a).norm();
                  chain.push_back(face);
                  break;
                }
            vertex = next;
          }
        if (chain.size() != faces.size())
          throw NumericalError("the section's outer faces are not one line from bead to bead");
      }
      // The arc length of a point of the plane: where the nearest face puts it.
      const auto arc_length = [&](const std::array<double, 2> &p) {
        double best = std::numeric_limits<double>::max(), s = 0.;
        for (const Face &face : chain)
          {
            const dealii::Tensor<1, 2> e      = face.b - face.a;
            const double               length = e.norm();
            const double               t      = std::clamp(
                                 ((p[0] - face.a[0]) * e[0] + (p[1] - face.a[1]) * e[1]) / (length * length), 0., 1.);
            const double d = std::hypot(p[0] - face.a[0] - t * e[0], p[1] - face.a[1] - t * e[1]);
            if (d < best)
              {
                best = d;
                s    = face.start + t * length;
              }
          }
        return s;
      };
      std::vector<double> position;
      for (const auto &p : line)
        position.push_back(arc_length(p));

      // Each face's part in each segment, by Gauss on the overlap of their
      // arcs.
      const unsigned int                           per_cell = fe.n_dofs_per_cell();
      std::vector<dealii::types::global_dof_index> local(per_cell);
      const dealii::QGauss<1>                      gauss(fe.degree + 2);
      for (const Face &face : chain)
        {
          const double length = (face.b - face.a).norm();
          // The outward normal: the edge turned, away from the cell's centre.
          dealii::Tensor<1, 2> normal({face.b[1] - face.a[1], face.a[0] - face.b[0]});
          normal /= normal.norm();
          if (normal * (face.cell->center() - 0.5 * (face.a + face.b)) > 0.)
            normal *= -1.;
          // The unit cell's points at a and b.
          const unsigned int v0 = dealii::GeometryInfo<2>::face_to_cell_vertices(face.face, 0);
          const unsigned int v1 = dealii::GeometryInfo<2>::face_to_cell_vertices(face.face, 1);
          dealii::Point<2>   u0 = dealii::GeometryInfo<2>::unit_cell_vertex(v0);
          dealii::Point<2>   u1 = dealii::GeometryInfo<2>::unit_cell_vertex(v1);
          if ((face.cell->vertex(v0) - face.a).norm() > 1e-12 * length)
            std::swap(u0, u1);
          face.cell->get_dof_indices(local);
          for (std::size_t s = 0; s < n_segments; ++s)
            {
              const double lo = std::min(position[s], position[s + 1]);
              const double hi = std::max(position[s], position[s + 1]);
              const double t0 = std::clamp((lo - face.start) / length, 0., 1.);
              const double t1 = std::clamp((hi - face.start) / length, 0., 1.);
              if (t1 - t0 < 1e-12)
                continue;
              for (unsigned int q = 0; q < gauss.size(); ++q)
                {
                  const double           t    = t0 + (t1 - t0) * gauss.point(q)[0];
                  const double           ds   = (t1 - t0) * gauss.weight(q) * length;
                  const dealii::Point<2> x    = face.a + t * (face.b - face.a);
                  const auto             unit = u0 + t * (u1 - u0);
                  W(s) += x[0] * ds;
                  for (unsigned int i = 0; i < per_cell; ++i)
                    {
                      const unsigned int c = fe.system_to_component_index(i).first;
                      if ((c == section_radial || c == section_axial) && free[local[i]] >= 0)
                        w(free[local[i]], s) += fe.shape_value_component(i, unit, c) *
                                                normal[c == section_radial ? 0 : 1] * x[0] * ds;
                    }
                }
            }
        }
      for (std::size_t s = 0; s < n_segments; ++s)
        {
          if (!(W(s) > 0.))
            throw NumericalError("segment " + std::to_string(s) + " of the outer line, from (" +
                                 format_short(line[s][0]) + ", " + format_short(line[s][1]) +
                                 ") to (" + format_short(line[s + 1][0]) + ", " +
                                 format_short(line[s + 1][1]) +
                                 ") m, covers no part of the section's outer faces");
          w.col(s) /= W(s);
        }
      return {w, W};
    }
  } // namespace fe
} // namespace greentread

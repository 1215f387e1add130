#include <greentread/base/exceptions.h>
#include <greentread/base/mesh_ids.h>
#include <greentread/radiation/tyre_surface.h>

#include <deal.II/base/numbers.h>
#include <deal.II/base/quadrature_lib.h>
#include <deal.II/fe/fe_dgq.h>
#include <deal.II/fe/fe_values.h>
#include <deal.II/fe/mapping_q1.h>
#include <deal.II/grid/tria_accessor.h>
#include <deal.II/grid/tria_iterator.h>

#include <algorithm>
#include <cmath>
#include <map>

namespace greentread
{
  namespace radiation
  {
    namespace
    {
      using dealii::numbers::PI;
      /// A piece of the line resampled at equal arc lengths, in segments of
      /// at most @p h, appended to @p out but for its first point.
      void
      resample_piece(const SectionLine &piece, const double h, SectionLine &out)
      {
        std::vector<double> s(1, 0.);
        for (std::size_t i = 1; i < piece.size(); ++i)
          s.push_back(s.back() +
                      std::hypot(piece[i][0] - piece[i - 1][0], piece[i][1] - piece[i - 1][1]));
        const auto  n = static_cast<unsigned int>(std::ceil(s.back() / h - 1e-9));
        std::size_t i = 0;
        for (unsigned int k = 1; k <= n; ++k)
          {
            const double target = s.back() * k / n;
            while (i + 2 < s.size() && s[i + 1] < target)
              ++i;
            const double t = std::clamp((target - s[i]) / (s[i + 1] - s[i]), 0., 1.);
            out.push_back({{piece[i][0] + t * (piece[i + 1][0] - piece[i][0]),
                            piece[i][1] + t * (piece[i + 1][1] - piece[i][1])}});
          }
      }

      /// The line resampled in segments of at most @p h, its corners (a
      /// turn of more than 20 degrees) kept, so that the surface keeps the
      /// shoulders' edges at every cell size.
      SectionLine
      resample(const SectionLine &line, const double h)
      {
        SectionLine out{line.front()}, piece{line.front()};
        for (std::size_t i = 1; i < line.size(); ++i)
          {
            piece.push_back(line[i]);
            bool corner = i + 1 == line.size();
            if (!corner)
              {
                const double ax = line[i][0] - line[i - 1][0], ay = line[i][1] - line[i - 1][1];
                const double bx = line[i + 1][0] - line[i][0], by = line[i + 1][1] - line[i][1];
                corner =
                  std::abs(std::atan2(ax * by - ay * bx, ax * bx + ay * by)) > 20. * PI / 180.;
              }
            if (corner)
              {
                resample_piece(piece, h, out);
                piece = {line[i]};
              }
          }
        return out;
      }

      /// Whether (r, a) lies inside the closed polygon (crossing rule).
      bool
      in_polygon(const SectionLine &polygon, const double r, const double a)
      {
        bool inside = false;
        for (std::size_t i = 0, j = polygon.size() - 1; i < polygon.size(); j = i++)
          {
            const auto &p = polygon[i], &q = polygon[j];
            if ((p[1] > a) != (q[1] > a) && r < p[0] + (a - p[1]) * (q[0] - p[0]) / (q[1] - p[1]))
              inside = !inside;
          }
        return inside;
      }
    } // namespace

    SectionLine
    outer_contour(const dealii::Triangulation<2> &section)
    {
      // Edges in the air, by their vertex indices, and each vertex's edges.
      std::vector<std::array<unsigned int, 2>>      edges;
      std::map<unsigned int, std::vector<unsigned>> at;
      for (const auto &cell : section.active_cell_iterators())
        for (const auto &face : cell->face_iterators())
          if (face->at_boundary() && (face->boundary_id() == geometry::free_surface ||
                                      face->boundary_id() == geometry::tread_surface))
            {
              const std::array<unsigned int, 2> e{{face->vertex_index(0), face->vertex_index(1)}};
              for (const unsigned int v : e)
                at[v].push_back(static_cast<unsigned>(edges.size()));
              edges.push_back(e);
            }
      std::vector<unsigned int> ends;
      for (const auto &[vertex, list] : at)
        if (list.size() == 1)
          ends.push_back(vertex);
      if (ends.size() != 2)
        throw InputError("the section's outer boundary (its tread surface and untagged outer "
                         "faces) has " +
                         std::to_string(ends.size()) +
                         " ends; allowed: one line from bead to bead (tag the other outer "
                         "faces 'rim seat' or 'inner surface' in the .geo file)");
      const auto &vertices = section.get_vertices();
      // Start at the end of smaller axial coordinate and walk the line.
      unsigned int      v = vertices[ends[0]][1] < vertices[ends[1]][1] ? ends[0] : ends[1];
      std::vector<bool> used(edges.size(), false);
      SectionLine       line{{{vertices[v][0], vertices[v][1]}}};
      for (std::size_t step = 0; step < edges.size(); ++step)
        {
          unsigned int next = dealii::numbers::invalid_unsigned_int;
          for (const unsigned e : at[v])
            if (!used[e])
              {
                used[e] = true;
                next    = edges[e][0] == v ? edges[e][1] : edges[e][0];
                break;
              }
          if (next == dealii::numbers::invalid_unsigned_int)
            break;
          v = next;
          line.push_back({{vertices[v][0], vertices[v][1]}});
        }
      if (line.size() != edges.size() + 1)
        throw InputError("the section's outer boundary is not one line: " +
                         std::to_string(edges.size() + 1 - line.size()) +
                         " of its edges are apart from the line from bead to bead");
      return line;
    }

    TyreSurface::TyreSurface(const SectionLine &contour,
                             const double       cell_size,
                             const double       deflection)
    {
      if (contour.size() < 2)
        throw InputError("the tyre's outer contour has " + std::to_string(contour.size()) +
                         " points; allowed: at least 2");
      for (const auto &p : contour)
        outer_radius = std::max(outer_radius, p[0]);
      const std::array<double, 2> first = contour.front(), last = contour.back();
      const double                wheel = std::min(first[0], last[0]);
      if (!(cell_size > 0.) || cell_size > 0.5 * wheel)
        throw InputError("tyre surface cell size " + format_number(cell_size) +
                         " m; allowed: (0, " + format_number(0.5 * wheel) +
                         "] m (half the wheel's radius)");
      if (!(deflection >= 0.) || deflection > 0.25 * (outer_radius - wheel))
        throw InputError("tyre deflection " + format_number(deflection) + " m; allowed: [0, " +
                         format_number(0.25 * (outer_radius - wheel)) +
                         "] m (a quarter of the section height)");
      axle_height       = outer_radius - deflection;
      patch_half_length = std::sqrt(outer_radius * outer_radius - axle_height * axle_height);
      // The widest point of the contour (the sidewalls' bulge), not its
      // ends at the beads.
      axial_min = axial_max = first[1];
      for (const auto &p : contour)
        {
          axial_min = std::min(axial_min, p[1]);
          axial_max = std::max(axial_max, p[1]);
        }

      const SectionLine line = resample(contour, cell_size);
      section_line           = line;
      polygon                = line;
      polygon.push_back({{0., last[1]}});
      polygon.push_back({{0., first[1]}});
      // The polygon's orientation, for the contour's outward normals.
      double area2 = 0.;
      for (std::size_t i = 0, j = polygon.size() - 1; i < polygon.size(); j = i++)
        area2 += polygon[j][0] * polygon[i][1] - polygon[i][0] * polygon[j][1];
      const double turn = area2 > 0. ? 1. : -1.;

      // Round the circumference: a multiple of 8, so that the discs' central
      // squares fit and a row of vertices lies at the bottom (theta = 0).
      const unsigned int n_theta =
        8 * static_cast<unsigned int>(std::ceil(2. * PI * outer_radius / (8. * cell_size)));
      arc                 = 2. * PI / n_theta;
      const auto angle_at = [&](const unsigned int k) {
        return -0.25 * PI + 2. * PI * (k % n_theta) / n_theta;
      };
      // (radius, axial, angle) -> the cut, lowered body.
      const auto place = [&](const double r, const double a, const double theta) {
        return dealii::Point<3>(r * std::sin(theta), a,
                                std::max(axle_height - r * std::cos(theta), 0.));
      };

      std::vector<dealii::Point<3>>     points;
      std::vector<dealii::CellData<2>>  cells;
      std::vector<dealii::Tensor<1, 3>> hints; // the outward direction per cell
      const auto                        add = [&](const std::array<dealii::Point<3>, 4> &v,
                           const dealii::Tensor<1, 3> &hint, const int row, const double middle) {
        if (v[0][2] <= 0. && v[1][2] <= 0. && v[2][2] <= 0. && v[3][2] <= 0.)
          return; // flat on the road: the contact patch
        dealii::CellData<2> cell;
        for (unsigned int i = 0; i < 4; ++i)
          {
            cell.vertices[i] = static_cast<unsigned int>(points.size());
            points.push_back(v[i]);
          }
        cells.push_back(cell);
        hints.push_back(hint);
        segment.push_back(row);
        angle.push_back(middle);
      };

      // The revolved contour.
      for (std::size_t i = 0; i + 1 < line.size(); ++i)
        {
          const double dr = line[i + 1][0] - line[i][0], da = line[i + 1][1] - line[i][1];
          // Outward in the (radius, axial) plane: the tangent turned clockwise
          // for a counter-clockwise polygon.
          const double nr = turn * da, na = -turn * dr;
          for (unsigned int k = 0; k < n_theta; ++k)
            {
              const double middle = angle_at(k) + PI / n_theta;
              add({{place(line[i][0], line[i][1], angle_at(k)),
                    place(line[i][0], line[i][1], angle_at(k + 1)),
                    place(line[i + 1][0], line[i + 1][1], angle_at(k)),
                    place(line[i + 1][0], line[i + 1][1], angle_at(k + 1))}},
                  dealii::Tensor<1, 3>({nr * std::sin(middle), na, -nr * std::cos(middle)}),
                  static_cast<int>(i), middle);
            }
        }

      // The wheel: at each end a disc, a square of m x m cells in its middle
      // and rings of cells from the square's edge to the rim.
      const unsigned int m = n_theta / 4;
      for (const auto &[end, side] : {std::pair(first, -1.), std::pair(last, 1.)})
        {
          const double rim = end[0], s = 0.45 * rim;
          // Disc coordinates (u, w) -> (u, axial, axle_height + w); the angle
          // theta is at (r sin theta, -r cos theta), as in place().
          const auto at_disc = [&](const double u, const double w) {
            return dealii::Point<3>(u, end[1], axle_height + w);
          };
          const dealii::Tensor<1, 3> hint({0., side, 0.});
          for (unsigned int i = 0; i < m; ++i)
            for (unsigned int j = 0; j < m; ++j)
              {
                const auto u = [&](const unsigned int q) {
                  return -s + 2. * s * q / m;
                };
                add({{at_disc(u(i), u(j)), at_disc(u(i + 1), u(j)), at_disc(u(i), u(j + 1)),
                      at_disc(u(i + 1), u(j + 1))}},
                    hint, -1, 0.);
              }
          // The square's edge, counter-clockwise from (-s, -s), point k at
          // the angle of angle_at(k).
          const auto square = [&](const unsigned int k) {
            const unsigned int edge         = (k % n_theta) / m;
            const double       t            = 2. * s * ((k % n_theta) % m) / m;
            const double       corner[4][2] = {{-s, -s}, {s, -s}, {s, s}, {-s, s}};
            const double       along[4][2]  = {{1, 0}, {0, 1}, {-1, 0}, {0, -1}};
            return std::array<double, 2>{
              {corner[edge][0] + t * along[edge][0], corner[edge][1] + t * along[edge][1]}};
          };
          const auto n_rings = static_cast<unsigned int>(std::ceil((rim - s) / cell_size));
          const auto ring    = [&](const unsigned int k, const unsigned int l) {
            const auto   q = square(k);
            const double t = static_cast<double>(l) / n_rings;
            return at_disc((1. - t) * q[0] + t * rim * std::sin(angle_at(k)),
                              (1. - t) * q[1] - t * rim * std::cos(angle_at(k)));
          };
          for (unsigned int k = 0; k < n_theta; ++k)
            for (unsigned int l = 0; l < n_rings; ++l)
              add({{ring(k, l), ring(k + 1, l), ring(k, l + 1), ring(k + 1, l + 1)}}, hint, -1,
                  angle_at(k) + PI / n_theta);
        }
      mesh.create_triangulation(points, cells, dealii::SubCellData());

      // The signs, from the normals the mapping gives.
      const dealii::MappingQ1<2, 3> mapping;
      const dealii::FE_DGQ<2, 3>    fe(0);
      dealii::FEValues<2, 3>        at_centre(mapping, fe, dealii::QMidpoint<2>(),
                                              dealii::update_normal_vectors);
      std::size_t                   index = 0;
      for (const auto &cell : mesh.active_cell_iterators())
        {
          at_centre.reinit(cell);
          outward.push_back(at_centre.normal_vector(0) * hints[index++] > 0. ? 1 : -1);
        }

      // CHIEF points, inside the wheel, at scattered radii, widths and angles.
      const double fractions[6][3] = {{0.37, 0.31, 0.7}, {0.58, 0.62, 2.1}, {0.21, 0.17, 3.9},
                                      {0.66, 0.83, 5.2}, {0.49, 0.45, 1.3}, {0.29, 0.71, 4.6}};
      for (const auto &f : fractions)
        interior_points.push_back(
          place(f[0] * wheel, first[1] + f[1] * (last[1] - first[1]), f[2]));
    }

    bool
    TyreSurface::inside(const dealii::Point<3> &point) const
    {
      if (point[2] < 0.)
        return true;
      const double r = std::hypot(point[0], point[2] - axle_height);
      return in_polygon(polygon, r, point[1]);
    }
  } // namespace radiation
} // namespace greentread

#include <greentread/base/exceptions.h>
#include <greentread/periodic/contact_patch.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <map>
#include <stdexcept>

namespace greentread
{
  namespace periodic
  {
    std::string
    ContactPatch::describe() const
    {
      double x_min = 0., x_max = 0., y_min = 0., y_max = 0., radius = 0.;
      for (const auto &p : points)
        {
          x_min  = std::min(x_min, p.x);
          x_max  = std::max(x_max, p.x);
          y_min  = std::min(y_min, p.y);
          y_max  = std::max(y_max, p.y);
          radius = std::max(radius, p.radius);
        }
      char text[512];
      if (load == PointLoad::node)
        std::snprintf(text, sizeof(text),
                      "%zu contact points (%u along x, %u across y) on tread-surface nodes, "
                      "radius up to %.2f mm:\n"
                      "  x from %.2f to %.2f mm every %.3f mm (asked %.3f: L_c / N_x)\n"
                      "  y from %.2f to %.2f mm every %.3f mm (asked %.3f: l_c / N_y)\n"
                      "  %u contact cells",
                      points.size(), points_along, points_across, 1e3 * radius, 1e3 * x_min,
                      1e3 * x_max, 1e3 * dx, 1e3 * asked_dx, 1e3 * y_min, 1e3 * y_max, 1e3 * dy,
                      1e3 * asked_dy, n_contact_cells);
      else
        std::snprintf(text, sizeof(text),
                      "%zu contact points (%u along x, %u across y), each the centre of its "
                      "tributary rectangle %.3f x %.3f mm (L_c / N_x x l_c / N_y) on the "
                      "tread, radius up to %.2f mm:\n"
                      "  x from %.3f to %.3f mm, y from %.3f to %.3f mm; %u contact cells",
                      points.size(), points_along, points_across, 1e3 * dx, 1e3 * dy, 1e3 * radius,
                      1e3 * x_min, 1e3 * x_max, 1e3 * y_min, 1e3 * y_max, n_contact_cells);
      return text;
    }



    namespace
    {
      /// The radial DoFs of the tread surface of the reference cell: the
      /// nodes' axial positions z (sorted), and at each the radial DoF on
      /// the left face and on the mid-plane (quadratic elements), and the
      /// radius.
      struct TreadNodes
      {
        std::vector<double>       z, radius;
        std::vector<unsigned int> face_dof, mid_dof;
        /// The element degree along the tread: 1 or 2.
        unsigned int degree = 1;
        /// The largest tread radius [m].
        double outer_radius = 0.;
      };

      TreadNodes
      tread_nodes(const PeriodicCell &cell)
      {
        double z_scale = 0.;
        for (const auto &d : cell.dofs)
          z_scale = std::max(z_scale, std::abs(d.axial) + d.radius);
        const auto key = [&](const double z) {
          return std::llround(z / (1e-9 * z_scale));
        };
        std::map<long long, unsigned int> face, mid;
        std::map<long long, double>       z_at, radius_at;
        for (unsigned int i = 0; i < cell.n_face + cell.n_interior; ++i)
          {
            const auto &d = cell.dofs[i];
            if (!d.on_tread || d.component != 0)
              continue;
            if (i < cell.n_face)
              {
                if (face.count(key(d.axial)))
                  throw InputError(
                    "the tread surface has two nodes at z = " + format_short(d.axial) +
                    " m; allowed: a tread surface that every axial position "
                    "crosses once (no vertical groove walls)");
                face[key(d.axial)]      = i;
                z_at[key(d.axial)]      = d.axial;
                radius_at[key(d.axial)] = d.radius;
              }
            else if (std::abs(d.angle - 0.5 * cell.angle) < 1e-6 * cell.angle)
              mid[key(d.axial)] = i;
          }
        if (face.empty())
          throw InputError("the cell has no tread surface nodes: the .geo must define the "
                           "physical curve 'tread surface'");
        TreadNodes nodes;
        nodes.degree = mid.empty() ? 1 : 2;
        for (const auto &[k, dof] : face)
          {
            nodes.z.push_back(z_at.at(k));
            nodes.radius.push_back(radius_at.at(k));
            nodes.face_dof.push_back(dof);
            nodes.outer_radius = std::max(nodes.outer_radius, radius_at.at(k));
            if (nodes.degree == 2)
              {
                const auto m = mid.find(k);
                if (m == mid.end())
                  throw InputError("the tread surface has no mid-plane node at z = " +
                                   format_short(z_at.at(k)) + " m");
                nodes.mid_dof.push_back(m->second);
              }
          }
        if ((nodes.z.size() - 1) % nodes.degree != 0)
          throw InputError("the tread surface has " + std::to_string(nodes.z.size()) +
                           " nodes across, which do not make whole faces of degree " +
                           std::to_string(nodes.degree));
        return nodes;
      }



      /// The 1D Lagrange basis function @p a of degree @p p on [0, 1] at @p t.
      double
      lagrange(const unsigned int p, const unsigned int a, const double t)
      {
        if (p == 1)
          return a == 0 ? 1. - t : t;
        if (a == 0)
          return 2. * (t - 0.5) * (t - 1.);
        if (a == 1)
          return -4. * t * (t - 1.);
        return 2. * t * (t - 0.5);
      }



      /**
       * The load of a uniform radial traction over theta in [theta_a,
       * theta_b], z in [z_a, z_b] of the tread surface, normalised to a
       * total of 1: each piece that lies in one face is integrated by 3 x 3
       * Gauss points, with dS = r sqrt(1 + (dr/dz)^2) dtheta dz.
       */
      std::vector<LoadEntry>
      tributary_load(const TreadNodes &nodes,
                     const double      cell_angle,
                     const double      theta_a,
                     const double      theta_b,
                     const double      z_a,
                     const double      z_b)
      {
        const double gauss_t[3] = {0.5 - 0.5 * std::sqrt(0.6), 0.5, 0.5 + 0.5 * std::sqrt(0.6)};
        const double gauss_w[3] = {5. / 18., 8. / 18., 5. / 18.};
        const unsigned int                                      p    = nodes.degree;
        const double                                            tiny = 1e-12;
        std::map<std::pair<unsigned int, unsigned int>, double> load;
        double                                                  total = 0.;
        const auto first_cell = static_cast<unsigned int>(std::floor(theta_a / cell_angle + tiny));
        for (unsigned int c = first_cell; c * cell_angle < theta_b - tiny * cell_angle; ++c)
          {
            const double ta = std::max(theta_a, c * cell_angle);
            const double tb = std::min(theta_b, (c + 1) * cell_angle);
            if (tb - ta <= tiny * cell_angle)
              continue;
            for (std::size_t f = 0; f + p < nodes.z.size(); f += p)
              {
                const double z0 = nodes.z[f], z1 = nodes.z[f + p];
                const double za = std::max(z_a, z0), zb = std::min(z_b, z1);
                if (zb - za <= tiny * (z1 - z0))
                  continue;
                const double r0 = nodes.radius[f], r1 = nodes.radius[f + p];
                const double slope = (r1 - r0) / (z1 - z0);
                for (unsigned int i = 0; i < 3; ++i)
                  for (unsigned int j = 0; j < 3; ++j)
                    {
                      const double theta = ta + gauss_t[i] * (tb - ta);
                      const double z     = za + gauss_t[j] * (zb - za);
                      const double xi    = theta / cell_angle - c;
                      const double eta   = (z - z0) / (z1 - z0);
                      const double r     = r0 + (r1 - r0) * eta;
                      const double dS = r * std::sqrt(1. + slope * slope) * (tb - ta) * (zb - za) *
                                        gauss_w[i] * gauss_w[j];
                      total += dS;
                      for (unsigned int a = 0; a <= p; ++a)
                        for (unsigned int b = 0; b <= p; ++b)
                          {
                            // Along theta: the left face of cell c, its
                            // mid-plane, or the left face of cell c + 1.
                            const unsigned int node = f + b;
                            const unsigned int cell = a == p ? c + 1 : c;
                            const unsigned int dof =
                              (a == 0 || a == p) ? nodes.face_dof[node] : nodes.mid_dof[node];
                            load[{cell, dof}] += lagrange(p, a, xi) * lagrange(p, b, eta) * dS;
                          }
                    }
              }
          }
        std::vector<LoadEntry> entries;
        for (const auto &[at, value] : load)
          entries.push_back({at.first, at.second, value / total});
        return entries;
      }



      /// The tread radius at @p z, linear between the nodes.
      double
      radius_at(const TreadNodes &nodes, const double z)
      {
        const auto it = std::lower_bound(nodes.z.begin(), nodes.z.end(), z);
        const auto k  = std::min<std::size_t>(std::max<std::ptrdiff_t>(it - nodes.z.begin(), 1),
                                             nodes.z.size() - 1);
        if (nodes.z.size() == 1)
          return nodes.radius[0];
        const double t = (z - nodes.z[k - 1]) / (nodes.z[k] - nodes.z[k - 1]);
        return nodes.radius[k - 1] + t * (nodes.radius[k] - nodes.radius[k - 1]);
      }
    } // namespace



    ContactPatch
    place_tributary_areas(const PeriodicCell &cell, const PatchRequest &request)
    {
      const TreadNodes   nodes = tread_nodes(cell);
      const unsigned int nx = request.points_along, ny = request.points_across;
      ContactPatch       patch;
      patch.points_along  = nx;
      patch.points_across = ny;
      patch.load          = PointLoad::tributary_area;
      patch.dx = patch.asked_dx = request.length / nx;
      patch.dy = patch.asked_dy = request.width / ny;

      // Across: the whole patch on the tread.
      const double half_width = 0.5 * request.width;
      if (half_width > -nodes.z.front() * (1. + 1e-9) || half_width > nodes.z.back() * (1. + 1e-9))
        throw InputError(
          "parameter 'Green's functions/Patch width' = " + format_number(request.width) +
          " does not fit on the tread surface (z from " + format_short(nodes.z.front()) + " to " +
          format_short(nodes.z.back()) + " m); allowed: a patch at most " +
          format_short(2. * std::min(-nodes.z.front(), nodes.z.back())) + " m wide");

      // Along: the centre on a cell face or mid-plane, the first that
      // leaves the patch in the cells from 0 on; arc lengths on the outer
      // tread radius.
      const double R          = nodes.outer_radius;
      const double half_angle = 0.5 * request.length / R;
      patch.arc               = patch.dx / R;
      const double step       = 0.5 * cell.angle;
      const double centre     = std::ceil(half_angle / step - 1e-9) * step;
      patch.n_contact_cells =
        static_cast<unsigned int>(std::ceil((centre + half_angle) / cell.angle - 1e-9));
      if (patch.n_contact_cells + 1 > cell.n_cells)
        throw InputError(
          "parameter 'Green's functions/Patch length' = " + format_number(request.length) +
          " spans " + std::to_string(patch.n_contact_cells) + " of the ring's " +
          std::to_string(cell.n_cells) +
          " cells; allowed: a patch shorter than the ring (at least one cell "
          "outside it)");

      for (unsigned int i = 0; i < nx; ++i)
        for (unsigned int j = 0; j < ny; ++j)
          {
            const double x     = (i - 0.5 * (nx - 1.)) * patch.dx;
            const double y     = (j - 0.5 * (ny - 1.)) * patch.dy;
            const double theta = centre + x / R;
            patch.points.push_back(
              {x, y, radius_at(nodes, y), theta,
               tributary_load(nodes, cell.angle, theta - 0.5 * patch.dx / R,
                              theta + 0.5 * patch.dx / R, y - 0.5 * patch.dy, y + 0.5 * patch.dy)});
          }
      return patch;
    }



    ContactPatch
    place_on_nodes(const PeriodicCell &cell, const PatchRequest &request)
    {
      // The radial tread DoFs of the left face and of the mid-plane.
      const TreadNodes           nodes  = tread_nodes(cell);
      const std::vector<double> &z      = nodes.z;
      const double               radius = nodes.outer_radius;

      ContactPatch patch;
      patch.points_along  = request.points_along;
      patch.points_across = request.points_across;
      patch.load          = PointLoad::node;
      patch.asked_dx      = request.length / request.points_along;
      patch.asked_dy      = request.width / request.points_across;

      // Across: a whole stride of tread nodes about the node nearest z = 0.
      const unsigned int ny     = request.points_across;
      std::size_t        centre = 0;
      for (std::size_t k = 0; k < z.size(); ++k)
        if (std::abs(z[k]) < std::abs(z[centre]))
          centre = k;
      const double node_dy  = z.size() > 1 ? (centre + 1 < z.size() ? z[centre + 1] - z[centre] :
                                                                      z[centre] - z[centre - 1]) :
                                             0.;
      const double asked_dy = request.width / ny;
      const long   qy       = ny == 1 ? 1 : std::max(1L, std::lround(asked_dy / node_dy));
      const long   first_y  = static_cast<long>(centre) - (static_cast<long>(ny) - 1) * qy / 2;
      const long   last_y   = first_y + (static_cast<long>(ny) - 1) * qy;
      if (first_y < 0 || last_y >= static_cast<long>(z.size()))
        throw InputError(
          "parameter 'Green's functions/Patch width' = " + format_number(request.width) + " with " +
          std::to_string(ny) + " points across does not fit on the tread surface (" +
          format_short(z.back() - z.front()) + " m wide, tread nodes every " +
          format_short(node_dy) + " m); allowed: a narrower patch or fewer points");

      // Along: a whole stride of half cells (faces and mid-planes).
      const unsigned int nx        = request.points_along;
      const double       half_cell = 0.5 * radius * cell.angle;
      const double       asked_dx  = request.length / nx;
      long               qx        = nx == 1 ? 2 : std::max(1L, std::lround(asked_dx / half_cell));
      if (nodes.degree == 1 && qx % 2 == 1)
        qx += 1; // no mid-plane nodes (linear elements): faces only
      const long last_s     = (static_cast<long>(nx) - 1) * qx;
      patch.n_contact_cells = static_cast<unsigned int>(last_s / 2 + 1);
      if (patch.n_contact_cells + 1 > cell.n_cells)
        throw InputError(
          "parameter 'Green's functions/Patch length' = " + format_number(request.length) +
          " with " + std::to_string(nx) + " points along spans " +
          std::to_string(patch.n_contact_cells) + " of the ring's " + std::to_string(cell.n_cells) +
          " cells; allowed: a patch shorter than the ring (at least one cell "
          "outside it)");

      patch.dx = qx * half_cell;
      patch.dy = ny > 1 ? (z[last_y] - z[first_y]) / (ny - 1) : 0.;
      // The tread nodes need not be evenly spaced (a coarse mesh grades
      // towards the shoulders): the grid must be, within 1%.
      for (unsigned int j = 0; j + 1 < ny; ++j)
        {
          const double step = z[first_y + (j + 1) * qy] - z[first_y + j * qy];
          if (std::abs(step - patch.dy) > 0.01 * patch.dy)
            throw InputError(
              "parameter 'Green's functions/Patch width' = " + format_number(request.width) +
              " with " + std::to_string(ny) +
              " points across: the tread nodes under it are not evenly spaced "
              "(a step of " +
              format_short(1e3 * step) + " mm against the mean " + format_short(1e3 * patch.dy) +
              " mm); allowed: a patch within the evenly meshed crown, or a "
              "smaller 'Geometry/Mesh size'");
        }
      for (unsigned int i = 0; i < nx; ++i)
        {
          const long s = i * qx;
          for (unsigned int j = 0; j < ny; ++j)
            {
              // Even strides are faces; odd ones mid-planes, which
              // quadratic elements alone have (qx is even otherwise).
              const std::size_t  k   = first_y + j * qy;
              const unsigned int dof = s % 2 == 0 ? nodes.face_dof[k] : nodes.mid_dof[k];
              patch.points.push_back({(s - 0.5 * last_s) * half_cell,
                                      z[k],
                                      nodes.radius[k],
                                      0.5 * s * cell.angle,
                                      {{static_cast<unsigned int>(s / 2), dof, 1.}}});
            }
        }
      return patch;
    }



    ContactPatch
    place_contact_points(const PeriodicCell &cell, const PatchRequest &request)
    {
      switch (request.load)
        {
          case PointLoad::node:
            return place_on_nodes(cell, request);
          case PointLoad::tributary_area:
            return place_tributary_areas(cell, request);
        }
      throw std::logic_error("place_contact_points: unknown point load");
    }
  } // namespace periodic
} // namespace greentread

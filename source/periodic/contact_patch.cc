#include <greentread/base/exceptions.h>
#include <greentread/periodic/contact_patch.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <map>

namespace greentread
{
  namespace periodic
  {
    std::string
    ContactPatch::describe(const PatchRequest &request) const
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
      std::snprintf(text, sizeof(text),
                    "%zu contact points (%u along x, %u across y) on tread-surface nodes, "
                    "radius up to %.2f mm:\n"
                    "  x from %.2f to %.2f mm every %.3f mm (asked %.3f: L_c / N_x)\n"
                    "  y from %.2f to %.2f mm every %.3f mm (asked %.3f: l_c / N_y)\n"
                    "  %u contact cells",
                    points.size(), points_along, points_across, 1e3 * radius, 1e3 * x_min,
                    1e3 * x_max, 1e3 * dx, 1e3 * request.length / request.points_along,
                    1e3 * y_min, 1e3 * y_max, 1e3 * dy, 1e3 * request.width / request.points_across,
                    n_contact_cells);
      return text;
    }



    ContactPatch
    place_contact_points(const PeriodicCell &cell, const PatchRequest &request)
    {
      // The radial tread DoFs of the left face (layer 0) and of the
      // mid-plane (layer 1), by their axial position.
      double radius = 0., z_scale = 0.;
      for (const auto &d : cell.dofs)
        {
          z_scale = std::max(z_scale, std::abs(d.axial) + d.radius);
          if (d.on_tread && d.component == 0)
            radius = std::max(radius, d.radius);
        }
      if (radius == 0.)
        throw InputError("the cell has no tread surface nodes: the .geo must define the "
                         "physical curve 'tread surface'");
      const auto key = [&](const double z) { return std::llround(z / (1e-9 * z_scale)); };
      std::map<long long, unsigned int> face_dof, mid_dof;
      std::map<long long, double>       radius_at;
      for (unsigned int i = 0; i < cell.n_face + cell.n_interior; ++i)
        {
          const auto &d = cell.dofs[i];
          if (!d.on_tread || d.component != 0)
            continue;
          if (i < cell.n_face)
            {
              face_dof[key(d.axial)]  = i;
              radius_at[key(d.axial)] = d.radius;
            }
          else if (std::abs(d.angle - 0.5 * cell.angle) < 1e-6 * cell.angle)
            mid_dof[key(d.axial)] = i;
        }
      std::vector<double> z;
      for (unsigned int i = 0; i < cell.n_face; ++i)
        if (cell.dofs[i].on_tread && cell.dofs[i].component == 0)
          z.push_back(cell.dofs[i].axial);
      std::sort(z.begin(), z.end());
      z.erase(std::unique(z.begin(), z.end(),
                          [&](double a, double b) { return key(a) == key(b); }),
              z.end());

      ContactPatch patch;
      patch.points_along  = request.points_along;
      patch.points_across = request.points_across;

      // Across: a whole stride of tread nodes about the node nearest z = 0.
      const unsigned int ny = request.points_across;
      std::size_t        centre = 0;
      for (std::size_t k = 0; k < z.size(); ++k)
        if (std::abs(z[k]) < std::abs(z[centre]))
          centre = k;
      const double node_dy = z.size() > 1 ? (centre + 1 < z.size() ? z[centre + 1] - z[centre] :
                                                                       z[centre] - z[centre - 1]) :
                                            0.;
      const double asked_dy = request.width / ny;
      const long   qy = ny == 1 ? 1 : std::max(1L, std::lround(asked_dy / node_dy));
      const long   first_y = static_cast<long>(centre) - (static_cast<long>(ny) - 1) * qy / 2;
      const long   last_y  = first_y + (static_cast<long>(ny) - 1) * qy;
      if (first_y < 0 || last_y >= static_cast<long>(z.size()))
        throw InputError("parameter 'Green's functions/Patch width' = " +
                         format_number(request.width) + " with " + std::to_string(ny) +
                         " points across does not fit on the tread surface (" +
                         format_short(z.back() - z.front()) + " m wide, tread nodes every " +
                         format_short(node_dy) + " m); allowed: a narrower patch or fewer points");

      // Along: a whole stride of half cells (faces and mid-planes).
      const unsigned int nx        = request.points_along;
      const double       half_cell = 0.5 * radius * cell.angle;
      const double       asked_dx  = request.length / nx;
      long qx = nx == 1 ? 2 : std::max(1L, std::lround(asked_dx / half_cell));
      if (mid_dof.empty() && qx % 2 == 1)
        qx += 1; // no mid-plane nodes (linear elements): faces only
      const long last_s = (static_cast<long>(nx) - 1) * qx;
      patch.n_contact_cells = static_cast<unsigned int>(last_s / 2 + 1);
      if (patch.n_contact_cells + 1 > cell.n_cells)
        throw InputError("parameter 'Green's functions/Patch length' = " +
                         format_number(request.length) + " with " + std::to_string(nx) +
                         " points along spans " + std::to_string(patch.n_contact_cells) +
                         " of the ring's " + std::to_string(cell.n_cells) +
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
            throw InputError("parameter 'Green's functions/Patch width' = " +
                             format_number(request.width) + " with " + std::to_string(ny) +
                             " points across: the tread nodes under it are not evenly spaced "
                             "(a step of " + format_short(1e3 * step) + " mm against the mean " +
                             format_short(1e3 * patch.dy) +
                             " mm); allowed: a patch within the evenly meshed crown, or a "
                             "smaller 'Geometry/Mesh size'");
        }
      for (unsigned int i = 0; i < nx; ++i)
        {
          const long s = i * qx;
          for (unsigned int j = 0; j < ny; ++j)
            {
              const double y      = z[first_y + j * qy];
              const auto  &layer  = s % 2 == 0 ? face_dof : mid_dof;
              const auto   found  = layer.find(key(y));
              if (found == layer.end())
                throw InputError("the tread surface has no mid-plane node at y = " +
                                 format_short(y) + " m for a contact point; change 'Patch "
                                 "length' or 'Points along'");
              patch.points.push_back({(s - 0.5 * last_s) * half_cell, y, radius_at.at(key(y)),
                                      0.5 * s * cell.angle, static_cast<unsigned int>(s / 2),
                                      found->second});
            }
        }
      return patch;
    }
  } // namespace periodic
} // namespace greentread

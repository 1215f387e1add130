#include <greentread/base/exceptions.h>
#include <greentread/base/output.h>
#include <greentread/road/patch_road.h>

#include <algorithm>
#include <cmath>
#include <utility>

namespace greentread
{
  namespace road
  {
    PatchRoad::PatchRoad(const Texture                            &texture,
                         const std::vector<std::array<double, 3>> &points,
                         const RoadSampling                        sampling,
                         const std::string                        &name)
        : spacing(texture.dx)
    {
      // The lattice of points: distinct x and y.
      std::vector<double> xs, ys;
      const auto          add = [](std::vector<double> &v, const double x) {
        for (const double y : v)
          if (std::abs(x - y) < 1e-7)
            return;
        v.push_back(x);
      };
      for (const auto &p : points)
        {
          add(xs, p[0]);
          add(ys, p[1]);
        }
      std::sort(xs.begin(), xs.end());
      std::sort(ys.begin(), ys.end());
      dx_points           = xs.size() > 1 ? (xs.back() - xs.front()) / (xs.size() - 1) : texture.dx;
      dy_points           = ys.size() > 1 ? (ys.back() - ys.front()) / (ys.size() - 1) : texture.dy;
      const double width  = ys.back() - ys.front() + dy_points;
      const double needed = width + 2. * texture.dy;
      if (texture.ny * texture.dy < needed && texture.ny > 1)
        throw InputError("road '" + name + "' is " + format_short(texture.ny * texture.dy) +
                         " m wide; the patch needs " + format_short(needed) +
                         " m (its width plus one point spacing)");
      x_offset = -xs.front() + 0.5 * dx_points;
      usable   = texture.length() - (xs.back() - xs.front()) - dx_points - 2. * texture.dx;
      if (usable <= 0.)
        throw InputError("road '" + name + "' is " + format_short(texture.length()) +
                         " m long, shorter than the patch (" +
                         format_short(xs.back() - xs.front() + dx_points) + " m)");

      // One profile per row of points across the tread.
      const double y_centre = 0.5 * (texture.ny - 1) * texture.dy;
      // The road at y across it, linear between its rows: the row j below y
      // and the weight w of the row above.
      const auto between_rows = [&](const double y) {
        const double       s = (y + y_centre) / texture.dy;
        const unsigned int j = std::min<unsigned int>(texture.ny - 2, std::max(0., std::floor(s)));
        return std::make_pair(j, s - j);
      };
      for (const double y : ys)
        {
          std::vector<double> profile(texture.nx, -INFINITY);
          if (texture.ny == 1)
            for (unsigned int i = 0; i < texture.nx; ++i)
              profile[i] = texture(i, 0);
          else if (sampling == RoadSampling::point)
            {
              const auto [j, w] = between_rows(y);
              for (unsigned int i = 0; i < texture.nx; ++i)
                profile[i] = (1. - w) * texture(i, j) + w * texture(i, j + 1);
            }
          else
            {
              // Highest point across the tributary strip...
              const int j0 =
                std::max(0, int(std::ceil((y - 0.5 * dy_points + y_centre) / texture.dy)));
              const int j1 =
                std::min(int(texture.ny) - 1,
                         int(std::floor((y + 0.5 * dy_points + y_centre) / texture.dy)));
              for (int j = j0; j <= j1; ++j)
                for (unsigned int i = 0; i < texture.nx; ++i)
                  profile[i] = std::max(profile[i], texture(i, j));
              // A strip narrower than the road's sampling (contact rectangles
              // finer than it) holds one sample or none: the highest point of
              // the road over it, linear between samples, is that sample or
              // one of its edges.
              if (dy_points < texture.dy)
                for (const double edge : {y - 0.5 * dy_points, y + 0.5 * dy_points})
                  {
                    const auto [j, w] = between_rows(edge);
                    for (unsigned int i = 0; i < texture.nx; ++i)
                      profile[i] =
                        std::max(profile[i], (1. - w) * texture(i, j) + w * texture(i, j + 1));
                  }
              // ... and along x over the tributary length (a sliding maximum).
              const int           half = std::max(0, int(std::floor(0.5 * dx_points / texture.dx)));
              std::vector<double> across = profile;
              std::deque<int>     window;
              for (int i = 0; i < int(texture.nx) + half; ++i)
                {
                  if (i < int(texture.nx))
                    {
                      while (!window.empty() && across[window.back()] <= across[i])
                        window.pop_back();
                      window.push_back(i);
                    }
                  const int centre = i - half;
                  while (!window.empty() && window.front() < centre - half)
                    window.pop_front();
                  if (centre >= 0)
                    profile[centre] = across[window.front()];
                }
            }
          rows.push_back(std::move(profile));
        }
      for (const auto &p : points)
        {
          const auto it = std::min_element(ys.begin(), ys.end(), [&](double a, double b) {
            return std::abs(a - p[1]) < std::abs(b - p[1]);
          });
          row_of.push_back(it - ys.begin());
          x_of.push_back(p[0] + x_offset);
        }
    }



    void
    PatchRoad::height(const unsigned int p, const double s, double &z, double &slope) const
    {
      const auto        &row = rows[row_of[p]];
      const double       x   = (x_of[p] + s) / spacing;
      const unsigned int i   = std::min<unsigned int>(row.size() - 2, std::max(0., std::floor(x)));
      const double       w   = x - i;
      z                      = (1. - w) * row[i] + w * row[i + 1];
      slope                  = (row[i + 1] - row[i]) / spacing;
    }



    void
    PatchRoad::heights(const double s, Eigen::VectorXd &z, Eigen::VectorXd &slope) const
    {
      z.resize(row_of.size());
      slope.resize(row_of.size());
      for (unsigned int p = 0; p < row_of.size(); ++p)
        height(p, s, z[p], slope[p]);
    }
  } // namespace road
} // namespace greentread

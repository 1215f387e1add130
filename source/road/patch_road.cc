#include <greentread/base/exceptions.h>
#include <greentread/base/output.h>
#include <greentread/base/parameters.h>
#include <greentread/road/patch_road.h>
#include <greentread/convolution/fft_length.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <utility>

namespace greentread
{
  namespace road
  {
    void
    RoadTextureParameters::declare_parameters(dealii::ParameterHandler &prm)
    {
      using base::RangePattern;
      prm.enter_subsection("Road texture");
      {
        prm.declare_entry("Roads", "road-A, road-B", dealii::Patterns::Anything(),
                          "The roads to roll over, a comma-separated list. Each is 'road-A' "
                          "(rough, surface-dressing-like, MPD about 1.9 mm) or 'road-B' (dense "
                          "asphalt, MPD about 0.7 mm), synthetic textures with the documented "
                          "target spectra (doc/methods/contact.md); 'sinusoid' (a sinusoid "
                          "along x, subsection Road/Sinusoid); 'flat'; or a texture file: SDF "
                          "(ISO 25178-71, ASCII or binary) or the plain height grid "
                          "(doc/getting-started.md). A relative file name is looked for "
                          "beside the scene file, then in the working directory.");
        prm.declare_entry("Seed", "1", dealii::Patterns::Integer(0),
                          "Seed of the synthetic textures: the same seed gives the same road.");
        prm.declare_entry("Length", "2.304", base::RangePattern::closed(0.05, 20., "m"),
                          "Length of the synthetic, sinusoidal and flat roads, or longer when a "
                          "run needs it ('Rolling/Distance', the low-rate run of 'Spectra'): "
                          "a longer preset road is made in pieces of this length, so that "
                          "its memory is about 6 MB per metre, with 290 samples across.");
        prm.declare_entry("Spacing", "0.000384", base::RangePattern::closed(1e-5, 5e-3, "m"),
                          "Sampling interval of the synthetic, sinusoidal and flat roads "
                          "(the paper's measured roads: 384 um).");
        prm.declare_entry("Height scale", "1", base::RangePattern::closed(0., 100., "1"),
                          "Factor on every road's heights (presets, sinusoid and texture "
                          "files): 2 raises the texture spectrum by 6.02 dB at every "
                          "wavelength and keeps its shape.");
        prm.declare_entry("Between points", "envelope",
                          dealii::Patterns::Selection("envelope|point"),
                          "How a tread point sees the road, which is sampled far more finely "
                          "than the points are spaced. 'envelope': the highest road point in "
                          "the point's tributary rectangle (dx by dy around it), since the "
                          "tread between points, interpolated as in the paper's Section 5.2, "
                          "rests on the highest asperity under it. 'point': the road height "
                          "under the point itself (bilinear).");
      }
      prm.leave_subsection();
      SinusoidParameters::declare_parameters(prm);
    }



    void
    RoadTextureParameters::parse_parameters(dealii::ParameterHandler &prm)
    {
      prm.enter_subsection("Road texture");
      {
        roads = base::split_list(prm.get("Roads"));
        if (roads.empty())
          throw InputError("parameter 'Road texture/Roads' is empty; allowed: a list of "
                           "road-A, road-B, sinusoid, flat or texture files");
        for (const auto &r : roads)
          if (!is_built_in(r) && !std::filesystem::exists(r))
            throw InputError("parameter 'Road texture/Roads': '" + r +
                             "' is neither road-A, road-B, sinusoid, flat nor an existing "
                             "texture file");
        seed       = prm.get_integer("Seed");
        length     = prm.get_double("Length");
        spacing    = prm.get_double("Spacing");
        height_scale = prm.get_double("Height scale");
        sampling   = prm.get("Between points") == "point" ? RoadSampling::point :
                                                             RoadSampling::envelope;
      }
      prm.leave_subsection();
      sinusoid.parse_parameters(prm);
    }



    Texture
    RoadTextureParameters::make(const std::string &name, const double width,
                                const double at_least) const
    {
      Texture t = make_unscaled(name, width, std::max(length, at_least));
      for (auto &z : t.z)
        z *= height_scale;
      return t;
    }



    namespace
    {
      /**
       * A preset texture @p nx samples long, made in pieces of the
       * 'Road texture/Length' (@p piece_nx samples) so that the FFT's
       * memory stays that of one piece however long the road: independent
       * realisations (seeds drawn from @p seed, the first piece's being
       * @p seed itself) joined by a crossfade cos(phi) z_a + sin(phi) z_b,
       * phi from 0 to pi/2 over crossfade_length, which keeps the variance
       * of two independent fields, so that the texture spectrum holds
       * across a join (the crossfade is twice the presets' longest
       * wavelength, 100 mm).
       */
      Texture
      preset_in_pieces(const std::vector<WavelengthBand> &bands,
                       const std::vector<double>         &levels,
                       const double                       spacing,
                       const unsigned int                 nx,
                       const unsigned int                 ny,
                       const unsigned int                 piece_nx,
                       const std::uint64_t                seed)
      {
        if (nx <= piece_nx)
          return synthetic_texture(bands, levels, spacing, nx, ny, seed);
        constexpr double   crossfade_length = 0.2;
        const unsigned int overlap =
          std::min(piece_nx / 2, unsigned(std::ceil(crossfade_length / spacing)));
        Texture t;
        t.dx = t.dy = spacing;
        t.nx        = nx;
        t.ny        = ny;
        t.z.assign(std::size_t(nx) * ny, 0.);
        for (unsigned int k = 0, i0 = 0; i0 + overlap < nx || k == 0; ++k, i0 += piece_nx - overlap)
          {
            const Texture piece = synthetic_texture(
              bands, levels, spacing, piece_nx, ny, seed + k * std::uint64_t(0x9E3779B97F4A7C15));
            for (unsigned int j = 0; j < ny; ++j)
              for (unsigned int i = 0; i < piece_nx && i0 + i < nx; ++i)
                {
                  double &z = t.z[std::size_t(j) * nx + i0 + i];
                  if (k > 0 && i < overlap)
                    {
                      const double phi = 0.5 * M_PI * (i + 0.5) / overlap;
                      z = std::cos(phi) * z + std::sin(phi) * piece(i, j);
                    }
                  else
                    z = piece(i, j);
                }
          }
        return t;
      }
    } // namespace



    Texture
    RoadTextureParameters::make_unscaled(const std::string &name, const double width,
                                         const double road_length) const
    {
      if (!is_built_in(name))
        return read_texture(name);
      Texture t;
      t.dx = t.dy = spacing;
      // Lengths with small factors keep the FFT fast (1.4 m is 3646 = 2 x
      // 1823 samples, 3750 once rounded up).
      t.nx        = unsigned(convolution::fast_fft_length(std::size_t(std::ceil(road_length / spacing))));
      t.ny        = static_cast<unsigned int>(std::ceil(width / spacing)) + 2;
      if (name == "road-A" || name == "road-B")
        {
          std::vector<WavelengthBand> bands;
          std::vector<double>               levels;
          texture_preset(name, bands, levels);
          t.ny += t.ny % 2;
          const unsigned int piece_nx =
            unsigned(convolution::fast_fft_length(std::size_t(std::ceil(length / spacing))));
          return preset_in_pieces(bands, levels, spacing, t.nx, t.ny, piece_nx, seed);
        }
      t.z.assign(std::size_t(t.nx) * t.ny, 0.);
      if (name == "sinusoid")
        for (unsigned int j = 0; j < t.ny; ++j)
          for (unsigned int i = 0; i < t.nx; ++i)
            t.z[std::size_t(j) * t.nx + i] =
              sinusoid.amplitude * std::sin(2. * M_PI * i * spacing / sinusoid.wavelength);
      return t;
    }



    PatchRoad::PatchRoad(const Texture                     &texture,
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
      dx_points = xs.size() > 1 ? (xs.back() - xs.front()) / (xs.size() - 1) : texture.dx;
      dy_points = ys.size() > 1 ? (ys.back() - ys.front()) / (ys.size() - 1) : texture.dy;
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
              const int j0 = std::max(0, int(std::ceil((y - 0.5 * dy_points + y_centre) / texture.dy)));
              const int j1 = std::min(int(texture.ny) - 1,
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

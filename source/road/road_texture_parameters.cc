#include <greentread/base/exceptions.h>
#include <greentread/base/parameters.h>
#include <greentread/convolution/fft_length.h>
#include <greentread/road/road_texture_parameters.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <filesystem>

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
        prm.declare_entry(
          "Roads", "road-A, road-B", dealii::Patterns::Anything(),
          "The roads to roll over, a comma-separated list. Each is 'road-A' "
          "(rough, surface-dressing-like, MPD about 1.9 mm) or 'road-B' (dense "
          "asphalt, MPD about 0.7 mm), synthetic textures with the documented "
          "target spectra (doc/methods/contact.md); 'sinusoid' (a sinusoid "
          "along x, subsection Road/Sinusoid); 'flat'; or a texture file: X3P "
          "(ISO 25178-72), SDF (ISO 25178-71, ASCII or binary), an "
          "ISO 13473-1 text profile in mm or the plain height grid "
          "(doc/getting-started.md, doc/methods/contact.md). A relative file name is looked for "
          "beside the scene file, then in the working directory. A road's "
          "samples may be at most 4 contact rectangles apart (3 mm at the "
          "default grid).");
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
        seed         = prm.get_integer("Seed");
        length       = prm.get_double("Length");
        spacing      = prm.get_double("Spacing");
        height_scale = prm.get_double("Height scale");
        sampling =
          prm.get("Between points") == "point" ? RoadSampling::point : RoadSampling::envelope;
      }
      prm.leave_subsection();
      sinusoid.parse_parameters(prm);
    }



    Texture
    RoadTextureParameters::make(const std::string &name,
                                const double       width,
                                const double       at_least) const
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
            const Texture piece = synthetic_texture(bands, levels, spacing, piece_nx, ny,
                                                    seed + k * std::uint64_t(0x9E3779B97F4A7C15));
            for (unsigned int j = 0; j < ny; ++j)
              for (unsigned int i = 0; i < piece_nx && i0 + i < nx; ++i)
                {
                  double &z = t.z[std::size_t(j) * nx + i0 + i];
                  if (k > 0 && i < overlap)
                    {
                      const double phi = 0.5 * M_PI * (i + 0.5) / overlap;
                      z                = std::cos(phi) * z + std::sin(phi) * piece(i, j);
                    }
                  else
                    z = piece(i, j);
                }
          }
        return t;
      }
    } // namespace



    Texture
    RoadTextureParameters::make_unscaled(const std::string &name,
                                         const double       width,
                                         const double       road_length) const
    {
      if (!is_built_in(name))
        return read_texture(name);
      Texture t;
      t.dx = t.dy = spacing;
      // Lengths with small factors keep the FFT fast (1.4 m is 3646 = 2 x
      // 1823 samples, 3750 once rounded up).
      t.nx = unsigned(convolution::fast_fft_length(std::size_t(std::ceil(road_length / spacing))));
      t.ny = static_cast<unsigned int>(std::ceil(width / spacing)) + 2;
      if (name == "road-A" || name == "road-B")
        {
          std::vector<WavelengthBand> bands;
          std::vector<double>         levels;
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
  } // namespace road
} // namespace greentread

// Road textures against closed forms: the texture spectrum and the MPD of a
// cosine, the one-third-octave band edges, and synthetic textures that must
// reproduce their target spectra.
#include "scratch.h"

#include <greentread/analysis/third_octave.h>
#include <greentread/base/exceptions.h>
#include <greentread/road/patch_road.h>
#include <greentread/road/texture.h>

#include <boost/test/unit_test.hpp>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <random>

using namespace greentread;

namespace
{
  /// A cos(2 pi x / lambda) along x, the same on every profile, sampled at
  /// the cell centres x_i = (i + 1/2) dx: over whole periods it is
  /// symmetric about the middle, so its least-squares line is exactly flat.
  road::Texture
  cosine(const double A, const double lambda, const double dx, const unsigned int nx)
  {
    road::Texture t;
    t.dx = t.dy = dx;
    t.nx        = nx;
    t.ny        = 3;
    for (unsigned int j = 0; j < t.ny; ++j)
      for (unsigned int i = 0; i < nx; ++i)
        t.z.push_back(A * std::cos(2. * M_PI * (i + 0.5) * dx / lambda));
    return t;
  }
} // namespace

BOOST_AUTO_TEST_SUITE(road_texture)

BOOST_AUTO_TEST_CASE(band_edges_follow_iec_61260_base_10)
{
  const auto bands = road::wavelength_bands(2e-3, 0.1);
  BOOST_TEST(bands.size() == 18u);
  BOOST_TEST(bands.front().nominal == 2e-3, boost::test_tools::tolerance(1e-12));
  BOOST_TEST(bands[5].nominal == 6.3e-3, boost::test_tools::tolerance(1e-12));
  BOOST_TEST(bands.back().nominal == 0.1, boost::test_tools::tolerance(1e-12));
  for (std::size_t b = 0; b < bands.size(); ++b)
    {
      BOOST_TEST(bands[b].upper / bands[b].lower == std::pow(10., 0.1),
                 boost::test_tools::tolerance(1e-12));
      if (b > 0) // contiguous
        BOOST_TEST(bands[b].lower == bands[b - 1].upper, boost::test_tools::tolerance(1e-12));
    }
}

BOOST_AUTO_TEST_CASE(spectrum_and_mpd_of_a_cosine)
{
  // 10 mm (the centre of its band) and amplitude 0.5 mm: mean square
  // A^2 / 2 in that band alone.
  const double A = 5e-4, lambda = 1e-2, dx = lambda / 32.;
  const auto   t     = cosine(A, lambda, dx, 32 * 80); // 0.8 m, whole periods
  const auto   bands = road::wavelength_bands(2e-3, 0.1);
  const auto   level = road::texture_spectrum(t, bands);
  for (std::size_t b = 0; b < bands.size(); ++b)
    if (bands[b].nominal == 1e-2)
      BOOST_TEST(level[b] == 10. * std::log10(A * A / 2. / 1e-12),
                 boost::test_tools::tolerance(1e-9));
    else
      BOOST_TEST(level[b] < -100.);

  // MPD: each 100 mm segment holds whole periods, its line is flat, and
  // both halves peak at the sample nearest a crest, half a step away.
  const double mpd = road::mean_profile_depth(t);
  BOOST_TEST(mpd == A * std::cos(M_PI * dx / lambda), boost::test_tools::tolerance(1e-12));

  // Too short for one segment: a clear error.
  BOOST_CHECK_THROW(road::mean_profile_depth(cosine(A, lambda, dx, 100)), InputError);
}

BOOST_AUTO_TEST_CASE(synthetic_textures_match_their_presets)
{
  for (const std::string name : {"road-A", "road-B"})
    BOOST_TEST_CONTEXT(name)
    {
      std::vector<road::WavelengthBand> bands;
      std::vector<double>               target;
      road::texture_preset(name, bands, target);
      // 384 um sampling (Section 5.2), 1.57 m x 98 mm.
      const auto t = road::synthetic_texture(bands, target, 384e-6, 4096, 256, 42, 1.);
      // The generator checks itself with road::texture_spectrum(). Here the
      // band levels come from another analysis: the one-third-octave band
      // spectra of the analysis stage (Hann window, its own band sums),
      // with x as time, so that the band of spatial frequency 1 / lambda is
      // the wavelength band lambda; the mean square over the profiles.
      std::vector<double>    mean_square(bands.size(), 0.);
      std::vector<double>    profile(t.nx);
      analysis::BandSpectrum spectrum;
      for (unsigned int j = 0; j < t.ny; ++j)
        {
          for (unsigned int i = 0; i < t.nx; ++i)
            profile[i] = t(i, j);
          spectrum = analysis::third_octave_spectrum(profile, t.dx, 1e-6, 1. / bands.back().nominal,
                                                     1. / bands.front().nominal);
          BOOST_TEST_REQUIRE(spectrum.bands.size() == bands.size());
          for (std::size_t b = 0; b < bands.size(); ++b)
            mean_square[b] += std::pow(spectrum.rms[bands.size() - 1 - b], 2) / t.ny;
        }
      double worst = 0.;
      for (std::size_t b = 0; b < bands.size(); ++b)
        {
          // Band b of wavelength is band B - 1 - b of spatial frequency.
          BOOST_TEST(spectrum.bands[bands.size() - 1 - b].centre * bands[b].centre == 1.,
                     boost::test_tools::tolerance(1e-9));
          const double level = 10. * std::log10(mean_square[b] / 1e-12);
          worst              = std::max(worst, std::abs(level - target[b]));
        }
      BOOST_TEST_MESSAGE(name << ": worst band " << worst
                              << " dB off target (band spectra of the analysis stage), MPD "
                              << 1e3 * road::mean_profile_depth(t) << " mm");
      BOOST_TEST(worst < 1.);

      // Reproducible with its seed, different with another.
      const auto again = road::synthetic_texture(bands, target, 384e-6, 4096, 256, 42, 1.);
      BOOST_TEST(again.z == t.z);
      const auto other = road::synthetic_texture(bands, target, 384e-6, 4096, 256, 43, 1.);
      BOOST_TEST(other.z != t.z);
    }
  std::vector<road::WavelengthBand> bands;
  std::vector<double>               levels;
  BOOST_CHECK_THROW(road::texture_preset("road-C", bands, levels), InputError);
}

BOOST_AUTO_TEST_CASE(a_long_preset_is_made_in_pieces_that_keep_its_spectrum)
{
  // A road longer than 'Road texture/Length' (2.304 m) is made of
  // independent pieces of that length crossfaded over 0.2 m. Against the
  // preset's own target and the one-piece road:
  // - the texture spectrum of the 8 m road within 1 dB of the target in
  //   every band (the generator holds one piece to 0.5 dB);
  // - the first piece is the one-piece road of the same seed up to its
  //   crossfade;
  // - the crossfades keep the variance: the rms over every join within 7%
  //   of the whole road's (measured 2.4% at most; a plain sum of two pieces
  //   would give +41%, a linear fade -18% over the join);
  // - its length is an FFT-friendly sample count (2, 3 and 5 only).
  road::RoadTextureParameters roads; // road-A, seed 1, 2.304 m in 384 um samples
  const double                width  = 0.1;
  const road::Texture         one    = roads.make("road-A", width);
  const road::Texture         longer = roads.make("road-A", width, 8.);
  BOOST_TEST(one.nx == 6000u);
  BOOST_TEST(longer.length() >= 8.);
  BOOST_TEST(longer.ny == one.ny);
  std::size_t n = longer.nx;
  for (const std::size_t p : {2, 3, 5})
    while (n % p == 0)
      n /= p;
  BOOST_TEST(n == 1u, longer.nx << " samples");

  std::vector<road::WavelengthBand> bands;
  std::vector<double>               target;
  road::texture_preset("road-A", bands, target);
  const auto levels = road::texture_spectrum(longer, bands);
  double     worst  = 0.;
  for (std::size_t b = 0; b < bands.size(); ++b)
    worst = std::max(worst, std::abs(levels[b] - target[b]));
  BOOST_TEST_MESSAGE("8 m of road-A in pieces: worst band "
                     << worst << " dB off target, MPD " << 1e3 * road::mean_profile_depth(longer)
                     << " mm (one piece: " << 1e3 * road::mean_profile_depth(one) << " mm)");
  // Measured 0.26 dB: the pieces' random phases scatter the band levels.
  BOOST_TEST(worst < 0.75);

  const unsigned int overlap = unsigned(std::ceil(0.2 / roads.spacing));
  bool               same    = true;
  for (unsigned int j = 0; j < one.ny; ++j)
    for (unsigned int i = 0; i + overlap < one.nx; ++i)
      same = same && longer(i, j) == one(i, j);
  BOOST_TEST(same);

  const auto rms = [&](const unsigned int i0, const unsigned int i1) {
    double sum = 0.;
    for (unsigned int j = 0; j < longer.ny; ++j)
      for (unsigned int i = i0; i < i1; ++i)
        sum += longer(i, j) * longer(i, j);
    return std::sqrt(sum / ((i1 - i0) * double(longer.ny)));
  };
  const double whole = rms(0, longer.nx);
  for (unsigned int i0 = one.nx - overlap; i0 + overlap < longer.nx; i0 += one.nx - overlap)
    {
      const double join = rms(i0, i0 + overlap);
      BOOST_TEST_MESSAGE("join at " << i0 * roads.spacing << " m: rms " << join / whole
                                    << " of the whole road's");
      BOOST_TEST(join / whole == 1., boost::test_tools::tolerance(0.07));
    }
}

BOOST_AUTO_TEST_CASE(envelope_of_strips_narrower_than_the_sampling)
{
  // Contact rectangles 0.25 mm wide across a road sampled every 0.384 mm
  // (grids with more than 17 x 17 points per Green's-function rectangle):
  // some strips hold no sample. The envelope must be the highest point of the
  // road, linear between samples, over each strip: against a brute-force
  // maximum over 4001 positions across it. The profiles are constant along x,
  // so that only the strip across y matters.
  road::Texture t;
  t.dx = t.dy = 0.384e-3;
  t.nx        = 60;
  t.ny        = 40;
  t.z.resize(std::size_t(t.nx) * t.ny);
  std::mt19937                           random(7);
  std::uniform_real_distribution<double> height(0., 1e-3);
  std::vector<double>                    f(t.ny);
  for (auto &v : f)
    v = height(random);
  for (unsigned int j = 0; j < t.ny; ++j)
    for (unsigned int i = 0; i < t.nx; ++i)
      t.z[std::size_t(j) * t.nx + i] = f[j];

  const double                       w = 0.25e-3;
  std::vector<std::array<double, 3>> points;
  for (int k = 0; k < 40; ++k)
    points.push_back({{0., (k - 19.5) * w, 0.27}});
  const road::PatchRoad road(t, points, road::RoadSampling::envelope, "strips");
  const double          y_centre = 0.5 * (t.ny - 1) * t.dy;
  const auto            linear   = [&](const double y) {
    const double       s = (y + y_centre) / t.dy;
    const unsigned int j = std::min<unsigned int>(t.ny - 2, std::floor(s));
    return (1. - (s - j)) * f[j] + (s - j) * f[j + 1];
  };
  double worst = 0.;
  for (unsigned int p = 0; p < points.size(); ++p)
    {
      double top = -1.;
      for (int m = 0; m <= 4000; ++m)
        top = std::max(top, linear(points[p][1] - 0.5 * w + w * m / 4000.));
      double z, slope;
      road.height(p, 10 * t.dx, z, slope);
      BOOST_TEST(std::isfinite(z));
      BOOST_TEST(z >= top - 1e-12, "strip " << p);
      worst = std::max(worst, std::abs(z - top));
    }
  // The brute force's spacing (62.5 nm) times the steepest slope (2.6).
  BOOST_TEST(worst < 2e-7, worst);
}

BOOST_AUTO_TEST_CASE(envelope_is_the_highest_sample_of_the_tributary_rectangle)
{
  // Contact rectangles wider than the road's sampling in both directions
  // (2.1 mm along, 1.9 mm across a road sampled every 0.384 mm): the envelope
  // of each point, at a position where it falls on a road sample, must be the
  // highest sample inside its tributary rectangle. The reference is a
  // brute-force search over every sample of the texture, which shares no code
  // with the rule's row range and sliding window. The point heights use
  // 'point' sampling on the same road as a second reference: the envelope is
  // never below it.
  road::Texture t;
  t.dx = t.dy = 0.384e-3;
  t.nx        = 300;
  t.ny        = 36;
  t.z.resize(std::size_t(t.nx) * t.ny);
  std::mt19937                           random(11);
  std::uniform_real_distribution<double> height(-1e-3, 1e-3);
  for (auto &z : t.z)
    z = height(random);

  const double                       ax = 2.1e-3, ay = 1.9e-3;
  std::vector<std::array<double, 3>> points;
  for (int j = 0; j < 4; ++j)
    for (int i = 0; i < 5; ++i)
      points.push_back({{i * ax, (j - 1.5) * ay, 0.27}});
  const road::PatchRoad envelope(t, points, road::RoadSampling::envelope, "rectangles");
  const road::PatchRoad point(t, points, road::RoadSampling::point, "rectangles");

  // A texture sample (i, j) sits at x = i dx along the road and at
  // y = j dy - y_centre across it; a point's rectangle is centred at
  // x_p + x_offset + s.
  const double y_centre = 0.5 * (t.ny - 1) * t.dy;
  const double x_offset = 0.5 * ax;
  double       worst = 0., below = 0.;
  unsigned int checked = 0;
  for (unsigned int p = 0; p < points.size(); ++p)
    for (const unsigned int i0 : {40u, 41u, 97u, 180u, 233u})
      {
        const double s   = i0 * t.dx - points[p][0] - x_offset;
        const double xc  = i0 * t.dx;
        double       top = -INFINITY;
        for (unsigned int j = 0; j < t.ny; ++j)
          for (unsigned int i = 0; i < t.nx; ++i)
            if (std::abs(i * t.dx - xc) <= 0.5 * ax &&
                std::abs(j * t.dy - y_centre - points[p][1]) <= 0.5 * ay)
              top = std::max(top, t(i, j));
        double z, slope, z_point;
        envelope.height(p, s, z, slope);
        point.height(p, s, z_point, slope);
        BOOST_TEST(std::isfinite(z));
        worst = std::max(worst, std::abs(z - top));
        below = std::max(below, z_point - z);
        ++checked;
      }
  BOOST_TEST(checked == 100u);
  // The rule and the search pick the same sample: equal to round-off in the
  // position s (measured 1.95e-18 m of heights of 1e-3 m; the point above
  // the envelope by 0). Round-off: within about 10 times.
  BOOST_TEST_MESSAGE("envelope against the brute-force maximum: " << worst << " m; point "
                                                                  << "above it by " << below);
  BOOST_TEST(worst <= 2e-17, worst);
  BOOST_TEST(below <= 2e-17, below);
}

BOOST_AUTO_TEST_CASE(texture_files_round_trip_and_bad_ones_are_refused)
{
  namespace fs   = std::filesystem;
  const auto dir = test::scratch_directory("texture");
  fs::create_directories(dir);
  std::vector<road::WavelengthBand> bands;
  std::vector<double>               target;
  road::texture_preset("road-B", bands, target);
  const auto t = road::synthetic_texture(bands, target, 384e-6, 1024, 64, 7, 5.);

  // SDF, binary and ASCII: the same heights, spacings and sizes back.
  for (const bool binary : {true, false})
    {
      const auto file = (dir / (binary ? "b.sdf" : "a.sdf")).string();
      road::write_sdf(file, t, binary);
      const auto back = road::read_texture(file);
      BOOST_TEST(back.nx == t.nx);
      BOOST_TEST(back.ny == t.ny);
      BOOST_TEST(back.dx == t.dx);
      BOOST_TEST(back.dy == t.dy);
      BOOST_TEST(back.z == t.z); // 17 digits in ASCII: exact
    }

  // Binary int16 heights (DataType 5) with Zscale 1 um, written by hand.
  {
    std::string bytes = "bISO-1.0";
    bytes += std::string(10 + 12 + 12, 'x');
    const auto put = [&bytes](const auto value) {
      bytes.append(reinterpret_cast<const char *>(&value), sizeof(value));
    };
    put(std::uint16_t(3));
    put(std::uint16_t(2));
    put(1e-3);
    put(2e-3);
    put(1e-6);
    put(-1.);
    put(std::uint8_t(0));
    put(std::uint8_t(5));
    put(std::uint8_t(0));
    for (const std::int16_t v : {-3, 0, 7, 100, -100, 1})
      put(v);
    std::ofstream(dir / "i16.sdf", std::ios::binary) << bytes;
    const auto back = road::read_texture((dir / "i16.sdf").string());
    BOOST_TEST(back.nx == 3u);
    BOOST_TEST(back.ny == 2u);
    BOOST_TEST(back.dy == 2e-3);
    BOOST_TEST(back(2, 0) == 7e-6, boost::test_tools::tolerance(1e-12));
    BOOST_TEST(back(1, 1) == -100e-6, boost::test_tools::tolerance(1e-12));
    // Cut short: refused.
    std::ofstream(dir / "short.sdf", std::ios::binary) << bytes.substr(0, bytes.size() - 2);
    BOOST_CHECK_THROW(road::read_texture((dir / "short.sdf").string()), InputError);
  }

  // The plain grid.
  std::ofstream(dir / "grid.txt") << "# two profiles\n0.5e-3 1e-3\n0 1e-4 2e-4\n3e-4 4e-4 5e-4\n";
  const auto grid = road::read_texture((dir / "grid.txt").string());
  BOOST_TEST(grid.nx == 3u);
  BOOST_TEST(grid.ny == 2u);
  BOOST_TEST(grid.dx == 0.5e-3);
  BOOST_TEST(grid(1, 1) == 4e-4);

  const auto refused = [&dir](const std::string &name, const std::string &text,
                              const std::string &message) {
    std::ofstream(dir / name) << text;
    BOOST_CHECK_EXCEPTION(
      road::read_texture((dir / name).string()), InputError, [&](const InputError &e) {
        const bool found = std::string(e.what()).find(message) != std::string::npos;
        if (!found)
          BOOST_TEST_MESSAGE("message: " << e.what());
        return found;
      });
  };
  refused("ragged.txt", "1e-3 1e-3\n1 2 3\n1 2\n", "2 heights where the first profile has 3");
  refused("word.txt", "1e-3 1e-3\n1 x 3\n", "'x' is not a number");
  refused("nan.txt", "1e-3 1e-3\n1 nan 3\n", "is not a finite number");
  refused("spacing.txt", "0 1e-3\n1 2 3\n", "must be finite and > 0");
  refused("star.sdf", "aISO-1.0\nNumPoints = 2\n", "no line '*' ends its header");
  refused("count.sdf",
          "aISO-1.0\nNumPoints = 2\nNumProfiles = 2\nXscale = 1\nYscale = 1\nZscale = 1\n*\n1 2 "
          "3\n*\n",
          "holds 3 values; its header announces NumPoints x NumProfiles = 4");
  BOOST_CHECK_EXCEPTION(road::read_texture((dir / "missing.sdf").string()), InputError,
                        [](const InputError &e) {
                          return std::string(e.what()).find("does not exist") != std::string::npos;
                        });
}

BOOST_AUTO_TEST_SUITE_END()

#include <greentread/base/exceptions.h>
#include <greentread/base/output.h>
#include <greentread/road/texture.h>
#include <greentread/road/texture_files.h>

#include <unsupported/Eigen/FFT>

#include <algorithm>
#include <cmath>
#include <complex>
#include <cstring>
#include <fstream>
#include <limits>
#include <map>
#include <random>
#include <sstream>

namespace greentread
{
  namespace road
  {
    namespace
    {
      /// The nominal values of a decade of one-third-octave bands.
      constexpr double nominal_decade[10] = {1., 1.25, 1.6, 2., 2.5, 3.15, 4., 5., 6.3, 8.};

      /// Remove the least-squares line from @p p.
      void
      remove_trend(std::vector<double> &p)
      {
        const double n  = p.size();
        double       sx = 0., sz = 0., sxx = 0., sxz = 0.;
        for (std::size_t i = 0; i < p.size(); ++i)
          {
            sx += i;
            sz += p[i];
            sxx += double(i) * i;
            sxz += i * p[i];
          }
        const double slope = (n * sxz - sx * sz) / (n * sxx - sx * sx);
        const double mean  = (sz - slope * sx) / n;
        for (std::size_t i = 0; i < p.size(); ++i)
          p[i] -= mean + slope * i;
      }

      /// The band of @p bands holding wavenumber @p k [1/m], or -1.
      int
      band_of(const std::vector<WavelengthBand> &bands, const double k)
      {
        if (k <= 0.)
          return -1;
        const double wavelength = 1. / k;
        for (std::size_t b = 0; b < bands.size(); ++b)
          if (wavelength >= bands[b].lower && wavelength < bands[b].upper)
            return static_cast<int>(b);
        return -1;
      }

      double
      level_of(const double mean_square)
      {
        return mean_square > 0. ? 10. * std::log10(mean_square / 1e-12) :
                                  -std::numeric_limits<double>::infinity();
      }
    } // namespace



    namespace
    {
      /// Throw unless the texture read is usable.
      void
      check_texture(const Texture &t, const std::string &file)
      {
        if (!(t.dx > 0.) || !(t.dy > 0.) || !std::isfinite(t.dx) || !std::isfinite(t.dy))
          throw InputError("texture file '" + file + "': the spacings dx = " + format_short(t.dx) +
                           " m, dy = " + format_short(t.dy) + " m must be finite and > 0");
        if (t.nx < 2 || t.ny < 1)
          throw InputError("texture file '" + file + "' has " + std::to_string(t.nx) + " x " +
                           std::to_string(t.ny) + " points; at least 2 x 1 are needed");
        for (std::size_t e = 0; e < t.z.size(); ++e)
          if (!std::isfinite(t.z[e]))
            throw InputError("texture file '" + file + "': height " + std::to_string(e % t.nx) +
                             " of profile " + std::to_string(e / t.nx) + " is not a finite number");
      }

      template <typename T>
      T
      take(const std::string &bytes, std::size_t &at)
      {
        T value;
        std::memcpy(&value, bytes.data() + at, sizeof(T));
        at += sizeof(T);
        return value;
      }

      Texture
      read_binary_sdf(const std::string &bytes, const std::string &file)
      {
        constexpr std::size_t header = 8 + 10 + 12 + 12 + 2 + 2 + 4 * 8 + 3;
        if (bytes.size() < header)
          throw InputError("SDF file '" + file + "' is shorter than its 81-byte header");
        std::size_t at = 8 + 10 + 12 + 12;
        Texture     t;
        t.nx                = take<std::uint16_t>(bytes, at);
        t.ny                = take<std::uint16_t>(bytes, at);
        t.dx                = take<double>(bytes, at);
        t.dy                = take<double>(bytes, at);
        const double zscale = take<double>(bytes, at);
        at += 8; // Zresolution
        const unsigned compression = take<std::uint8_t>(bytes, at);
        const unsigned type        = take<std::uint8_t>(bytes, at);
        at += 1; // CheckType
        if (compression != 0)
          throw InputError("SDF file '" + file + "': Compression = " + std::to_string(compression) +
                           " is not supported; allowed: 0");
        const std::size_t size[8] = {1, 2, 4, 4, 1, 2, 4, 8};
        if (type > 7)
          throw InputError("SDF file '" + file + "': DataType = " + std::to_string(type) +
                           " is not allowed; allowed: 0 to 7 (ISO 25178-71)");
        const std::size_t n = std::size_t(t.nx) * t.ny;
        if (bytes.size() < header + n * size[type])
          throw InputError("SDF file '" + file + "' is truncated: " + std::to_string(n) +
                           " values of " + std::to_string(size[type]) + " bytes need " +
                           std::to_string(header + n * size[type]) + " bytes, it has " +
                           std::to_string(bytes.size()));
        t.z.resize(n);
        for (std::size_t e = 0; e < n; ++e)
          {
            double v = 0.;
            switch (type)
              {
                case 0:
                  v = take<std::uint8_t>(bytes, at);
                  break;
                case 1:
                  v = take<std::uint16_t>(bytes, at);
                  break;
                case 2:
                  v = take<std::uint32_t>(bytes, at);
                  break;
                case 3:
                  v = take<float>(bytes, at);
                  break;
                case 4:
                  v = take<std::int8_t>(bytes, at);
                  break;
                case 5:
                  v = take<std::int16_t>(bytes, at);
                  break;
                case 6:
                  v = take<std::int32_t>(bytes, at);
                  break;
                default:
                  v = take<double>(bytes, at);
                  break;
              }
            t.z[e] = v * zscale;
          }
        return t;
      }

      Texture
      read_ascii_sdf(const std::string &text, const std::string &file)
      {
        std::istringstream            in(text);
        std::string                   line;
        std::map<std::string, double> header;
        unsigned int                  number = 0;
        std::getline(in, line); // aISO-1.0
        ++number;
        bool star = false;
        while (std::getline(in, line))
          {
            ++number;
            if (line.find('*') != std::string::npos)
              {
                star = true;
                break;
              }
            const auto equal = line.find('=');
            if (equal == std::string::npos)
              continue;
            std::string key = line.substr(0, equal);
            key.erase(key.find_last_not_of(" \t") + 1);
            key.erase(0, key.find_first_not_of(" \t"));
            std::istringstream value(line.substr(equal + 1));
            double             v;
            if (value >> v)
              header[key] = v;
          }
        if (!star)
          throw InputError("SDF file '" + file + "': no line '*' ends its header");
        for (const char *key : {"NumPoints", "NumProfiles", "Xscale", "Yscale", "Zscale"})
          if (header.count(key) == 0)
            throw InputError("SDF file '" + file + "': the header has no number " + key);
        if (header.count("Compression") && header["Compression"] != 0.)
          throw InputError("SDF file '" + file + "': Compression = " +
                           format_number(header["Compression"]) + " is not supported; allowed: 0");
        Texture t;
        t.nx                     = static_cast<unsigned int>(header["NumPoints"]);
        t.ny                     = static_cast<unsigned int>(header["NumProfiles"]);
        t.dx                     = header["Xscale"];
        t.dy                     = header["Yscale"];
        const double      zscale = header["Zscale"];
        const std::size_t n      = std::size_t(t.nx) * t.ny;
        t.z.reserve(n);
        std::string word;
        while (t.z.size() < n && in >> word)
          {
            if (word == "*")
              break;
            char        *end = nullptr;
            const double v   = std::strtod(word.c_str(), &end);
            if (end == word.c_str() || *end != '\0')
              throw InputError("SDF file '" + file + "': value " + std::to_string(t.z.size()) +
                               " '" + word + "' is not a number");
            t.z.push_back(v * zscale);
          }
        if (t.z.size() != n)
          throw InputError(
            "SDF file '" + file + "' holds " + std::to_string(t.z.size()) +
            " values; its header announces NumPoints x NumProfiles = " + std::to_string(n));
        return t;
      }

      Texture
      read_grid(const std::string &text, const std::string &file)
      {
        std::istringstream in(text);
        std::string        line;
        unsigned int       number = 0;
        Texture            t;
        bool               spacing = false;
        while (std::getline(in, line))
          {
            ++number;
            const auto first = line.find_first_not_of(" \t\r");
            if (first == std::string::npos || line[first] == '#')
              continue;
            std::istringstream  values(line);
            std::vector<double> row;
            std::string         word;
            while (values >> word)
              {
                char        *end = nullptr;
                const double v   = std::strtod(word.c_str(), &end);
                if (end == word.c_str() || *end != '\0')
                  throw InputError("texture file '" + file + "', line " + std::to_string(number) +
                                   ": '" + word +
                                   "' is not a number (the plain grid: a line 'dx dy', then "
                                   "one line of heights per profile, in m)");
                row.push_back(v);
              }
            if (!spacing)
              {
                if (row.size() != 2)
                  throw InputError("texture file '" + file + "', line " + std::to_string(number) +
                                   ": the first line must be 'dx dy' (m), two numbers");
                t.dx    = row[0];
                t.dy    = row[1];
                spacing = true;
                continue;
              }
            if (t.ny == 0)
              t.nx = row.size();
            else if (row.size() != t.nx)
              throw InputError("texture file '" + file + "', line " + std::to_string(number) +
                               ": " + std::to_string(row.size()) +
                               " heights where the first "
                               "profile has " +
                               std::to_string(t.nx));
            t.z.insert(t.z.end(), row.begin(), row.end());
            ++t.ny;
          }
        if (!spacing)
          throw InputError("texture file '" + file + "' is empty");
        return t;
      }
    } // namespace



    Texture
    read_texture(const std::string &file)
    {
      std::ifstream in(file, std::ios::binary);
      if (!in)
        throw InputError("texture file '" + file + "' does not exist or cannot be read");
      const std::string bytes((std::istreambuf_iterator<char>(in)),
                              std::istreambuf_iterator<char>());
      Texture           t;
      if (bytes.compare(0, 4, std::string("PK\x03\x04", 4)) == 0)
        t = read_x3p(file);
      else if (is_text_profile(bytes))
        t = read_text_profile(bytes, file);
      else if (bytes.compare(0, 8, "bISO-1.0") == 0)
        t = read_binary_sdf(bytes, file);
      else if (bytes.compare(0, 8, "aISO-1.0") == 0)
        t = read_ascii_sdf(bytes, file);
      else
        t = read_grid(bytes, file);
      check_texture(t, file);
      return t;
    }



    void
    write_sdf(const std::string &file, const Texture &t, const bool binary)
    {
      if (t.nx > 65535 || t.ny > 65535)
        throw InputError("SDF file '" + file + "': " + std::to_string(t.nx) + " x " +
                         std::to_string(t.ny) + " points; SDF allows at most 65535 each");
      base::AtomicFile out(file, std::ios::binary);
      auto            &o = out.stream();
      if (binary)
        {
          const auto put = [&](const auto value) {
            o.write(reinterpret_cast<const char *>(&value), sizeof(value));
          };
          o.write("bISO-1.0", 8);
          o.write("GreenTread", 10);
          o.write("000000000000", 12);
          o.write("000000000000", 12);
          put(std::uint16_t(t.nx));
          put(std::uint16_t(t.ny));
          put(t.dx);
          put(t.dy);
          put(1.);
          put(-1.);
          put(std::uint8_t(0));
          put(std::uint8_t(7));
          put(std::uint8_t(0));
          for (const double z : t.z)
            put(z);
        }
      else
        {
          o.precision(17);
          o << "aISO-1.0\nManufacID   = GreenTread\nNumPoints   = " << t.nx
            << "\nNumProfiles = " << t.ny << "\nXscale      = " << t.dx
            << "\nYscale      = " << t.dy
            << "\nZscale      = 1\nZresolution = -1\nCompression = 0\nDataType    = 7\n"
               "CheckType   = 0\n*\n";
          for (unsigned int j = 0; j < t.ny; ++j)
            {
              for (unsigned int i = 0; i < t.nx; ++i)
                o << t(i, j) << (i + 1 < t.nx ? ' ' : '\n');
            }
          o << "*\n";
        }
      out.commit();
    }



    std::vector<WavelengthBand>
    wavelength_bands(const double shortest, const double longest)
    {
      std::vector<WavelengthBand> bands;
      // Centres 10^(k/10) mm.
      for (int k = -30; k <= 40; ++k)
        {
          const int    decade  = static_cast<int>(std::floor(k / 10.));
          const double nominal = 1e-3 * nominal_decade[k - 10 * decade] * std::pow(10., decade);
          if (nominal < shortest * (1. - 1e-9) || nominal > longest * (1. + 1e-9))
            continue;
          const double centre = 1e-3 * std::pow(10., k / 10.);
          bands.push_back(
            {k, nominal, centre, centre * std::pow(10., -0.05), centre * std::pow(10., 0.05)});
        }
      return bands;
    }



    std::vector<double>
    texture_spectrum(const Texture &texture, const std::vector<WavelengthBand> &bands)
    {
      const unsigned int                n = texture.nx;
      std::vector<double>               mean_square(bands.size(), 0.);
      Eigen::FFT<double>                fft;
      std::vector<double>               profile(n);
      std::vector<std::complex<double>> spectrum;
      std::vector<int>                  band(n / 2 + 1);
      for (unsigned int m = 0; m <= n / 2; ++m)
        band[m] = band_of(bands, m / texture.length());
      for (unsigned int j = 0; j < texture.ny; ++j)
        {
          for (unsigned int i = 0; i < n; ++i)
            profile[i] = texture(i, j);
          remove_trend(profile);
          fft.fwd(spectrum, profile);
          // One-sided: lines m and n - m together, the Nyquist line alone.
          for (unsigned int m = 1; m <= n / 2; ++m)
            if (band[m] >= 0)
              mean_square[band[m]] +=
                (2 * m == n ? 1. : 2.) * std::norm(spectrum[m]) / (double(n) * n);
        }
      std::vector<double> levels(bands.size());
      for (std::size_t b = 0; b < bands.size(); ++b)
        levels[b] = level_of(mean_square[b] / texture.ny);
      return levels;
    }



    double
    mean_profile_depth(const Texture &texture, const double baseline)
    {
      const unsigned int points =
        static_cast<unsigned int>(std::floor(baseline / texture.dx * (1. + 1e-12)));
      if (points < 4 || points > texture.nx)
        throw InputError("the texture's profiles (" + format_short(texture.length()) +
                         " m, every " + format_short(texture.dx) +
                         " m) are too short for one MPD segment of " + format_short(baseline) +
                         " m (ISO 13473-1)");
      double              sum   = 0.;
      unsigned int        count = 0;
      std::vector<double> segment(points);
      for (unsigned int j = 0; j < texture.ny; ++j)
        for (unsigned int start = 0; start + points <= texture.nx; start += points)
          {
            for (unsigned int i = 0; i < points; ++i)
              segment[i] = texture(start + i, j);
            remove_trend(segment);
            const auto   half   = segment.begin() + points / 2;
            const double peak_1 = *std::max_element(segment.begin(), half);
            const double peak_2 = *std::max_element(half, segment.end());
            // The segment's mean is zero after the trend is removed.
            sum += 0.5 * (peak_1 + peak_2);
            ++count;
          }
      return sum / count;
    }



    Texture
    synthetic_texture(const std::vector<WavelengthBand> &bands,
                      const std::vector<double>         &target,
                      const double                       spacing,
                      const unsigned int                 nx,
                      const unsigned int                 ny,
                      const std::uint64_t                seed,
                      const double                       tolerance)
    {
      if (bands.size() != target.size())
        throw InputError("synthetic texture: " + std::to_string(target.size()) + " levels for " +
                         std::to_string(bands.size()) + " bands");
      // White noise and its 2D transform: rows (x) first, then columns (y).
      std::mt19937_64                   random(seed);
      std::normal_distribution<double>  normal(0., 1.);
      std::vector<std::complex<double>> W(std::size_t(nx) * ny);
      for (auto &w : W)
        w = normal(random);
      Eigen::FFT<double>                fft;
      std::vector<std::complex<double>> line, out;
      const auto transform = [&](std::vector<std::complex<double>> &A, const bool forward) {
        line.resize(nx);
        for (unsigned int j = 0; j < ny; ++j)
          {
            std::copy(A.begin() + std::size_t(j) * nx, A.begin() + std::size_t(j + 1) * nx,
                      line.begin());
            forward ? fft.fwd(out, line) : fft.inv(out, line);
            std::copy(out.begin(), out.end(), A.begin() + std::size_t(j) * nx);
          }
        line.resize(ny);
        for (unsigned int i = 0; i < nx; ++i)
          {
            for (unsigned int j = 0; j < ny; ++j)
              line[j] = A[std::size_t(j) * nx + i];
            forward ? fft.fwd(out, line) : fft.inv(out, line);
            for (unsigned int j = 0; j < ny; ++j)
              A[std::size_t(j) * nx + i] = out[j];
          }
      };
      transform(W, true);

      // The filter is separable, H(kx, ky) = g_b(kx) h(ky). Across y, h has
      // the target's spectral shape (the band level spread evenly over the
      // band's wavenumbers), so that the texture has like scales in both
      // directions. Averaged over the profiles, the cross terms between
      // different ky vanish, so the profiles' mean square in band b is
      // exactly g_b^2 M_b, M_b summing |W h|^2 over the lines with k_x in
      // b: the gains follow band by band.
      const double Lx = nx * spacing, Ly = ny * spacing;
      const auto   wavenumber = [](const unsigned int m, const unsigned int n, const double L) {
        return (m <= n / 2 ? double(m) : double(m) - n) / L;
      };
      const std::size_t   B = bands.size();
      std::vector<double> across(ny, 0.);
      for (unsigned int j = 0; j < ny; ++j)
        {
          const int c = band_of(bands, std::abs(wavenumber(j, ny, Ly)));
          if (c >= 0)
            across[j] =
              std::pow(10., target[c] / 20.) / std::sqrt(1. / bands[c].lower - 1. / bands[c].upper);
        }
      if (std::all_of(across.begin(), across.end(), [](const double a) {
            return a == 0.;
          }))
        throw InputError("synthetic texture: the grid is " + format_short(Ly) +
                         " m wide across y, too narrow for any band from " +
                         format_number(1e3 * bands.front().nominal) + " to " +
                         format_number(1e3 * bands.back().nominal) + " mm");
      std::vector<int>    along(nx, -1);
      std::vector<double> M(B, 0.);
      const double        scale = 1. / (double(nx) * nx * double(ny) * ny);
      for (unsigned int i = 0; i < nx; ++i)
        {
          along[i] = band_of(bands, std::abs(wavenumber(i, nx, Lx)));
          if (along[i] >= 0)
            for (unsigned int j = 0; j < ny; ++j)
              M[along[i]] += std::norm(W[std::size_t(j) * nx + i] * across[j]) * scale;
        }
      std::vector<double> gain(B);
      for (std::size_t b = 0; b < B; ++b)
        {
          if (M[b] <= 0.)
            throw NumericalError("synthetic texture: no Fourier line of the grid falls in the " +
                                 format_number(1e3 * bands[b].nominal) +
                                 " mm band; use a longer or finer grid");
          gain[b] = std::sqrt(1e-12 * std::pow(10., target[b] / 10.) / M[b]);
        }
      for (unsigned int j = 0; j < ny; ++j)
        for (unsigned int i = 0; i < nx; ++i)
          W[std::size_t(j) * nx + i] *= along[i] >= 0 ? gain[along[i]] * across[j] : 0.;
      transform(W, false);

      Texture texture;
      texture.dx = texture.dy = spacing;
      texture.nx              = nx;
      texture.ny              = ny;
      texture.z.resize(W.size());
      for (std::size_t e = 0; e < W.size(); ++e)
        texture.z[e] = W[e].real();

      // Check what was made, as any texture is checked.
      const auto achieved = texture_spectrum(texture, bands);
      for (std::size_t b = 0; b < B; ++b)
        if (!(std::abs(achieved[b] - target[b]) <= tolerance))
          throw NumericalError("synthetic texture: the " + format_number(1e3 * bands[b].nominal) +
                               " mm band came out at " + format_short(achieved[b]) +
                               " dB against the target " + format_short(target[b]) +
                               " dB (tolerance " + format_short(tolerance) +
                               " dB): the grid is too short or too coarse for the band");
      return texture;
    }



    void
    texture_preset(const std::string           &name,
                   std::vector<WavelengthBand> &bands,
                   std::vector<double>         &levels)
    {
      bands = wavelength_bands(2e-3, 0.1);
      // 2, 2.5, 3.15, 4, 5, 6.3, 8, 10, 12.5, 16, 20, 25, 31.5, 40, 50, 63, 80, 100 mm.
      if (name == "road-A")
        levels = {36., 38.,  40.,  42., 44., 46., 48., 49.5, 50.,
                  50., 49.5, 48.5, 47., 46., 45., 44., 43.,  42.};
      else if (name == "road-B")
        levels = {28.,  30., 32., 34., 36., 38., 40.,  41., 41.,
                  40.5, 40., 39., 38., 37., 36., 35.5, 35., 34.5};
      else
        throw InputError("texture preset '" + name + "' is not known; allowed: road-A, road-B");
    }
  } // namespace road
} // namespace greentread

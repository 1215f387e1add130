#include <greentread/base/exceptions.h>
#include <greentread/base/frequency_response.h>
#include <greentread/base/hdf5_writer.h>
#include <greentread/base/parameters.h>

#include <deal.II/base/hdf5.h>

#include <hdf5.h>

#include <cmath>
#include <cstdlib>
#include <fstream>
#include <regex>
#include <sstream>

namespace greentread
{
  namespace base
  {
    namespace
    {



      /// Check a grid of line frequencies: from 0, uniform. Returns df.
      double
      check_grid(const std::vector<double> &f, const std::string &where)
      {
        if (f.size() < 2)
          throw InputError(where + ": an FRF needs at least 2 frequency lines, it has " +
                           std::to_string(f.size()));
        const double df = (f.back() - f.front()) / (f.size() - 1);
        if (!(df > 0.))
          throw InputError(where + ": the frequencies must increase; they go from " +
                           format_number(f.front()) + " to " + format_number(f.back()) + " Hz");
        if (std::abs(f.front()) > 1e-6 * df)
          throw InputError(where + ": the frequency grid must start at 0 Hz (it starts at " +
                           format_number(f.front()) +
                           " Hz): LSCE extends the FRF to negative "
                           "frequencies by symmetry and needs the whole band from 0");
        for (std::size_t k = 0; k < f.size(); ++k)
          if (std::abs(f[k] - k * df) > 1e-6 * df)
            throw InputError(where + ": the frequency grid is not uniform: line " +
                             std::to_string(k) + " is at " + format_number(f[k]) +
                             " Hz, expected " + format_number(k * df) + " Hz (spacing " +
                             format_number(df) + " Hz); resample it on a uniform grid");
        return df;
      }
    } // namespace



    FrequencyResponse
    read_frf_csv(const std::string &file)
    {
      std::ifstream in(file);
      if (!in)
        throw InputError("FRF file '" + file +
                         "' cannot be opened: it does not exist or is not "
                         "readable");
      std::string         line;
      unsigned int        number = 0;
      bool                header = false;
      std::vector<double> f;
      FrequencyResponse   frf;
      while (std::getline(in, line))
        {
          ++number;
          const std::string text = trim(line);
          if (text.empty() || text[0] == '#')
            continue;
          const std::string where = "FRF file '" + file + "', line " + std::to_string(number);
          if (!header)
            {
              std::string compact;
              for (const char c : text)
                if (c != ' ')
                  compact += c;
              if (compact != "f,re,im")
                throw InputError(where + ": expected the header 'f,re,im', found '" + text + "'");
              header = true;
              continue;
            }
          double      x[3];
          const char *p = text.c_str();
          for (unsigned int c = 0; c < 3; ++c)
            {
              char *end = nullptr;
              x[c]      = std::strtod(p, &end);
              if (end == p)
                throw InputError(where + ": expected three numbers 'f,re,im', found '" + text +
                                 "'");
              if (!std::isfinite(x[c]))
                throw InputError(where + ": the value '" +
                                 trim(std::string(p, static_cast<std::size_t>(end - p))) +
                                 "' is not a finite number (NaN or inf in the FRF)");
              p = end;
              while (*p == ' ' || *p == '\t')
                ++p;
              if (c < 2)
                {
                  if (*p != ',')
                    throw InputError(where + ": expected three comma-separated numbers, found '" +
                                     text + "'");
                  ++p;
                }
            }
          if (trim(p) != "")
            throw InputError(where + ": unexpected text after three numbers: '" + text + "'");
          f.push_back(x[0]);
          frf.values.emplace_back(x[1], x[2]);
        }
      if (!header)
        throw InputError("FRF file '" + file +
                         "' is empty: expected the header 'f,re,im' and "
                         "one line per frequency");
      frf.df = check_grid(f, "FRF file '" + file + "'");
      return frf;
    }



    void
    write_frf_csv(const std::filesystem::path &file,
                  const FrequencyResponse     &frf,
                  const base::ParameterRecord &record)
    {
      base::AtomicFile out(file);
      out.stream().precision(16);
      out.stream() << "f,re,im\n";
      for (std::size_t k = 0; k < frf.values.size(); ++k)
        out.stream() << k * frf.df << ',' << frf.values[k].real() << ',' << frf.values[k].imag()
                     << '\n';
      record.write_comments(out.stream());
      out.commit();
    }



    std::vector<std::pair<unsigned int, unsigned int>>
    parse_point_pairs(const std::string &text, const unsigned int n, const std::string &parameter)
    {
      std::vector<std::pair<unsigned int, unsigned int>> pairs;
      if (text == "all")
        {
          for (unsigned int i = 0; i < n; ++i)
            for (unsigned int j = 0; j < n; ++j)
              pairs.emplace_back(i, j);
          return pairs;
        }
      if (text == "diagonal")
        {
          for (unsigned int i = 0; i < n; ++i)
            pairs.emplace_back(i, i);
          return pairs;
        }
      const std::regex item("^\\s*([0-9]+)\\s*:\\s*([0-9]+)\\s*$");
      std::size_t      begin = 0;
      while (begin <= text.size())
        {
          const std::size_t comma = std::min(text.find(',', begin), text.size());
          const std::string part  = text.substr(begin, comma - begin);
          std::smatch       m;
          if (!std::regex_match(part, m, item))
            throw InputError("parameter '" + parameter + "' = " + text +
                             " is not allowed; allowed: 'all', 'diagonal' or a list "
                             "'i:j, i:j, ...' of 0-based point indices ('" +
                             part + "')");
          const unsigned int i = std::stoul(m[1]), j = std::stoul(m[2]);
          if (i >= n || j >= n)
            throw InputError("parameter '" + parameter + "' names the pair " + part +
                             ", but there are only " + std::to_string(n) +
                             " points (indices 0 to " + std::to_string(n - 1) + ")");
          pairs.emplace_back(i, j);
          begin = comma + 1;
        }
      return pairs;
    }



    FrequencyResponse
    FrequencyResponseMatrix::get(const unsigned int i, const unsigned int j) const
    {
      const unsigned int n = n_points();
      FrequencyResponse  frf;
      frf.df = df;
      frf.values.resize(n_lines);
      for (unsigned int k = 0; k < n_lines; ++k)
        frf.values[k] = values[(std::size_t(k) * n + i) * n + j];
      return frf;
    }



    namespace
    {
      /// Silences HDF5's own error printing while it lives (and restores
      /// it on every exit, exceptions included).
      class QuietHdf5
      {
      public:
        QuietHdf5()
        {
          H5Eget_auto2(H5E_DEFAULT, &handler, &data);
          H5Eset_auto2(H5E_DEFAULT, nullptr, nullptr);
        }
        ~QuietHdf5()
        {
          H5Eset_auto2(H5E_DEFAULT, handler, data);
        }
        QuietHdf5(const QuietHdf5 &) = delete;
        QuietHdf5 &
        operator=(const QuietHdf5 &) = delete;

      private:
        H5E_auto2_t handler;
        void       *data;
      };



      /**
       * Check with the HDF5 C API that @p file is an HDF5 file holding the
       * datasets @p names, before deal.II's wrappers open it: they do not
       * report a bad file, they abort.
       */
      void
      check_hdf5_layout(const std::string &file, const std::vector<std::string> &names)
      {
        std::string problem;
        {
          const QuietHdf5 quiet;
          if (H5Fis_hdf5(file.c_str()) <= 0)
            problem = "it is not an HDF5 file";
          else
            {
              const hid_t id = H5Fopen(file.c_str(), H5F_ACC_RDONLY, H5P_DEFAULT);
              if (id < 0)
                problem = "HDF5 cannot open it";
              else
                {
                  for (const auto &name : names)
                    if (problem.empty() && H5Lexists(id, name.c_str(), H5P_DEFAULT) <= 0)
                      problem = "it has no dataset /" + name;
                  H5Fclose(id);
                }
            }
        }
        if (!problem.empty())
          throw InputError("Green's function file '" + file + "' cannot be read: " + problem +
                           "; expected the layout /frequency [n_f], /points [n_p][3], /green "
                           "complex [n_f][n_p][n_p] (doc/getting-started.md, 'File formats')");
      }
    } // namespace



    FrequencyResponseMatrix
    read_green_hdf5(const std::string &file)
    {
      if (!std::filesystem::exists(file))
        throw InputError("Green's function file '" + file + "' does not exist");
      check_hdf5_layout(file, {"frequency", "points", "green"});
      // deal.II's HDF5 objects abort the program when they are destroyed
      // while an exception is in flight (an MPI build): each check records
      // its problem, and the error is thrown once they are closed.
      FrequencyResponseMatrix green;
      std::string             dataset = "/frequency";
      std::vector<double>     f;
      std::string             problem;
      try
        {
          dealii::HDF5::File h5(file, dealii::HDF5::File::FileAccessMode::open);
          f = h5.open_dataset("frequency").read<std::vector<double>>();

          dataset           = "/points";
          auto       points = h5.open_dataset("points");
          const auto pdims  = points.get_dimensions();
          if (pdims.size() != 2 || pdims[1] != 3)
            problem = "/points must be a double array [n_p][3]";
          else
            {
              const auto p = points.read<std::vector<double>>();
              for (std::size_t i = 0; i < pdims[0]; ++i)
                green.points.push_back({{p[3 * i], p[3 * i + 1], p[3 * i + 2]}});

              dataset         = "/green";
              auto       data = h5.open_dataset("green");
              const auto dims = data.get_dimensions();
              const auto n    = green.points.size();
              if (dims.size() != 3 || dims[0] != f.size() || dims[1] != n || dims[2] != n)
                problem = "/green must be complex [n_f][n_p][n_p] = [" + std::to_string(f.size()) +
                          "][" + std::to_string(n) + "][" + std::to_string(n) + "]";
              else
                green.values = data.read<std::vector<std::complex<double>>>();
            }
        }
      catch (const dealii::ExceptionBase &e)
        {
          std::ostringstream info;
          e.print_info(info);
          throw InputError("Green's function file '" + file + "': cannot read " + dataset +
                           " (is it an HDF5 file in the documented layout?): " + info.str());
        }
      if (!problem.empty())
        throw InputError("Green's function file '" + file + "': " + problem);
      green.df      = check_grid(f, "Green's function file '" + file + "', /frequency");
      green.n_lines = static_cast<unsigned int>(f.size());
      for (const auto &v : green.values)
        if (!std::isfinite(v.real()) || !std::isfinite(v.imag()))
          throw InputError("Green's function file '" + file + "': /green holds NaN or inf values");
      return green;
    }



    std::string
    read_hdf5_stage_key(const std::string &file, const std::vector<std::string> &datasets)
    {
      if (!std::filesystem::exists(file))
        return {};
      // A file without the attribute, or not an HDF5 file at all, simply
      // has no key: HDF5 need not print its errors.
      const QuietHdf5 quiet;
      std::string     key;
      if (H5Fis_hdf5(file.c_str()) > 0)
        {
          const hid_t id = H5Fopen(file.c_str(), H5F_ACC_RDONLY, H5P_DEFAULT);
          if (id >= 0)
            {
              bool complete = H5Aexists(id, "stage_key") > 0;
              for (const auto &name : datasets)
                complete = complete && H5Lexists(id, name.c_str(), H5P_DEFAULT) > 0;
              H5Fclose(id);
              if (complete)
                {
                  dealii::HDF5::File h5(file, dealii::HDF5::File::FileAccessMode::open);
                  key = h5.get_attribute<std::string>("stage_key");
                }
            }
        }
      return key;
    }



    std::string
    read_green_stage_key(const std::string &file)
    {
      return read_hdf5_stage_key(file, {});
    }



    void
    write_hdf5_stage(const std::filesystem::path              &file,
                     const std::vector<std::array<double, 3>> &points,
                     const base::ParameterRecord              &record,
                     const std::string                        &stage_key,
                     const std::function<void(Hdf5Writer &)>  &fill)
    {
      // HDF5 writes through its own file handle: reserve the temporary name
      // with an AtomicFile, let HDF5 fill it, then rename.
      base::AtomicFile target(file, std::ios::binary);
      target.stream().close();
      {
        Hdf5Writer h5(target.temporary_path().string());
        fill(h5);
        std::vector<double> p;
        for (const auto &x : points)
          p.insert(p.end(), x.begin(), x.end());
        h5.create_dataset<double>("points", {points.size(), 3}).write(p);
        h5.set_attribute("parameters", record.text());
        if (!stage_key.empty())
          h5.set_attribute("stage_key", stage_key);
      }
      target.commit();
    }



    void
    write_green_hdf5(const std::filesystem::path   &file,
                     const FrequencyResponseMatrix &green,
                     const base::ParameterRecord   &record,
                     const std::string             &stage_key)
    {
      write_hdf5_stage(file, green.points, record, stage_key, [&](Hdf5Writer &h5) {
        std::vector<double> f(green.n_lines);
        for (unsigned int k = 0; k < green.n_lines; ++k)
          f[k] = k * green.df;
        h5.create_dataset<double>("frequency", {green.n_lines}).write(f);
        h5.create_dataset<std::complex<double>>(
            "green", {green.n_lines, green.points.size(), green.points.size()})
          .write(green.values);
      });
    }
  } // namespace base
} // namespace greentread

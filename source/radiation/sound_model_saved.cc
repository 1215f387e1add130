#include <greentread/base/exceptions.h>
#include <greentread/base/frequency_response.h>
#include <greentread/base/hdf5_writer.h>
#include <greentread/radiation/sound_model.h>

#include <deal.II/base/hdf5.h>
#include <deal.II/base/utilities.h>

#include <cmath>
#include <complex>
#include <iostream>
#include <optional>

/**
 * @file
 * The radiation stage's saved file: SoundModel::save(), read(), and the
 * stage that reuses it.
 */

namespace greentread
{
  namespace radiation
  {
    namespace
    {
      const char *const level_names[2] = {"mesh", "coarser_mesh"};

      /// The datasets whose presence marks a complete file.
      const std::vector<std::string> sound_datasets = {
        "bands_hz", "deflection", "fewer_harmonics", "microphone_positions", "coarser_mesh_power"};

      /// The per-level datasets that hold a SurfaceMobility::Saved.
      template <typename F>
      void
      for_each_array(SurfaceMobility::Saved &s, F &&f)
      {
        f("modes", s.modes);
        f("coupled", s.coupled);
        f("cell_segment", s.cell_segment);
        f("point_strip", s.point_strip);
        f("omega", s.omega);
        f("damping_ratio", s.damping_ratio);
        f("cell_angle", s.cell_angle);
        f("point_angle", s.point_angle);
        f("at_segments", s.at_segments);
        f("at_strips", s.at_strips);
        f("residual", s.residual);
        f("strip_residual", s.strip_residual);
        f("sizes", s.sizes);
      }
    } // namespace



    void
    SoundModel::save(const std::filesystem::path              &file,
                     const std::vector<std::array<double, 3>> &points,
                     const base::ParameterRecord              &record,
                     const std::string                        &key) const
    {
      base::write_hdf5_stage(file, points, record, key, [&](base::Hdf5Writer &h5) {
        std::vector<double> nominal;
        for (const auto &b : bands)
          nominal.push_back(b.nominal);
        h5.create_dataset<double>("bands_hz", {nominal.size()}).write(nominal);
        h5.create_dataset<double>("deflection", {1}).write({deflection});
        h5.create_dataset<int>("fewer_harmonics", {1}).write({static_cast<int>(fewer_harmonics)});
        std::vector<double> positions;
        std::string         names;
        for (const auto &m : microphones)
          {
            for (unsigned int d = 0; d < 3; ++d)
              positions.push_back(m.position[d]);
            names += (names.empty() ? "" : ";") + m.name;
          }
        h5.create_dataset<double>("microphone_positions", {microphones.size(), 3}).write(positions);
        h5.set_attribute("microphone_names", names);
        for (unsigned int l = 0; l < 2; ++l)
          {
            const SoundLevel &level  = levels[l];
            const std::string prefix = std::string(level_names[l]) + "_";
            h5.create_dataset<double>(prefix + "level", {3})
              .write({level.cell_size, double(level.cells), double(level.harmonics)});
            SurfaceMobility::Saved saved = level.mobility->saved();
            for_each_array(saved, [&](const char *name, const auto &values) {
              using T = typename std::decay_t<decltype(values)>::value_type;
              h5.create_dataset<T>(prefix + name, {values.size()}).write(values);
            });
            std::vector<std::complex<double>> mics, power;
            std::vector<int>                  power_rows;
            for (const BandTransfer &t : level.transfers)
              {
                for (Eigen::Index r = 0; r < t.microphones.rows(); ++r)
                  for (Eigen::Index c = 0; c < t.microphones.cols(); ++c)
                    mics.push_back(t.microphones(r, c));
                for (Eigen::Index r = 0; r < t.power.rows(); ++r)
                  for (Eigen::Index c = 0; c < t.power.cols(); ++c)
                    power.push_back(t.power(r, c));
                power_rows.push_back(static_cast<int>(t.power.rows()));
              }
            h5.create_dataset<std::complex<double>>(prefix + "microphones", {mics.size()})
              .write(mics);
            h5.create_dataset<int>(prefix + "power_rows", {power_rows.size()}).write(power_rows);
            h5.create_dataset<std::complex<double>>(prefix + "power", {power.size()}).write(power);
          }
      });
    }



    std::string
    SoundModel::read_key(const std::filesystem::path &file)
    {
      return base::read_hdf5_stage_key(file.string(), sound_datasets);
    }



    SoundModel
    SoundModel::read(const std::filesystem::path &file)
    {
      const std::string name = "radiation stage file '" + file.string() + "'";
      if (read_key(file).empty())
        throw InputError(name + " is missing or incomplete; delete it to recompute it");
      // Everything read, and the file closed, before any check can throw:
      // deal.II's HDF5 objects abort when destroyed during an exception.
      std::vector<double>                              nominal, deflection, positions;
      std::vector<int>                                 fewer_harmonics;
      std::string                                      names;
      std::array<std::vector<double>, 2>               level_sizes;
      std::array<SurfaceMobility::Saved, 2>            saved;
      std::array<std::vector<std::complex<double>>, 2> mics, power;
      std::array<std::vector<int>, 2>                  power_rows;
      {
        dealii::HDF5::File h5(file.string(), dealii::HDF5::File::FileAccessMode::open);
        nominal         = h5.open_dataset("bands_hz").read<std::vector<double>>();
        deflection      = h5.open_dataset("deflection").read<std::vector<double>>();
        fewer_harmonics = h5.open_dataset("fewer_harmonics").read<std::vector<int>>();
        positions       = h5.open_dataset("microphone_positions").read<std::vector<double>>();
        names           = h5.get_attribute<std::string>("microphone_names");
        for (unsigned int l = 0; l < 2; ++l)
          {
            const std::string prefix = std::string(level_names[l]) + "_";
            level_sizes[l] = h5.open_dataset(prefix + "level").read<std::vector<double>>();
            for_each_array(saved[l], [&](const char *array, auto &values) {
              using V = std::decay_t<decltype(values)>;
              values  = h5.open_dataset(prefix + array).read<V>();
            });
            mics[l] =
              h5.open_dataset(prefix + "microphones").read<std::vector<std::complex<double>>>();
            power_rows[l] = h5.open_dataset(prefix + "power_rows").read<std::vector<int>>();
            power[l] = h5.open_dataset(prefix + "power").read<std::vector<std::complex<double>>>();
          }
      }
      const auto fail = [&](const std::string &what) {
        throw InputError(name + ": " + what + "; delete it to recompute it");
      };
      SoundModel model;
      if (nominal.empty() || deflection.size() != 1 || positions.size() % 3 != 0 ||
          fewer_harmonics.size() != 1 || fewer_harmonics[0] < 1)
        fail("its bands, deflection or microphones are malformed");
      model.bands      = analysis::third_octave_bands(nominal.front(), nominal.back());
      model.deflection = deflection[0];
      const auto split = dealii::Utilities::split_string_list(names, ';');
      if (split.size() * 3 != positions.size())
        fail("its microphones' names and positions do not match");
      for (std::size_t m = 0; m < split.size(); ++m)
        model.microphones.push_back(
          {split[m],
           dealii::Point<3>(positions[3 * m], positions[3 * m + 1], positions[3 * m + 2])});
      const std::size_t B = model.bands.size(), M = split.size();
      for (unsigned int l = 0; l < 2; ++l)
        {
          SoundLevel &level = model.levels[l];
          if (level_sizes[l].size() != 3 || power_rows[l].size() != B)
            fail("its " + std::string(level_names[l]) + " is malformed");
          level.cell_size        = level_sizes[l][0];
          level.cells            = static_cast<unsigned int>(level_sizes[l][1]);
          level.harmonics        = static_cast<unsigned int>(level_sizes[l][2]);
          level.mobility         = std::make_unique<SurfaceMobility>(saved[l]);
          const std::size_t C    = level.mobility->n_cells();
          std::size_t       rows = 0;
          for (const int r : power_rows[l])
            rows += static_cast<std::size_t>(std::max(r, 0));
          if (mics[l].size() != B * M * C || power[l].size() != rows * C)
            fail("its " + std::string(level_names[l]) + "'s transfers do not fit its cells");
          for (const auto *values : {&mics[l], &power[l]})
            for (const auto &v : *values)
              if (!std::isfinite(v.real()) || !std::isfinite(v.imag()))
                fail("it holds a value that is not a finite number");
          using RowMajor =
            Eigen::Matrix<std::complex<double>, Eigen::Dynamic, Eigen::Dynamic, Eigen::RowMajor>;
          std::size_t at = 0;
          for (std::size_t b = 0; b < B; ++b)
            {
              BandTransfer t;
              t.frequency   = model.bands[b].centre;
              t.microphones = Eigen::Map<const RowMajor>(mics[l].data() + b * M * C, M, C);
              t.power = Eigen::Map<const RowMajor>(power[l].data() + at * C, power_rows[l][b], C);
              at += power_rows[l][b];
              level.transfers.push_back(std::move(t));
            }
        }
      model.fewer_harmonics = static_cast<unsigned int>(fewer_harmonics[0]);
      model.fewer           = std::make_unique<SurfaceMobility>(
        model.levels[0].mobility->truncated(model.fewer_harmonics));
      return model;
    }



    SoundModel
    sound_model_stage(const std::function<SoundModel()>        &build,
                      const std::filesystem::path              &file,
                      const std::string                        &key,
                      const std::vector<std::array<double, 3>> &points,
                      const base::ParameterRecord              &record,
                      const bool                                reuse)
    {
      std::optional<SoundModel> model;
      if (reuse && SoundModel::read_key(file) == key && base::read_saved_stage(file, [&] {
            model.emplace(SoundModel::read(file));
          }))
        {
          std::cout << "Reusing " << file.string()
                    << ": same tyre, modes, bands, boundary element meshes and microphones\n";
          return std::move(*model);
        }
      SoundModel built = build();
      built.save(file, points, record, key);
      return built;
    }
  } // namespace radiation
} // namespace greentread

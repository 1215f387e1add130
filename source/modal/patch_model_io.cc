#include <greentread/base/exceptions.h>
#include <greentread/base/hdf5_writer.h>
#include <greentread/modal/patch_model.h>

#include <deal.II/base/hdf5.h>

#include <algorithm>
#include <cmath>

// The HDF5 file of a patch model, patch_model.h5 (see write_patch_model()).

namespace greentread
{
  namespace modal
  {
    namespace
    {
      const std::vector<std::string> patch_datasets = {"lambda", "real", "residues",     "errors",
                                                       "points", "info", "instantaneous"};
    } // namespace



    void
    write_patch_model(const std::filesystem::path &file,
                      const PatchModel            &model,
                      const base::ParameterRecord &record,
                      const std::string           &stage_key)
    {
      if (model.is_rank_one())
        throw NumericalError("write_patch_model: a model from the ring's modes is saved as "
                             "modal_model.h5 (write_modal_model), not as a patch model");
      write_hdf5_stage(file, model.points, record, stage_key, [&](base::Hdf5Writer &h5) {
        const std::size_t n = model.n_points(), m = model.n_terms();
        h5.create_dataset<std::complex<double>>("lambda", {m}).write(model.lambda);
        std::vector<int> real(model.real.begin(), model.real.end());
        h5.create_dataset<int>("real", {m}).write(real);
        std::vector<std::complex<double>> r(m * n * n);
        for (std::size_t t = 0; t < m; ++t)
          for (std::size_t i = 0; i < n; ++i)
            for (std::size_t j = 0; j < n; ++j)
              r[(t * n + i) * n + j] = model.residues[t](i, j);
        h5.create_dataset<std::complex<double>>("residues", {m, n, n}).write(r);
        std::vector<double> e(n * n);
        for (std::size_t i = 0; i < n; ++i)
          for (std::size_t j = 0; j < n; ++j)
            e[i * n + j] = model.errors(i, j);
        h5.create_dataset<double>("errors", {n, n}).write(e);
        // G_r, all zero for a model with a real residual pole.
        for (std::size_t i = 0; i < n; ++i)
          for (std::size_t j = 0; j < n; ++j)
            e[i * n + j] = model.instantaneous.size() ? model.instantaneous(i, j) : 0.;
        h5.create_dataset<double>("instantaneous", {n, n}).write(e);
        h5.create_dataset<double>("info", {3})
          .write(std::vector<double>{model.f_max, double(model.identified_modes), model.sum_error});
      });
    }



    std::string
    read_patch_model_key(const std::string &file)
    {
      return base::read_hdf5_stage_key(file, patch_datasets);
    }



    PatchModel
    read_patch_model(const std::string &file)
    {
      if (read_patch_model_key(file).empty())
        throw InputError("patch model file '" + file +
                         "' is missing or incomplete; delete it to recompute it");
      // Read everything, and close the file, before any check can throw:
      // deal.II's HDF5 objects abort when destroyed during an exception.
      PatchModel                        model;
      std::vector<int>                  real;
      std::vector<double>               p, e, info, gr;
      std::vector<std::complex<double>> r;
      {
        dealii::HDF5::File h5(file, dealii::HDF5::File::FileAccessMode::open);
        model.lambda = h5.open_dataset("lambda").read<std::vector<std::complex<double>>>();
        real         = h5.open_dataset("real").read<std::vector<int>>();
        p            = h5.open_dataset("points").read<std::vector<double>>();
        e            = h5.open_dataset("errors").read<std::vector<double>>();
        r            = h5.open_dataset("residues").read<std::vector<std::complex<double>>>();
        info         = h5.open_dataset("info").read<std::vector<double>>();
        gr           = h5.open_dataset("instantaneous").read<std::vector<double>>();
      }
      const std::size_t m = model.lambda.size(), n = p.size() / 3;
      if (real.size() != m || e.size() != n * n || r.size() != m * n * n || info.size() != 3 ||
          gr.size() != n * n)
        throw InputError("patch model file '" + file +
                         "' has inconsistent dataset sizes; delete it to recompute it");
      const auto finite = [](const auto &values) {
        return std::all_of(values.begin(), values.end(), [](const auto &x) {
          return std::isfinite(std::abs(x));
        });
      };
      if (!finite(model.lambda) || !finite(r) || !finite(gr) || !finite(p) || !finite(info))
        throw InputError("patch model file '" + file +
                         "' holds a value that is not a finite number; delete it to recompute it");
      model.real.assign(real.begin(), real.end());
      for (std::size_t i = 0; i < n; ++i)
        model.points.push_back({{p[3 * i], p[3 * i + 1], p[3 * i + 2]}});
      model.errors.resize(n, n);
      for (std::size_t i = 0; i < n; ++i)
        for (std::size_t j = 0; j < n; ++j)
          model.errors(i, j) = e[i * n + j];
      model.residues.assign(m, Eigen::MatrixXcd(n, n));
      for (std::size_t t = 0; t < m; ++t)
        for (std::size_t i = 0; i < n; ++i)
          for (std::size_t j = 0; j < n; ++j)
            model.residues[t](i, j) = r[(t * n + i) * n + j];
      if (std::any_of(gr.begin(), gr.end(), [](const double x) {
            return x != 0.;
          }))
        model.instantaneous =
          Eigen::Map<const Eigen::Matrix<double, Eigen::Dynamic, Eigen::Dynamic, Eigen::RowMajor>>(
            gr.data(), n, n);
      model.f_max            = info[0];
      model.identified_modes = static_cast<unsigned int>(info[1]);
      model.sum_error        = info[2];
      return model;
    }
  } // namespace modal
} // namespace greentread

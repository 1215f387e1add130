#include <greentread/base/exceptions.h>
#include <greentread/base/hdf5_writer.h>
#include <greentread/synthesis/mode_synthesis.h>

#include <deal.II/base/hdf5.h>

#include <Eigen/Eigenvalues>

#include <algorithm>
#include <cmath>

// The modal model as a patch model (rank one per mode) and its HDF5 file,
// modal_model.h5 (layout in write_modal_model()).

namespace greentread
{
  namespace synthesis
  {
    modal::PatchModel
    to_patch_model(const ModeSynthesis   &synthesis,
                   const Eigen::MatrixXd &errors,
                   const double           f_max)
    {
      modal::PatchModel  model;
      const Eigen::Index P      = synthesis.shapes.cols();
      model.points              = synthesis.points;
      model.residual_relaxation = synthesis.residual_relaxation;
      if (!(model.residual_relaxation > 0.))
        model.instantaneous = synthesis.instantaneous;
      model.errors           = errors.size() ? errors : Eigen::MatrixXd::Zero(P, P);
      model.f_max            = f_max;
      model.identified_modes = synthesis.n_modes();
      std::vector<Eigen::Index> rows;
      for (unsigned int k = 0; k < synthesis.n_modes(); ++k)
        {
          const double w  = 2. * M_PI * synthesis.frequency_hz(k);
          double       xi = synthesis.damping_ratio(k);
          if (!(w > 0.) || !std::isfinite(w) || !(xi >= 0.) || !std::isfinite(xi))
            throw NumericalError("mode " + std::to_string(k) + ": natural frequency " +
                                 format_short(synthesis.frequency_hz(k)) +
                                 " Hz and damping ratio " + format_short(xi) +
                                 "; a mode needs a frequency > 0 and a damping ratio >= 0");
          const bool complex_shape =
            synthesis.shapes_imag.size() && synthesis.shapes_imag.row(k).cwiseAbs().maxCoeff() > 0.;
          if (complex_shape && !(xi < 1.))
            throw NumericalError("mode " + std::to_string(k) +
                                 ": a complex shape with a damping "
                                 "ratio of " +
                                 format_short(xi) + "; a complex shape needs < 1");
          if (xi < 1.)
            {
              const double wd = w * std::sqrt(1. - xi * xi);
              model.lambda.emplace_back(-xi * w, wd);
              model.real.push_back(false);
              model.factor.push_back(1. / std::complex<double>(0., 2. * wd));
              rows.push_back(k);
              continue;
            }
          // Over-critical: 1 / ((s - l1)(s - l2)) = (1/(s-l1) - 1/(s-l2)) / (l1 - l2).
          xi              = std::max(xi, 1. + 1e-6);
          const double r  = w * std::sqrt(xi * xi - 1.);
          const double l1 = -xi * w + r, l2 = -xi * w - r;
          model.lambda.emplace_back(l1, 0.);
          model.lambda.emplace_back(l2, 0.);
          model.real.insert(model.real.end(), {true, true});
          model.factor.emplace_back(1. / (l1 - l2));
          model.factor.emplace_back(-1. / (l1 - l2));
          rows.insert(rows.end(), {Eigen::Index(k), Eigen::Index(k)});
        }
      model.shapes.resize(rows.size(), P);
      for (std::size_t t = 0; t < rows.size(); ++t)
        model.shapes.row(t) = synthesis.shapes.row(rows[t]);
      if (synthesis.shapes_imag.size())
        {
          model.shapes_imag.resize(rows.size(), P);
          for (std::size_t t = 0; t < rows.size(); ++t)
            model.shapes_imag.row(t) = synthesis.shapes_imag.row(rows[t]);
        }
      if (model.residual_relaxation > 0.)
        {
          // G_r / (1 + s beta) = sum_i (d_i / beta) v_i v_i^T / (s + 1 / beta).
          const double                                         beta = model.residual_relaxation;
          const Eigen::SelfAdjointEigenSolver<Eigen::MatrixXd> eigen(synthesis.instantaneous);
          const Eigen::Index                                   m = model.shapes.rows();
          model.shapes.conservativeResize(m + P, P);
          if (model.shapes_imag.size())
            model.shapes_imag.conservativeResizeLike(Eigen::MatrixXd::Zero(m + P, P));
          for (Eigen::Index i = 0; i < P; ++i)
            {
              const double d          = std::max(eigen.eigenvalues()(i), 0.);
              model.shapes.row(m + i) = std::sqrt(d) * eigen.eigenvectors().col(i).transpose();
              model.lambda.emplace_back(-1. / beta, 0.);
              model.real.push_back(true);
              model.factor.emplace_back(1. / beta);
            }
        }
      return model;
    }



    modal::PatchModel
    full_form(const modal::PatchModel &model)
    {
      if (!model.is_rank_one())
        return model;
      modal::PatchModel full = model;
      full.shapes.resize(0, 0);
      full.shapes_imag.resize(0, 0);
      full.factor.clear();
      for (unsigned int k = 0; k < model.n_terms(); ++k)
        {
          Eigen::VectorXcd phi = model.shapes.row(k).transpose().cast<std::complex<double>>();
          if (model.shapes_imag.size())
            phi.imag() = model.shapes_imag.row(k).transpose();
          full.residues.push_back(model.factor[k] * (phi * phi.transpose()));
        }
      return full;
    }



    namespace
    {
      const std::vector<std::string> modal_datasets = {
        "frequency_hz",  "damping_ratio",       "wavenumber", "shapes",    "shapes_imag",
        "instantaneous", "residual_relaxation", "points",     "dispersion"};
    } // namespace



    void
    write_modal_model(const std::filesystem::path &file,
                      const ModeSynthesis         &synthesis,
                      const base::ParameterRecord &record,
                      const std::string           &stage_key)
    {
      write_hdf5_stage(file, synthesis.points, record, stage_key, [&](base::Hdf5Writer &h5) {
        const std::size_t   m = synthesis.n_modes(), n = synthesis.shapes.cols();
        std::vector<double> f(synthesis.frequency_hz.data(), synthesis.frequency_hz.data() + m);
        h5.create_dataset<double>("frequency_hz", {m}).write(f);
        f.assign(synthesis.damping_ratio.data(), synthesis.damping_ratio.data() + m);
        h5.create_dataset<double>("damping_ratio", {m}).write(f);
        std::vector<double> k(m, 0.);
        for (std::size_t i = 0; i < std::min(m, synthesis.wavenumber.size()); ++i)
          k[i] = synthesis.wavenumber[i];
        h5.create_dataset<double>("wavenumber", {m}).write(k);
        std::vector<double> values(m * n);
        for (std::size_t i = 0; i < m; ++i)
          for (std::size_t j = 0; j < n; ++j)
            values[i * n + j] = synthesis.shapes(i, j);
        h5.create_dataset<double>("shapes", {m, n}).write(values);
        for (std::size_t i = 0; i < m; ++i)
          for (std::size_t j = 0; j < n; ++j)
            values[i * n + j] = synthesis.shapes_imag.size() ? synthesis.shapes_imag(i, j) : 0.;
        h5.create_dataset<double>("shapes_imag", {m, n}).write(values);
        values.resize(n * n);
        for (std::size_t i = 0; i < n; ++i)
          for (std::size_t j = 0; j < n; ++j)
            values[i * n + j] = synthesis.instantaneous(i, j);
        h5.create_dataset<double>("instantaneous", {n, n}).write(values);
        h5.create_dataset<double>("residual_relaxation", {1})
          .write(std::vector<double>{synthesis.residual_relaxation});
        values.clear();
        const auto &d = synthesis.dispersion;
        for (std::size_t w = 0; w < d.frequency_hz.size(); ++w)
          for (Eigen::Index b = 0; b < d.frequency_hz[w].size(); ++b)
            values.insert(values.end(),
                          {double(w), double(b), d.frequency_hz[w](b), d.damping_ratio[w](b)});
        h5.create_dataset<double>("dispersion", {values.size() / 4, 4}).write(values);
      });
    }



    std::string
    read_modal_model_key(const std::string &file)
    {
      return base::read_hdf5_stage_key(file, modal_datasets);
    }



    ModeSynthesis
    read_modal_model(const std::string &file)
    {
      if (read_modal_model_key(file).empty())
        throw InputError("modal model file '" + file +
                         "' is missing or incomplete; delete it to recompute it");
      // Read everything, and close the file, before any check can throw:
      // deal.II's HDF5 objects abort when destroyed during an exception.
      std::vector<double> f, xi, k, shapes, imag, gr, relaxation, p, d;
      {
        dealii::HDF5::File h5(file, dealii::HDF5::File::FileAccessMode::open);
        f          = h5.open_dataset("frequency_hz").read<std::vector<double>>();
        xi         = h5.open_dataset("damping_ratio").read<std::vector<double>>();
        k          = h5.open_dataset("wavenumber").read<std::vector<double>>();
        shapes     = h5.open_dataset("shapes").read<std::vector<double>>();
        imag       = h5.open_dataset("shapes_imag").read<std::vector<double>>();
        gr         = h5.open_dataset("instantaneous").read<std::vector<double>>();
        relaxation = h5.open_dataset("residual_relaxation").read<std::vector<double>>();
        p          = h5.open_dataset("points").read<std::vector<double>>();
        d          = h5.open_dataset("dispersion").read<std::vector<double>>();
      }
      const std::size_t m = f.size(), n = p.size() / 3;
      if (xi.size() != m || k.size() != m || shapes.size() != m * n || imag.size() != m * n ||
          gr.size() != n * n || relaxation.size() != 1 || p.size() != 3 * n || d.size() % 4 != 0)
        throw InputError("modal model file '" + file +
                         "' has inconsistent dataset sizes; delete it to recompute it");
      for (const auto *values : {&f, &xi, &shapes, &imag, &gr, &relaxation, &p, &d})
        if (!std::all_of(values->begin(), values->end(), [](const double x) {
              return std::isfinite(x);
            }))
          throw InputError("modal model file '" + file +
                           "' holds a value that is not a finite number; delete it to "
                           "recompute it");
      ModeSynthesis s;
      s.frequency_hz        = Eigen::Map<const Eigen::VectorXd>(f.data(), m);
      s.damping_ratio       = Eigen::Map<const Eigen::VectorXd>(xi.data(), m);
      s.residual_relaxation = relaxation[0];
      s.shapes =
        Eigen::Map<const Eigen::Matrix<double, Eigen::Dynamic, Eigen::Dynamic, Eigen::RowMajor>>(
          shapes.data(), m, n);
      if (std::any_of(imag.begin(), imag.end(), [](const double x) {
            return x != 0.;
          }))
        {
          s.shapes_imag = Eigen::Map<
            const Eigen::Matrix<double, Eigen::Dynamic, Eigen::Dynamic, Eigen::RowMajor>>(
            imag.data(), m, n);
          for (std::size_t i = 0; i < m; ++i)
            if (!(xi[i] < 1.) && s.shapes_imag.row(i).cwiseAbs().maxCoeff() > 0.)
              throw InputError("modal model file '" + file + "': mode " + std::to_string(i) +
                               " has a complex shape and a damping ratio of " +
                               format_short(xi[i]) + "; allowed: below 1");
        }
      s.instantaneous =
        Eigen::Map<const Eigen::Matrix<double, Eigen::Dynamic, Eigen::Dynamic, Eigen::RowMajor>>(
          gr.data(), n, n);
      for (std::size_t i = 0; i < n; ++i)
        s.points.push_back({{p[3 * i], p[3 * i + 1], p[3 * i + 2]}});
      for (const double x : k)
        s.wavenumber.push_back(static_cast<unsigned int>(x));
      for (std::size_t r = 0; r < d.size() / 4; ++r)
        {
          const auto w = static_cast<std::size_t>(d[4 * r]);
          if (s.dispersion.frequency_hz.size() <= w)
            {
              s.dispersion.frequency_hz.resize(w + 1);
              s.dispersion.damping_ratio.resize(w + 1);
            }
          auto &fw = s.dispersion.frequency_hz[w];
          auto &xw = s.dispersion.damping_ratio[w];
          fw.conservativeResize(fw.size() + 1);
          xw.conservativeResize(xw.size() + 1);
          fw(fw.size() - 1) = d[4 * r + 2];
          xw(xw.size() - 1) = d[4 * r + 3];
        }
      return s;
    }
  } // namespace synthesis
} // namespace greentread

#include <greentread/base/exceptions.h>
#include <greentread/contact/contact_grid.h>
#include <greentread/contact/projected_cg.h>
#include <greentread/contact/tread_block.h>

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <tuple>

namespace greentread
{
  namespace contact
  {
    ContactGrid::ContactGrid(const std::vector<std::array<double, 3>> &coarse_points,
                             const unsigned int                        subdivisions_,
                             const ElasticLayer                       &layer,
                             const bool                                matrix_free_,
                             const bool                                candidate_set_,
                             const double                              tolerance_)
        : subdivisions(subdivisions_)
        , matrix_free(matrix_free_)
        , candidate_set(candidate_set_)
        , tolerance(tolerance_)
        , n_coarse(coarse_points.size())
    {
      if (subdivisions == 0)
        throw InputError("parameter 'Contact grid/Subdivisions' = 0; allowed: 1 to 32");
      if (!(tolerance > 0. && tolerance <= 1e-3))
        throw InputError("parameter 'Contact grid/Tolerance' = " + format_number(tolerance) +
                         "; allowed: above 0 and up to 1e-3");
      // The coarse lattice: its distinct x and y, increasing.
      std::vector<double> xs, ys;
      const auto          add = [](std::vector<double> &v, const double x) {
        if (std::none_of(v.begin(), v.end(), [&](double y) {
              return std::abs(x - y) < 1e-7;
            }))
          v.push_back(x);
      };
      for (const auto &p : coarse_points)
        {
          add(xs, p[0]);
          add(ys, p[1]);
        }
      std::sort(xs.begin(), xs.end());
      std::sort(ys.begin(), ys.end());
      cnx = xs.size();
      cny = ys.size();
      if (cnx * cny != n_coarse || cnx < 2 || cny < 2)
        throw InputError("contact grid: the Green's functions' " + std::to_string(n_coarse) +
                         " points are not a lattice of at least 2 x 2 (" + std::to_string(cnx) +
                         " x " + std::to_string(cny) + ")");
      coarse_dx        = (xs.back() - xs.front()) / (cnx - 1);
      coarse_dy        = (ys.back() - ys.front()) / (cny - 1);
      const auto index = [](const std::vector<double> &v, const double x) {
        return static_cast<unsigned int>(std::min_element(v.begin(), v.end(),
                                                          [&](double a, double b) {
                                                            return std::abs(a - x) <
                                                                   std::abs(b - x);
                                                          }) -
                                         v.begin());
      };
      coarse_at.assign(n_coarse, 0);
      for (unsigned int c = 0; c < n_coarse; ++c)
        coarse_at[index(xs, coarse_points[c][0]) * cny + index(ys, coarse_points[c][1])] = c;

      const unsigned int s = subdivisions;
      nx                   = s * cnx;
      ny                   = s * cny;
      dx                   = coarse_dx / s;
      dy                   = coarse_dy / s;
      points.resize(nx * ny);
      coarse_of.resize(nx * ny);
      for (unsigned int ix = 0; ix < nx; ++ix)
        for (unsigned int iy = 0; iy < ny; ++iy)
          {
            const unsigned int c = coarse_at[(ix / s) * cny + iy / s];
            const unsigned int p = ix * ny + iy;
            coarse_of[p]         = c;
            points[p]            = {{coarse_points[c][0] + ((ix % s) + 0.5 - 0.5 * s) * dx,
                                     coarse_points[c][1] + ((iy % s) + 0.5 - 0.5 * s) * dy,
                                     coarse_points[c][2]}};
          }
      if (s == 1)
        return;

      // The layer between the contact rectangles, on a period 4 thicknesses
      // wider on each side than the patch, and its part that acts on and
      // returns the variation within the coarse cells: (I - P) L_f (I - P),
      // P the mean over each cell.
      const double margin = 4. * layer.thickness;
      layer_product       = std::make_shared<const convolution::LatticeConvolution>(
        layer_lattice_kernel(layer, dx, dy, nx, ny, margin));
      if (matrix_free)
        {
          tabulate_cell_sums();
          return;
        }
      local                        = layer_product->dense();
      const auto remove_cell_means = [&](Eigen::MatrixXd &m) {
        const double n_cell = static_cast<double>(s) * s;
        for (Eigen::Index j = 0; j < m.cols(); ++j)
          m.col(j) -= expand(Eigen::VectorXd(gather(m.col(j)) / n_cell));
      };
      remove_cell_means(local);
      local.transposeInPlace();
      remove_cell_means(local);
      local = 0.5 * (local + local.transpose()).eval();
    }



    Eigen::MatrixXd
    ContactGrid::expand(const Eigen::MatrixXd &coarse) const
    {
      const unsigned int n = points.size();
      Eigen::MatrixXd    m(n, n);
      for (unsigned int q = 0; q < n; ++q)
        for (unsigned int p = 0; p < n; ++p)
          m(p, q) = coarse(coarse_of[p], coarse_of[q]);
      return m;
    }



    Eigen::VectorXd
    ContactGrid::expand(const Eigen::VectorXd &coarse) const
    {
      Eigen::VectorXd v(points.size());
      for (unsigned int p = 0; p < points.size(); ++p)
        v[p] = coarse[coarse_of[p]];
      return v;
    }



    Eigen::VectorXd
    ContactGrid::gather(const Eigen::VectorXd &fine) const
    {
      Eigen::VectorXd v;
      gather(fine, v);
      return v;
    }



    void
    ContactGrid::gather(const Eigen::VectorXd &fine, Eigen::VectorXd &coarse) const
    {
      // Row by row of the lattice, each cell's s contiguous points at once.
      const unsigned int s = subdivisions;
      coarse.setZero(n_coarse);
      for (unsigned int ix = 0; ix < nx; ++ix)
        {
          const double       *row   = fine.data() + std::size_t(ix) * ny;
          const unsigned int *cells = coarse_at.data() + std::size_t(ix / s) * cny;
          for (unsigned int cy = 0; cy < cny; ++cy)
            {
              double sum = 0.;
              for (unsigned int a = 0; a < s; ++a)
                sum += row[cy * s + a];
              coarse[cells[cy]] += sum;
            }
        }
    }



    Eigen::MatrixXd
    ContactGrid::compliance(const Eigen::MatrixXd &coarse_static) const
    {
      Eigen::MatrixXd m = expand(coarse_static);
      if (local.size() > 0)
        m += local;
      return m;
    }



    void
    ContactGrid::add_local(const Eigen::VectorXd &x, Eigen::VectorXd &y) const
    {
      if (!layer_product)
        return;
      add_product(nullptr, x, y);
    }



    void
    ContactGrid::apply(const Eigen::MatrixXd &coarse,
                       const Eigen::VectorXd &x,
                       Eigen::VectorXd       &y) const
    {
      y.setZero(points.size());
      add_product(&coarse, x, y);
    }



    void
    ContactGrid::add_product(const Eigen::MatrixXd *coarse,
                             const Eigen::VectorXd &x,
                             Eigen::VectorXd       &y) const
    {
      // y += A^T (M A x - A L v / s^2) + L v, v = (I - P) x: the cells'
      // sums taken once each way, the work vectors the thread's own.
      thread_local Eigen::VectorXd x_cells, y_cells, v, v_cells;
      const unsigned int           n = points.size();
      gather(x, x_cells);
      if (coarse != nullptr)
        y_cells.noalias() = *coarse * x_cells;
      else
        y_cells.setZero(n_coarse);
      if (layer_product)
        {
          const double inverse = 1. / (double(subdivisions) * subdivisions);
          v.resize(n);
          for (unsigned int p = 0; p < n; ++p)
            v[p] = x[p] - inverse * x_cells[coarse_of[p]];
          layer_product->apply(v, v);
          gather(v, v_cells);
          y_cells -= inverse * v_cells;
          for (unsigned int p = 0; p < n; ++p)
            y[p] += v[p] + y_cells[coarse_of[p]];
        }
      else
        for (unsigned int p = 0; p < n; ++p)
          y[p] += y_cells[coarse_of[p]];
    }



    void
    ContactGrid::tabulate_cell_sums()
    {
      const Eigen::MatrixXd &T = layer_product->kernel_values();
      const int              s = subdivisions, mx = nx, my = ny;
      // The kernel at any offset, and the sums of file contact_grid.h.
      const auto kernel = [&](const int u, const int v) {
        return T(std::abs(u), std::abs(v));
      };
      cell_sums.setZero(2 * mx - 1, 2 * my - 1);
      for (int u = 1 - mx; u <= mx - s; ++u)
        for (int v = 1 - my; v <= my - s; ++v)
          {
            double sum = 0.;
            for (int a = 0; a < s; ++a)
              for (int b = 0; b < s; ++b)
                sum += kernel(u + a, v + b);
            cell_sums(u + mx - 1, v + my - 1) = sum / (s * s);
          }
      const int cx = cnx, cy = cny;
      cell_pair_sums.setZero(2 * cx - 1, 2 * cy - 1);
      for (int u = 1 - cx; u < cx; ++u)
        for (int v = 1 - cy; v < cy; ++v)
          {
            double sum = 0.;
            for (int a = 0; a < s; ++a)
              for (int b = 0; b < s; ++b)
                sum += cell_sums(u * s - a + mx - 1, v * s - b + my - 1);
            cell_pair_sums(u + cx - 1, v + cy - 1) = sum / (s * s);
          }
    }



    void
    ContactGrid::block(const Eigen::MatrixXd           &coarse,
                       const std::vector<unsigned int> &rows,
                       const std::vector<unsigned int> &columns,
                       Eigen::MatrixXd                 &out) const
    {
      const Eigen::Index m = rows.size(), n = columns.size();
      out.resize(m, n);
      for (Eigen::Index l = 0; l < n; ++l)
        for (Eigen::Index k = 0; k < m; ++k)
          out(k, l) = coarse(coarse_of[rows[k]], coarse_of[columns[l]]);
      if (!layer_product)
        return;
      if (cell_sums.size() == 0)
        throw InputError("contact grid: block() needs the matrix-free grid's cell sums");
      // Each point's lattice and cell indices, once.
      struct Where
      {
        int x, y, cx, cy;
      };
      const int  s = subdivisions, mx = nx, my = ny, cx0 = cnx - 1, cy0 = cny - 1;
      const auto where = [&](const std::vector<unsigned int> &set) {
        std::vector<Where> w(set.size());
        for (std::size_t k = 0; k < set.size(); ++k)
          {
            const int x = set[k] / ny, y = set[k] % ny;
            w[k] = {x, y, x / s, y / s};
          }
        return w;
      };
      const std::vector<Where> r = where(rows), c = where(columns);
      const Eigen::MatrixXd   &T = layer_product->kernel_values();
      // (I - P) L (I - P), P the mean over each coarse cell:
      // L_ij - (P L)_ij - (P L)_ji + (P L P)_ij.
      for (Eigen::Index l = 0; l < n; ++l)
        {
          const Where j = c[l];
          double     *o = out.col(l).data();
          for (Eigen::Index k = 0; k < m; ++k)
            {
              const Where i = r[k];
              o[k] += T(std::abs(i.x - j.x), std::abs(i.y - j.y)) -
                      cell_sums(i.cx * s - j.x + mx - 1, i.cy * s - j.y + my - 1) -
                      cell_sums(j.cx * s - i.x + mx - 1, j.cy * s - i.y + my - 1) +
                      cell_pair_sums(i.cx - j.cx + cx0, i.cy - j.cy + cy0);
            }
        }
    }



    Eigen::VectorXd
    ContactGrid::reporting_weights(const double along, const double across) const
    {
      const double a = along > 0. ? along : coarse_dx, b = across > 0. ? across : coarse_dy;
      // The grid's extent: the rectangles' outer edges.
      const auto extent = [&](const unsigned axis, const double width) {
        double e = 0.;
        for (const auto &p : points)
          e = std::max(e, std::abs(p[axis]) + 0.5 * width);
        return e;
      };
      for (const auto &[name, size, half] :
           {std::tuple<const char *, double, double>{"along", a, extent(0, dx)},
            {"across", b, extent(1, dy)}})
        if (!(size <= 2. * half * (1. + 1e-9)) || !std::isfinite(size))
          throw InputError("parameter 'Spectra/Reporting cell " + std::string(name) +
                           "' = " + format_number(1e3 * size) +
                           " mm; allowed: 0 (the Green's-function "
                           "rectangle) or up to the contact patch's " +
                           format_number(1e3 * 2. * half) + " mm");
      // The overlap of each contact rectangle with the cell |x| <= a / 2,
      // |y| <= b / 2.
      // (A rectangle that only touches the cell, to round-off, gets none.)
      const auto overlap = [](const double centre, const double width, const double half) {
        const double o =
          std::min(centre + 0.5 * width, half) - std::max(centre - 0.5 * width, -half);
        return o > 1e-9 * width ? o : 0.;
      };
      Eigen::VectorXd w(points.size());
      for (unsigned int p = 0; p < points.size(); ++p)
        w[p] = overlap(points[p][0], dx, 0.5 * a) * overlap(points[p][1], dy, 0.5 * b) / (a * b);
      return w;
    }



    namespace
    {
      /// The convolution of the contact points of a grid with s > 1.
      class GridConvolution : public convolution::PatchConvolution
      {
      public:
        GridConvolution(std::unique_ptr<convolution::PatchConvolution> coarse_,
                        const ContactGrid                             &grid_,
                        const BlockState                              *blocks_)
            : convolution::PatchConvolution(grid_.n_points(), coarse_->time_step())
            , coarse(std::move(coarse_))
            , grid(grid_)
            , blocks(blocks_)
            , coarse_load(coarse->n_points())
        {
          // The scene refuses finite blocks with the pivoting solver.
          if (blocks != nullptr && !grid.matrix_free)
            throw std::logic_error("make_grid_convolution: finite blocks need the matrix-free "
                                   "solver");
          const convolution::PatchInfluence &c = coarse->influence();
          psi.instantaneous                    = true;
          if (grid.matrix_free)
            {
              // The products through the coarse cells and the layer's FFT.
              if (!c.instantaneous)
                throw InputError("'Contact grid/Solver' = projected CG needs a patch model "
                                 "with an instantaneous compliance; allowed with it: 'Patch "
                                 "model/Source' = fe modes");
              const double asymmetry =
                (c.u[2] - c.u[2].transpose()).cwiseAbs().maxCoeff() / c.u[2].cwiseAbs().maxCoeff();
              if (!(asymmetry < 1e-8))
                throw InputError("'Contact grid/Solver' = projected CG needs a reciprocal "
                                 "patch model; this one's instantaneous compliance is "
                                 "asymmetric by " +
                                 format_short(asymmetry) +
                                 " (relative); allowed: 'Patch model/Source' = fe modes, or "
                                 "'Contact grid/Solver' = pivoting");
              // The solve's operator is symmetric: the end compliance's
              // symmetric part (it differs by the asymmetry checked above).
              end_compliance = 0.5 * (c.u[2] + c.u[2].transpose());
              psi.tolerance  = grid.tolerance;
              psi.add_u      = [this](const unsigned int g, const Eigen::VectorXd &x,
                                 Eigen::VectorXd &y) {
                if (g == 2)
                  {
                    // The step's end, the solve's operator: in one pass.
                    grid.add_product(&end_compliance, x, y);
                    if (blocks != nullptr)
                      blocks->add_product(x, y);
                    return;
                  }
                const Eigen::VectorXd xc = grid.gather(x);
                if (xc.cwiseAbs().maxCoeff() > 0.)
                  y += grid.expand(Eigen::VectorXd(coarse->influence().u[g] * xc));
              };
              if (grid.candidate_set)
                psi.block_u = [this](const std::vector<unsigned int> &rows,
                                     const std::vector<unsigned int> &columns,
                                     Eigen::MatrixXd                 &out) {
                  grid.block(end_compliance, rows, columns, out);
                  if (blocks != nullptr)
                    blocks->add_block(rows, columns, out);
                };
              // The blocks move: the solve's step length from the largest
              // norm over positions round the pattern.
              if (blocks != nullptr)
                psi.end_norm =
                  blocks->largest_norm([&](const Eigen::VectorXd &x, Eigen::VectorXd &y) {
                    grid.apply(end_compliance, x, y);
                  });
              return;
            }
          for (unsigned int g = 0; g < 4; ++g)
            {
              psi.u[g] = grid.expand(c.u[g]);
              psi.v[g] = grid.expand(c.v[g]);
            }
          // The local term acts on the force at the step's end, which is
          // continuous (linear over the step from its start value): its rate
          // is the change over the step.
          psi.u[2] += grid.local;
          psi.v[2] += grid.local / dt;
          psi.v[1] -= grid.local / dt;
        }

        void
        history(Eigen::VectorXd &u, Eigen::VectorXd &v) override
        {
          coarse->history(uc, vc);
          u = grid.expand(uc);
          v = grid.expand(vc);
        }

        void
        history_u(Eigen::VectorXd &u) override
        {
          coarse->history_u(uc);
          u = grid.expand(uc);
        }

        void
        advance(const convolution::PatchLoad &load) override
        {
          for (unsigned int g = 0; g < 4; ++g)
            coarse_load.component[g] = grid.gather(load.component[g]);
          coarse->advance(coarse_load);
        }

        void
        preload(const Eigen::VectorXd &q0) override
        {
          coarse->preload(grid.gather(q0));
        }

        std::string
        name() const override
        {
          return coarse->name() + " on " + std::to_string(grid.subdivisions) + " x " +
                 std::to_string(grid.subdivisions) + " contact points per cell";
        }

      private:
        std::unique_ptr<convolution::PatchConvolution> coarse;
        const ContactGrid                             &grid;
        const BlockState                              *blocks;
        convolution::PatchLoad                         coarse_load;
        Eigen::VectorXd                                uc, vc;
        /// The symmetric part of the coarse end compliance (matrix-free).
        Eigen::MatrixXd end_compliance;
      };
    } // namespace



    std::unique_ptr<convolution::PatchConvolution>
    make_grid_convolution(std::unique_ptr<convolution::PatchConvolution> coarse,
                          const ContactGrid                             &grid,
                          const BlockState                              *blocks)
    {
      if (grid.subdivisions == 1 && !grid.matrix_free && blocks == nullptr)
        return coarse;
      return std::make_unique<GridConvolution>(std::move(coarse), grid, blocks);
    }



    StaticContact
    start_grid_contact(const ContactGrid      &grid,
                       const Eigen::MatrixXd  &coarse_static,
                       const Eigen::VectorXd  &tread,
                       const PatchRoadHeights &road,
                       const RollingSetup     &setup,
                       const BlockState       *blocks)
    {
      if (!grid.matrix_free && blocks == nullptr)
        return start_contact(grid.compliance(coarse_static), tread, road, setup);
      if (!grid.matrix_free)
        throw std::logic_error("start_grid_contact: finite blocks need the matrix-free solver");
      const SymmetricOperator W = [&](const Eigen::VectorXd &x, Eigen::VectorXd &y) {
        grid.apply(coarse_static, x, y);
        if (blocks != nullptr)
          blocks->add_product(x, y);
      };
      ProjectedCgOptions options;
      // (The blocks' share is bounded, not measured: road() sets their
      // position only when the solve starts.)
      options.operator_norm = operator_norm(
                                [&](const Eigen::VectorXd &x, Eigen::VectorXd &y) {
                                  grid.apply(coarse_static, x, y);
                                },
                                grid.n_points()) +
                              (blocks != nullptr ? blocks->norm_bound() : 0.);
      Eigen::VectorXd last; // each bisection's solve starts from the last one's forces
      return start_contact(
        [&](const Eigen::VectorXd &c) {
          LcpResult r = solve_lcp_projected_cg(W, c, last, options);
          last        = r.z;
          return r;
        },
        tread, road, setup);
    }
  } // namespace contact
} // namespace greentread

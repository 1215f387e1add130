#include <greentread/base/exceptions.h>
#include <greentread/base/job_runner.h>
#include <greentread/base/output.h>
#include <greentread/base/serial_deal_ii.h>
#include <greentread/contact/projected_cg.h>
#include <greentread/contact/tread_block.h>

#include <Eigen/Eigenvalues>

#include <algorithm>
#include <cmath>
#include <iostream>
#include <map>
#include <sstream>
#include <stdexcept>

// The finite blocks of a tread pattern in the contact grid
// (greentread/contact/tread_block.h): each block shape's table from the
// block's finite-element model (tread_block.cc), and its product with the
// contact points' forces as the pattern moves.

namespace greentread
{
  namespace contact
  {
    BlockCompliance::BlockCompliance(const TreadPattern           &pattern_,
                                     const TreadPatternParameters &parameters,
                                     const ElasticLayer           &tread,
                                     const double                  tread_width,
                                     const double                  mesh_size,
                                     const unsigned int            n_threads,
                                     const bool                    progress)
        : pattern(pattern_)
        , lateral(parameters.lateral_groove_width)
    {
      // TreadPatternParameters refuses finite blocks with another pattern.
      if (parameters.pattern != "blocks")
        throw std::logic_error("BlockCompliance: the pattern is '" + parameters.pattern +
                               "', not blocks");
      if (!(mesh_size > 0.) || !std::isfinite(mesh_size))
        throw InputError("parameter 'Tread pattern/Block mesh size' = " + format_short(mesh_size) +
                         " m; allowed: > 0");
      // The ribs: the tread less the circumferential grooves.
      const double                       w = parameters.circumferential_width;
      std::vector<std::array<double, 2>> grooves;
      for (const double c : parameters.circumferential_centres)
        grooves.push_back({{c - 0.5 * w, c + 0.5 * w}});
      std::sort(grooves.begin(), grooves.end());
      double edge = -0.5 * tread_width;
      for (const auto &g : grooves)
        {
          if (g[0] > edge)
            ribs.push_back({{edge, g[0]}});
          edge = std::max(edge, g[1]);
        }
      if (0.5 * tread_width > edge)
        ribs.push_back({{edge, 0.5 * tread_width}});

      // One table per shape: the blocks' lengths and the ribs' widths.
      TreadBlockGeometry geometry;
      geometry.height = pattern.depth();
      geometry.base   = std::max(0., tread.thickness - pattern.depth());
      // An isolated block: the undertread reaches twice the tread's
      // thickness beyond it, so that neither model feels its walls' images.
      geometry.margin_along = geometry.margin_across = 2. * tread.thickness;
      std::map<std::array<long long, 2>, unsigned int> known;
      const auto                                       key = [](const double x) {
        return std::llround(x * 1e9);
      };
      shape_of.resize(pattern.pitches().size());
      for (std::size_t k = 0; k < pattern.pitches().size(); ++k)
        for (const auto &rib : ribs)
          {
            const double length = pattern.pitches()[k] - lateral, width = rib[1] - rib[0];
            const auto [found, added] = known.emplace(
              std::array<long long, 2>{{key(length), key(width)}}, unsigned(shape_list.size()));
            if (added)
              {
                Shape shape;
                shape.length = length;
                shape.width  = width;
                shape.nx     = std::max(1u, unsigned(std::ceil(length / mesh_size * (1. - 1e-9))));
                shape.ny     = std::max(1u, unsigned(std::ceil(width / mesh_size * (1. - 1e-9))));
                shape_list.push_back(shape);
              }
            shape_of[k].push_back(found->second);
          }

      // Each shape's tables, on threads (each a result of its own: the same
      // whatever their number), deal.II's own set-up serial
      // (base/serial_deal_ii.h).
      const base::SerialDealII serial;
      base::for_each_index(
        shape_list.size(), std::max(1u, n_threads), [&](const std::size_t i, unsigned int) {
          Shape                    &shape = shape_list[i];
          std::vector<TopRectangle> table;
          const double              a = shape.length / shape.nx, b = shape.width / shape.ny;
          for (unsigned int x = 0; x < shape.nx; ++x)
            for (unsigned int y = 0; y < shape.ny; ++y)
              table.push_back({x * a, (x + 1) * a, y * b, (y + 1) * b});
          table.push_back({0., shape.length, 0., shape.width});
          TreadBlockGeometry block_geometry = geometry;
          block_geometry.length             = shape.length;
          block_geometry.width              = shape.width;
          const Eigen::MatrixXd block =
            TreadBlock(block_geometry, tread, table, mesh_size, true).compliance();
          const Eigen::MatrixXd layer =
            TreadBlock(block_geometry, tread, table, mesh_size, false).compliance();
          const Eigen::Index n = table.size() - 1;
          shape.delta          = block.topLeftCorner(n, n) - layer.topLeftCorner(n, n);
          // Kept in single precision (Shape::single), and the double table
          // made the same operator.
          shape.single = shape.delta.cast<float>();
          shape.delta  = shape.single.cast<double>();
          shape.norm =
            Eigen::SelfAdjointEigenSolver<Eigen::MatrixXd>(shape.delta, Eigen::EigenvaluesOnly)
              .eigenvalues()
              .cwiseAbs()
              .maxCoeff();
          shape.top_block    = block(n, n);
          shape.top_layer    = layer(n, n);
          shape.corner_block = block(0, 0);
          shape.corner_layer = layer(0, 0);
          if (progress)
            {
              std::ostringstream line;
              line << "  Tread block " << format_printf("%.2f", 1e3 * shape.length) << " x "
                   << format_printf("%.2f", 1e3 * shape.width) << " mm: " << shape.nx << " x "
                   << shape.ny << " table; its whole top "
                   << format_printf("%.2f", shape.top_block / shape.top_layer) << " and its corner "
                   << format_printf("%.2f", shape.corner_block / shape.corner_layer)
                   << " times as compliant as the endless layer\n";
              std::cout << line.str() << std::flush;
            }
        });
    }



    std::string
    BlockCompliance::summary() const
    {
      std::ostringstream out;
      out << shape_list.size() << " block shapes on " << ribs.size()
          << " ribs; under a uniform load on the whole top, "
          << "the blocks are";
      double low = INFINITY, high = 0.;
      for (const Shape &s : shape_list)
        {
          low  = std::min(low, s.top_block / s.top_layer);
          high = std::max(high, s.top_block / s.top_layer);
        }
      out << ' ' << format_printf("%.2f", low) << " to " << format_printf("%.2f", high)
          << " times as compliant as the endless layer";
      return out.str();
    }



    BlockState::BlockState(const BlockCompliance                    &blocks_,
                           const std::vector<std::array<double, 3>> &points_)
        : blocks(blocks_)
        , points(points_)
        , slot(points_.size(), -1)
        , cell(points_.size(), 0)
    {
      // The lattice's spacing, and from it the most points a table
      // rectangle a x b can hold.
      const auto spacing = [&](const unsigned int axis) {
        std::vector<double> x;
        for (const auto &p : points)
          x.push_back(p[axis]);
        std::sort(x.begin(), x.end());
        double gap = INFINITY;
        for (std::size_t k = 1; k < x.size(); ++k)
          if (x[k] - x[k - 1] > 1e-12)
            gap = std::min(gap, x[k] - x[k - 1]);
        return gap;
      };
      const double dx = spacing(0), dy = spacing(1);
      for (const BlockCompliance::Shape &s : blocks.shape_list)
        {
          const double most =
            (std::floor(s.length / s.nx / dx) + 1.) * (std::floor(s.width / s.ny / dy) + 1.);
          bound = std::max(bound, most * s.norm);
        }
    }



    void
    BlockState::set_position(const double s)
    {
      const std::size_t n_ribs = blocks.ribs.size();
      slot_shape.clear();
      slot_block.clear();
      for (std::size_t q = 0; q < points.size(); ++q)
        {
          slot[q]                  = -1;
          const auto [k, position] = blocks.pattern.locate(s + points[q][0]);
          const double along       = position - blocks.lateral;
          if (along < 0.)
            continue;
          const double y = points[q][1];
          std::size_t  r = 0;
          while (r < n_ribs && !(y >= blocks.ribs[r][0] && y < blocks.ribs[r][1]))
            ++r;
          if (r == n_ribs)
            continue;
          // The block's slot: a handful of blocks are in the patch.
          const std::size_t block = k * n_ribs + r;
          std::size_t       b     = 0;
          while (b < slot_block.size() && slot_block[b] != block)
            ++b;
          if (b == slot_block.size())
            {
              slot_block.push_back(block);
              slot_shape.push_back(blocks.shape_of[k][r]);
            }
          const BlockCompliance::Shape &shape = blocks.shape_list[slot_shape[b]];
          const unsigned int            i =
            std::min(shape.nx - 1, unsigned(along / shape.length * double(shape.nx)));
          const unsigned int j = std::min(
            shape.ny - 1, unsigned((y - blocks.ribs[r][0]) / shape.width * double(shape.ny)));
          slot[q] = int(b);
          cell[q] = i * shape.ny + j;
        }
      load.resize(slot_shape.size());
      response.resize(slot_shape.size());
      loaded.resize(slot_shape.size());
    }



    void
    BlockState::add_product(const Eigen::VectorXd &x, Eigen::VectorXd &y) const
    {
      // The forces are zero but at the few points in contact: each block's
      // table loads, and its response from the loaded rectangles' columns,
      // read in single precision and summed in double.
      std::fill(loaded.begin(), loaded.end(), false);
      for (std::size_t q = 0; q < points.size(); ++q)
        if (slot[q] >= 0 && x[q] != 0.)
          {
            const int b = slot[q];
            if (!loaded[b])
              {
                load[b].setZero(blocks.shape_list[slot_shape[b]].delta.rows());
                loaded[b] = true;
              }
            load[b][cell[q]] += x[q];
          }
      for (std::size_t b = 0; b < slot_shape.size(); ++b)
        if (loaded[b])
          {
            const Eigen::MatrixXf &delta = blocks.shape_list[slot_shape[b]].single;
            const Eigen::Index     N     = delta.rows();
            response[b].setZero(N);
            double *r = response[b].data();
            for (Eigen::Index I = 0; I < N; ++I)
              if (load[b][I] != 0.)
                {
                  const double a = load[b][I];
                  const float *c = delta.data() + I * N;
#pragma omp simd
                  for (Eigen::Index k = 0; k < N; ++k)
                    r[k] += a * double(c[k]);
                }
          }
      for (std::size_t q = 0; q < points.size(); ++q)
        if (slot[q] >= 0 && loaded[slot[q]])
          y[q] += response[slot[q]][cell[q]];
    }



    double
    BlockState::largest_norm(
      const std::function<void(const Eigen::VectorXd &, Eigen::VectorXd &)> &W,
      const unsigned int                                                     n_positions) const
    {
      BlockState   probe(*this);
      const double period = blocks.pattern.circumference(), golden = 0.5 * (std::sqrt(5.) - 1.);
      double       largest = 0.;
      for (unsigned int k = 0; k < n_positions; ++k)
        {
          const double fraction = k * golden - std::floor(k * golden);
          probe.set_position(fraction * period);
          largest = std::max(largest, operator_norm(
                                        [&](const Eigen::VectorXd &x, Eigen::VectorXd &y) {
                                          W(x, y);
                                          probe.add_product(x, y);
                                        },
                                        points.size()));
        }
      return 1.05 * largest;
    }



    void
    BlockState::add_block(const std::vector<unsigned int> &rows,
                          const std::vector<unsigned int> &columns,
                          Eigen::MatrixXd                 &out) const
    {
      for (std::size_t l = 0; l < columns.size(); ++l)
        {
          const int b = slot[columns[l]];
          if (b < 0)
            continue;
          const Eigen::MatrixXd &delta = blocks.shape_list[slot_shape[b]].delta;
          const unsigned int     J     = cell[columns[l]];
          for (std::size_t k = 0; k < rows.size(); ++k)
            if (slot[rows[k]] == b)
              out(k, l) += delta(cell[rows[k]], J);
        }
    }
  } // namespace contact
} // namespace greentread

#include <greentread/base/exceptions.h>
#include <greentread/base/mesh_ids.h>
#include <greentread/base/output.h>
#include <greentread/contact/tread_block.h>

#include <deal.II/base/quadrature_lib.h>
#include <deal.II/dofs/dof_handler.h>
#include <deal.II/dofs/dof_tools.h>
#include <deal.II/fe/fe_q.h>
#include <deal.II/fe/fe_system.h>
#include <deal.II/fe/fe_values.h>
#include <deal.II/grid/grid_generator.h>
#include <deal.II/lac/affine_constraints.h>
#include <deal.II/lac/dynamic_sparsity_pattern.h>
#include <deal.II/lac/sparse_direct.h>
#include <deal.II/lac/sparse_matrix.h>
#include <deal.II/lac/vector.h>
#include <deal.II/numerics/vector_tools.h>

#include <algorithm>
#include <cmath>
#include <set>

namespace greentread
{
  namespace contact
  {
    using namespace dealii;

    struct TreadBlock::Model
    {
      Triangulation<3>          mesh;
      FESystem<3>               fe{FE_Q<3>(2), 3};
      DoFHandler<3>             dofs;
      AffineConstraints<double> constraints;
      SparsityPattern           pattern;
      SparseMatrix<double>      stiffness;
      /// One load vector per rectangle: a unit force spread uniformly over it.
      std::vector<Vector<double>> loads;
    };



    namespace
    {
      void
      check_size(const char *what, const double value, const bool zero_allowed = false)
      {
        if (!std::isfinite(value) || value < 0. || (!zero_allowed && value == 0.))
          throw InputError("tread block: " + std::string(what) + " = " + format_short(value) +
                           " m; allowed: " + (zero_allowed ? ">= 0" : "> 0"));
      }

      /// Steps of at most @p cell between sorted, distinct breakpoints.
      std::vector<double>
      steps_through(std::vector<double> points, const double cell)
      {
        std::sort(points.begin(), points.end());
        std::vector<double> kept;
        for (const double p : points)
          if (kept.empty() || p - kept.back() > 1e-9 * cell)
            kept.push_back(p);
        std::vector<double> steps;
        for (std::size_t k = 1; k < kept.size(); ++k)
          {
            const double       length = kept[k] - kept[k - 1];
            const unsigned int n = std::max(1u, unsigned(std::ceil(length / cell * (1. - 1e-9))));
            steps.insert(steps.end(), n, length / n);
          }
        return steps;
      }

      /// The isotropic elasticity tensor's action: sigma(eps).
      SymmetricTensor<2, 3>
      stress(const SymmetricTensor<2, 3> &strain, const double lambda, const double mu)
      {
        return lambda * trace(strain) * unit_symmetric_tensor<3>() + 2. * mu * strain;
      }
    } // namespace



    TreadBlock::TreadBlock(const TreadBlockGeometry        &shape,
                           const ElasticLayer              &rubber,
                           const std::vector<TopRectangle> &rectangles,
                           const double                     cell_size)
        : model(std::make_unique<Model>())
    {
      check_size("length", shape.length);
      check_size("width", shape.width);
      check_size("height", shape.height);
      check_size("base", shape.base);
      check_size("margin", shape.margin, true);
      check_size("cell size", cell_size);
      ElasticLayer material = rubber;
      material.thickness    = shape.height + shape.base;
      layer_compliance(material, 1.); // checks E and nu
      const double top = shape.base + shape.height;

      // The mesh: a box over block and margins, its lines through the block's
      // sides and every rectangle's edges, less the cells beside the block
      // above the undertread.
      std::vector<double> xs{-shape.margin, 0., shape.length, shape.length + shape.margin};
      std::vector<double> ys{-shape.margin, 0., shape.width, shape.width + shape.margin};
      for (const TopRectangle &r : rectangles)
        {
          const double tiny = 0.01 * cell_size;
          if (!(r.x0 >= 0. && r.x1 <= shape.length && r.y0 >= 0. && r.y1 <= shape.width &&
                r.x1 - r.x0 >= tiny && r.y1 - r.y0 >= tiny))
            throw InputError("tread block: a loaded rectangle [" + format_short(r.x0) + ", " +
                             format_short(r.x1) + "] x [" + format_short(r.y0) + ", " +
                             format_short(r.y1) + "] m; allowed: inside the block's top (" +
                             format_short(shape.length) + " x " + format_short(shape.width) +
                             " m), at least " + format_short(tiny) + " m across");
          xs.insert(xs.end(), {r.x0, r.x1});
          ys.insert(ys.end(), {r.y0, r.y1});
        }
      const std::vector<std::vector<double>> steps = {
        steps_through(xs, cell_size), steps_through(ys, cell_size),
        steps_through({0., shape.base, top}, cell_size)};
      const double cells = double(steps[0].size()) * steps[1].size() * steps[2].size();
      if (cells > 2e5)
        throw InputError("tread block: a cell size of " + format_short(cell_size) + " m makes " +
                         format_short(cells) + " cells; allowed: at most 200000");
      Triangulation<3> box;
      GridGenerator::subdivided_hyper_rectangle(
        box, steps, Point<3>(-shape.margin, -shape.margin, 0.),
        Point<3>(shape.length + shape.margin, shape.width + shape.margin, top));
      std::set<Triangulation<3>::active_cell_iterator> beside;
      for (const auto &cell : box.active_cell_iterators())
        {
          const Point<3> c = cell->center();
          if (c[2] > shape.base &&
              (c[0] < 0. || c[0] > shape.length || c[1] < 0. || c[1] > shape.width))
            beside.insert(cell);
        }
      if (beside.empty())
        model->mesh.copy_triangulation(box);
      else
        GridGenerator::create_triangulation_with_removed_cells(box, beside, model->mesh);
      for (const auto &cell : model->mesh.active_cell_iterators())
        {
          cell->set_material_id(fe::tread_id);
          for (const auto &face : cell->face_iterators())
            if (face->at_boundary())
              {
                const Point<3> c = face->center();
                const double   e = 1e-9 * top;
                if (std::abs(c[2]) < e)
                  face->set_boundary_id(geometry::rim_seat);
                else if (std::abs(c[0] + shape.margin) < e ||
                         std::abs(c[0] - shape.length - shape.margin) < e)
                  face->set_boundary_id(tread_block_side_x);
                else if (std::abs(c[1] + shape.margin) < e ||
                         std::abs(c[1] - shape.width - shape.margin) < e)
                  face->set_boundary_id(tread_block_side_y);
                else
                  face->set_boundary_id(geometry::free_surface);
              }
        }

      // The stiffness, the belt's faces clamped.
      Model &m = *model;
      m.dofs.reinit(m.mesh);
      m.dofs.distribute_dofs(m.fe);
      VectorTools::interpolate_boundary_values(m.dofs, geometry::rim_seat,
                                               Functions::ZeroFunction<3>(3), m.constraints);
      for (const unsigned int axis : {0u, 1u})
        {
          ComponentMask normal(3, false);
          normal.set(axis, true);
          VectorTools::interpolate_boundary_values(
            m.dofs, axis == 0 ? tread_block_side_x : tread_block_side_y,
            Functions::ZeroFunction<3>(3), m.constraints, normal);
        }
      m.constraints.close();
      DynamicSparsityPattern dsp(m.dofs.n_dofs());
      DoFTools::make_sparsity_pattern(m.dofs, dsp, m.constraints, false);
      m.pattern.copy_from(dsp);
      m.stiffness.reinit(m.pattern);
      const double       nu = rubber.poissons_ratio, E = rubber.youngs_modulus;
      const double       mu = E / (2. * (1. + nu)), lambda = E * nu / ((1. + nu) * (1. - 2. * nu));
      const QGauss<3>    quadrature(3);
      FEValues<3>        values(m.fe, quadrature, update_gradients | update_JxW_values);
      const unsigned int n = m.fe.n_dofs_per_cell();
      FullMatrix<double> local(n, n);
      std::vector<types::global_dof_index> indices(n);
      const FEValuesExtractors::Vector     u(0);
      std::vector<SymmetricTensor<2, 3>>   strain(n);
      for (const auto &cell : m.dofs.active_cell_iterators())
        {
          values.reinit(cell);
          local = 0.;
          for (unsigned int q = 0; q < quadrature.size(); ++q)
            {
              for (unsigned int i = 0; i < n; ++i)
                strain[i] = values[u].symmetric_gradient(i, q);
              for (unsigned int i = 0; i < n; ++i)
                {
                  const SymmetricTensor<2, 3> s = stress(strain[i], lambda, mu);
                  for (unsigned int j = 0; j <= i; ++j)
                    local(i, j) += (s * strain[j]) * values.JxW(q);
                }
            }
          for (unsigned int i = 0; i < n; ++i)
            for (unsigned int j = i + 1; j < n; ++j)
              local(i, j) = local(j, i);
          cell->get_dof_indices(indices);
          m.constraints.distribute_local_to_global(local, indices, m.stiffness);
        }

      // The loads: on the top faces inside each rectangle, a pressure of one
      // over its area pushing down (a unit force into the block).
      const QGauss<2> face_quadrature(3);
      FEFaceValues<3> face_values(m.fe, face_quadrature, update_values | update_JxW_values);
      Vector<double>  local_load(n);
      m.loads.assign(rectangles.size(), Vector<double>(m.dofs.n_dofs()));
      std::vector<double> covered(rectangles.size(), 0.);
      for (const auto &cell : m.dofs.active_cell_iterators())
        for (unsigned int f = 0; f < cell->n_faces(); ++f)
          {
            const auto face = cell->face(f);
            if (!face->at_boundary() || std::abs(face->center()[2] - top) > 1e-9 * top)
              continue;
            const Point<3> c = face->center();
            for (std::size_t r = 0; r < rectangles.size(); ++r)
              {
                const TopRectangle &R = rectangles[r];
                if (c[0] < R.x0 || c[0] > R.x1 || c[1] < R.y0 || c[1] > R.y1)
                  continue;
                const double area = (R.x1 - R.x0) * (R.y1 - R.y0);
                face_values.reinit(cell, f);
                local_load = 0.;
                for (unsigned int q = 0; q < face_quadrature.size(); ++q)
                  for (unsigned int i = 0; i < n; ++i)
                    local_load[i] +=
                      face_values[u].value(i, q)[2] * (-1. / area) * face_values.JxW(q);
                covered[r] += face->measure();
                cell->get_dof_indices(indices);
                m.constraints.distribute_local_to_global(local_load, indices, m.loads[r]);
              }
          }
      for (std::size_t r = 0; r < rectangles.size(); ++r)
        {
          const TopRectangle &R    = rectangles[r];
          const double        area = (R.x1 - R.x0) * (R.y1 - R.y0);
          if (std::abs(covered[r] - area) > 1e-9 * area)
            throw NumericalError("tread block: rectangle " + std::to_string(r) + " covers " +
                                 format_short(covered[r]) + " m^2 of faces for its " +
                                 format_short(area) + " m^2");
        }
    }



    TreadBlock::~TreadBlock() = default;



    Eigen::MatrixXd
    TreadBlock::compliance() const
    {
      const Model        &m = *model;
      SparseDirectUMFPACK inverse;
      inverse.initialize(m.stiffness);
      const std::size_t n = m.loads.size();
      Eigen::MatrixXd   C(n, n);
      Vector<double>    x;
      for (std::size_t i = 0; i < n; ++i)
        {
          x = m.loads[i];
          inverse.solve(x);
          m.constraints.distribute(x);
          // The load pushes down (-z): the displacement into the block is
          // -u_z, and the load vectors carry that sign already.
          for (std::size_t j = 0; j < n; ++j)
            C(i, j) = m.loads[j] * x;
        }
      for (Eigen::Index i = 0; i < C.rows(); ++i)
        for (Eigen::Index j = 0; j < C.cols(); ++j)
          if (!std::isfinite(C(i, j)))
            throw NumericalError("tread block: the compliance between rectangles " +
                                 std::to_string(i) + " and " + std::to_string(j) +
                                 " is not finite");
      return 0.5 * (C + C.transpose());
    }



    const Triangulation<3> &
    TreadBlock::triangulation() const
    {
      return model->mesh;
    }



    unsigned int
    TreadBlock::n_dofs() const
    {
      return model->dofs.n_dofs();
    }
  } // namespace contact
} // namespace greentread

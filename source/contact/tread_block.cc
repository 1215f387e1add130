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
#include <deal.II/lac/sparse_matrix.h>
#include <deal.II/lac/vector.h>
#include <deal.II/numerics/vector_tools.h>

#include <Eigen/CholmodSupport>
#include <Eigen/SparseCore>

#include <algorithm>
#include <cmath>
#include <mutex>
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
      /// One load vector per rectangle, a unit force spread uniformly over
      /// it: the columns of a sparse matrix, as (dof, rectangle, value).
      std::vector<Eigen::Triplet<double>> loads;
      Eigen::Index                        n_loads = 0;
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

      /// Steps of at most @p cell between sorted, distinct breakpoints; of
      /// at most twice that outside [@p inner_low, @p inner_high] (the
      /// margins, away from the loads).
      std::vector<double>
      steps_through(std::vector<double> points,
                    const double        cell,
                    const double        inner_low  = -INFINITY,
                    const double        inner_high = INFINITY)
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
            const double       mid    = 0.5 * (kept[k] + kept[k - 1]);
            const double       size   = mid > inner_low && mid < inner_high ? cell : 2. * cell;
            const unsigned int n = std::max(1u, unsigned(std::ceil(length / size * (1. - 1e-9))));
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
                           const double                     cell_size,
                           const bool                       grooves)
        : model(std::make_unique<Model>())
    {
      check_size("length", shape.length);
      check_size("width", shape.width);
      check_size("height", shape.height);
      check_size("base", shape.base, true);
      check_size("margin along", shape.margin_along, true);
      check_size("margin across", shape.margin_across, true);
      check_size("cell size", cell_size);
      ElasticLayer material = rubber;
      material.thickness    = shape.height + shape.base;
      layer_compliance(material, 1.); // checks E and nu
      const double top = shape.base + shape.height;

      // The mesh: a box over block and margins, its lines through the block's
      // sides and every rectangle's edges, less the cells beside the block
      // above the undertread.
      const double        mx = shape.margin_along, my = shape.margin_across;
      std::vector<double> xs{-mx, 0., shape.length, shape.length + mx};
      std::vector<double> ys{-my, 0., shape.width, shape.width + my};
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
        steps_through(xs, cell_size, 0., shape.length),
        steps_through(ys, cell_size, 0., shape.width),
        steps_through({0., shape.base, top}, cell_size)};
      const double cells = double(steps[0].size()) * steps[1].size() * steps[2].size();
      if (cells > 2e5)
        throw InputError("tread block: a cell size of " + format_short(cell_size) + " m makes " +
                         format_short(cells) + " cells; allowed: at most 200000");
      Triangulation<3> box;
      GridGenerator::subdivided_hyper_rectangle(box, steps, Point<3>(-mx, -my, 0.),
                                                Point<3>(shape.length + mx, shape.width + my, top));
      std::set<Triangulation<3>::active_cell_iterator> beside;
      for (const auto &cell : box.active_cell_iterators())
        {
          const Point<3> c = cell->center();
          if (grooves && c[2] > shape.base &&
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
                else if (std::abs(c[0] + mx) < e || std::abs(c[0] - shape.length - mx) < e)
                  face->set_boundary_id(tread_block_side_x);
                else if (std::abs(c[1] + my) < e || std::abs(c[1] - shape.width - my) < e)
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
      m.n_loads = rectangles.size();
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
                for (unsigned int i = 0; i < n; ++i)
                  if (local_load[i] != 0. && !m.constraints.is_constrained(indices[i]))
                    m.loads.emplace_back(indices[i], r, local_load[i]);
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
      // K X = B for every rectangle's load at once: K is symmetric positive
      // definite (the constrained rows keep their diagonal), so CHOLMOD's
      // supernodal Cholesky factor, with its fill-reducing ordering, and one
      // solve with all the loads as columns. (UMFPACK's LU, one load at a
      // time, took 76 s for 273 loads on 44,000 unknowns.)
      const Model                        &m = *model;
      const Eigen::Index                  n = m.dofs.n_dofs();
      std::vector<Eigen::Triplet<double>> entries;
      entries.reserve(m.stiffness.n_nonzero_elements());
      for (const auto &entry : m.stiffness)
        if (entry.row() >= entry.column()) // the lower triangle
          entries.emplace_back(entry.row(), entry.column(), entry.value());
      Eigen::SparseMatrix<double> K(n, n);
      K.setFromTriplets(entries.begin(), entries.end());
      // One factorisation at a time: two at once on two threads (CHOLMOD's
      // dense kernels through OpenBLAS) both reported matrices that are not
      // positive definite; one at a time, OpenBLAS's threads serve it.
      static std::mutex                                                      one_at_a_time;
      const std::lock_guard<std::mutex>                                      lock(one_at_a_time);
      Eigen::CholmodSupernodalLLT<Eigen::SparseMatrix<double>, Eigen::Lower> factor(K);
      if (factor.info() != Eigen::Success)
        throw NumericalError("tread block: the stiffness matrix (" + std::to_string(n) +
                             " unknowns) is not positive definite");
      // The loads are sparse (the faces of one rectangle each), and the
      // solves go 64 loads at a time, so that memory holds the factor and
      // little more (all at once, two blocks of 1.33 mm cells on two
      // threads exhausted 24 GB).
      const Eigen::Index          r = m.n_loads;
      Eigen::SparseMatrix<double> B(n, r);
      B.setFromTriplets(m.loads.begin(), m.loads.end());
      // The load pushes down (-z): the displacement into the block is -u_z,
      // and the load vectors carry that sign already.
      Eigen::MatrixXd C(r, r);
      for (Eigen::Index j = 0; j < r; j += 64)
        {
          const Eigen::Index    width = std::min<Eigen::Index>(64, r - j);
          const Eigen::MatrixXd X     = factor.solve(Eigen::MatrixXd(B.middleCols(j, width)));
          C.middleCols(j, width)      = B.transpose() * X;
        }
      if (!C.allFinite())
        throw NumericalError("tread block: a compliance between its rectangles is not finite");
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

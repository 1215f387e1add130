#include <greentread/base/exceptions.h>
#include <greentread/fe/elastic_model.h>

#include <deal.II/base/quadrature_lib.h>
#include <deal.II/dofs/dof_renumbering.h>
#include <deal.II/dofs/dof_tools.h>
#include <deal.II/fe/fe_q.h>
#include <deal.II/fe/fe_values.h>
#include <deal.II/grid/grid_tools.h>
#include <deal.II/lac/dynamic_sparsity_pattern.h>
#include <deal.II/lac/full_matrix.h>
#include <deal.II/lac/sparse_direct.h>
#include <deal.II/numerics/data_out.h>
#include <deal.II/numerics/data_postprocessor.h>
#include <deal.II/numerics/vector_tools.h>

#include <greentread/base/output.h>

#include <cmath>

namespace greentread
{
  namespace fe
  {
    using namespace dealii;

    double
    von_mises(const SymmetricTensor<2, 3> &sigma)
    {
      const SymmetricTensor<2, 3> s = deviator(sigma);
      return std::sqrt(1.5 * (s * s));
    }



    ElasticModel::ElasticModel(const Triangulation<3>                 &triangulation_,
                               const std::map<unsigned int, Material> &materials_,
                               const unsigned int                      degree)
        : triangulation(triangulation_)
        , materials(materials_)
        , fe(FE_Q<3>(degree), 3)
        , map(degree)
        , dofs(triangulation_)
    {
      for (const auto &cell : triangulation.active_cell_iterators())
        if (materials.count(cell->material_id()) == 0)
          throw InputError("the mesh has cells of material id " +
                           std::to_string(cell->material_id()) + ", which has no material");
      dofs.distribute_dofs(fe);
      DoFRenumbering::Cuthill_McKee(dofs);
      DynamicSparsityPattern dsp(dofs.n_dofs());
      DoFTools::make_sparsity_pattern(dofs, dsp);
      pattern.copy_from(dsp);
      for (auto *A : {&K, &M, &C, &C_mass, &Kp})
        A->reinit(pattern);
    }



    const Material &
    ElasticModel::material(const unsigned int id) const
    {
      return materials.at(id);
    }



    void
    ElasticModel::assemble()
    {
      K      = 0.;
      M      = 0.;
      C      = 0.;
      C_mass = 0.;
      const QGauss<3>                      quadrature(fe.degree + 1);
      FEValues<3>                          values(map, fe, quadrature,
                                                  update_values | update_gradients | update_JxW_values |
                                                    update_quadrature_points);
      const FEValuesExtractors::Vector     u(0);
      const unsigned int                   n = fe.n_dofs_per_cell();
      FullMatrix<double>                   k(n, n), m(n, n), c(n, n), c_mass(n, n);
      std::vector<types::global_dof_index> indices(n);
      std::vector<SymmetricTensor<2, 3>>   strain(n), stress_of(n);
      std::vector<Tensor<1, 3>>            shape(n);

      for (const auto &cell : dofs.active_cell_iterators())
        {
          values.reinit(cell);
          k                   = 0.;
          m                   = 0.;
          const Material &mat = material(cell->material_id());
          for (unsigned int q = 0; q < quadrature.size(); ++q)
            {
              const SymmetricTensor<4, 3> stiffness = mat.stiffness_at(values.quadrature_point(q));
              const double                dx        = values.JxW(q);
              for (unsigned int i = 0; i < n; ++i)
                {
                  strain[i]    = values[u].symmetric_gradient(i, q);
                  stress_of[i] = stiffness * strain[i];
                  shape[i]     = values[u].value(i, q);
                }
              for (unsigned int i = 0; i < n; ++i)
                for (unsigned int j = 0; j <= i; ++j)
                  {
                    k(i, j) += (stress_of[i] * strain[j]) * dx;
                    m(i, j) += mat.density * (shape[i] * shape[j]) * dx;
                  }
            }
          for (unsigned int i = 0; i < n; ++i)
            for (unsigned int j = 0; j < i; ++j)
              {
                k(j, i) = k(i, j);
                m(j, i) = m(i, j);
              }
          for (unsigned int i = 0; i < n; ++i)
            for (unsigned int j = 0; j < n; ++j)
              {
                c_mass(i, j) = mat.alpha * m(i, j);
                c(i, j)      = c_mass(i, j) + mat.beta * k(i, j);
              }
          cell->get_dof_indices(indices);
          K.add(indices, k);
          M.add(indices, m);
          C.add(indices, c);
          C_mass.add(indices, c_mass);
        }
    }



    Vector<double>
    ElasticModel::traction_load(const types::boundary_id                             boundary,
                                const std::function<Tensor<1, 3>(const Point<3> &)> &t) const
    {
      Vector<double>                       f(dofs.n_dofs());
      const QGauss<2>                      quadrature(fe.degree + 1);
      FEFaceValues<3>                      values(map, fe, quadrature,
                                                  update_values | update_JxW_values | update_quadrature_points |
                                                    update_normal_vectors);
      const FEValuesExtractors::Vector     u(0);
      std::vector<types::global_dof_index> indices(fe.n_dofs_per_cell());
      Vector<double>                       local(fe.n_dofs_per_cell());
      for (const auto &cell : dofs.active_cell_iterators())
        for (const unsigned int face : cell->face_indices())
          if (cell->face(face)->at_boundary() && cell->face(face)->boundary_id() == boundary)
            {
              values.reinit(cell, face);
              local = 0.;
              for (unsigned int q = 0; q < quadrature.size(); ++q)
                {
                  const Tensor<1, 3> traction = t(values.quadrature_point(q));
                  for (unsigned int i = 0; i < fe.n_dofs_per_cell(); ++i)
                    local(i) += values[u].value(i, q) * traction * values.JxW(q);
                }
              cell->get_dof_indices(indices);
              for (unsigned int i = 0; i < fe.n_dofs_per_cell(); ++i)
                f(indices[i]) += local(i);
            }
      return f;
    }



    Vector<double>
    ElasticModel::pressure_load(const types::boundary_id boundary, const double pressure) const
    {
      Vector<double>                       f(dofs.n_dofs());
      const QGauss<2>                      quadrature(fe.degree + 1);
      FEFaceValues<3>                      values(map, fe, quadrature,
                                                  update_values | update_JxW_values | update_normal_vectors);
      const FEValuesExtractors::Vector     u(0);
      std::vector<types::global_dof_index> indices(fe.n_dofs_per_cell());
      for (const auto &cell : dofs.active_cell_iterators())
        for (const unsigned int face : cell->face_indices())
          if (cell->face(face)->at_boundary() && cell->face(face)->boundary_id() == boundary)
            {
              values.reinit(cell, face);
              cell->get_dof_indices(indices);
              for (unsigned int q = 0; q < quadrature.size(); ++q)
                for (unsigned int i = 0; i < fe.n_dofs_per_cell(); ++i)
                  f(indices[i]) +=
                    values[u].value(i, q) * (-pressure * values.normal_vector(q)) * values.JxW(q);
            }
      return f;
    }



    void
    ElasticModel::add_clamp(const types::boundary_id   boundary,
                            AffineConstraints<double> &constraints) const
    {
      VectorTools::interpolate_boundary_values(map, dofs, boundary, Functions::ZeroFunction<3>(3),
                                               constraints);
    }



    void
    ElasticModel::add_rotational_periodicity(const types::boundary_id   first,
                                             const types::boundary_id   second,
                                             const double               angle,
                                             AffineConstraints<double> &constraints) const
    {
      FullMatrix<double> R(3, 3);
      R(0, 0)           = std::cos(angle);
      R(0, 1)           = -std::sin(angle);
      R(1, 0)           = std::sin(angle);
      R(1, 1)           = std::cos(angle);
      R(2, 2)           = 1.;
      const auto rotate = [&](const Point<3> &p) {
        return Point<3>(R(0, 0) * p[0] + R(0, 1) * p[1], R(1, 0) * p[0] + R(1, 1) * p[1], p[2]);
      };
      const auto center = [](const auto &face) {
        Point<3> c;
        for (unsigned int v = 0; v < face->n_vertices(); ++v)
          c += face->vertex(v) / double(face->n_vertices());
        return c;
      };
      struct Face
      {
        DoFHandler<3>::active_cell_iterator cell;
        unsigned int                        face;
        Point<3>                            center;
      };
      std::vector<Face> firsts, seconds;
      double            size = 0.;
      for (const auto &cell : dofs.active_cell_iterators())
        for (const unsigned int f : cell->face_indices())
          if (cell->face(f)->at_boundary())
            {
              size = std::max(size, cell->face(f)->diameter());
              if (cell->face(f)->boundary_id() == first)
                firsts.push_back({cell, f, center(cell->face(f))});
              else if (cell->face(f)->boundary_id() == second)
                seconds.push_back({cell, f, center(cell->face(f))});
            }
      if (firsts.size() != seconds.size())
        throw NumericalError("rotational periodicity: the two periodic boundaries have " +
                             std::to_string(firsts.size()) + " and " +
                             std::to_string(seconds.size()) + " faces; their meshes must match");
      for (const auto &a : firsts)
        {
          const Point<3> target = rotate(a.center);
          const Face    *match  = nullptr;
          for (const auto &b : seconds)
            if (b.center.distance(target) < 1e-6 * size)
              match = &b;
          if (!match)
            throw NumericalError("rotational periodicity: the face at (" +
                                 format_short(a.center[0]) + ", " + format_short(a.center[1]) +
                                 ", " + format_short(a.center[2]) +
                                 ") has no partner on the "
                                 "other side rotated by " +
                                 format_short(angle) +
                                 " rad: the "
                                 "periodic faces of the mesh do not match");
          // Match vertices ignoring the coordinate most normal to the faces.
          const auto         face2     = match->cell->face(match->face);
          const Tensor<1, 3> normal    = cross_product_3d(face2->vertex(1) - face2->vertex(0),
                                                          face2->vertex(2) - face2->vertex(0));
          unsigned int       direction = 0;
          for (unsigned int d = 1; d < 3; ++d)
            if (std::abs(normal[d]) > std::abs(normal[direction]))
              direction = d;
          std::bitset<3> orientation;
          if (!GridTools::orthogonal_equality(orientation, a.cell->face(a.face), face2, direction,
                                              Tensor<1, 3>(), R))
            throw NumericalError("rotational periodicity: two faces with matching centres do "
                                 "not match vertex by vertex");
          DoFTools::make_periodicity_constraints(a.cell->face(a.face), face2, constraints,
                                                 ComponentMask(), orientation[0], orientation[1],
                                                 orientation[2], R, std::vector<unsigned int>{0});
        }
    }



    Vector<double>
    ElasticModel::solve_static(const AffineConstraints<double> &constraints,
                               const Vector<double>            &load) const
    {
      DynamicSparsityPattern dsp(dofs.n_dofs());
      DoFTools::make_sparsity_pattern(dofs, dsp);
      constraints.condense(dsp);
      SparsityPattern sp;
      sp.copy_from(dsp);
      SparseMatrix<double> A(sp);
      for (auto entry = K.begin(); entry != K.end(); ++entry)
        A.add(entry->row(), entry->column(), entry->value());
      Vector<double> b = load;
      constraints.condense(A, b);

      SparseDirectUMFPACK solver;
      try
        {
          solver.initialize(A);
        }
      catch (const std::exception &)
        {
          throw NumericalError("the static system K u = f is singular: some rigid-body motion "
                               "is not held (check the clamped boundary and the constraints)");
        }
      Vector<double> u(dofs.n_dofs());
      solver.vmult(u, b);
      Vector<double> residual(dofs.n_dofs());
      A.vmult(residual, u);
      residual -= b;
      const double relative = residual.l2_norm() / std::max(b.l2_norm(), 1e-300);
      if (!(relative < 1e-8))
        throw NumericalError("the static solve K u = f left a relative residual of " +
                             format_short(relative) +
                             ": the system is ill-conditioned (a nearly free motion?)");
      constraints.distribute(u);
      return u;
    }



    SymmetricTensor<2, 3>
    ElasticModel::stress(const Point<3>              &point,
                         const unsigned int           material_id,
                         const SymmetricTensor<2, 3> &strain) const
    {
      return material(material_id).stiffness_at(point) * strain;
    }



    namespace
    {
      /// Kp of one cell from the stress at its quadrature points.
      template <typename Stress>
      void
      add_geometric_stiffness(const DoFHandler<3>  &dofs,
                              const FESystem<3>    &fe,
                              const Mapping<3>     &mapping,
                              SparseMatrix<double> &Kp,
                              const Stress         &stress_at)
      {
        Kp = 0.;
        const QGauss<3>                      quadrature(fe.degree + 1);
        FEValues<3>                          values(mapping, fe, quadrature,
                                                    update_gradients | update_JxW_values | update_quadrature_points);
        const unsigned int                   n = fe.n_dofs_per_cell();
        FullMatrix<double>                   k(n, n);
        std::vector<types::global_dof_index> indices(n);
        std::vector<Tensor<1, 3>>            sigma_grad(n);
        for (const auto &cell : dofs.active_cell_iterators())
          {
            values.reinit(cell);
            k = 0.;
            for (unsigned int q = 0; q < quadrature.size(); ++q)
              {
                const SymmetricTensor<2, 3> sigma = stress_at(cell, values, q);
                for (unsigned int i = 0; i < n; ++i)
                  sigma_grad[i] = sigma * values.shape_grad(i, q);
                for (unsigned int i = 0; i < n; ++i)
                  for (unsigned int j = 0; j < n; ++j)
                    if (fe.system_to_component_index(i).first ==
                        fe.system_to_component_index(j).first)
                      k(i, j) += (sigma_grad[i] * values.shape_grad(j, q)) * values.JxW(q);
              }
            cell->get_dof_indices(indices);
            Kp.add(indices, k);
          }
      }
    } // namespace



    void
    ElasticModel::assemble_geometric_stiffness(const Vector<double> &u)
    {
      const FEValuesExtractors::Vector   disp(0);
      std::vector<SymmetricTensor<2, 3>> strains;
      add_geometric_stiffness(
        dofs, fe, map, Kp, [&](const auto &cell, const FEValues<3> &values, unsigned int q) {
          if (q == 0)
            {
              strains.resize(values.n_quadrature_points);
              values[disp].get_function_symmetric_gradients(u, strains);
            }
          return stress(values.quadrature_point(q), cell->material_id(), strains[q]);
        });
    }



    void
    ElasticModel::assemble_geometric_stiffness(
      const std::function<SymmetricTensor<2, 3>(const Point<3> &)> &prestress)
    {
      add_geometric_stiffness(dofs, fe, map, Kp,
                              [&](const auto &, const FEValues<3> &values, unsigned int q) {
                                return prestress(values.quadrature_point(q));
                              });
    }



    std::map<unsigned int, double>
    ElasticModel::masses() const
    {
      std::map<unsigned int, double> mass;
      const QGauss<3>                quadrature(fe.degree + 1);
      FEValues<3>                    values(map, fe, quadrature, update_JxW_values);
      for (const auto &cell : dofs.active_cell_iterators())
        {
          values.reinit(cell);
          for (unsigned int q = 0; q < quadrature.size(); ++q)
            mass[cell->material_id()] += material(cell->material_id()).density * values.JxW(q);
        }
      return mass;
    }



    double
    ElasticModel::max_von_mises(const Vector<double> &u) const
    {
      const QGauss<3> quadrature(fe.degree + 1);
      FEValues<3>     values(map, fe, quadrature, update_gradients | update_quadrature_points);
      const FEValuesExtractors::Vector   disp(0);
      std::vector<SymmetricTensor<2, 3>> strains(quadrature.size());
      double                             largest = 0.;
      for (const auto &cell : dofs.active_cell_iterators())
        {
          values.reinit(cell);
          values[disp].get_function_symmetric_gradients(u, strains);
          for (unsigned int q = 0; q < quadrature.size(); ++q)
            largest = std::max(largest, von_mises(stress(values.quadrature_point(q),
                                                         cell->material_id(), strains[q])));
        }
      return largest;
    }



    namespace
    {
      /// Von Mises stress and material id at the output points.
      class StressPostprocessor : public DataPostprocessor<3>
      {
      public:
        explicit StressPostprocessor(const ElasticModel &model)
            : model(model)
        {
        }

        void
        evaluate_vector_field(const DataPostprocessorInputs::Vector<3> &inputs,
                              std::vector<Vector<double>>              &computed) const override
        {
          const auto cell = inputs.template get_cell<3>();
          for (unsigned int p = 0; p < inputs.evaluation_points.size(); ++p)
            {
              SymmetricTensor<2, 3> strain;
              for (unsigned int i = 0; i < 3; ++i)
                for (unsigned int j = i; j < 3; ++j)
                  strain[i][j] =
                    0.5 * (inputs.solution_gradients[p][i][j] + inputs.solution_gradients[p][j][i]);
              computed[p](0) =
                von_mises(model.stress(inputs.evaluation_points[p], cell->material_id(), strain));
              computed[p](1) = cell->material_id();
            }
        }

        std::vector<std::string>
        get_names() const override
        {
          return {"von_mises", "material_id"};
        }

        UpdateFlags
        get_needed_update_flags() const override
        {
          return update_gradients | update_quadrature_points;
        }

      private:
        const ElasticModel &model;
      };
    } // namespace



    void
    ElasticModel::write_vtu(const Vector<double> &u, const std::filesystem::path &file) const
    {
      // The postprocessor first: DataOut keeps a pointer to it and must be
      // destroyed before it.
      StressPostprocessor stress_output(*this);
      DataOut<3>          out;
      out.attach_dof_handler(dofs);
      std::vector<std::string> names(3, "displacement");
      std::vector<DataComponentInterpretation::DataComponentInterpretation> kinds(
        3, DataComponentInterpretation::component_is_part_of_vector);
      out.add_data_vector(u, names, DataOut<3>::type_dof_data, kinds);
      out.add_data_vector(u, stress_output);
      out.build_patches(map, fe.degree, DataOut<3>::curved_inner_cells);
      out.set_flags(base::undated_vtk_flags());
      base::AtomicFile vtu(file);
      out.write_vtu(vtu.stream());
      vtu.commit();
    }
  } // namespace fe
} // namespace greentread

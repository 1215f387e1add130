#include <greentread/base/exceptions.h>
#include <greentread/base/mesh_ids.h>
#include <greentread/base/parameters.h>
#include <greentread/fe/harmonic_section.h>

#include <deal.II/base/geometry_info.h>
#include <deal.II/base/quadrature_lib.h>
#include <deal.II/dofs/dof_tools.h>
#include <deal.II/fe/fe_q.h>
#include <deal.II/fe/fe_values.h>

#include <Eigen/SparseCholesky>

#include <array>
#include <cmath>

namespace greentread
{
  namespace fe
  {
    namespace
    {
      using Strain = dealii::SymmetricTensor<2, 3>;
      using Grad   = dealii::Tensor<2, 3>;
      /// Tensor indices of the cylindrical axes (the materials' order).
      constexpr unsigned int R = 0, T = 1, Z = 2;
      /// FE components: radial, axial, circumferential.
      constexpr unsigned int UR = 0, UZ = 1, UT = 2;

      /// The amplitude strains of a shape function of component @p c with
      /// value @p v and gradient (dr, dz) at radius @p r: B_0 and B_1
      /// (source/fe/harmonic_section.h).
      std::array<Strain, 2>
      strains(const unsigned int c,
              const double       v,
              const double       dr,
              const double       dz,
              const double       r)
      {
        Strain e0, e1;
        if (c == UR)
          {
            e0[R][R] = dr;
            e0[T][T] = v / r;
            e0[R][Z] = 0.5 * dz;
            e1[R][T] = -0.5 * v / r;
          }
        else if (c == UZ)
          {
            e0[Z][Z] = dz;
            e0[R][Z] = 0.5 * dr;
            e1[T][Z] = -0.5 * v / r;
          }
        else
          {
            e0[R][T] = 0.5 * (dr - v / r);
            e0[T][Z] = 0.5 * dz;
            e1[T][T] = v / r;
          }
        return {{e0, e1}};
      }

      /// The amplitude displacement gradient (row: component, column:
      /// direction, both in (r, theta, z)), parts G_0 and G_1.
      std::array<Grad, 2>
      gradients(const unsigned int c,
                const double       v,
                const double       dr,
                const double       dz,
                const double       r)
      {
        Grad g0, g1;
        if (c == UR)
          {
            g0[R][R] = dr;
            g0[R][Z] = dz;
            g0[T][T] = v / r;
            g1[R][T] = -v / r;
          }
        else if (c == UZ)
          {
            g0[Z][R] = dr;
            g0[Z][Z] = dz;
            g1[Z][T] = -v / r;
          }
        else
          {
            g0[T][R] = dr;
            g0[T][Z] = dz;
            g0[R][T] = -v / r;
            g1[T][T] = v / r;
          }
        return {{g0, g1}};
      }

      using Triplets = std::vector<Eigen::Triplet<double>>;

      /// The three parts (a, b, c) of a quadratic form in n from the local
      /// products x0_i.x0_j, x0_i.x1_j (+ its transpose), x1_i.x1_j.
      struct LocalQuadratic
      {
        dealii::FullMatrix<double> a, b, c;
        explicit LocalQuadratic(const unsigned int n)
            : a(n, n)
            , b(n, n)
            , c(n, n)
        {
        }
      };

      /// Call @p add(free row, free column, i, j) for every pair of a cell's
      /// DoFs @p local that are both free.
      template <typename Add>
      void
      for_free_pairs(const std::vector<dealii::types::global_dof_index> &local,
                     const std::vector<long>                            &free,
                     const Add                                          &add)
      {
        for (unsigned int i = 0; i < local.size(); ++i)
          for (unsigned int j = 0; j < local.size(); ++j)
            if (free[local[i]] >= 0 && free[local[j]] >= 0)
              add(free[local[i]], free[local[j]], i, j);
      }

      Eigen::SparseMatrix<double>
      to_sparse(const Triplets &t, const unsigned int n)
      {
        Eigen::SparseMatrix<double> m(n, n);
        m.setFromTriplets(t.begin(), t.end());
        return m;
      }

      using Sparse = Eigen::SparseMatrix<double>;

      /**
       * sum_k w_k A_k. The section's matrices are all assembled from the
       * same pairs of unknowns, so they share one pattern, and the sum is
       * then one pass over their values: Eigen's sparse sums, which merge
       * the patterns term by term, took a fifth of the mode search (one
       * K_n - s M per shift) and of the static harmonics. Terms with no
       * entries (Kp before the inflation) are skipped; other patterns take
       * Eigen's sums.
       */
      Sparse
      combine(const std::vector<std::pair<double, const Sparse *>> &terms)
      {
        std::vector<std::pair<double, const Sparse *>> used;
        for (const auto &t : terms)
          if (t.first != 0. && t.second->nonZeros() > 0)
            used.push_back(t);
        if (used.empty())
          return Sparse(terms.front().second->rows(), terms.front().second->cols());
        bool shared = true;
        for (const auto &t : used)
          shared = shared && same_pattern(*t.second, *used.front().second);
        if (!shared)
          {
            Sparse sum = used.front().first * *used.front().second;
            for (std::size_t k = 1; k < used.size(); ++k)
              sum = Sparse(sum + used[k].first * *used[k].second);
            return sum;
          }
        Sparse     sum = *used.front().second;
        double    *v   = sum.valuePtr();
        const auto nnz = sum.nonZeros();
        for (Eigen::Index i = 0; i < nnz; ++i)
          v[i] *= used.front().first;
        for (std::size_t k = 1; k < used.size(); ++k)
          {
            const double  w = used[k].first;
            const double *a = used[k].second->valuePtr();
            for (Eigen::Index i = 0; i < nnz; ++i)
              v[i] += w * a[i];
          }
        return sum;
      }
    } // namespace



    HarmonicSection::HarmonicSection(const dealii::Triangulation<2>         &section,
                                     const std::map<unsigned int, Material> &materials,
                                     const unsigned int                      degree)
        : triangulation(section)
        , materials(materials)
        , fe(dealii::FE_Q<2>(std::max(1u, std::min(degree, 4u))), 3)
        , mapping(1)
        , dofs(section)
    {
      if (degree < 1 || degree > 4)
        throw InputError("parameter 'Geometry/Element degree' = " + std::to_string(degree) +
                         " is not allowed; allowed: 1 to 4 on the section (harmonic route), "
                         "1 or 2 for the 3D cell");
      dofs.distribute_dofs(fe);
      const auto held = dealii::DoFTools::extract_boundary_dofs(
        dofs, dealii::ComponentMask(), {dealii::types::boundary_id(geometry::rim_seat)});
      free.assign(dofs.n_dofs(), -1);
      long n_free = 0;
      for (dealii::types::global_dof_index i = 0; i < dofs.n_dofs(); ++i)
        if (!held.is_element(i))
          free[i] = n_free++;
      assemble();
    }



    void
    HarmonicSection::assemble()
    {
      const unsigned int n = size_t(std::count_if(free.begin(), free.end(), [](long f) {
        return f >= 0;
      }));
      // The 3D cell's Gauss rule (degree + 1 points), so that the two
      // routes differ only by the discretisation along the ring.
      const dealii::QGauss<2>                      quadrature(fe.degree + 1);
      dealii::FEValues<2>                          values(mapping, fe, quadrature,
                                                          dealii::update_values | dealii::update_gradients |
                                                            dealii::update_quadrature_points | dealii::update_JxW_values);
      const unsigned int                           per_cell = fe.n_dofs_per_cell();
      std::vector<dealii::types::global_dof_index> local(per_cell);
      Triplets                                     ka, kb, kc, ca, cb, cc, m, cm;
      std::vector<std::array<Strain, 2>>           eps(per_cell), sig(per_cell);
      for (const auto &cell : dofs.active_cell_iterators())
        {
          const auto found = materials.find(cell->material_id());
          if (found == materials.end())
            throw InputError("the section has material id " + std::to_string(cell->material_id()) +
                             ", which no material defines");
          const Material &mat = found->second;
          values.reinit(cell);
          cell->get_dof_indices(local);
          LocalQuadratic             k(per_cell);
          dealii::FullMatrix<double> mass(per_cell, per_cell);
          for (unsigned int q = 0; q < quadrature.size(); ++q)
            {
              const double r  = values.quadrature_point(q)[0];
              const double dV = r * values.JxW(q);
              for (unsigned int i = 0; i < per_cell; ++i)
                {
                  const unsigned int c = fe.system_to_component_index(i).first;
                  const auto         g = values.shape_grad_component(i, q, c);
                  eps[i] = strains(c, values.shape_value_component(i, q, c), g[0], g[1], r);
                  sig[i] = {{mat.stiffness * eps[i][0], mat.stiffness * eps[i][1]}};
                }
              for (unsigned int i = 0; i < per_cell; ++i)
                for (unsigned int j = 0; j < per_cell; ++j)
                  {
                    k.a(i, j) += (eps[i][0] * sig[j][0]) * dV;
                    k.b(i, j) += (eps[i][0] * sig[j][1] + eps[i][1] * sig[j][0]) * dV;
                    k.c(i, j) += (eps[i][1] * sig[j][1]) * dV;
                    if (fe.system_to_component_index(i).first ==
                        fe.system_to_component_index(j).first)
                      mass(i, j) +=
                        mat.density * values.shape_value(i, q) * values.shape_value(j, q) * dV;
                  }
            }
          for_free_pairs(
            local, free,
            [&](const long fi, const long fj, const unsigned int i, const unsigned int j) {
              ka.emplace_back(fi, fj, k.a(i, j));
              kb.emplace_back(fi, fj, k.b(i, j));
              kc.emplace_back(fi, fj, k.c(i, j));
              ca.emplace_back(fi, fj, mat.beta * k.a(i, j));
              cb.emplace_back(fi, fj, mat.beta * k.b(i, j));
              cc.emplace_back(fi, fj, mat.beta * k.c(i, j));
              m.emplace_back(fi, fj, mass(i, j));
              cm.emplace_back(fi, fj, mat.alpha * mass(i, j));
            });
        }
      K       = {to_sparse(ka, n), to_sparse(kb, n), to_sparse(kc, n)};
      C_beta  = {to_sparse(ca, n), to_sparse(cb, n), to_sparse(cc, n)};
      M       = to_sparse(m, n);
      C_alpha = to_sparse(cm, n);
      Kp      = {Eigen::SparseMatrix<double>(n, n), Eigen::SparseMatrix<double>(n, n),
                 Eigen::SparseMatrix<double>(n, n)};
    }



    Eigen::SparseMatrix<double>
    HarmonicSection::stiffness(const unsigned int n) const
    {
      return shifted_stiffness(n, 0.);
    }



    Eigen::SparseMatrix<double>
    HarmonicSection::shifted_stiffness(const unsigned int n, const double s) const
    {
      const double n1 = n, n2 = n1 * n1;
      return combine(
        {{1., &K.a}, {n1, &K.b}, {n2, &K.c}, {1., &Kp.a}, {n1, &Kp.b}, {n2, &Kp.c}, {-s, &M}});
    }



    Eigen::SparseMatrix<double>
    HarmonicSection::damping(const unsigned int n) const
    {
      const double n1 = n;
      return combine({{1., &C_alpha}, {1., &C_beta.a}, {n1, &C_beta.b}, {n1 * n1, &C_beta.c}});
    }



    std::array<Eigen::SparseMatrix<std::complex<double>>, 3>
    HarmonicSection::dynamic_stiffness(const double omega) const
    {
      using C = std::complex<double>;
      const C    jw(0., omega);
      const auto part = [&](const Eigen::SparseMatrix<double> &k,
                            const Eigen::SparseMatrix<double> &kp,
                            const Eigen::SparseMatrix<double> &c) {
        return Eigen::SparseMatrix<C>(k.cast<C>() + kp.cast<C>() + jw * c.cast<C>());
      };
      auto a = part(K.a, Kp.a, C_beta.a);
      a += Eigen::SparseMatrix<C>(jw * C_alpha.cast<C>() - C(omega * omega) * M.cast<C>());
      return {{a, part(K.b, Kp.b, C_beta.b), part(K.c, Kp.c, C_beta.c)}};
    }



    void
    HarmonicSection::inflate(const double pressure)
    {
      const unsigned int                           n        = size();
      const unsigned int                           per_cell = fe.n_dofs_per_cell();
      std::vector<dealii::types::global_dof_index> local(per_cell);

      // The pressure's load: the traction -p n on the inner surface.
      Eigen::VectorXd         load = Eigen::VectorXd::Zero(n);
      const dealii::QGauss<1> face_quadrature(fe.degree + 2);
      dealii::FEFaceValues<2> face_values(mapping, fe, face_quadrature,
                                          dealii::update_values | dealii::update_normal_vectors |
                                            dealii::update_quadrature_points |
                                            dealii::update_JxW_values);
      for (const auto &cell : dofs.active_cell_iterators())
        for (const unsigned int f : cell->face_indices())
          if (cell->face(f)->at_boundary() &&
              cell->face(f)->boundary_id() == geometry::inner_surface)
            {
              face_values.reinit(cell, f);
              cell->get_dof_indices(local);
              for (unsigned int q = 0; q < face_quadrature.size(); ++q)
                for (unsigned int i = 0; i < per_cell; ++i)
                  {
                    const unsigned int c = fe.system_to_component_index(i).first;
                    if (c == UT || free[local[i]] < 0)
                      continue;
                    load(free[local[i]]) += -pressure * face_values.normal_vector(q)[c] *
                                            face_values.shape_value(i, q) *
                                            face_values.quadrature_point(q)[0] * face_values.JxW(q);
                  }
            }

      Eigen::SimplicialLDLT<Eigen::SparseMatrix<double>> solver(K.a);
      if (solver.info() != Eigen::Success)
        throw NumericalError("the section's inflation: the static stiffness (n = 0) could not "
                             "be factorised; is the section held at its rim seat?");
      const Eigen::VectorXd u = solver.solve(load);
      if (!u.allFinite() || (K.a * u - load).norm() > 1e-8 * load.norm())
        throw NumericalError("the section's inflation: the static solve failed (residual " +
                             format_printf("%.2g", (K.a * u - load).norm() / load.norm()) + ")");

      // Its stress at every quadrature point, and Kp of that prestress.
      const dealii::QGauss<2>          quadrature(fe.degree + 1);
      dealii::FEValues<2>              values(mapping, fe, quadrature,
                                              dealii::update_values | dealii::update_gradients |
                                                dealii::update_quadrature_points | dealii::update_JxW_values);
      Triplets                         pa, pb, pc;
      std::vector<std::array<Grad, 2>> grad(per_cell);
      for (const auto &cell : dofs.active_cell_iterators())
        {
          const Material &mat = materials.at(cell->material_id());
          values.reinit(cell);
          cell->get_dof_indices(local);
          LocalQuadratic kp(per_cell);
          for (unsigned int q = 0; q < quadrature.size(); ++q)
            {
              const double r  = values.quadrature_point(q)[0];
              const double dV = r * values.JxW(q);
              Strain       strain;
              for (unsigned int i = 0; i < per_cell; ++i)
                {
                  const unsigned int c = fe.system_to_component_index(i).first;
                  const auto         g = values.shape_grad_component(i, q, c);
                  const double       v = values.shape_value_component(i, q, c);
                  grad[i]              = gradients(c, v, g[0], g[1], r);
                  if (free[local[i]] >= 0)
                    strain += u(free[local[i]]) * strains(c, v, g[0], g[1], r)[0];
                }
              const Strain sigma = mat.stiffness * strain;
              for (unsigned int i = 0; i < per_cell; ++i)
                for (unsigned int j = 0; j < per_cell; ++j)
                  {
                    kp.a(i, j) += dealii::scalar_product(grad[i][0] * sigma, grad[j][0]) * dV;
                    kp.b(i, j) += (dealii::scalar_product(grad[i][0] * sigma, grad[j][1]) +
                                   dealii::scalar_product(grad[i][1] * sigma, grad[j][0])) *
                                  dV;
                    kp.c(i, j) += dealii::scalar_product(grad[i][1] * sigma, grad[j][1]) * dV;
                  }
            }
          for_free_pairs(
            local, free,
            [&](const long fi, const long fj, const unsigned int i, const unsigned int j) {
              pa.emplace_back(fi, fj, kp.a(i, j));
              pb.emplace_back(fi, fj, kp.b(i, j));
              pc.emplace_back(fi, fj, kp.c(i, j));
            });
        }
      Kp = {to_sparse(pa, n), to_sparse(pb, n), to_sparse(pc, n)};

      // The tread's growth: the largest radial amplitude on its nodes.
      growth = 0.;
      for (const auto &cell : dofs.active_cell_iterators())
        for (const unsigned int f : cell->face_indices())
          if (cell->face(f)->at_boundary() &&
              cell->face(f)->boundary_id() == geometry::tread_surface)
            {
              cell->get_dof_indices(local);
              for (unsigned int i = 0; i < per_cell; ++i)
                if (fe.system_to_component_index(i).first == UR && fe.has_support_on_face(i, f) &&
                    free[local[i]] >= 0)
                  growth = std::max(growth, u(free[local[i]]));
            }
    }
  } // namespace fe
} // namespace greentread

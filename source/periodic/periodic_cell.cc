#include <greentread/base/exceptions.h>
#include <greentread/fe/cylindrical.h>
#include <greentread/periodic/periodic_cell.h>

#include <deal.II/dofs/dof_tools.h>
#include <deal.II/fe/component_mask.h>
#include <deal.II/lac/affine_constraints.h>

#include <cmath>
#include <limits>
#include <map>

namespace greentread
{
  namespace periodic
  {
    SparseComplex
    PeriodicCell::dynamic_stiffness(const double omega) const
    {
      SparseComplex D = stiffness.cast<Complex>();
      D += Complex(0., omega) * damping.cast<Complex>();
      D -= Complex(omega * omega) * mass.cast<Complex>();
      return D;
    }



    namespace
    {
      /// A deal.II matrix as T A T^T over the kept DoFs, in the new order.
      SparseReal
      rotate_and_reorder(
        const dealii::SparseMatrix<double>                                &A,
        const std::vector<int>                                            &new_index,
        const std::vector<unsigned int>                                   &node_of_dof,
        const std::vector<unsigned int>                                   &component_of_dof,
        const std::vector<std::array<double, 2>>                          &cos_sin,
        const std::vector<std::array<dealii::types::global_dof_index, 3>> &triplets,
        const unsigned int                                                 size)
      {
        // t = [[c, s, 0], [-s, c, 0], [0, 0, 1]]: u_r = c u_x + s u_y,
        // u_theta = -s u_x + c u_y. Column q of t (the Cartesian component
        // q) contributes to the cylindrical rows with nonzero t(., q).
        const auto t = [&](const unsigned int node, const unsigned int row, const unsigned int q) {
          const double c = cos_sin[node][0], s = cos_sin[node][1];
          if (row == 2 || q == 2)
            return row == q ? 1. : 0.;
          if (row == 0)
            return q == 0 ? c : s;
          return q == 0 ? -s : c;
        };
        std::vector<Eigen::Triplet<double>> entries;
        entries.reserve(4 * A.n_nonzero_elements());
        for (auto e = A.begin(); e != A.end(); ++e)
          {
            if (e->value() == 0.)
              continue;
            const unsigned int a = node_of_dof[e->row()], b = node_of_dof[e->column()];
            const unsigned int p = component_of_dof[e->row()], q = component_of_dof[e->column()];
            for (unsigned int pp = 0; pp < 3; ++pp)
              {
                const double tp = t(a, pp, p);
                const int    i  = new_index[triplets[a][pp]];
                if (tp == 0. || i < 0)
                  continue;
                for (unsigned int qq = 0; qq < 3; ++qq)
                  {
                    const double tq = t(b, qq, q);
                    const int    j  = new_index[triplets[b][qq]];
                    if (tq != 0. && j >= 0)
                      entries.emplace_back(i, j, tp * e->value() * tq);
                  }
              }
          }
        SparseReal result(size, size);
        result.setFromTriplets(entries.begin(), entries.end());
        result.makeCompressed();
        return result;
      }
    } // namespace



    PeriodicCell
    make_periodic_cell(const fe::ElasticModel          &model,
                       const double                     angle,
                       const unsigned int               n_cells,
                       const dealii::types::boundary_id clamped,
                       const dealii::types::boundary_id tread,
                       const bool                       with_prestress)
    {
      const auto                        nodes = fe::nodes(model.dof_handler(), model.mapping());
      const std::size_t                 n     = model.dof_handler().n_dofs();
      dealii::AffineConstraints<double> clamp;
      model.add_clamp(clamped, clamp);
      clamp.close();
      const dealii::IndexSet tread_dofs = dealii::DoFTools::extract_boundary_dofs(
        model.dof_handler(), dealii::ComponentMask(), {tread});

      // Sort the nodes into the left face, the interior and the right face.
      double size = 0.;
      for (const auto &node : nodes)
        size = std::max(size, node.position.norm());
      const double              length_tolerance = 1e-8 * size, angle_tolerance = 1e-6 * angle;
      std::vector<unsigned int> node_of_dof(n), component_of_dof(n);
      std::vector<std::array<double, 2>>                          cos_sin(nodes.size());
      std::vector<std::array<dealii::types::global_dof_index, 3>> triplets(nodes.size());
      std::vector<unsigned int>                                   left, interior, right;
      std::vector<double>                                         theta(nodes.size());
      for (unsigned int a = 0; a < nodes.size(); ++a)
        {
          const auto &x = nodes[a].position;
          theta[a]      = std::atan2(x[1], x[0]);
          cos_sin[a]    = {{std::cos(theta[a]), std::sin(theta[a])}};
          triplets[a]   = nodes[a].dofs;
          for (unsigned int c = 0; c < 3; ++c)
            {
              node_of_dof[nodes[a].dofs[c]]      = a;
              component_of_dof[nodes[a].dofs[c]] = c;
            }
          if (std::abs(theta[a]) < angle_tolerance)
            left.push_back(a);
          else if (std::abs(theta[a] - angle) < angle_tolerance)
            right.push_back(a);
          else if (theta[a] > 0. && theta[a] < angle)
            interior.push_back(a);
          else
            throw InputError("the cell has a node at theta = " + format_short(theta[a]) +
                             " rad, outside [0, " + format_short(angle) +
                             "]: it is not the section revolved by 2 pi / N about the z-axis");
        }

      // Pair each right-face node with the left-face node at the same
      // (radius, z).
      const auto key = [&](const unsigned int a) {
        const auto &x = nodes[a].position;
        return std::make_pair(std::llround(std::hypot(x[0], x[1]) / length_tolerance),
                              std::llround(x[2] / length_tolerance));
      };
      std::map<std::pair<long long, long long>, unsigned int> left_at;
      for (const unsigned int a : left)
        left_at[key(a)] = a;
      std::vector<unsigned int> right_of(nodes.size(), dealii::numbers::invalid_unsigned_int);
      for (const unsigned int a : right)
        {
          auto found = left_at.find(key(a));
          // Rounding can split one position over two neighbouring keys.
          for (long long dr = -1; found == left_at.end() && dr <= 1; ++dr)
            for (long long dz = -1; found == left_at.end() && dz <= 1; ++dz)
              found = left_at.find({key(a).first + dr, key(a).second + dz});
          if (found == left_at.end())
            {
              const auto &x = nodes[a].position;
              throw InputError("the periodic faces of the cell do not match: the node at "
                               "(radius, z) = (" +
                               format_number(std::hypot(x[0], x[1])) + ", " + format_number(x[2]) +
                               ") m on the face theta = 2 pi / N "
                               "has no partner on the face theta = 0 (tolerance " +
                               format_short(length_tolerance) + " m)");
            }
          if (right_of[found->second] != dealii::numbers::invalid_unsigned_int)
            throw InputError("the periodic faces of the cell do not match: two nodes of the "
                             "face theta = 2 pi / N fall on one node of the face theta = 0");
          right_of[found->second] = a;
        }
      if (left.size() != right.size())
        throw InputError(
          "the periodic faces of the cell do not match: " + std::to_string(left.size()) +
          " nodes at theta = 0 against " + std::to_string(right.size()) + " at theta = 2 pi / N");

      // The new order: L, I, R, each node's r, theta, z; clamped DoFs out.
      PeriodicCell cell;
      cell.angle   = angle;
      cell.n_cells = n_cells;
      std::vector<int> new_index(n, -1);
      int              next  = 0;
      const auto       place = [&](const unsigned int a) {
        bool held = true;
        for (unsigned int c = 0; c < 3; ++c)
          held = held && clamp.is_constrained(nodes[a].dofs[c]);
        if (held)
          cell.held_nodes.push_back({{std::hypot(nodes[a].position[0], nodes[a].position[1]),
                                      nodes[a].position[2], theta[a]}});
        for (unsigned int c = 0; c < 3; ++c)
          if (!clamp.is_constrained(nodes[a].dofs[c]))
            {
              new_index[nodes[a].dofs[c]] = next++;
              const auto &x               = nodes[a].position;
              cell.dofs.push_back({std::hypot(x[0], x[1]), x[2], theta[a], c,
                                   tread_dofs.is_element(nodes[a].dofs[c])});
            }
      };
      for (const unsigned int a : left)
        place(a);
      cell.n_face = next;
      for (const unsigned int a : interior)
        place(a);
      cell.n_interior = next - cell.n_face;
      for (const unsigned int a : left)
        {
          // R in the order of L: the partner of each left node.
          const unsigned int b = right_of[a];
          for (unsigned int c = 0; c < 3; ++c)
            {
              const bool left_free  = !clamp.is_constrained(nodes[a].dofs[c]);
              const bool right_free = !clamp.is_constrained(nodes[b].dofs[c]);
              if (left_free != right_free)
                throw InputError("the clamped boundary is not the same on both periodic "
                                 "faces of the cell");
              if (right_free)
                {
                  new_index[nodes[b].dofs[c]] = next++;
                  const auto &x               = nodes[b].position;
                  cell.dofs.push_back({std::hypot(x[0], x[1]), x[2], theta[b], c,
                                       tread_dofs.is_element(nodes[b].dofs[c])});
                }
            }
        }
      if (static_cast<unsigned int>(next) != cell.size())
        throw NumericalError("make_periodic_cell: inconsistent DoF count");

      const auto rotate = [&](const dealii::SparseMatrix<double> &A) {
        return rotate_and_reorder(A, new_index, node_of_dof, component_of_dof, cos_sin, triplets,
                                  cell.size());
      };
      cell.stiffness = rotate(model.stiffness());
      if (with_prestress)
        cell.stiffness += rotate(model.geometric_stiffness());
      cell.damping      = rotate(model.damping());
      cell.mass_damping = rotate(model.mass_damping());
      cell.mass         = rotate(model.mass());
      return cell;
    }



    double
    move_tread_mass_inward(PeriodicCell &cell)
    {
      const Eigen::Index n        = cell.size();
      const auto         position = [&](const Eigen::Index i) {
        const CellDof &d = cell.dofs[i];
        return Eigen::Vector3d(d.radius * std::cos(d.angle), d.radius * std::sin(d.angle), d.axial);
      };
      // The mass matrix's pattern is the DoFs' element adjacency.
      std::vector<Eigen::Triplet<double>> map;
      map.reserve(n);
      Eigen::VectorXd axial = Eigen::VectorXd::Zero(n);
      for (Eigen::Index i = 0; i < n; ++i)
        {
          if (cell.dofs[i].component == 2)
            axial(i) = 1.;
          if (!cell.dofs[i].on_tread)
            {
              map.emplace_back(i, i, 1.);
              continue;
            }
          Eigen::Index partner  = -1;
          double       distance = std::numeric_limits<double>::infinity();
          for (SparseReal::InnerIterator it(cell.mass, i); it; ++it)
            {
              const Eigen::Index j = it.row();
              if (cell.dofs[j].on_tread || cell.dofs[j].component != cell.dofs[i].component)
                continue;
              const double d = (position(j) - position(i)).norm();
              if (d < distance)
                {
                  distance = d;
                  partner  = j;
                }
            }
          if (partner < 0)
            throw NumericalError(
              "move_tread_mass_inward: the tread-surface node at (radius, z) = (" +
              format_number(cell.dofs[i].radius) + ", " + format_number(cell.dofs[i].axial) +
              ") m shares no element with a node off the surface");
          map.emplace_back(i, partner, 1.);
        }
      SparseReal T(n, n);
      T.setFromTriplets(map.begin(), map.end());
      const Eigen::VectorXd row_sums = cell.mass * axial;
      const double          total    = axial.dot(row_sums);
      double                moved    = 0.;
      for (Eigen::Index i = 0; i < n; ++i)
        if (cell.dofs[i].on_tread)
          moved += axial(i) * row_sums(i);
      // The damping's part alpha M moves with the mass; its part beta K stays
      // where the stiffness is, so that a damping proportional to M and K
      // stays proportional to the new M and K.
      const SparseReal Tt            = T.transpose();
      const SparseReal moved_damping = SparseReal(Tt * cell.mass_damping * T);
      cell.mass                      = SparseReal(Tt * cell.mass * T).pruned();
      cell.damping      = SparseReal(cell.damping - cell.mass_damping + moved_damping).pruned();
      cell.mass_damping = moved_damping.pruned();
      cell.mass.makeCompressed();
      cell.damping.makeCompressed();
      cell.mass_damping.makeCompressed();
      return moved / total;
    }
  } // namespace periodic
} // namespace greentread

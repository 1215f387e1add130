#include <greentread/base/exceptions.h>
#include <greentread/fe/cylindrical.h>

#include <deal.II/dofs/dof_tools.h>
#include <deal.II/fe/fe.h>

#include <cmath>
#include <map>

namespace greentread
{
  namespace fe
  {
    using namespace dealii;

    std::vector<Node>
    nodes(const DoFHandler<3> &dofs, const Mapping<3> &mapping)
    {
      const FiniteElement<3> &fe = dofs.get_fe();
      if (fe.n_components() != 3)
        throw NumericalError("nodes(): a vector field with three components is needed");
      std::vector<Point<3>> points(dofs.n_dofs());
      DoFTools::map_dofs_to_support_points(mapping, dofs, points);
      // On each cell, the DoFs with the same index within their component
      // belong to the same node.
      std::map<types::global_dof_index, std::size_t> node_of_x;
      std::vector<Node>                              result;
      std::vector<types::global_dof_index>           local(fe.n_dofs_per_cell());
      for (const auto &cell : dofs.active_cell_iterators())
        {
          cell->get_dof_indices(local);
          std::map<unsigned int, std::array<types::global_dof_index, 3>> triplets;
          for (unsigned int i = 0; i < local.size(); ++i)
            {
              const auto [component, index] = fe.system_to_component_index(i);
              triplets[index][component]    = local[i];
            }
          for (const auto &[index, triplet] : triplets)
            if (node_of_x.emplace(triplet[0], result.size()).second)
              result.push_back({triplet, points[triplet[0]]});
        }
      return result;
    }



    FullMatrix<double>
    to_cylindrical(const FullMatrix<double> &A, const std::vector<Node> &nodes)
    {
      // T is block diagonal: rotate the rows, then the columns, node by node.
      FullMatrix<double> B(A);
      for (const auto &node : nodes)
        {
          const double theta = std::atan2(node.position[1], node.position[0]);
          const double c = std::cos(theta), s = std::sin(theta);
          const auto   x = node.dofs[0], y = node.dofs[1];
          for (unsigned int j = 0; j < B.n(); ++j)
            {
              const double bx = B(x, j), by = B(y, j);
              B(x, j) = c * bx + s * by;
              B(y, j) = -s * bx + c * by;
            }
          for (unsigned int i = 0; i < B.m(); ++i)
            {
              const double bx = B(i, x), by = B(i, y);
              B(i, x) = c * bx + s * by;
              B(i, y) = -s * bx + c * by;
            }
        }
      return B;
    }
  } // namespace fe
} // namespace greentread

#include <greentread/base/mesh_ids.h>
#include <greentread/fe/cylindrical.h>
#include <greentread/fe/inflation.h>

#include <deal.II/lac/affine_constraints.h>

#include <cmath>

namespace greentread
{
  namespace fe
  {
    dealii::Vector<double>
    solve_inflation(const ElasticModel &model, const double cell_angle, const double pressure)
    {
      // The cell closed into the ring by rotational periodicity.
      dealii::AffineConstraints<double> constraints;
      model.add_clamp(geometry::rim_seat, constraints);
      model.add_rotational_periodicity(geometry::periodic_first, geometry::periodic_second,
                                       cell_angle, constraints);
      constraints.close();
      return model.solve_static(constraints,
                                model.pressure_load(geometry::inner_surface, pressure));
    }



    std::pair<double, double>
    tread_growth(const ElasticModel &model, const dealii::Vector<double> &u, const double outer)
    {
      // The radial displacement of the nodes on the outer radius.
      double largest = 0., crown = 0.;
      for (const auto &node : nodes(model.dof_handler(), model.mapping()))
        {
          const double r = std::hypot(node.position[0], node.position[1]);
          if (std::abs(r - outer) < 1e-9 * outer)
            {
              const double u_r =
                (node.position[0] * u[node.dofs[0]] + node.position[1] * u[node.dofs[1]]) / r;
              largest = std::max(largest, u_r);
              if (std::abs(node.position[2]) < 1e-9)
                crown = u_r;
            }
        }
      return {largest, crown};
    }
  } // namespace fe
} // namespace greentread

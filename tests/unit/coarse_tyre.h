#pragma once

// The tests' coarse tyre cell (4 cm mesh) and its contact points, inflated
// to 2 bar with its prestress, or, for the checks that need a damping
// proportional to the stiffness, with no inflation and one loss factor for
// every layer.

#include <greentread/fe/elastic_model.h>
#include <greentread/fe/material.h>
#include <greentread/geometry/tyre_cell.h>
#include <greentread/periodic/contact_patch.h>
#include <greentread/periodic/periodic_cell.h>

#include <deal.II/lac/affine_constraints.h>

#include <memory>

namespace test
{
  using namespace greentread;

  struct CoarseTyre
  {
    geometry::GeometryParameters        geometry;
    fe::MaterialParameters              materials;
    std::unique_ptr<geometry::TyreCell> cell;
    std::unique_ptr<fe::ElasticModel>   model;
    periodic::PeriodicCell              periodic_cell;
    periodic::ContactPatch              patch;

    /// @p inflated: 2 bar and Kp, the materials as they are; otherwise no
    /// pressure and every layer's loss factor 0.05, so that C = a M + b K.
    CoarseTyre(const unsigned int            n_cells,
               const periodic::PatchRequest &request,
               const bool                    inflated = true)
    {
      geometry.geo_file  = GREENTREAD_SOURCE_DIR "/geometry/tyre_165_65_r13.geo";
      geometry.mesh_size = 0.04;
      geometry.n_cells   = n_cells;
      if (!inflated)
        materials.tread_loss = materials.belt_loss = materials.sidewall_loss = materials.bead_loss =
          0.05;
      cell  = std::make_unique<geometry::TyreCell>(geometry);
      model = std::make_unique<fe::ElasticModel>(cell->cell(), materials.materials());
      model->assemble();
      if (inflated)
        {
          dealii::AffineConstraints<double> constraints;
          model->add_clamp(geometry::rim_seat, constraints);
          model->add_rotational_periodicity(geometry::periodic_first, geometry::periodic_second,
                                            cell->angle(), constraints);
          constraints.close();
          const auto u =
            model->solve_static(constraints, model->pressure_load(geometry::inner_surface, 2e5));
          model->assemble_geometric_stiffness(u);
        }
      periodic_cell = periodic::make_periodic_cell(
        *model, cell->angle(), n_cells, geometry::rim_seat, geometry::tread_surface, inflated);
      patch = periodic::place_contact_points(periodic_cell, request);
    }
  };
} // namespace test

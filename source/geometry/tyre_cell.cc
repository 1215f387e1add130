#include <greentread/base/exceptions.h>
#include <greentread/base/mesh_ids.h>
#include <greentread/base/parameters.h>
#include <greentread/geometry/tyre_cell.h>

#include <deal.II/grid/grid_generator.h>
#include <deal.II/grid/grid_tools.h>
#include <deal.II/grid/manifold_lib.h>

#include <gmsh.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <regex>
#include <set>

namespace greentread
{
  namespace geometry
  {
    namespace
    {
      /// gmsh's session for the lifetime of one build, finalized however it ends.
      struct GmshSession
      {
        GmshSession()
        {
          // No user option files: the same .geo gives the same mesh anywhere.
          gmsh::initialize(0, nullptr, false);
          try
            {
              gmsh::option::setNumber("General.Terminal", 0);
              gmsh::logger::start();
              // gmsh's ONELAB parameters outlive gmsh::finalize: without
              // this, a constant set through 'Other constants' for one cell
              // (Crown refinement=3, say) stayed set for the next cell built
              // in the same process, even when that cell's parameters did
              // not name it.
              gmsh::onelab::clear();
            }
          catch (...)
            {
              gmsh::finalize();
              throw;
            }
        }
        ~GmshSession()
        {
          gmsh::logger::stop();
          gmsh::finalize();
        }
        /// Run one gmsh call and throw an InputError if gmsh reported an error.
        /// gmsh 4.8 reports some errors (a .geo syntax error, for one) by
        /// throwing a std::string, which no std::exception handler catches.
        template <typename Call>
        void
        run(const std::string &file, const std::string &when, const Call &call) const
        {
          std::string error;
          try
            {
              call();
            }
          catch (const std::string &message)
            {
              error = message;
            }
          if (error.empty())
            gmsh::logger::getLastError(error);
          if (!error.empty())
            throw InputError("geometry file '" + file + "': gmsh failed while " + when + ": " +
                             error);
        }
      };

      /// gmsh's mesh nodes: the coordinates of each, and its index by tag.
      struct MeshNodes
      {
        std::vector<std::array<double, 3>>  xyz;
        std::map<std::size_t, unsigned int> index;
      };

      MeshNodes
      mesh_nodes()
      {
        std::vector<std::size_t> tags;
        std::vector<double>      coordinates, parametric;
        gmsh::model::mesh::getNodes(tags, coordinates, parametric);
        MeshNodes nodes;
        for (std::size_t i = 0; i < tags.size(); ++i)
          {
            nodes.index[tags[i]] = nodes.xyz.size();
            nodes.xyz.push_back(
              {{coordinates[3 * i], coordinates[3 * i + 1], coordinates[3 * i + 2]}});
          }
        return nodes;
      }

      /// The elements gmsh made on the entity (dim, tag), each as the indices
      /// of its @p n_vertices vertices in gmsh's order; any element of
      /// another type than @p type is refused with @p complaint.
      std::vector<std::vector<unsigned int>>
      mesh_elements(const int          dim,
                    const int          tag,
                    const int          type,
                    const unsigned int n_vertices,
                    const MeshNodes   &mesh,
                    const std::string &complaint)
      {
        std::vector<int>                      types;
        std::vector<std::vector<std::size_t>> tags, nodes;
        gmsh::model::mesh::getElements(types, tags, nodes, dim, tag);
        std::vector<std::vector<unsigned int>> elements;
        for (std::size_t t = 0; t < types.size(); ++t)
          {
            if (types[t] != type)
              throw InputError(complaint);
            for (std::size_t e = 0; e < nodes[t].size() / n_vertices; ++e)
              {
                elements.emplace_back(n_vertices);
                for (unsigned int k = 0; k < n_vertices; ++k)
                  elements.back()[k] = mesh.index.at(nodes[t][n_vertices * e + k]);
              }
          }
        return elements;
      }

      const std::map<std::string, unsigned int> material_names = {{"tread", fe::tread_id},
                                                                  {"belt", fe::belt_id},
                                                                  {"sidewall", fe::sidewall_id},
                                                                  {"bead", fe::bead_id}};
      const std::map<std::string, unsigned int> boundary_names = {{"rim seat", rim_seat},
                                                                  {"inner surface", inner_surface},
                                                                  {"tread surface", tread_surface}};
    } // namespace



    namespace
    {
      /// The materials (2D) and boundaries (1D) of a .geo file, by the ids
      /// GreenTread uses.
      struct PhysicalGroups
      {
        std::map<unsigned int, std::vector<int>> surfaces_of_material;
        std::map<unsigned int, std::vector<int>> curves_of_boundary;
      };

      /// The physical groups of the open gmsh model, checked: every surface
      /// in exactly one known material, every boundary present.
      PhysicalGroups
      read_physical_groups(const std::string &file)
      {
        PhysicalGroups   result;
        auto            &surfaces_of_material = result.surfaces_of_material;
        auto            &curves_of_boundary   = result.curves_of_boundary;
        gmsh::vectorpair groups;
        gmsh::model::getPhysicalGroups(groups);
        for (const auto &[dim, tag] : groups)
          {
            std::string name;
            gmsh::model::getPhysicalName(dim, tag, name);
            std::vector<int> entities;
            gmsh::model::getEntitiesForPhysicalGroup(dim, tag, entities);
            if (dim == 2)
              {
                const auto m = material_names.find(name);
                if (m == material_names.end())
                  throw InputError("geometry file '" + file + "': physical surface '" + name +
                                   "' is not a material GreenTread knows; allowed: tread, belt, "
                                   "sidewall, bead");
                auto &surfaces = surfaces_of_material[m->second];
                surfaces.insert(surfaces.end(), entities.begin(), entities.end());
              }
            else if (dim == 1)
              {
                const auto b = boundary_names.find(name);
                if (b == boundary_names.end())
                  throw InputError("geometry file '" + file + "': physical curve '" + name +
                                   "' is not a boundary GreenTread knows; allowed: rim seat, inner "
                                   "surface, tread surface (leave interfaces untagged)");
                auto &curves = curves_of_boundary[b->second];
                curves.insert(curves.end(), entities.begin(), entities.end());
              }
          }
        if (surfaces_of_material.empty())
          throw InputError("geometry file '" + file + "' defines no physical surface (material)");
        // Every surface in exactly one material: a surface left out would
        // silently cut a hole in the section.
        {
          std::map<int, unsigned int> groups_of_surface;
          for (const auto &[material, surfaces] : surfaces_of_material)
            for (const int s : surfaces)
              ++groups_of_surface[s];
          gmsh::vectorpair entities;
          gmsh::model::getEntities(entities, 2);
          for (const auto &[dim, s] : entities)
            if (groups_of_surface[s] != 1)
              throw InputError("geometry file '" + file + "': surface " + std::to_string(s) +
                               (groups_of_surface[s] == 0 ?
                                  " is in no physical surface" :
                                  " is in more than one physical surface") +
                               "; each surface must be in exactly one of tread, belt, sidewall, "
                               "bead");
        }
        for (const auto &[name, id] : boundary_names)
          if (curves_of_boundary.count(id) == 0)
            throw InputError("geometry file '" + file + "' has no physical curve '" + name + "'");
        return result;
      }



      /// The quadrilateral blocks of the section (for Pappus), and each
      /// surface's material.
      std::vector<SectionBlock>
      read_section_blocks(const std::string           &file,
                          const PhysicalGroups        &groups,
                          gmsh::vectorpair            &all_surfaces,
                          std::map<int, unsigned int> &material_of_surface)
      {
        std::vector<SectionBlock> section_blocks;
        for (const auto &[material, surfaces] : groups.surfaces_of_material)
          for (const int s : surfaces)
            {
              all_surfaces.emplace_back(2, s);
              material_of_surface[s] = material;
              gmsh::vectorpair curves;
              gmsh::model::getBoundary({{2, s}}, curves, false, true, false);
              SectionBlock block{material, {}, true};
              for (const auto &[dim, signed_curve] : curves)
                {
                  std::string type;
                  gmsh::model::getType(1, std::abs(signed_curve), type);
                  block.straight = block.straight && type == "Line";
                  gmsh::vectorpair ends;
                  gmsh::model::getBoundary({{1, signed_curve}}, ends, false, true, false);
                  std::vector<double> xyz;
                  if (!ends.empty())
                    gmsh::model::getValue(0, ends.front().second, {}, xyz);
                  if (xyz.size() != 3)
                    throw InputError("geometry file '" + file + "': curve " +
                                     std::to_string(std::abs(signed_curve)) + " of surface " +
                                     std::to_string(s) +
                                     " has no end points; the section must be "
                                     "made of quadrilateral blocks bounded by open curves");
                  block.corners.push_back({{xyz[0], xyz[2]}});
                }
              section_blocks.push_back(block);
            }
        return section_blocks;
      }



      /// The section's quadrilaterals from the 2D mesh, (x, z) -> (radius,
      /// axial), into @p section_triangulation.
      void
      make_section(const std::string        &file,
                   const PhysicalGroups     &groups,
                   dealii::Triangulation<2> &section_triangulation)
      {
        {
          const MeshNodes               mesh = mesh_nodes();
          std::vector<dealii::Point<2>> vertices;
          for (const auto &xyz : mesh.xyz)
            vertices.emplace_back(xyz[0], xyz[2]);
          std::vector<dealii::CellData<2>> cells;
          for (const auto &[material, surfaces] : groups.surfaces_of_material)
            for (const int s : surfaces)
              for (auto q : mesh_elements(2, s, 3, 4, mesh,
                                          "geometry file '" + file +
                                            "': the section mesh has "
                                            "elements that are not quadrilaterals; make every "
                                            "surface transfinite and recombined"))
                {
                  // gmsh goes around the quadrilateral, in either sense
                  // (surfaces differ); make it counterclockwise, then deal.II's
                  // lexicographic order.
                  double area = 0.;
                  for (unsigned int v = 0; v < 4; ++v)
                    {
                      const auto &a = vertices[q[v]], &b = vertices[q[(v + 1) % 4]];
                      area += a[0] * b[1] - b[0] * a[1];
                    }
                  if (area < 0.)
                    std::swap(q[1], q[3]);
                  dealii::CellData<2> c;
                  c.vertices    = {q[0], q[1], q[3], q[2]};
                  c.material_id = material;
                  cells.push_back(c);
                }
          dealii::GridTools::consistently_order_cells(cells);
          section_triangulation.create_triangulation(vertices, cells, dealii::SubCellData());
        }
        gmsh::model::mesh::clear();
      }



      /// The cell's volumes and boundary surfaces after the revolution.
      struct RevolvedCell
      {
        std::map<unsigned int, std::vector<int>> volumes_of_material;
        std::map<unsigned int, std::set<int>>    surfaces_of_boundary;
        std::vector<int>                         bottom, top_surfaces;
      };

      /// Sort what gmsh's revolve() returned (@p out) into volumes by
      /// material and surfaces by boundary, and tag them as physical groups.
      RevolvedCell
      sort_revolved(const gmsh::vectorpair            &out,
                    const gmsh::vectorpair            &all_surfaces,
                    const std::map<int, unsigned int> &material_of_surface,
                    const PhysicalGroups              &groups)
      {
        RevolvedCell     cell;
        auto            &volumes_of_material  = cell.volumes_of_material;
        auto            &surfaces_of_boundary = cell.surfaces_of_boundary;
        auto            &top_surfaces         = cell.top_surfaces;
        auto            &bottom               = cell.bottom;
        std::vector<int> lateral_surfaces;
        for (std::size_t i = 0, k = 0; i < out.size(); ++i)
          if (out[i].first == 3)
            {
              volumes_of_material[material_of_surface.at(all_surfaces[k].second)].push_back(
                out[i].second);
              top_surfaces.push_back(out[i - 1].second);
              ++k;
            }
          else if (out[i].first == 2 && (i + 1 == out.size() || out[i + 1].first != 3))
            lateral_surfaces.push_back(out[i].second);
        // A lateral surface belongs to the boundary whose curve it was swept from.
        for (const int lateral : lateral_surfaces)
          {
            gmsh::vectorpair curves;
            gmsh::model::getBoundary({{2, lateral}}, curves, false, false, false);
            for (const auto &[id, boundary_curves] : groups.curves_of_boundary)
              for (const auto &[dim, c] : curves)
                if (std::find(boundary_curves.begin(), boundary_curves.end(), std::abs(c)) !=
                    boundary_curves.end())
                  surfaces_of_boundary[id].insert(lateral);
          }
        gmsh::model::removePhysicalGroups();
        for (const auto &[material, volumes] : volumes_of_material)
          gmsh::model::addPhysicalGroup(3, volumes, material);
        for (const auto &[id, surfaces] : surfaces_of_boundary)
          gmsh::model::addPhysicalGroup(2, std::vector<int>(surfaces.begin(), surfaces.end()), id);
        for (const auto &[dim, s] : all_surfaces)
          bottom.push_back(s);
        gmsh::model::addPhysicalGroup(2, bottom, periodic_first);
        gmsh::model::addPhysicalGroup(2, top_surfaces, periodic_second);
        return cell;
      }



      /// The cell's hexahedra and boundary faces, straight from gmsh's
      /// arrays, into @p cell_triangulation.
      void
      make_cell(const std::string        &file,
                const RevolvedCell       &revolved,
                dealii::Triangulation<3> &cell_triangulation)
      {
        const auto                   &volumes_of_material  = revolved.volumes_of_material;
        const auto                   &surfaces_of_boundary = revolved.surfaces_of_boundary;
        const auto                   &bottom               = revolved.bottom;
        const auto                   &top_surfaces         = revolved.top_surfaces;
        const MeshNodes               mesh                 = mesh_nodes();
        std::vector<dealii::Point<3>> vertices;
        for (const auto &xyz : mesh.xyz)
          vertices.emplace_back(xyz[0], xyz[1], xyz[2]);
        std::vector<dealii::CellData<3>> cells;
        for (const auto &[material, volumes] : volumes_of_material)
          for (const int v : volumes)
            for (auto h : mesh_elements(3, v, 5, 8, mesh,
                                        "geometry file '" + file +
                                          "': the cell mesh has elements "
                                          "that are not hexahedra; make every surface transfinite "
                                          "and recombined"))
              {
                // gmsh: bottom face 0-1-2-3 around, top 4-5-6-7 above it;
                // mirror the bottom order if that is left-handed.
                const auto a = vertices[h[1]] - vertices[h[0]];
                const auto b = vertices[h[3]] - vertices[h[0]];
                const auto n = vertices[h[4]] - vertices[h[0]];
                if (dealii::cross_product_3d(a, b) * n < 0.)
                  {
                    std::swap(h[1], h[3]);
                    std::swap(h[5], h[7]);
                  }
                dealii::CellData<3> c;
                c.vertices    = {h[0], h[1], h[3], h[2], h[4], h[5], h[7], h[6]};
                c.material_id = material;
                cells.push_back(c);
              }
        dealii::SubCellData                       boundary;
        std::vector<std::pair<int, unsigned int>> surface_ids;
        for (const auto &[id, surfaces] : surfaces_of_boundary)
          for (const int s : surfaces)
            surface_ids.emplace_back(s, id);
        for (const int s : bottom)
          surface_ids.emplace_back(s, periodic_first);
        for (const int s : top_surfaces)
          surface_ids.emplace_back(s, periodic_second);
        for (const auto &[s, id] : surface_ids)
          for (const auto &f : mesh_elements(2, s, 3, 4, mesh,
                                             "geometry file '" + file +
                                               "': the cell's boundary "
                                               "has faces that are not quadrilaterals"))
            {
              dealii::CellData<2> q;
              q.vertices    = {f[0], f[1], f[3], f[2]};
              q.boundary_id = id;
              boundary.boundary_quads.push_back(q);
            }
        if (cells.empty())
          throw InputError("geometry file '" + file + "': gmsh made no cells");
        try
          {
            dealii::GridTools::consistently_order_cells(cells);
            cell_triangulation.create_triangulation(vertices, cells, boundary);
          }
        catch (const dealii::ExceptionBase &e)
          {
            std::ostringstream info;
            e.print_info(info);
            throw InputError("geometry file '" + file +
                             "': the mesh gmsh made is not a valid "
                             "deal.II mesh (distorted cells?): " +
                             info.str());
          }
      }

      /// Give the section's boundary edges the ids of the cell faces swept
      /// from them (rim seat, inner and tread surface; free otherwise), so
      /// that the harmonic route (fe/harmonic_section.h) loads and holds the
      /// section as the cell. A swept face and its edge have the same mean
      /// (radius, axial) of their vertices.
      void
      label_section_boundary(const dealii::Triangulation<3> &cell,
                             dealii::Triangulation<2>       &section)
      {
        double size = 0.;
        for (const auto &v : section.get_vertices())
          size = std::max(size, v.norm());
        const double scale = 1e-7 * size;
        const auto   key   = [scale](const double r, const double z) {
          return std::make_pair(std::llround(r / scale), std::llround(z / scale));
        };
        std::map<std::pair<long long, long long>, dealii::types::boundary_id> ids;
        for (const auto &c : cell.active_cell_iterators())
          for (const auto &face : c->face_iterators())
            if (face->at_boundary() && face->boundary_id() != periodic_first &&
                face->boundary_id() != periodic_second)
              {
                double r = 0., z = 0.;
                for (unsigned int v = 0; v < 4; ++v)
                  {
                    r += std::hypot(face->vertex(v)[0], face->vertex(v)[1]) / 4.;
                    z += face->vertex(v)[2] / 4.;
                  }
                ids[key(r, z)] = face->boundary_id();
              }
        for (const auto &c : section.active_cell_iterators())
          for (const auto &face : c->face_iterators())
            if (face->at_boundary())
              {
                const auto m     = 0.5 * (face->vertex(0) + face->vertex(1));
                const auto found = ids.find(key(m[0], m[1]));
                face->set_boundary_id(
                  found == ids.end() ? dealii::types::boundary_id(free_surface) : found->second);
              }
      }
    } // namespace



    TyreCell::TyreCell(const GeometryParameters &parameters)
        : cell_angle(parameters.angle())
        , ring_cells(parameters.n_cells)
    {
      const std::string &file = parameters.geo_file;
      if (!std::filesystem::exists(file))
        throw InputError("parameter 'Geometry/Geometry file' = " + file +
                         ": no such file (paths are relative to the working directory)");
      GmshSession gmsh_session;
      for (const auto &[name, value] : parameters.onelab_numbers())
        gmsh::onelab::setNumber("Parameters/" + name, {value});
      gmsh_session.run(file, "reading it", [&] {
        gmsh::open(file);
      });

      // The coordinates are in metres: a section drawn in millimetres would
      // mesh without a word as a tyre a thousand times too large. Its largest
      // radius (x; the axis is z) must be a tyre's.
      {
        double x0 = 0., y0 = 0., z0 = 0., x1 = 0., y1 = 0., z1 = 0.;
        gmsh::model::getBoundingBox(-1, -1, x0, y0, z0, x1, y1, z1);
        const double radius = std::max(std::abs(x0), std::abs(x1));
        if (!(radius >= 0.05 && radius <= 2.))
          throw InputError("geometry file '" + file + "': the section's largest radius is " +
                           format_short(radius) +
                           " (x, in the file's units); allowed: 0.05 to 2, the coordinates "
                           "in metres (a section drawn in millimetres is 1000 times too large)");
      }
      const PhysicalGroups        groups = read_physical_groups(file);
      gmsh::vectorpair            all_surfaces;
      std::map<int, unsigned int> material_of_surface;
      section_blocks = read_section_blocks(file, groups, all_surfaces, material_of_surface);

      gmsh_session.run(file, "meshing the section", [] {
        gmsh::model::mesh::generate(2);
      });
      make_section(file, groups, section_triangulation);
      gmsh::model::mesh::clear();

      // Revolve into the cell.
      gmsh::vectorpair out;
      gmsh_session.run(file, "revolving the section", [&] {
        gmsh::model::geo::revolve(all_surfaces, 0., 0., 0., 0., 0., 1., cell_angle, out, {1}, {},
                                  true);
        gmsh::model::geo::synchronize();
      });
      const RevolvedCell revolved = sort_revolved(out, all_surfaces, material_of_surface, groups);

      gmsh_session.run(file, "meshing the cell", [] {
        gmsh::model::mesh::generate(3);
      });
      make_cell(file, revolved, cell_triangulation);
      label_section_boundary(cell_triangulation, section_triangulation);
      attach_cylindrical_manifold(cell_triangulation);
    }



    std::optional<double>
    TyreCell::analytic_volume(const unsigned int material_id) const
    {
      // angle x integral of the radius over the section; for a polygon,
      // integral of x dA = 1/6 sum (x_i + x_i+1)(x_i y_i+1 - x_i+1 y_i).
      double integral = 0.;
      for (const auto &block : section_blocks)
        if (block.material_id == material_id)
          {
            if (!block.straight)
              return std::nullopt;
            double sum = 0.;
            for (std::size_t i = 0; i < block.corners.size(); ++i)
              {
                const auto &a = block.corners[i],
                           &b = block.corners[(i + 1) % block.corners.size()];
                sum += (a[0] + b[0]) * (a[0] * b[1] - b[0] * a[1]);
              }
            integral += std::abs(sum) / 6.;
          }
      return cell_angle * integral;
    }
  } // namespace geometry
} // namespace greentread

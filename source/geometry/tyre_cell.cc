#include <greentread/base/exceptions.h>
#include <greentread/base/parameters.h>
#include <greentread/base/mesh_ids.h>
#include <greentread/geometry/tyre_cell.h>

#include <deal.II/grid/grid_generator.h>
#include <deal.II/grid/grid_tools.h>
#include <deal.II/grid/manifold_lib.h>

#include <gmsh.h>

#include <cmath>
#include <filesystem>
#include <regex>
#include <set>

namespace greentread
{
  namespace geometry
  {
    void
    GeometryParameters::declare_parameters(dealii::ParameterHandler &prm)
    {
      using base::RangePattern;
      prm.enter_subsection("Geometry");
      {
        prm.declare_entry("Geometry file", "geometry/tyre_165_65_r13.geo",
                          dealii::Patterns::Anything(),
                          "The gmsh .geo description of the section (relative to the working "
                          "directory). Its DefineConstant parameters 'Parameters/<name>' are "
                          "set from this subsection; a new design is a new file.");
        const auto length = [&](const char *name, const char *value, const char *doc) {
          prm.declare_entry(name, value, RangePattern::positive("m"), std::string(doc) +
                                                                         " Unit: m.");
        };
        length("Rim diameter", "0.3302", "Diameter of the rim seat. Table A.3: 13 in = 330.2 mm.");
        length("Section height", "0.10725",
               "From the rim seat to the tread surface. The default is the size code's "
               "0.65 x 165 mm = 107.25 mm (outer diameter 545 mm, a real 165/65 R13); "
               "Table A.3's 65 mm 'height of the sidewall' gives a 460 mm tyre.");
        length("Tread width", "0.165", "Width of the tread pattern and belt. Table A.3: 165 mm.");
        length("Section width", "0.175",
               "Width of the section at the bulge of the sidewalls (outer faces).");
        length("Rim width", "0.1143", "Distance between the outer faces of the beads (4.5 in).");
        length("Tread thickness", "0.008", "Thickness of the tread pattern (rubber).");
        length("Belt thickness", "0.006", "Thickness of the belt (rubber and steel cords).");
        length("Sidewall thickness", "0.006", "Thickness of the sidewalls (rubber and nylon).");
        length("Bead width", "0.008", "Axial width of each bead (steel).");
        length("Bead height", "0.008", "Radial height of each bead.");
        prm.declare_entry("Bulge height", "0.5", RangePattern::closed(0.05, 0.95, ""),
                          "Where the sidewall is widest, as a fraction of the way from the "
                          "bead up to the belt. Unit: 1.");
        length("Mesh size", "0.008",
               "Target element size in the section (transfinite: every block gets "
               "ceil(length / size) elements per side).");
        prm.declare_entry("Number of cells", "256", dealii::Patterns::Integer(3, 100000),
                          "N, cells in the ring: the cell is the section revolved by 2 pi / N. "
                          "Powers of two suit the recursive doubling of the periodic stage.");
        prm.declare_entry("Other constants", "", dealii::Patterns::Anything(),
                          "More ONELAB numbers for a .geo of your own, 'Name=value, "
                          "Name=value' (SI units); each becomes 'Parameters/Name'.");
      }
      prm.leave_subsection();
    }



    void
    GeometryParameters::parse_parameters(dealii::ParameterHandler &prm)
    {
      prm.enter_subsection("Geometry");
      {
        geo_file           = prm.get("Geometry file");
        rim_diameter       = prm.get_double("Rim diameter");
        section_height     = prm.get_double("Section height");
        tread_width        = prm.get_double("Tread width");
        section_width      = prm.get_double("Section width");
        rim_width          = prm.get_double("Rim width");
        tread_thickness    = prm.get_double("Tread thickness");
        belt_thickness     = prm.get_double("Belt thickness");
        sidewall_thickness = prm.get_double("Sidewall thickness");
        bead_width         = prm.get_double("Bead width");
        bead_height        = prm.get_double("Bead height");
        bulge_height       = prm.get_double("Bulge height");
        mesh_size          = prm.get_double("Mesh size");
        n_cells            = prm.get_integer("Number of cells");
        other_constants    = prm.get("Other constants");
      }
      prm.leave_subsection();

      // The layers must fit: an impossible geometry is named here, before
      // gmsh sees it.
      const auto fail = [](const std::string &what) {
        throw InputError("impossible geometry (subsection Geometry): " + what);
      };
      const double stack = tread_thickness + belt_thickness + bead_height;
      if (!(stack < section_height))
        fail("'Tread thickness' + 'Belt thickness' + 'Bead height' = " + format_short(stack) +
             " m does not fit under 'Section height' = " + format_short(section_height) +
             " m: the layers overlap");
      if (!(sidewall_thickness < 0.5 * tread_width))
        fail("'Sidewall thickness' = " + format_short(sidewall_thickness) +
             " m must be less than half the 'Tread width' = " + format_short(tread_width) +
             " m: the shoulders under the belt would overlap");
      if (!(bead_width < 0.5 * rim_width))
        fail("'Bead width' = " + format_short(bead_width) + " m must be less than half the "
             "'Rim width' = " + format_short(rim_width) + " m: the beads would overlap");
      if (!(sidewall_thickness < 0.5 * section_width))
        fail("'Sidewall thickness' = " + format_short(sidewall_thickness) +
             " m must be less than half the 'Section width' = " + format_short(section_width) +
             " m");
      // A mesh that would not fit in memory.
      const double area = section_height * section_width;
      if (area / (mesh_size * mesh_size) > 2e5)
        throw InputError("parameter 'Geometry/Mesh size' = " + format_number(mesh_size) +
                         " is not allowed; allowed: at least " +
                         format_short(std::sqrt(area / 2e5)) +
                         " m for this section (more than 2e5 elements otherwise)");
      // Elements too flat to solve: the cell's thickness at the rim, R 2 pi / N,
      // against the element size in the section. The static solve of the
      // default section fails near an aspect ratio of 500; 200 is allowed.
      const double max_cells = std::floor(200. * M_PI * rim_diameter / mesh_size);
      if (n_cells > max_cells)
        throw InputError("parameter 'Geometry/Number of cells' = " + std::to_string(n_cells) +
                         " is not allowed with 'Mesh size' = " + format_short(mesh_size) +
                         " m; allowed: at most " + std::to_string(static_cast<unsigned long>(max_cells)) +
                         " (the cell would be " +
                         format_short(M_PI * rim_diameter / n_cells * 1e3) +
                         " mm thick at the rim, more than 200 times thinner than its elements)");
      onelab_numbers(); // checks 'Other constants'
    }



    double
    GeometryParameters::angle() const
    {
      return 2. * M_PI / n_cells;
    }



    std::map<std::string, double>
    GeometryParameters::onelab_numbers() const
    {
      std::map<std::string, double> numbers = {
        {"Rim diameter", rim_diameter},       {"Section height", section_height},
        {"Tread width", tread_width},         {"Section width", section_width},
        {"Rim width", rim_width},             {"Tread thickness", tread_thickness},
        {"Belt thickness", belt_thickness},   {"Sidewall thickness", sidewall_thickness},
        {"Bead width", bead_width},           {"Bead height", bead_height},
        {"Bulge height", bulge_height},       {"Mesh size", mesh_size}};
      const std::regex item("^\\s*([^=,]+?)\\s*=\\s*([-+0-9.eE]+)\\s*$");
      std::size_t      begin = 0;
      while (!other_constants.empty() && begin <= other_constants.size())
        {
          const std::size_t comma = std::min(other_constants.find(',', begin), other_constants.size());
          const std::string part  = other_constants.substr(begin, comma - begin);
          std::smatch       m;
          if (!std::regex_match(part, m, item))
            throw InputError("parameter 'Geometry/Other constants' = " + other_constants +
                             " is not allowed; allowed: 'Name=value, Name=value' ('" + part + "')");
          numbers[m[1]] = std::stod(m[2]);
          begin         = comma + 1;
        }
      return numbers;
    }



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
            nodes.xyz.push_back({{coordinates[3 * i], coordinates[3 * i + 1], coordinates[3 * i + 2]}});
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

      const std::map<std::string, unsigned int> material_names = {
        {"tread", fe::tread_id}, {"belt", fe::belt_id}, {"sidewall", fe::sidewall_id},
        {"bead", fe::bead_id}};
      const std::map<std::string, unsigned int> boundary_names = {
        {"rim seat", rim_seat}, {"inner surface", inner_surface}, {"tread surface", tread_surface}};
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
      gmsh_session.run(file, "reading it", [&] { gmsh::open(file); });

      // Materials (2D) and boundaries (1D) as the .geo names them.
      std::map<unsigned int, std::vector<int>> surfaces_of_material;
      std::map<unsigned int, std::vector<int>> curves_of_boundary;
      gmsh::vectorpair                         groups;
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
                             (groups_of_surface[s] == 0 ? " is in no physical surface" :
                                                          " is in more than one physical surface") +
                             "; each surface must be in exactly one of tread, belt, sidewall, "
                             "bead");
      }
      for (const auto &[name, id] : boundary_names)
        if (curves_of_boundary.count(id) == 0)
          throw InputError("geometry file '" + file + "' has no physical curve '" + name + "'");

      // The blocks of the section, for Pappus.
      gmsh::vectorpair all_surfaces;
      std::map<int, unsigned int> material_of_surface;
      for (const auto &[material, surfaces] : surfaces_of_material)
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
                                   std::to_string(s) + " has no end points; the section must be "
                                   "made of quadrilateral blocks bounded by open curves");
                block.corners.push_back({{xyz[0], xyz[2]}});
              }
            section_blocks.push_back(block);
          }

      // The section mesh, (x, z) -> (radius, axial).
      gmsh_session.run(file, "meshing the section", [] { gmsh::model::mesh::generate(2); });
      {
        const MeshNodes               mesh = mesh_nodes();
        std::vector<dealii::Point<2>> vertices;
        for (const auto &xyz : mesh.xyz)
          vertices.emplace_back(xyz[0], xyz[2]);
        std::vector<dealii::CellData<2>> cells;
        for (const auto &[material, surfaces] : surfaces_of_material)
          for (const int s : surfaces)
            for (auto q : mesh_elements(2, s, 3, 4, mesh,
                                        "geometry file '" + file + "': the section mesh has "
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

      // Revolve into the cell.
      gmsh::vectorpair out;
      gmsh_session.run(file, "revolving the section", [&] {
        gmsh::model::geo::revolve(all_surfaces, 0., 0., 0., 0., 0., 1., cell_angle, out, {1}, {},
                                  true);
        gmsh::model::geo::synchronize();
      });

      std::map<unsigned int, std::vector<int>> volumes_of_material;
      std::vector<int>                         top_surfaces, lateral_surfaces;
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
      std::map<unsigned int, std::set<int>> surfaces_of_boundary;
      for (const int lateral : lateral_surfaces)
        {
          gmsh::vectorpair curves;
          gmsh::model::getBoundary({{2, lateral}}, curves, false, false, false);
          for (const auto &[id, boundary_curves] : curves_of_boundary)
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
      std::vector<int> bottom;
      for (const auto &[dim, s] : all_surfaces)
        bottom.push_back(s);
      gmsh::model::addPhysicalGroup(2, bottom, periodic_first);
      gmsh::model::addPhysicalGroup(2, top_surfaces, periodic_second);

      gmsh_session.run(file, "meshing the cell", [] { gmsh::model::mesh::generate(3); });

      // The cell, straight from gmsh's arrays.
      const MeshNodes               mesh = mesh_nodes();
      std::vector<dealii::Point<3>> vertices;
      for (const auto &xyz : mesh.xyz)
        vertices.emplace_back(xyz[0], xyz[1], xyz[2]);
      std::vector<dealii::CellData<3>> cells;
      for (const auto &[material, volumes] : volumes_of_material)
        for (const int v : volumes)
          for (auto h : mesh_elements(3, v, 5, 8, mesh,
                                      "geometry file '" + file + "': the cell mesh has elements "
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
      dealii::SubCellData                        boundary;
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
                                           "geometry file '" + file + "': the cell's boundary "
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
          throw InputError("geometry file '" + file + "': the mesh gmsh made is not a valid "
                           "deal.II mesh (distorted cells?): " + info.str());
        }
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
                const auto &a = block.corners[i], &b = block.corners[(i + 1) % block.corners.size()];
                sum += (a[0] + b[0]) * (a[0] * b[1] - b[0] * a[1]);
              }
            integral += std::abs(sum) / 6.;
          }
      return cell_angle * integral;
    }



    void
    attach_cylindrical_manifold(dealii::Triangulation<3> &triangulation)
    {
      triangulation.set_all_manifold_ids(0);
      triangulation.set_manifold(0, dealii::CylindricalManifold<3>(2));
    }



    void
    make_ring(const dealii::Triangulation<3> &cell,
              const double                    angle,
              const unsigned int              n_cells,
              dealii::Triangulation<3>       &ring)
    {
      std::vector<std::unique_ptr<dealii::Triangulation<3>>> copies;
      std::vector<const dealii::Triangulation<3> *>          pointers;
      for (unsigned int k = 0; k < n_cells; ++k)
        {
          copies.push_back(std::make_unique<dealii::Triangulation<3>>());
          copies.back()->copy_triangulation(cell);
          dealii::GridTools::rotate(k * angle, 2, *copies.back());
          pointers.push_back(copies.back().get());
        }
      double size = 0.;
      for (const auto &v : cell.get_vertices())
        size = std::max(size, v.norm());
      dealii::GridGenerator::merge_triangulations(pointers, ring, 1e-9 * size, false);

      // merge_triangulations drops boundary ids. A face of the ring is a
      // rotated face of the cell: the radius and axial position of its
      // vertex average identify it.
      const auto key = [size](const dealii::TriaAccessor<2, 3, 3> &face) {
        dealii::Point<3> c;
        for (unsigned int v = 0; v < 4; ++v)
          c += face.vertex(v) / 4.;
        const double scale = 1e-9 * size;
        return std::make_pair(std::llround(std::hypot(c[0], c[1]) / scale),
                              std::llround(c[2] / scale));
      };
      std::map<std::pair<long long, long long>, dealii::types::boundary_id> ids;
      std::size_t outer_faces = 0, ring_faces = 0;
      for (const auto &cell_iterator : cell.active_cell_iterators())
        for (const auto &face : cell_iterator->face_iterators())
          if (face->at_boundary() && face->boundary_id() != periodic_first &&
              face->boundary_id() != periodic_second)
            {
              ids[key(*face)] = face->boundary_id();
              ++outer_faces;
            }
      for (const auto &cell_iterator : ring.active_cell_iterators())
        for (const auto &face : cell_iterator->face_iterators())
          ring_faces += face->at_boundary();
      // Every seam closed: a vertex left unmerged would leave a slit.
      if (ring_faces != n_cells * outer_faces)
        throw NumericalError("the ring of " + std::to_string(n_cells) + " cells has " +
                             std::to_string(ring_faces) + " boundary faces, not " +
                             std::to_string(n_cells * outer_faces) +
                             ": the periodic faces of the cell do not match when rotated");
      for (const auto &cell_iterator : ring.active_cell_iterators())
        for (const auto &face : cell_iterator->face_iterators())
          if (face->at_boundary())
            {
              const auto found = ids.find(key(*face));
              face->set_boundary_id(found == ids.end() ?
                                      dealii::types::boundary_id(free_surface) :
                                      found->second);
            }
      attach_cylindrical_manifold(ring);
    }
  } // namespace geometry
} // namespace greentread

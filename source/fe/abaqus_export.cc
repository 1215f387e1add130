#include <greentread/base/mesh_ids.h>
#include <greentread/fe/abaqus_export.h>

#include <deal.II/grid/tria_accessor.h>

#include <map>
#include <set>
#include <sstream>

namespace greentread
{
  namespace fe
  {
    using namespace dealii;

    void
    write_abaqus(const std::filesystem::path &file,
                 const Triangulation<3>      &triangulation,
                 const Mapping<3>            &mapping,
                 const MaterialParameters    &m,
                 const base::ParameterRecord &record)
    {
      base::AtomicFile out_file(file);
      auto            &out = out_file.stream();
      // 12 significant digits: CalculiX reads at most 20 characters per
      // number, and "-1.05623843005276e-13" (15 digits) would become -0.1056.
      out.precision(12);
      out << "*HEADING\n"
          << "GreenTread tyre mesh, C3D20 elements, SI units\n";
      record.write_comments(out, "** ");

      // Abaqus corner k is deal.II vertex corner[k]; mid-edge node 9 + k joins
      // the corners edge[k].
      const unsigned int corner[8]   = {0, 1, 3, 2, 4, 5, 7, 6};
      const unsigned int edge[12][2] = {{0, 1}, {1, 3}, {3, 2}, {2, 0}, {4, 5}, {5, 7},
                                        {7, 6}, {6, 4}, {0, 4}, {1, 5}, {3, 7}, {2, 6}};
      // deal.II face of each Abaqus face S1..S6.
      const unsigned int face_of[6] = {4, 5, 2, 1, 3, 0};

      const unsigned int                                   n_vertices = triangulation.n_vertices();
      std::map<unsigned int, Point<3>>                     node;
      std::map<unsigned int, std::array<unsigned int, 20>> element;
      for (const auto &cell : triangulation.active_cell_iterators())
        {
          std::array<unsigned int, 20> e;
          for (unsigned int k = 0; k < 8; ++k)
            {
              e[k]       = cell->vertex_index(corner[k]) + 1;
              node[e[k]] = cell->vertex(corner[k]);
            }
          for (unsigned int k = 0; k < 12; ++k)
            for (unsigned int l = 0; l < 12; ++l)
              {
                const unsigned int a = GeometryInfo<3>::line_to_cell_vertices(l, 0);
                const unsigned int b = GeometryInfo<3>::line_to_cell_vertices(l, 1);
                if ((a == edge[k][0] && b == edge[k][1]) || (a == edge[k][1] && b == edge[k][0]))
                  {
                    e[8 + k]            = n_vertices + cell->line_index(l) + 1;
                    const Point<3> unit = 0.5 * (GeometryInfo<3>::unit_cell_vertex(a) +
                                                 GeometryInfo<3>::unit_cell_vertex(b));
                    node[e[8 + k]]      = mapping.transform_unit_to_real_cell(cell, unit);
                  }
              }
          element[cell->active_cell_index() + 1] = e;
        }

      out << "*NODE, NSET=NALL\n";
      for (const auto &[id, p] : node)
        out << id << ", " << p[0] << ", " << p[1] << ", " << p[2] << '\n';

      const std::map<unsigned int, std::string> set_name = {
        {tread_id, "TREAD"}, {belt_id, "BELT"}, {sidewall_id, "SIDEWALL"}, {bead_id, "BEAD"}};
      std::map<unsigned int, std::vector<unsigned int>> by_material;
      for (const auto &cell : triangulation.active_cell_iterators())
        by_material[cell->material_id()].push_back(cell->active_cell_index() + 1);
      for (const auto &[material, ids] : by_material)
        {
          out << "*ELEMENT, TYPE=C3D20, ELSET=" << set_name.at(material) << '\n';
          for (const unsigned int id : ids)
            {
              const auto &e = element.at(id);
              // 15 numbers per line at most, then a continuation line.
              out << id;
              for (unsigned int k = 0; k < 20; ++k)
                out << (k == 14 ? ",\n" : ", ") << e[k];
              out << '\n';
            }
        }

      // Rim seat nodes and the inner surface, by face.
      std::set<unsigned int>                            seat;
      std::map<unsigned int, std::vector<unsigned int>> inner;
      for (const auto &cell : triangulation.active_cell_iterators())
        for (unsigned int s = 0; s < 6; ++s)
          {
            const auto face = cell->face(face_of[s]);
            if (!face->at_boundary())
              continue;
            const auto &e = element.at(cell->active_cell_index() + 1);
            if (face->boundary_id() == geometry::rim_seat)
              for (unsigned int k = 0; k < 20; ++k)
                {
                  // A node is on the face if it is a vertex of the face or
                  // the midpoint of one of its lines.
                  const Point<3> &p       = node.at(e[k]);
                  bool            on_face = false;
                  for (unsigned int v = 0; v < 4; ++v)
                    on_face = on_face || p.distance(face->vertex(v)) < 1e-12;
                  for (unsigned int l = 0; l < 4; ++l)
                    on_face =
                      on_face || (k >= 8 && e[k] == n_vertices + face->line(l)->index() + 1);
                  if (on_face)
                    seat.insert(e[k]);
                }
            if (face->boundary_id() == geometry::inner_surface)
              inner[s + 1].push_back(cell->active_cell_index() + 1);
          }
      const auto write_set = [&](const std::string &kind, const std::string &name,
                                 const auto &ids) {
        out << '*' << kind << ", " << (kind == "NSET" ? "NSET=" : "ELSET=") << name << '\n';
        unsigned int count = 0;
        for (const unsigned int id : ids)
          out << id << (++count % 16 == 0 || count == ids.size() ? "\n" : ", ");
      };
      write_set("NSET", "RIMSEAT", seat);
      for (const auto &[s, ids] : inner)
        write_set("ELSET", "INNER_S" + std::to_string(s), ids);
      out << "*SURFACE, NAME=INNER, TYPE=ELEMENT\n";
      for (const auto &[s, ids] : inner)
        out << "INNER_S" << s << ", S" << s << '\n';

      // Materials, with the belt orthotropic in cylindrical axes.
      out << "*ORIENTATION, NAME=CYL, SYSTEM=CYLINDRICAL\n0., 0., 0., 0., 0., 1.\n";
      const auto isotropic = [&](const std::string &name, double E, double nu, double rho) {
        out << "*MATERIAL, NAME=" << name << "\n*ELASTIC\n"
            << E << ", " << nu << "\n*DENSITY\n"
            << rho << '\n';
      };
      isotropic("TREAD", m.tread_E, m.tread_nu, m.tread_density);
      isotropic("SIDEWALL", m.sidewall_E, m.sidewall_nu, m.sidewall_density);
      isotropic("BEAD", m.bead_E, m.bead_nu, m.bead_density);
      out << "*MATERIAL, NAME=BELT\n*ELASTIC, TYPE=ENGINEERING CONSTANTS\n"
          << m.belt_E_r << ", " << m.belt_E_theta << ", " << m.belt_E_z << ", " << m.belt_nu_rtheta
          << ", " << m.belt_nu_rz << ", " << m.belt_nu_thetaz << ", " << m.belt_G_rtheta << ", "
          << m.belt_G_rz << ",\n"
          << m.belt_G_thetaz << ", 0.\n*DENSITY\n"
          << m.belt_density << '\n';
      // Rayleigh damping as comments: Abaqus would take '*DAMPING, ALPHA=,
      // BETA=' under each material, CalculiX does not.
      out << "** Rayleigh damping C = alpha M + beta K of each material (GreenTread's):\n";
      for (const auto &[id, material] : m.materials())
        out << "**   " << material.name << ": alpha = " << material.alpha
            << " 1/s, beta = " << material.beta << " s\n";
      for (const auto &[material, ids] : by_material)
        out << "*SOLID SECTION, ELSET=" << set_name.at(material)
            << ", MATERIAL=" << set_name.at(material)
            << (material == belt_id ? ", ORIENTATION=CYL" : "") << '\n';
      out_file.commit();
    }
  } // namespace fe
} // namespace greentread

#include <greentread/base/exceptions.h>
#include <greentread/base/parameters.h>
#include <greentread/geometry/geometry_parameters.h>

#include <cmath>
#include <regex>

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
                          "The gmsh .geo description of the section (a relative path is looked "
                          "for beside the scene file, then in the working "
                          "directory). Its DefineConstant parameters 'Parameters/<name>' are "
                          "set from this subsection; a new design is a new file.");
        const auto length = [&](const char *name, const char *value, const char *doc) {
          prm.declare_entry(name, value, base::RangePattern::positive("m"),
                            std::string(doc) + " Unit: m.");
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
        prm.declare_entry("Bulge height", "0.5", base::RangePattern::closed(0.05, 0.95, ""),
                          "Where the sidewall is widest, as a fraction of the way from the "
                          "bead up to the belt. Unit: 1.");
        length("Mesh size", "0.008",
               "Target element size in the section (transfinite: every block gets "
               "ceil(length / size) elements per side).");
        prm.declare_entry("Number of cells", "256", dealii::Patterns::Integer(3, 100000),
                          "N, cells in the ring: the cell is the section revolved by 2 pi / N. "
                          "Powers of two suit the recursive doubling of the periodic stage.");
        prm.declare_entry("Element degree", "auto", dealii::Patterns::Selection("auto|1|2|3|4"),
                          "The Lagrange degree of the elements: 1 or 2 for the 3D cell "
                          "(trilinear elements lock with nu = 0.49), 1 to 4 on the section of "
                          "'Green's functions/Method' = harmonic, so that p-refinement can be "
                          "set against h-refinement. 'auto': 4 on the section (within 2% of "
                          "the section twice as fine, doc/benchmarks.md), 2 on a 3D cell.");
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
        degree = prm.get("Element degree") == "auto" ? 0 : prm.get_integer("Element degree");
        other_constants = prm.get("Other constants");
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
        fail("'Bead width' = " + format_short(bead_width) +
             " m must be less than half the "
             "'Rim width' = " +
             format_short(rim_width) + " m: the beads would overlap");
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
        throw InputError(
          "parameter 'Geometry/Number of cells' = " + std::to_string(n_cells) +
          " is not allowed with 'Mesh size' = " + format_short(mesh_size) +
          " m; allowed: at most " + std::to_string(static_cast<unsigned long>(max_cells)) +
          " (the cell would be " + format_short(M_PI * rim_diameter / n_cells * 1e3) +
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
        {"Rim diameter", rim_diameter},     {"Section height", section_height},
        {"Tread width", tread_width},       {"Section width", section_width},
        {"Rim width", rim_width},           {"Tread thickness", tread_thickness},
        {"Belt thickness", belt_thickness}, {"Sidewall thickness", sidewall_thickness},
        {"Bead width", bead_width},         {"Bead height", bead_height},
        {"Bulge height", bulge_height},     {"Mesh size", mesh_size}};
      const std::regex item("^\\s*([^=,]+?)\\s*=\\s*([-+0-9.eE]+)\\s*$");
      std::size_t      begin = 0;
      while (!other_constants.empty() && begin <= other_constants.size())
        {
          const std::size_t comma =
            std::min(other_constants.find(',', begin), other_constants.size());
          const std::string part = other_constants.substr(begin, comma - begin);
          std::smatch       m;
          if (!std::regex_match(part, m, item))
            throw InputError("parameter 'Geometry/Other constants' = " + other_constants +
                             " is not allowed; allowed: 'Name=value, Name=value' ('" + part + "')");
          numbers[m[1]] = std::stod(m[2]);
          begin         = comma + 1;
        }
      return numbers;
    }
  } // namespace geometry
} // namespace greentread

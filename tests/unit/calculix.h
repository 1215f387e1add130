#pragma once

// CalculiX (Debian calculix-ccx), the independent finite-element program
// of the unit/calculix and unit/calculix_green checks, and the coarse tyre
// they export to it (2 cm mesh, 32 cells).

#include <greentread/geometry/tyre_cell.h>

#include <boost/test/unit_test.hpp>

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>

namespace test
{
  inline bool
  calculix_available()
  {
    return std::system("command -v ccx > /dev/null 2>&1") == 0;
  }

  /// Run ccx on job.inp in @p dir; the contents of job.dat.
  inline std::string
  run_calculix(const std::filesystem::path &dir, const std::string &input)
  {
    std::ofstream(dir / "job.inp") << input;
    const std::string command =
      "cd '" + dir.string() + "' && OMP_NUM_THREADS=2 ccx -i job > ccx.log 2>&1";
    BOOST_REQUIRE_MESSAGE(std::system(command.c_str()) == 0,
                          "CalculiX failed; see " << (dir / "ccx.log").string());
    std::ifstream     in(dir / "job.dat");
    std::stringstream text;
    text << in.rdbuf();
    return text.str();
  }

  inline greentread::geometry::GeometryParameters
  coarse_tyre()
  {
    greentread::geometry::GeometryParameters p;
    p.geo_file  = GREENTREAD_SOURCE_DIR "/geometry/tyre_165_65_r13.geo";
    p.mesh_size = 0.02;
    p.n_cells   = 32;
    return p;
  }
} // namespace test

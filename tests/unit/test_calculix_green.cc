// The static Green's functions of the ring against CalculiX (Debian
// calculix-ccx 2.20) on the exported ring. The coarse
// ring (2 cm mesh, 32 cells), rim clamped, no inflation (no Kp, nor any
// pressure in CalculiX). Ours: the Bloch solver at w = 0, 3 x 2
// tributary-area points on the crown, each rectangle one whole tread face
// (one cell along, 53.5 mm; one face across, 19.1 mm, two of them about
// y = 0), which the test checks from the exported nodes. CalculiX: one
// *STATIC step per point, a pressure p = 1 (*DLOAD P<s>) on that face, and
// the mean radial displacement over each face by the faces' own 8-node
// serendipity shape functions; g_ij = -mean_i / (p A_j).
//
// They differ by the elements: CalculiX's C3D20 (serendipity, fully
// integrated, on the exported 20 nodes of each brick) against our Q2
// 27-node bricks with a quadratic mapping onto the arc; one element through
// the 8 mm tread, nu = 0.49. The loads are the same: the crown is a
// cylinder, so the pressure is the radial traction (the faces' areas
// agree to 2e-6). Measured on the coarse ring: ours 3.4% more compliant at
// the driving points, every pair within 6.8% (the far diagonal transfer,
// 5% of the driving point). On a finer ring (1 cm, 64 cells) with the same
// rectangles, each 2 x 2 faces, 0.47% and 0.97%: they converge together,
// while each program's driving point moves 6.5% (ours) and 9.7% (CalculiX)
// between the meshes. The finer case takes about 40 s of CalculiX and runs
// only with GREENTREAD_FINE_CALCULIX=1. CalculiX's matrix is symmetric to
// its printed digits (7e-8).
#include "calculix.h"
#include "scratch.h"
#include <greentread/fe/abaqus_export.h>
#include <greentread/fe/elastic_model.h>
#include <greentread/geometry/tyre_cell.h>
#include <greentread/periodic/contact_patch.h>
#include <greentread/periodic/green_solvers.h>
#include <greentread/periodic/periodic_cell.h>

#include <boost/test/unit_test.hpp>

#include <algorithm>
#include <array>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <map>
#include <regex>
#include <set>
#include <sstream>

using namespace greentread;
using namespace dealii;

namespace
{
  using test::calculix_available;
  using test::coarse_tyre;
  using test::run_calculix;

  /// The nodes and C3D20 elements of an Abaqus input as fe::write_abaqus
  /// writes them (each element's 20 nodes on two lines).
  struct AbaqusMesh
  {
    std::map<unsigned int, Point<3>>                     nodes;
    std::map<unsigned int, std::array<unsigned int, 20>> elements;
  };

  AbaqusMesh
  read_abaqus(const std::filesystem::path &file)
  {
    AbaqusMesh          mesh;
    std::ifstream       in(file);
    std::string         line, block;
    std::vector<double> numbers;
    while (std::getline(in, line))
      {
        if (line.rfind("**", 0) == 0)
          continue;
        if (!line.empty() && line[0] == '*')
          {
            block = line.substr(0, line.find(','));
            numbers.clear();
            continue;
          }
        std::replace(line.begin(), line.end(), ',', ' ');
        std::istringstream fields(line);
        for (double v; fields >> v;)
          numbers.push_back(v);
        if (block == "*NODE" && numbers.size() == 4)
          mesh.nodes[static_cast<unsigned int>(numbers[0])] =
            Point<3>(numbers[1], numbers[2], numbers[3]);
        else if (block == "*ELEMENT" && numbers.size() == 21)
          for (unsigned int k = 0; k < 20; ++k)
            mesh.elements[static_cast<unsigned int>(numbers[0])][k] =
              static_cast<unsigned int>(numbers[k + 1]);
        if (block != "*ELEMENT" || numbers.size() == 21)
          numbers.clear();
      }
    return mesh;
  }

  /// CalculiX's faces P1..P6 of a C3D20 (its manual, element C3D20): the
  /// four corners in turn, then the mid-edge nodes between them, as
  /// positions (from 1) in the element's node list.
  // clang-format off
  constexpr unsigned int c3d20_face[6][8] = {{1, 2, 3, 4, 9, 10, 11, 12},
                                             {5, 8, 7, 6, 16, 15, 14, 13},
                                             {1, 5, 6, 2, 17, 13, 18, 9},
                                             {2, 6, 7, 3, 18, 14, 19, 10},
                                             {3, 7, 8, 4, 19, 15, 20, 11},
                                             {4, 8, 5, 1, 20, 16, 17, 12}};
  // clang-format on

  /// The area of a face of 8 nodes @p x (corners, then mid-edges) and the
  /// integral of @p v over it, both with the face's serendipity shape
  /// functions, by 3 x 3 Gauss points.
  std::array<double, 2>
  integrate_face(const std::array<Point<3>, 8> &x, const std::array<double, 8> &v)
  {
    const double xi_k[8]  = {-1., 1., 1., -1., 0., 1., 0., -1.};
    const double eta_k[8] = {-1., -1., 1., 1., -1., 0., 1., 0.};
    const double g[3] = {-std::sqrt(0.6), 0., std::sqrt(0.6)}, w[3] = {5. / 9., 8. / 9., 5. / 9.};
    std::array<double, 2> sum = {{0., 0.}};
    for (unsigned int a = 0; a < 3; ++a)
      for (unsigned int b = 0; b < 3; ++b)
        {
          const double xi = g[a], eta = g[b];
          Tensor<1, 3> d_xi, d_eta;
          double       value = 0.;
          for (unsigned int k = 0; k < 8; ++k)
            {
              const double s = xi * xi_k[k], t = eta * eta_k[k];
              double       N, N_xi, N_eta;
              if (k < 4)
                {
                  N     = 0.25 * (1. + s) * (1. + t) * (s + t - 1.);
                  N_xi  = 0.25 * xi_k[k] * (1. + t) * (2. * s + t);
                  N_eta = 0.25 * eta_k[k] * (1. + s) * (s + 2. * t);
                }
              else if (xi_k[k] == 0.)
                {
                  N     = 0.5 * (1. - xi * xi) * (1. + t);
                  N_xi  = -xi * (1. + t);
                  N_eta = 0.5 * eta_k[k] * (1. - xi * xi);
                }
              else
                {
                  N     = 0.5 * (1. + s) * (1. - eta * eta);
                  N_xi  = 0.5 * xi_k[k] * (1. - eta * eta);
                  N_eta = -eta * (1. + s);
                }
              d_xi += N_xi * x[k];
              d_eta += N_eta * x[k];
              value += N * v[k];
            }
          const double dS = cross_product_3d(d_xi, d_eta).norm() * w[a] * w[b];
          sum[0] += dS;
          sum[1] += value * dS;
        }
    return sum;
  }

  /// One C3D20 face: its element and its number s (P<s>).
  struct Face
  {
    unsigned int element, number;
  };

  /**
   * The tread faces of @p mesh that tile the rectangle of the tread
   * surface theta in [t0, t1], z in [z0, z1]: the faces whose corners are
   * all on the outer surface (no node further out at the same theta and
   * z) and in the closed rectangle. Each must span @p dtheta x @p dz, and
   * together they must cover the rectangle; the test fails otherwise.
   */
  std::vector<Face>
  faces_of_rectangle(const AbaqusMesh &mesh,
                     const double      t0,
                     const double      t1,
                     const double      z0,
                     const double      z1,
                     const double      dtheta,
                     const double      dz)
  {
    const double tol = 1e-9;
    const double tc = 0.5 * (t0 + t1), zc = 0.5 * (z0 + z1);
    const auto   theta_of = [&](const Point<3> &p) {
      return tc + std::remainder(std::atan2(p[1], p[0]) - tc, 2. * M_PI);
    };
    std::vector<unsigned int> inside;
    for (const auto &[id, p] : mesh.nodes)
      if (std::abs(theta_of(p) - tc) < 0.5 * (t1 - t0) + tol &&
          std::abs(p[2] - zc) < 0.5 * (z1 - z0) + tol)
        inside.push_back(id);
    std::set<unsigned int> outer;
    for (const unsigned int a : inside)
      {
        const Point<3> &p   = mesh.nodes.at(a);
        bool            top = true;
        for (const unsigned int b : inside)
          {
            const Point<3> &q = mesh.nodes.at(b);
            top               = top && !(std::abs(theta_of(q) - theta_of(p)) < tol &&
                           std::abs(q[2] - p[2]) < tol && q.norm() > p.norm() + tol);
          }
        if (top)
          outer.insert(a);
      }
    std::vector<Face> faces;
    for (const auto &[id, e] : mesh.elements)
      for (unsigned int s = 0; s < 6; ++s)
        {
          bool   on    = true;
          double t_min = 1e9, t_max = -1e9, z_min = 1e9, z_max = -1e9;
          for (unsigned int c = 0; c < 4; ++c)
            {
              const unsigned int node = e[c3d20_face[s][c] - 1];
              on                      = on && outer.count(node);
              const Point<3> &p       = mesh.nodes.at(node);
              t_min                   = std::min(t_min, theta_of(p));
              t_max                   = std::max(t_max, theta_of(p));
              z_min                   = std::min(z_min, p[2]);
              z_max                   = std::max(z_max, p[2]);
            }
          if (!on)
            continue;
          BOOST_TEST(std::abs(t_max - t_min - dtheta) < tol * dtheta);
          BOOST_TEST(std::abs(z_max - z_min - dz) < tol * dz);
          faces.push_back({id, s + 1});
        }
    BOOST_TEST(std::abs(faces.size() * dtheta * dz - (t1 - t0) * (z1 - z0)) <
               tol * (t1 - t0) * (z1 - z0));
    return faces;
  }

  /// The static Green's functions of the rim-clamped, uninflated ring,
  /// ours and CalculiX's, at 3 x 2 points on the crown whose tributary
  /// rectangles are each s x s whole tread faces.
  struct StaticGreen
  {
    Eigen::MatrixXd          ours, theirs;
    std::vector<std::string> names;
    /// CalculiX's area of each rectangle (its faces') over ours.
    double area_ratio   = 0.;
    double seconds_ours = 0., seconds_calculix = 0.;
  };

  StaticGreen
  static_green_functions(const double mesh_size, const unsigned int n_cells, const unsigned int s)
  {
    using clock                             = std::chrono::steady_clock;
    auto                         start      = clock::now();
    geometry::GeometryParameters parameters = coarse_tyre();
    parameters.mesh_size                    = mesh_size;
    parameters.n_cells                      = n_cells;
    const geometry::TyreCell     tyre(parameters);
    const fe::MaterialParameters materials;
    fe::ElasticModel             model(tyre.cell(), materials.materials());
    model.assemble();
    const auto cell = periodic::make_periodic_cell(model, tyre.angle(), n_cells, geometry::rim_seat,
                                                   geometry::tread_surface, false);

    // The tread nodes across (corners and mid-edges of the quadratic faces)
    // on the cell's left face; a corner at z = 0, and 2 s faces of one
    // width w about it.
    std::vector<double> z;
    double              R = 0.;
    for (unsigned int i = 0; i < cell.n_face; ++i)
      if (cell.dofs[i].on_tread && cell.dofs[i].component == 0)
        {
          z.push_back(cell.dofs[i].axial);
          R = std::max(R, cell.dofs[i].radius);
        }
    std::sort(z.begin(), z.end());
    const std::size_t k = std::min_element(z.begin(), z.end(),
                                           [](double a, double b) {
                                             return std::abs(a) < std::abs(b);
                                           }) -
                          z.begin();
    BOOST_REQUIRE(std::abs(z[k]) < 1e-12 && k % 2 == 0 && k >= 4 * s && k + 4 * s < z.size());
    const double w = z[k + 2] - z[k];
    for (std::size_t f = k - 4 * s; f < k + 4 * s; f += 2)
      BOOST_REQUIRE(std::abs(z[f + 2] - z[f] - w) < 1e-9 * w);

    // Ours: 3 x 2 points, each rectangle s cells along and s faces across.
    periodic::PatchRequest request;
    request.points_along  = 3;
    request.points_across = 2;
    request.length        = 3. * s * R * tyre.angle();
    request.width         = 2. * s * w;
    request.load          = periodic::PointLoad::tributary_area;
    const auto patch      = periodic::place_contact_points(cell, request);
    BOOST_REQUIRE(patch.points.size() == 6u);
    for (const auto &p : patch.points)
      BOOST_REQUIRE(std::abs(p.radius - R) < 1e-12);
    periodic::SolveDiagnostics diagnostics;
    StaticGreen                result;
    result.ours = periodic::make_green_solver(periodic::Method::bloch, cell, patch)
                    ->solve(0., diagnostics)
                    .real();
    result.seconds_ours = std::chrono::duration<double>(clock::now() - start).count();

    // CalculiX: the ring exported, p = 1 on the faces of one rectangle per
    // step, the faces' nodal displacements printed.
    start = clock::now();
    Triangulation<3> ring;
    geometry::make_ring(tyre.cell(), tyre.angle(), n_cells, ring);
    const fe::ElasticModel ring_model(ring, materials.materials());
    const auto             dir = test::scratch_directory("calculix_green");
    base::ParameterRecord  record;
    record.header = "calculix static Green's functions";
    fe::write_abaqus(dir / "ring.inp", ring, ring_model.mapping(), materials, record);
    const AbaqusMesh mesh = read_abaqus(dir / "ring.inp");

    std::vector<std::vector<Face>> faces;
    std::set<unsigned int>         printed;
    std::string                    steps;
    for (const auto &p : patch.points)
      {
        // The rectangle's edges must be cell faces along theta and tread
        // nodes across.
        const double t0 = p.angle - 0.5 * patch.dx / R, t1 = p.angle + 0.5 * patch.dx / R;
        const double z0 = p.y - 0.5 * patch.dy, z1 = p.y + 0.5 * patch.dy;
        BOOST_TEST(std::abs(t0 / tyre.angle() - std::round(t0 / tyre.angle())) < 1e-9);
        BOOST_TEST(std::abs(z0 / w - std::round(z0 / w)) < 1e-9);
        faces.push_back(faces_of_rectangle(mesh, t0, t1, z0, z1, tyre.angle(), w));
        BOOST_REQUIRE(faces.back().size() == s * s);
        steps += "*STEP\n*STATIC\n*DLOAD, OP=NEW\n";
        for (const auto &f : faces.back())
          {
            steps += std::to_string(f.element) + ", P" + std::to_string(f.number) + ", 1.\n";
            for (const unsigned int n : c3d20_face[f.number - 1])
              printed.insert(mesh.elements.at(f.element)[n - 1]);
          }
        steps += "*NODE PRINT, NSET=FACES\nU\n*END STEP\n";
        char name[64];
        std::snprintf(name, sizeof(name), "(%.1f, %.1f) mm", 1e3 * p.x, 1e3 * p.y);
        result.names.push_back(name);
      }
    std::string set;
    for (const unsigned int n : printed)
      set += std::to_string(n) + ",\n";
    const std::string dat = run_calculix(dir, "*INCLUDE, INPUT=ring.inp\n*NSET, NSET=FACES\n" +
                                                set + "*BOUNDARY\nRIMSEAT, 1, 3\n" + steps);

    // Each step's block of displacements, in order.
    std::vector<std::map<unsigned int, Point<3>>> u;
    std::istringstream                            lines(dat);
    std::string                                   line;
    std::smatch                                   m;
    const std::regex row("^\\s*([0-9]+)\\s+([-+0-9.Ee]+)\\s+([-+0-9.Ee]+)\\s+([-+0-9.Ee]+)\\s*$");
    while (std::getline(lines, line))
      if (line.find("displacements (vx,vy,vz)") != std::string::npos)
        u.emplace_back();
      else if (!u.empty() && std::regex_match(line, m, row))
        u.back()[std::stoul(m[1])] = Point<3>(std::stod(m[2]), std::stod(m[3]), std::stod(m[4]));
    BOOST_REQUIRE(u.size() == patch.points.size());

    // g_ij: the mean radial displacement over rectangle i under a unit
    // force on rectangle j, its pressure's total p A_j (inward, hence the
    // minus sign).
    const unsigned int  P = patch.points.size();
    std::vector<double> area(P, 0.);
    result.theirs.resize(P, P);
    for (unsigned int j = 0; j < P; ++j)
      for (unsigned int i = 0; i < P; ++i)
        {
          double integral = 0.;
          area[i]         = 0.;
          for (const auto &f : faces[i])
            {
              std::array<Point<3>, 8> x;
              std::array<double, 8>   u_r;
              for (unsigned int n = 0; n < 8; ++n)
                {
                  const unsigned int node =
                    mesh.elements.at(f.element)[c3d20_face[f.number - 1][n] - 1];
                  x[n] = mesh.nodes.at(node);
                  BOOST_REQUIRE(u[j].count(node));
                  u_r[n] = (u[j].at(node)[0] * x[n][0] + u[j].at(node)[1] * x[n][1]) /
                           std::hypot(x[n][0], x[n][1]);
                }
              const auto sum = integrate_face(x, u_r);
              area[i] += sum[0];
              integral += sum[1];
            }
          result.theirs(i, j) = integral / area[i];
        }
    for (unsigned int j = 0; j < P; ++j)
      result.theirs.col(j) /= -area[j];
    // Ours: dx (the arc at R) x dy, the crown being a cylinder of radius R.
    result.area_ratio       = area[0] / (patch.dx * patch.dy);
    result.seconds_calculix = std::chrono::duration<double>(clock::now() - start).count();
    return result;
  }

  /**
   * Print ours against CalculiX's for every pair, and check: every
   * |ours / CalculiX - 1| within @p bound, the driving points' within
   * @p driving_bound; CalculiX's matrix symmetric to its printed digits.
   */
  void
  compare(const StaticGreen &g,
          const std::string &mesh,
          const double       driving_bound,
          const double       bound)
  {
    BOOST_TEST_MESSAGE("static Green's functions, "
                       << mesh << ": CalculiX's face areas / ours " << g.area_ratio << "; ours "
                       << g.seconds_ours << " s, CalculiX " << g.seconds_calculix << " s");
    double worst = 0., worst_driving = 0., asymmetry = 0.;
    for (unsigned int i = 0; i < g.ours.rows(); ++i)
      for (unsigned int j = 0; j < g.ours.cols(); ++j)
        {
          const double ratio = g.ours(i, j) / g.theirs(i, j);
          worst              = std::max(worst, std::abs(ratio - 1.));
          if (i == j)
            worst_driving = std::max(worst_driving, std::abs(ratio - 1.));
          asymmetry =
            std::max(asymmetry, std::abs(g.theirs(i, j) - g.theirs(j, i)) / g.theirs(i, i));
          if (j >= i)
            BOOST_TEST_MESSAGE("  g at " << g.names[i] << " from " << g.names[j] << ": ours "
                                         << g.ours(i, j) << " m/N, CalculiX " << g.theirs(i, j)
                                         << " m/N, ratio " << ratio);
        }
    BOOST_TEST_MESSAGE("  largest |ours / CalculiX - 1|: " << worst << " (driving points "
                                                           << worst_driving << ")");
    BOOST_TEST_MESSAGE("  CalculiX's reciprocity, largest |g_ij - g_ji| / g_ii: " << asymmetry);
    BOOST_TEST(std::abs(g.area_ratio - 1.) < 1e-5);
    BOOST_TEST(worst_driving < driving_bound);
    BOOST_TEST(worst < bound);
    BOOST_TEST(asymmetry < 1e-6);
  }

  /// The finer mesh's case runs only when asked for (about 40 s of
  /// CalculiX): GREENTREAD_FINE_CALCULIX=1.
  boost::test_tools::assertion_result
  fine_mesh_asked(boost::unit_test::test_unit_id)
  {
    return std::getenv("GREENTREAD_FINE_CALCULIX") != nullptr;
  }
} // namespace

BOOST_AUTO_TEST_SUITE(calculix_green)

BOOST_AUTO_TEST_CASE(static_green_functions_with_pressure_loads)
{
  BOOST_REQUIRE_MESSAGE(calculix_available(),
                        "ccx not found: apt-get install calculix-ccx (scripts/setup.sh does)");
  // Measured: driving points 3.4%, every pair 6.8%.
  compare(static_green_functions(0.02, 32, 1), "2 cm, N = 32", 0.04, 0.08);
}

BOOST_AUTO_TEST_CASE(static_green_functions_on_a_finer_mesh,
                     *boost::unit_test::precondition(fine_mesh_asked))
{
  BOOST_REQUIRE_MESSAGE(calculix_available(),
                        "ccx not found: apt-get install calculix-ccx (scripts/setup.sh does)");
  // Measured: driving points 0.47%, every pair 0.97%.
  compare(static_green_functions(0.01, 64, 2),
          "1 cm, N = 64, the same rectangles, 2 x 2 faces each", 0.006, 0.012);
}

BOOST_AUTO_TEST_SUITE_END()

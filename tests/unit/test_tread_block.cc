// The tread block's finite-element compliance (contact/tread_block.h),
// the reference for the blocks of a tread pattern:
// - with no grooves (margins 0, sliding sides) the block is one period of an
//   endless layer under a periodic load, whose compliance the layer's
//   Fourier series gives in closed form (contact/elastic_layer.h): the FE
//   converges to it as the mesh is refined;
// - a block with its grooves against CalculiX (an independent program) on
//   the same mesh of 20-node bricks, at the block's corner and centre;
// - the contact grid with a `blocks` pattern's finite blocks (the endless
//   layer plus what the blocks add, BlockCompliance) against the FE block on
//   a finer mesh, at the block's corner and centre.
#include "calculix.h"
#include "scratch.h"
#include <greentread/base/mesh_ids.h>
#include <greentread/contact/contact_grid.h>
#include <greentread/contact/elastic_layer.h>
#include <greentread/contact/tread_block.h>
#include <greentread/contact/tread_pattern.h>
#include <greentread/fe/abaqus_export.h>
#include <greentread/fe/material_parameters.h>

#include <deal.II/fe/mapping_q1.h>
#include <deal.II/grid/tria_accessor.h>

#include <boost/test/unit_test.hpp>

#include <Eigen/Eigenvalues>

#include <cmath>
#include <fstream>
#include <map>
#include <regex>
#include <sstream>

using namespace greentread;
using namespace greentread::contact;

namespace
{
  /// The default tread rubber (7 MPa, nu = 0.49).
  ElasticLayer
  rubber()
  {
    return ElasticLayer();
  }

  /// The layer's series for a centred a x a rectangle on a period P.
  double
  series(const double a, const double P)
  {
    const LayerComplianceTable table(rubber());
    const unsigned int         n = std::lround(P / a);
    return rectangle_lattice_compliance(
      [&](const double k) {
        return table(k);
      },
      a, a, 0, 0, n, n, 64)(0, 0);
  }

  /// The FE's compliance of that rectangle on a slab P x P x 8 mm.
  double
  slab(const double a, const double P, const double cell)
  {
    TreadBlockGeometry g;
    g.length = g.width = P;
    g.height           = 0.006;
    g.base             = 0.002;
    g.margin_along = g.margin_across = 0.;
    const TreadBlock block(g, rubber(),
                           {{0.5 * (P - a), 0.5 * (P + a), 0.5 * (P - a), 0.5 * (P + a)}}, cell);
    return block.compliance()(0, 0);
  }
} // namespace

BOOST_AUTO_TEST_SUITE(tread_block)

BOOST_AUTO_TEST_CASE(endless_layer_against_its_series)
{
  // A 4 mm square on a 24 mm period of the 8 mm layer. Measured
  // (2026-12-07): the FE below the series by 7.1% on 2 mm cells, 3.1% on
  // 1.33 mm and 2.1% on 1 mm (not run here): it converges to it, the
  // error about h^2 at first (the pressure's edges slow it). Bounds within
  // 1.6x of each.
  const double a = 0.004, P = 0.024, exact = series(a, P);
  const double coarse = slab(a, P, 0.002), fine = slab(a, P, 0.004 / 3.);
  BOOST_TEST_MESSAGE("layer series " << exact << " m/N; FE " << coarse << " (2 mm cells), " << fine
                                     << " (1.33 mm)");
  BOOST_TEST(std::abs(coarse / exact - 1.) < 0.1);
  BOOST_TEST(std::abs(fine / exact - 1.) < 0.05);
  BOOST_TEST(std::abs(fine - exact) < 0.7 * std::abs(coarse - exact));
}

BOOST_AUTO_TEST_CASE(block_against_calculix)
{
  BOOST_REQUIRE_MESSAGE(test::calculix_available(),
                        "ccx not found: apt-get install calculix-ccx (scripts/setup.sh does)");
  // A block 16 x 16 x 6 mm on 2 mm of undertread reaching 2 mm beyond it;
  // 4 mm squares at its corner and centre, and its whole top; 2 mm cells.
  TreadBlockGeometry g;
  g.length = g.width = 0.016;
  g.margin_along = g.margin_across  = 0.002;
  const double                    a = 0.004;
  const std::vector<TopRectangle> squares{
    {0., a, 0., a}, {0.006, 0.010, 0.006, 0.010}, {0., g.length, 0., g.width}};
  const TreadBlock      block(g, rubber(), squares, 0.002);
  const Eigen::MatrixXd C = block.compliance();

  // Symmetric and positive definite; the corner softer than the centre.
  BOOST_TEST((C - C.transpose()).cwiseAbs().maxCoeff() < 1e-12 * C.maxCoeff());
  BOOST_TEST(Eigen::SelfAdjointEigenSolver<Eigen::MatrixXd>(C).eigenvalues().minCoeff() > 0.);
  BOOST_TEST(C(0, 0) > 1.5 * C(1, 1));

  // CalculiX: the same mesh as 20-node bricks, each square loaded alone.
  const std::filesystem::path dir = test::scratch_directory("tread_block");
  const double                top = g.base + g.height;
  for (std::size_t r = 0; r < squares.size(); ++r)
    {
      const TopRectangle      &R = squares[r];
      dealii::Triangulation<3> mesh;
      mesh.copy_triangulation(block.triangulation());
      const auto inside = [&](const dealii::Point<3> &c) {
        return std::abs(c[2] - top) < 1e-9 && c[0] > R.x0 && c[0] < R.x1 && c[1] > R.y0 &&
               c[1] < R.y1;
      };
      for (const auto &cell : mesh.active_cell_iterators())
        for (const auto &face : cell->face_iterators())
          if (face->at_boundary() && inside(face->center()))
            face->set_boundary_id(geometry::inner_surface);
      fe::MaterialParameters materials;
      materials.tread_E  = rubber().youngs_modulus;
      materials.tread_nu = rubber().poissons_ratio;
      base::ParameterRecord record;
      record.header = "tread block test";
      fe::write_abaqus(dir / "block.inp", mesh, dealii::MappingQ1<3>(), materials, record);

      // Node sets: the undertread's sliding sides, and the loaded faces'
      // nodes with their weights in the mean over the square (a flat
      // 8-node face: corners -1/12, mid-edges 1/3, times its share).
      std::ostringstream                   sides_x, sides_y, loaded;
      std::map<unsigned, double>           weight;
      const unsigned int                   n_vertices = mesh.n_vertices();
      std::map<unsigned, dealii::Point<3>> node;
      for (const auto &cell : mesh.active_cell_iterators())
        for (const auto &face : cell->face_iterators())
          {
            for (unsigned int v = 0; v < 4; ++v)
              node[face->vertex_index(v) + 1] = face->vertex(v);
            for (unsigned int l = 0; l < 4; ++l)
              node[n_vertices + face->line(l)->index() + 1] = face->line(l)->center();
            if (!face->at_boundary() || face->boundary_id() != geometry::inner_surface)
              continue;
            const double share = face->measure() / ((R.x1 - R.x0) * (R.y1 - R.y0));
            for (unsigned int v = 0; v < 4; ++v)
              weight[face->vertex_index(v) + 1] -= share / 12.;
            for (unsigned int l = 0; l < 4; ++l)
              weight[n_vertices + face->line(l)->index() + 1] += share / 3.;
          }
      for (const auto &[id, p] : node)
        {
          if (p[2] > g.base + 1e-12)
            continue;
          if (std::abs(p[0] + g.margin_along) < 1e-12 ||
              std::abs(p[0] - g.length - g.margin_along) < 1e-12)
            sides_x << id << "\n";
          if (std::abs(p[1] + g.margin_across) < 1e-12 ||
              std::abs(p[1] - g.width - g.margin_across) < 1e-12)
            sides_y << id << "\n";
        }
      for (const auto &[id, w] : weight)
        loaded << id << "\n";
      std::ifstream     in(dir / "block.inp");
      std::stringstream all;
      all << in.rdbuf();
      std::string  dload;
      const double pressure = 1. / ((R.x1 - R.x0) * (R.y1 - R.y0));
      for (unsigned int s = 1; s <= 6; ++s)
        if (all.str().find("ELSET=INNER_S" + std::to_string(s)) != std::string::npos)
          dload += "INNER_S" + std::to_string(s) + ", P" + std::to_string(s) + ", " +
                   std::to_string(pressure) + "\n";
      const std::string out = test::run_calculix(
        dir, "*INCLUDE, INPUT=block.inp\n*NSET, NSET=SIDEX\n" + sides_x.str() +
               "*NSET, NSET=SIDEY\n" + sides_y.str() + "*NSET, NSET=LOADED\n" + loaded.str() +
               "*BOUNDARY\nRIMSEAT, 1, 3\nSIDEX, 1, 1\nSIDEY, 2, 2\n*STEP\n*STATIC\n*DLOAD\n" +
               dload + "*NODE PRINT, NSET=LOADED\nU\n*END STEP\n");
      // "node ux uy uz" rows: the mean displacement into the block.
      double           mean  = 0.;
      unsigned int     found = 0;
      const std::regex row("\\n\\s*([0-9]+)\\s+([-+0-9.Ee]+)\\s+([-+0-9.Ee]+)\\s+([-+0-9.Ee]+)");
      for (std::sregex_iterator m(out.begin(), out.end(), row), end; m != end; ++m)
        {
          const auto w = weight.find(std::stoul((*m)[1]));
          if (w == weight.end())
            continue;
          mean -= w->second * std::stod((*m)[4]);
          ++found;
        }
      BOOST_REQUIRE_EQUAL(found, weight.size());
      const char *name[] = {"corner", "centre", "whole top"};
      BOOST_TEST_MESSAGE(name[r] << ": ours " << C(r, r) << " m/N, CalculiX " << mean << " (ratio "
                                 << C(r, r) / mean << ")");
      // Measured (2026-12-07): ours 0.7% above CalculiX at the corner and
      // the centre, 0.4% on the whole top (27-node against 20-node bricks).
      BOOST_TEST(std::abs(C(r, r) / mean - 1.) < 0.02);
    }
}

BOOST_AUTO_TEST_CASE(contact_grid_blocks_against_fe)
{
  // A pattern of 12 x 12 mm blocks, 6 mm high on 2 mm of undertread: pitches
  // of 16 mm with lateral grooves 4 mm wide, and circumferential grooves 4
  // mm wide at +-8 mm (the tread 20 mm wide: one rib). Thirty pitches fill
  // the circumference exactly.
  const double                    P = 0.016, g = 0.004, W = 0.012;
  contact::TreadPatternParameters parameters;
  parameters.pattern                 = "blocks";
  parameters.pitch_lengths           = {P};
  parameters.lateral_groove_width    = g;
  parameters.circumferential_centres = {-0.5 * (W + g), 0.5 * (W + g)};
  parameters.circumferential_width   = g;
  parameters.groove_depth            = 0.006;
  const TreadPattern    pattern(parameters, 30. * P / (2. * M_PI));
  const BlockCompliance blocks(pattern, parameters, rubber(), W + 2. * g, 0.002);
  BOOST_REQUIRE_EQUAL(blocks.shapes().size(), 1u);
  const BlockCompliance::Shape &shape = blocks.shapes()[0];
  BOOST_TEST(shape.nx == 6u);
  BOOST_TEST(shape.ny == 6u);
  // What the blocks add is positive semidefinite (removing cells can only
  // soften a finite-element model): its smallest eigenvalue is round-off.
  const Eigen::VectorXd eigenvalues =
    Eigen::SelfAdjointEigenSolver<Eigen::MatrixXd>(shape.delta).eigenvalues();
  BOOST_TEST_MESSAGE("Delta C: eigenvalues " << eigenvalues.minCoeff() << " to "
                                             << eigenvalues.maxCoeff() << " m/N");
  BOOST_TEST(eigenvalues.minCoeff() > -1e-9 * eigenvalues.maxCoeff());

  // The contact grid: 4 mm coarse cells over x in [0, 20] mm and y in
  // [-10, 10] mm, 4 x 4 contact points each (1 mm); the endless layer's
  // compliance between the coarse cells in the place of the Green's
  // functions. At s = 0 the block of the first pitch covers x in [4, 16)
  // mm and y in [-6, 6) mm: its corner square [4, 8) x [-6, -2) and centre
  // square [8, 12) x [-2, 2) are coarse cells.
  std::vector<std::array<double, 3>> coarse;
  for (unsigned int i = 0; i < 5; ++i)
    for (unsigned int j = 0; j < 5; ++j)
      coarse.push_back({{0.002 + 0.004 * i, -0.008 + 0.004 * j, 0.3}});
  const ContactGrid     grid(coarse, 4, rubber(), true, true);
  const Eigen::MatrixXd G = layer_patch_compliance(rubber(), 0.004, 0.004, 5, 5, 0.05);
  BlockState            state(blocks, grid.points);
  state.set_position(0.);

  // The products agree with the blocks' dense form.
  std::vector<unsigned int> all(grid.n_points());
  for (unsigned int p = 0; p < all.size(); ++p)
    all[p] = p;
  Eigen::MatrixXd dense = Eigen::MatrixXd::Zero(all.size(), all.size());
  state.add_block(all, all, dense);
  const Eigen::VectorXd x = Eigen::VectorXd::LinSpaced(all.size(), 1., 2.);
  Eigen::VectorXd       y = Eigen::VectorXd::Zero(all.size());
  state.add_product(x, y);
  BOOST_TEST((y - dense * x).norm() < 1e-12 * y.norm());
  // ||Delta C|| over the points stays under the solve's bound.
  BOOST_TEST(Eigen::SelfAdjointEigenSolver<Eigen::MatrixXd>(dense).eigenvalues().maxCoeff() <=
             state.norm_bound());

  // The whole grid's solve takes its step length from the grid's operator
  // plus the blocks, largest over positions round the pattern: against the
  // dense eigenvalues at 200 positions between its samples, 0.17 mm apart
  // over two pitches (the points are 1 mm apart).
  const unsigned int n = grid.n_points();
  Eigen::MatrixXd    grid_dense(n, n);
  for (unsigned int p = 0; p < n; ++p)
    {
      Eigen::VectorXd column;
      grid.apply(G, Eigen::VectorXd::Unit(n, p), column);
      grid_dense.col(p) = column;
    }
  const double sampled = state.largest_norm([&](const Eigen::VectorXd &x, Eigen::VectorXd &y) {
    grid.apply(G, x, y);
  });
  double       largest = 0.;
  for (unsigned int k = 0; k < 200; ++k)
    {
      BlockState probe(blocks, grid.points);
      probe.set_position(1e-4 + 1.7e-4 * k);
      Eigen::MatrixXd W = grid_dense;
      probe.add_block(all, all, W);
      largest = std::max(largest, Eigen::SelfAdjointEigenSolver<Eigen::MatrixXd>(
                                    0.5 * (W + W.transpose()), Eigen::EigenvaluesOnly)
                                    .eigenvalues()
                                    .maxCoeff());
    }
  const double grid_norm =
    Eigen::SelfAdjointEigenSolver<Eigen::MatrixXd>(grid_dense, Eigen::EigenvaluesOnly)
      .eigenvalues()
      .maxCoeff();
  BOOST_TEST_MESSAGE("the step length's norm " << sampled << " m/N, the largest at 200 positions "
                                               << largest << " (ratio " << sampled / largest
                                               << "); the sum of the bounds "
                                               << grid_norm + state.norm_bound());
  // Measured (2026-12-07): 1.036 times the largest (the sum of the grid's
  // norm and norm_bound() is 1.81 times). At least 1 is the check of the
  // sampling and its margin; the solve would still converge down to 0.95.
  BOOST_TEST(sampled >= largest);
  BOOST_TEST(sampled <= 1.1 * largest);

  // A unit force spread over a square: its mean displacement, by the grid
  // alone (the endless layer) and with the blocks.
  const auto square = [&](const double x0, const double y0, const bool with_blocks) {
    Eigen::VectorXd f = Eigen::VectorXd::Zero(grid.n_points()), u;
    for (unsigned int p = 0; p < grid.n_points(); ++p)
      if (grid.points[p][0] > x0 && grid.points[p][0] < x0 + 0.004 && grid.points[p][1] > y0 &&
          grid.points[p][1] < y0 + 0.004)
        f[p] = 1. / 16.;
    grid.apply(G, f, u);
    if (with_blocks)
      state.add_product(f, u);
    return f.dot(u);
  };
  const double corner = square(0.004, -0.006, true), centre = square(0.008, -0.002, true);
  const double layer = square(0.004, -0.006, false);

  // The reference: the block alone, on cells of 1 mm (2 in the margins).
  TreadBlockGeometry geometry;
  geometry.length = geometry.width = W;
  geometry.margin_along = geometry.margin_across = 0.016; // alone, as BlockCompliance's
  const TreadBlock      reference(geometry, rubber(),
                                  {{0., 0.004, 0., 0.004}, {0.004, 0.008, 0.004, 0.008}}, 0.001);
  const Eigen::MatrixXd C = reference.compliance();
  BOOST_TEST_MESSAGE("the contact grid's compliance of the block's corner square "
                     << corner << " m/N (the endless layer's " << layer << "), the FE block's "
                     << C(0, 0) << " (ratio " << corner / C(0, 0) << "); centre " << centre
                     << ", the FE block's " << C(1, 1) << " (ratio " << centre / C(1, 1) << ")");
  // Measured (2026-12-07): the grid 1.0% above the FE block at the corner,
  // 1.7% at the centre (the FE on 1 mm cells is itself about 2% too stiff,
  // unit/tread_block's first case).
  BOOST_TEST(std::abs(corner / C(0, 0) - 1.) < 0.03);
  BOOST_TEST(std::abs(centre / C(1, 1) - 1.) < 0.05);
  // The blocks matter: the corner is far softer than the endless layer's.
  BOOST_TEST(corner > 1.5 * layer);
}

BOOST_AUTO_TEST_SUITE_END()

// The periodic stage against independent references: the whole ring solved
// directly (from the same cell, and from deal.II's own ring mesh in
// Cartesian components), the paper's doubling against the Bloch transform,
// reciprocity, passivity, and a thin ring's analytic natural frequencies.
#include "bounds.h"
#include "coarse_tyre.h"
#include "scratch.h"
#include <greentread/base/exceptions.h>
#include <greentread/fe/cylindrical.h>
#include <greentread/fe/elastic_model.h>
#include <greentread/geometry/tyre_cell.h>
#include <greentread/periodic/contact_patch.h>
#include <greentread/periodic/green_functions.h>
#include <greentread/periodic/green_solvers.h>
#include <greentread/periodic/periodic_cell.h>

#include <deal.II/base/multithread_info.h>
#include <deal.II/lac/affine_constraints.h>

#include <Eigen/Eigenvalues>
#include <Eigen/SparseLU>

#include <boost/test/unit_test.hpp>

#include <cmath>
#include <filesystem>
#include <fstream>

using namespace greentread;
using namespace dealii;
using periodic::Complex;

namespace
{
  /// Points on faces and mid-planes alike: 3 x 3 at half-cell spacing (as
  /// nodes, or as the centres of tributary areas).
  periodic::PatchRequest
  small_patch(const unsigned int        n_cells,
              const periodic::PointLoad load = periodic::PointLoad::node)
  {
    periodic::PatchRequest r;
    r.load                 = load;
    const double half_cell = M_PI * 0.2725 / n_cells;
    r.points_along         = 3;
    r.points_across        = 3;
    r.length               = 3 * half_cell;
    r.width                = 0.03;
    return r;
  }

  double
  relative_difference(const Eigen::MatrixXcd &a, const Eigen::MatrixXcd &b)
  {
    return (a - b).cwiseAbs().maxCoeff() / b.cwiseAbs().maxCoeff();
  }

  /// The ring from deal.II's own mesh of N rotated cells, in Cartesian
  /// components: its own inflation, Kp, and a direct solve.
  Eigen::MatrixXcd
  cartesian_ring_green(const test::CoarseTyre &tyre, const double omega)
  {
    Triangulation<3> ring;
    geometry::make_ring(tyre.cell->cell(), tyre.cell->angle(), tyre.cell->n_cells(), ring);
    fe::ElasticModel model(ring, tyre.materials.materials());
    model.assemble();
    AffineConstraints<double> clamp;
    model.add_clamp(geometry::rim_seat, clamp);
    clamp.close();
    const auto u = model.solve_static(clamp, model.pressure_load(geometry::inner_surface, 2e5));
    model.assemble_geometric_stiffness(u);

    const unsigned int n = model.dof_handler().n_dofs();
    std::vector<int>   free(n, -1);
    int                n_free = 0;
    for (unsigned int i = 0; i < n; ++i)
      if (!clamp.is_constrained(i))
        free[i] = n_free++;
    std::vector<Eigen::Triplet<Complex>> entries;
    const auto add = [&](const SparseMatrix<double> &A, const Complex factor) {
      for (auto e = A.begin(); e != A.end(); ++e)
        if (free[e->row()] >= 0 && free[e->column()] >= 0)
          entries.emplace_back(free[e->row()], free[e->column()], factor * e->value());
    };
    add(model.stiffness(), 1.);
    add(model.geometric_stiffness(), 1.);
    add(model.damping(), Complex(0., omega));
    add(model.mass(), -omega * omega);
    periodic::SparseComplex D(n_free, n_free);
    D.setFromTriplets(entries.begin(), entries.end());

    // The contact points' loads: each entry's node and radial direction
    // in the ring, from the reference DoF's position rotated to its cell.
    const auto         nodes = fe::nodes(model.dof_handler(), model.mapping());
    const unsigned int P     = tyre.patch.points.size();
    const double       alpha = tyre.cell->angle();
    struct Entry
    {
      std::array<int, 2>    dof;
      std::array<double, 2> direction;
      double                weight;
    };
    std::vector<std::vector<Entry>> load(P);
    for (unsigned int p = 0; p < P; ++p)
      for (const auto &e : tyre.patch.points[p].load)
        {
          const auto  &d     = tyre.periodic_cell.dofs[e.dof];
          const double theta = d.angle + e.cell * alpha;
          const double c = std::cos(theta), s = std::sin(theta);
          bool         found = false;
          for (const auto &node : nodes)
            if (node.position.distance(Point<3>(d.radius * c, d.radius * s, d.axial)) < 1e-9)
              {
                load[p].push_back({{{free[node.dofs[0]], free[node.dofs[1]]}}, {{c, s}}, e.weight});
                found = true;
              }
          BOOST_REQUIRE(found);
        }
    Eigen::MatrixXcd B = Eigen::MatrixXcd::Zero(n_free, P);
    for (unsigned int q = 0; q < P; ++q)
      for (const auto &e : load[q])
        {
          B(e.dof[0], q) += e.weight * e.direction[0];
          B(e.dof[1], q) += e.weight * e.direction[1];
        }
    Eigen::SparseLU<periodic::SparseComplex> lu(D);
    BOOST_REQUIRE(lu.info() == Eigen::Success);
    const Eigen::MatrixXcd X = lu.solve(B);
    Eigen::MatrixXcd       g = Eigen::MatrixXcd::Zero(P, P);
    for (unsigned int p = 0; p < P; ++p)
      for (const auto &e : load[p])
        g.row(p) +=
          e.weight * (e.direction[0] * X.row(e.dof[0]) + e.direction[1] * X.row(e.dof[1]));
    return g;
  }
} // namespace

// Bounds: the methods against each other are equal to round-off amplified by
// the dynamic stiffness's conditioning (about 1e8 here): 4.6e-12 to 3.8e-11
// measured, bounds about 3 times the largest of each kind, as round-off
// differs between machines. The thin ring against Hoppe's formula: the
// formula's own approximation (measured 1.1e-4), bound 3 times.
BOOST_AUTO_TEST_SUITE(periodic_stage)

BOOST_AUTO_TEST_CASE(doubling_and_bloch_equal_the_full_ring)
{
  // N a power of two (N_l = 14: three pieces) and not (N_l = 10: two).
  for (const auto load : {periodic::PointLoad::node, periodic::PointLoad::tributary_area})
    for (const unsigned int N : {16u, 12u})
      {
        test::CoarseTyre tyre(N, small_patch(N, load));
        BOOST_TEST_CONTEXT(
          "N = " << N << (load == periodic::PointLoad::node ? ", node loads" : ", tributary areas"))
        {
          BOOST_TEST(tyre.patch.points.size() == 9u);
          BOOST_TEST(tyre.patch.n_contact_cells == 2u); // faces and mid-planes both used
          auto full = periodic::make_green_solver(periodic::Method::full_ring, tyre.periodic_cell,
                                                  tyre.patch);
          auto doubling =
            periodic::make_green_solver(periodic::Method::doubling, tyre.periodic_cell, tyre.patch);
          auto bloch =
            periodic::make_green_solver(periodic::Method::bloch, tyre.periodic_cell, tyre.patch);
          // The driving point's resonance peak on a 5 Hz scan, and a few lines.
          periodic::SolveDiagnostics diagnostics;
          double                     peak = 0., largest = 0.;
          for (double f = 20.; f <= 400.; f += 5.)
            {
              const double a = std::abs(bloch->solve(2. * M_PI * f, diagnostics)(4, 4));
              if (a > largest)
                {
                  largest = a;
                  peak    = f;
                }
            }
          for (const double f : {0., 150., peak, 1500.})
            {
              const double omega = 2. * M_PI * f;
              const auto   g     = full->solve(omega, diagnostics);
              BOOST_TEST_CONTEXT("f = " << f << " Hz")
              {
                CHECK_BOUND(relative_difference(doubling->solve(omega, diagnostics), g), 1.2e-10);
                CHECK_BOUND(relative_difference(bloch->solve(omega, diagnostics), g), 1.2e-10);
                // A few columns alone (Bloch: one load per wavenumber and its
                // transposed solve for N - k; doubling: the default, the
                // whole of g and the columns copied).
                const std::vector<unsigned int> columns{4u, 0u, 8u};
                Eigen::MatrixXcd                expected(g.rows(), columns.size());
                for (std::size_t c = 0; c < columns.size(); ++c)
                  expected.col(c) = g.col(columns[c]);
                CHECK_BOUND(
                  relative_difference(bloch->solve_columns(omega, columns, diagnostics), expected),
                  1.2e-10);
                CHECK_BOUND(relative_difference(
                              doubling->solve_columns(omega, columns, diagnostics), expected),
                            1.2e-10);
              }
            }
          BOOST_CHECK_THROW(bloch->solve_columns(0., {9u}, diagnostics), NumericalError);
          BOOST_TEST(diagnostics.max_residual < 1e-14);
        }
      }
}

BOOST_AUTO_TEST_CASE(every_method_on_two_threads_equals_one_thread_of_bloch)
{
  // The lines spread over two threads. The doubling and the full ring call
  // UMFPACK, and so the BLAS, from both at once; Debian's serial OpenBLAS is
  // not thread-safe, so those calls hold one lock (base/serial_blas.h).
  // Without it this run stopped at a spurious "nearly singular" check.
  const unsigned int N = 12;
  test::CoarseTyre   tyre(N, small_patch(N));
  const auto         run = [&](const periodic::Method method, const unsigned int threads) {
    MultithreadInfo::set_thread_limit(threads);
    periodic::GreenRunReport report;
    const auto g = periodic::compute_green_functions(tyre.periodic_cell, tyre.patch, method, 100.,
                                                             24, MPI_COMM_SELF, false, report);
    MultithreadInfo::set_thread_limit();
    BOOST_TEST(report.threads == threads);
    return g;
  };
  const auto reference = run(periodic::Method::bloch, 1);
  for (const auto method : {periodic::Method::doubling, periodic::Method::full_ring})
    {
      const auto g     = run(method, 2);
      double     worst = 0., size = 0.;
      for (std::size_t i = 0; i < g.values.size(); ++i)
        {
          worst = std::max(worst, std::abs(g.values[i] - reference.values[i]));
          size  = std::max(size, std::abs(reference.values[i]));
        }
      BOOST_TEST_MESSAGE((method == periodic::Method::doubling ? "doubling" : "full ring")
                         << " on two threads against Bloch on one: " << worst / size);
      CHECK_BOUND(worst / size, 4e-11);
    }
}

BOOST_AUTO_TEST_CASE(tributary_loads_have_the_moments_of_their_rectangles)
{
  // The consistent load of a uniform traction over a rectangle, read at the
  // nodes' positions: the shape functions reproduce quadratics, so its
  // weights have the rectangle's area (1), centroid and second moments
  // (d^2 / 12) exactly; on the flat crown of the default section dS is
  // uniform in (theta, z). Points on any grid: 7 x 5 points on a patch that
  // neither starts nor ends on nodes.
  periodic::PatchRequest request;
  request.points_along  = 7;
  request.points_across = 5;
  request.length        = 0.0913;
  request.width         = 0.0771;
  request.load          = periodic::PointLoad::tributary_area;
  test::CoarseTyre tyre(64, request);
  const auto      &patch = tyre.patch;
  const double     alpha = tyre.cell->angle();
  BOOST_TEST(patch.points.size() == 35u);
  BOOST_TEST(patch.dx == request.length / 7, boost::test_tools::tolerance(1e-14));
  BOOST_TEST(patch.dy == request.width / 5, boost::test_tools::tolerance(1e-14));
  for (unsigned int p = 0; p < patch.points.size(); ++p)
    {
      const auto &point = patch.points[p];
      // Symmetric about the patch centre.
      BOOST_TEST(std::abs(point.x + patch.points[patch.points.size() - 1 - p].x) < 1e-15);
      BOOST_TEST(std::abs(point.y + patch.points[patch.points.size() - 1 - p].y) < 1e-15);
      double sum = 0., s1 = 0., z1 = 0., s2 = 0., z2 = 0.;
      for (const auto &e : point.load)
        {
          const auto &d = tyre.periodic_cell.dofs[e.dof];
          BOOST_TEST(d.on_tread);
          BOOST_TEST(d.component == 0u);
          const double s = point.radius * (d.angle + e.cell * alpha - point.angle);
          const double z = d.axial - point.y;
          sum += e.weight;
          s1 += e.weight * s;
          z1 += e.weight * z;
          s2 += e.weight * s * s;
          z2 += e.weight * z * z;
        }
      BOOST_TEST_CONTEXT("point " << p << " at x = " << point.x << ", y = " << point.y)
      {
        BOOST_TEST(std::abs(sum - 1.) < 1e-13);
        BOOST_TEST(std::abs(s1) < 1e-12 * patch.dx);
        BOOST_TEST(std::abs(z1) < 1e-12 * patch.dy);
        BOOST_TEST(s2 == patch.dx * patch.dx / 12., boost::test_tools::tolerance(1e-10));
        BOOST_TEST(z2 == patch.dy * patch.dy / 12., boost::test_tools::tolerance(1e-10));
      }
    }
}

BOOST_AUTO_TEST_CASE(ring_response_equals_the_full_ring)
{
  // The deflection shape's field, read at the contact points, is the
  // full ring's Green's function column of the loaded point.
  const unsigned int N = 12;
  for (const auto load : {periodic::PointLoad::node, periodic::PointLoad::tributary_area})
    {
      test::CoarseTyre tyre(N, small_patch(N, load));
      auto             full =
        periodic::make_green_solver(periodic::Method::full_ring, tyre.periodic_cell, tyre.patch);
      periodic::SolveDiagnostics diagnostics;
      for (const double f : {0., 333.})
        {
          const double omega = 2. * M_PI * f;
          const auto   g     = full->solve(omega, diagnostics);
          const auto  &q     = tyre.patch.points[4];
          const auto   u = periodic::ring_response(tyre.periodic_cell, omega, q.load, diagnostics);
          BOOST_TEST(u.cols() == static_cast<long>(N));
          double largest = 0.;
          for (unsigned int p = 0; p < tyre.patch.points.size(); ++p)
            {
              Complex mean = 0.;
              for (const auto &e : tyre.patch.points[p].load)
                mean += e.weight * u(e.dof, e.cell);
              largest = std::max(largest, std::abs(mean - g(p, 4)));
            }
          BOOST_TEST_CONTEXT("f = " << f << " Hz, " << tyre.patch.points[4].load.size()
                                    << " load DoFs")
          CHECK_BOUND(largest / g.col(4).cwiseAbs().maxCoeff(), 1.5e-11);
        }
    }
}

BOOST_AUTO_TEST_CASE(bloch_equals_a_cartesian_ring_from_deal_ii)
{
  // Independent of the cylindrical transform and of the cell's periodic
  // inflation: deal.II's ring mesh, its own inflation, Cartesian DoFs.
  const unsigned int N = 8;
  for (const auto load : {periodic::PointLoad::node, periodic::PointLoad::tributary_area})
    {
      test::CoarseTyre tyre(N, small_patch(N, load));
      auto             bloch =
        periodic::make_green_solver(periodic::Method::bloch, tyre.periodic_cell, tyre.patch);
      periodic::SolveDiagnostics diagnostics;
      for (const double f : {0., 90., 700.})
        BOOST_TEST_CONTEXT("f = " << f << " Hz, " << tyre.patch.points[0].load.size()
                                  << " load DoFs")
        {
          const double omega = 2. * M_PI * f;
          CHECK_BOUND(relative_difference(bloch->solve(omega, diagnostics),
                                          cartesian_ring_green(tyre, omega)),
                      2e-11);
        }
    }
}

BOOST_AUTO_TEST_CASE(reciprocity_and_passivity)
{
  // On the full ring: the Bloch solver pairs g(p, q) and g(q, p) from the
  // same terms, so there reciprocity would hold by construction.
  const unsigned int N = 16;
  for (const auto load : {periodic::PointLoad::node, periodic::PointLoad::tributary_area})
    {
      test::CoarseTyre tyre(N, small_patch(N, load));
      auto             full =
        periodic::make_green_solver(periodic::Method::full_ring, tyre.periodic_cell, tyre.patch);
      periodic::SolveDiagnostics diagnostics;
      for (double f = 10.; f <= 2000.; f += 220.)
        {
          const auto g = full->solve(2. * M_PI * f, diagnostics);
          BOOST_TEST_CONTEXT("f = " << f << " Hz, " << tyre.patch.points[0].load.size()
                                    << " load DoFs")
          {
            // g_ij = g_ji.
            CHECK_BOUND((g - g.transpose()).cwiseAbs().maxCoeff() / g.cwiseAbs().maxCoeff(), 5e-11);
            // With e^{j w t}, a damped driving point dissipates: Im g_ii < 0.
            for (unsigned int i = 0; i < g.rows(); ++i)
              BOOST_TEST(g(i, i).imag() < 0.);
          }
        }
    }
}

BOOST_AUTO_TEST_CASE(thin_ring_natural_frequencies)
{
  // A thin ring, R = 1 m, 10 mm thick radially, 20 mm wide, nu = 0: its
  // in-plane flexural modes cos(n theta) have (Hoppe)
  //   w_n^2 = E I n^2 (n^2 - 1)^2 / (rho A R^4 (n^2 + 1)), I = w t^3 / 12,
  // and mode n is the Bloch wavenumber k = n. With 256 cells each cell is
  // 2.5 times longer than thick; at 64 cells (20 times) the curved quadratic
  // elements lock in membrane and the frequencies come out 3% high, at 128
  // cells 0.2%, here 0.01%.
  const double R = 1., t = 0.01, w = 0.02;
  const auto   dir = test::scratch_directory("ring");
  std::filesystem::create_directories(dir);
  {
    std::ofstream geo(dir / "ring.geo");
    geo << "a = " << R - t / 2 << "; b = " << R + t / 2 << "; h = " << w / 2 << ";\n"
        << "Point(1) = {a, 0, -h}; Point(2) = {b, 0, -h}; Point(3) = {b, 0, h};"
           " Point(4) = {a, 0, h};\n"
           "Line(1) = {1, 2}; Line(2) = {2, 3}; Line(3) = {3, 4}; Line(4) = {4, 1};\n"
           "Curve Loop(1) = {1, 2, 3, 4}; Plane Surface(1) = {1};\n"
           "Transfinite Curve{1, 3} = 3; Transfinite Curve{2, 4} = 3;\n"
           "Transfinite Surface{1}; Recombine Surface{1};\n"
           "Physical Surface(\"tread\") = {1};\n"
           "Physical Curve(\"rim seat\") = {1};\n"
           "Physical Curve(\"inner surface\") = {4};\n"
           "Physical Curve(\"tread surface\") = {2};\n";
  }
  geometry::GeometryParameters geometry;
  geometry.geo_file     = (dir / "ring.geo").string();
  geometry.rim_diameter = 1.; // only checked for plausibility
  geometry.mesh_size    = 0.01;
  geometry.n_cells      = 256;
  const geometry::TyreCell cell(geometry);
  fe::MaterialParameters   parameters;
  parameters.tread_nu        = 0.;
  parameters.tread_loss      = 0.;
  const auto       materials = parameters.materials();
  fe::ElasticModel model(cell.cell(), materials);
  model.assemble();
  // Nothing held (no boundary has id 99), no prestress.
  const auto periodic_cell = periodic::make_periodic_cell(model, cell.angle(), geometry.n_cells, 99,
                                                          geometry::tread_surface, false);
  periodic::BlochCell bloch(periodic_cell);
  const auto         &tread = materials.at(fe::tread_id);
  const double E = parameters.tread_E, rho = tread.density, I = w * t * t * t / 12., A = w * t;
  for (const unsigned int n : {2u, 3u, 4u})
    {
      const double phi = 2. * M_PI * n / geometry.n_cells;
      bloch.set_frequency(0.);
      const Eigen::MatrixXcd K = Eigen::MatrixXcd(bloch.assemble(phi));
      bloch.set_frequency(1.);
      const Eigen::MatrixXcd M = K - Eigen::MatrixXcd(bloch.assemble(phi)); // C = 0
      const Eigen::GeneralizedSelfAdjointEigenSolver<Eigen::MatrixXcd> eigen(
        0.5 * (K + K.adjoint()), 0.5 * (M + M.adjoint()));
      const double computed = std::sqrt(eigen.eigenvalues()(0));
      const double exact    = std::sqrt(E * I * n * n * std::pow(n * n - 1., 2) /
                                        (rho * A * std::pow(R, 4) * (n * n + 1.)));
      BOOST_TEST_MESSAGE("thin ring, n = " << n << ": Bloch " << computed / (2. * M_PI)
                                           << " Hz, Hoppe " << exact / (2. * M_PI) << " Hz");
      CHECK_BOUND(std::abs(computed / exact - 1.), 3.5e-4);

      // Undamped, exactly at the resonance: D is singular and every method
      // must say so, naming the frequency; just below it, the solves pass.
      periodic::PatchRequest one_point;
      one_point.length = one_point.width = 0.01;
      one_point.points_along = one_point.points_across = 1;
      const auto patch = periodic::place_contact_points(periodic_cell, one_point);
      auto solver      = periodic::make_green_solver(periodic::Method::bloch, periodic_cell, patch);
      periodic::SolveDiagnostics diagnostics;
      BOOST_CHECK_EXCEPTION(solver->solve(computed, diagnostics), NumericalError,
                            [](const NumericalError &e) {
                              const std::string what = e.what();
                              BOOST_TEST_MESSAGE("at the resonance: " << what);
                              return what.find("singular at f = ") != std::string::npos;
                            });
      BOOST_TEST(std::isfinite(solver->solve(0.99 * computed, diagnostics)(0, 0).real()));
    }
}

BOOST_AUTO_TEST_CASE(faces_that_do_not_match_are_refused)
{
  geometry::GeometryParameters geometry;
  geometry.geo_file  = GREENTREAD_SOURCE_DIR "/geometry/tyre_165_65_r13.geo";
  geometry.mesh_size = 0.02;
  geometry.n_cells   = 16;
  const geometry::TyreCell cell(geometry);
  Triangulation<3>         moved;
  moved.copy_triangulation(cell.cell());
  // Push one vertex of the face theta = 2 pi / N outwards by 1 mm.
  bool done = false;
  for (const auto &c : moved.active_cell_iterators())
    for (const auto &face : c->face_iterators())
      if (!done && face->at_boundary() && face->boundary_id() == geometry::periodic_second)
        {
          face->vertex(0) *= 1. + 1e-3 / face->vertex(0).norm();
          done = true;
        }
  BOOST_REQUIRE(done);
  fe::MaterialParameters materials;
  fe::ElasticModel       model(moved, materials.materials());
  model.assemble();
  BOOST_CHECK_EXCEPTION(periodic::make_periodic_cell(model, cell.angle(), 16, geometry::rim_seat,
                                                     geometry::tread_surface, false),
                        InputError, [](const InputError &e) {
                          return std::string(e.what()).find(
                                   "the periodic faces of the cell do not match") !=
                                 std::string::npos;
                        });
}

BOOST_AUTO_TEST_SUITE_END()

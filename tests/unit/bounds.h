#pragma once

// A check of a figure against its bound that prints both, so that the
// figure a bound sits above can be read from the test's own run
// (--log_level=message) and the bound kept within about 3x of it
// (doc/verification.md).

#include <boost/test/unit_test.hpp>

/// Asserts (measured) <= (bound), a figure that is not a number failing,
/// and prints the figure beside its bound.
#define CHECK_BOUND(measured, bound)                                               \
  do                                                                               \
    {                                                                              \
      const double check_bound_measured_ = (measured);                             \
      const double check_bound_bound_    = (bound);                                \
      BOOST_TEST_MESSAGE(#measured << " = " << check_bound_measured_ << " (bound " \
                                   << check_bound_bound_ << ")");                  \
      BOOST_TEST(check_bound_measured_ <= check_bound_bound_);                     \
    }                                                                              \
  while (false)

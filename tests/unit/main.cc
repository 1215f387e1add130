// The Boost.Test module of GreenTread's unit tests. deal.II's MPI build wants
// MPI initialised before some of its objects are used.
#define BOOST_TEST_MODULE greentread unit tests
#include <deal.II/base/mpi.h>

#include <boost/test/unit_test.hpp>

struct MpiFixture
{
  MpiFixture()
      : mpi(boost::unit_test::framework::master_test_suite().argc,
            boost::unit_test::framework::master_test_suite().argv,
            dealii::numbers::invalid_unsigned_int)
  {
  }
  dealii::Utilities::MPI::MPI_InitFinalize mpi;
};

BOOST_TEST_GLOBAL_FIXTURE(MpiFixture);

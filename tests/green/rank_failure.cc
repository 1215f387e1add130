// rank_failure: run under mpirun -np 2 (tests/green/check_mpi.cmake).
//
// The MPI failure rule the frequency loop of the Green's stage and the
// tyre-green scene use (throw_if_any_rank_failed, base/exceptions.h): a
// failure on one rank only must reach every rank, as the same exception
// with the lowest failing rank's message, so that no rank waits for the
// others in a collective call. Each case is checked on every rank; the exit
// status is 0 only if every rank saw what it should.
#include <greentread/base/exceptions.h>

#include <deal.II/base/mpi.h>

#include <iostream>
#include <string>

namespace
{
  using greentread::RankFailure;

  /// What this rank caught: "none", "input: <message>" or "numerical: <message>".
  std::string
  outcome(const MPI_Comm comm, const RankFailure failure, const std::string &message)
  {
    try
      {
        greentread::throw_if_any_rank_failed(comm, failure, message);
        return "none";
      }
    catch (const greentread::InputError &e)
      {
        return std::string("input: ") + e.what();
      }
    catch (const greentread::NumericalError &e)
      {
        return std::string("numerical: ") + e.what();
      }
  }
} // namespace

int
main(int argc, char **argv)
{
  dealii::Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  const MPI_Comm                           comm = MPI_COMM_WORLD;
  const unsigned int                       rank = dealii::Utilities::MPI::this_mpi_process(comm);
  if (dealii::Utilities::MPI::n_mpi_processes(comm) != 2)
    {
      std::cerr << "rank_failure: run it with mpirun -np 2\n";
      return 2;
    }
  struct Case
  {
    const char *name;
    RankFailure on_rank[2];
    std::string expected;
  };
  const Case   cases[] = {{"no failure", {RankFailure::none, RankFailure::none}, "none"},
                          {"a numerical failure on rank 1 only",
                           {RankFailure::none, RankFailure::numerical},
                           "numerical: rank 1 failed"},
                          {"an input error on rank 0 only",
                           {RankFailure::input, RankFailure::none},
                           "input: rank 0 failed"},
                          {"both ranks fail: the lowest rank's message",
                           {RankFailure::numerical, RankFailure::input},
                           "numerical: rank 0 failed"}};
  unsigned int wrong   = 0;
  for (const auto &c : cases)
    {
      const RankFailure mine = c.on_rank[rank];
      const std::string got  = outcome(
         comm, mine, mine == RankFailure::none ? "" : "rank " + std::to_string(rank) + " failed");
      const bool ok = got == c.expected;
      std::cout << "rank " << rank << ", " << c.name << ": " << got
                << (ok ? "" : "  WRONG, expected " + c.expected) << '\n';
      wrong += ok ? 0 : 1;
    }
  // Every rank must agree that all went well.
  return dealii::Utilities::MPI::max(wrong, comm) == 0 ? 0 : 1;
}

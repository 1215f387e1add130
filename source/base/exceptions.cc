#include <greentread/base/exceptions.h>

#include <deal.II/base/mpi.h>

#include <cstdio>
#include <cstdlib>

namespace greentread
{
  std::string
  format_number(const double value)
  {
    // The shortest %g precision that reads back exactly.
    char buffer[64];
    for (int precision = 6; precision <= 17; ++precision)
      {
        std::snprintf(buffer, sizeof(buffer), "%.*g", precision, value);
        if (std::strtod(buffer, nullptr) == value)
          break;
      }
    return buffer;
  }



  std::string
  format_short(const double value)
  {
    char buffer[32];
    std::snprintf(buffer, sizeof(buffer), "%.4g", value);
    return buffer;
  }



  std::string
  format_printf(const char *format, const double value)
  {
    char buffer[64];
    std::snprintf(buffer, sizeof(buffer), format, value);
    return buffer;
  }



  void
  require_parameter(const bool         condition,
                    const std::string &path,
                    const double       value,
                    const std::string &allowed)
  {
    require_parameter(condition, path, format_number(value), allowed);
  }



  void
  require_parameter(const bool         condition,
                    const std::string &path,
                    const std::string &value,
                    const std::string &allowed)
  {
    if (!condition)
      throw InputError("parameter '" + path + "' = " + value +
                       " is not allowed; allowed: " + allowed);
  }



  void
  throw_if_any_rank_failed(const MPI_Comm     comm,
                           const RankFailure  failure,
                           const std::string &message)
  {
    const unsigned int rank   = dealii::Utilities::MPI::this_mpi_process(comm);
    const unsigned int failed = dealii::Utilities::MPI::min(
      failure != RankFailure::none ? rank : dealii::numbers::invalid_unsigned_int, comm);
    if (failed == dealii::numbers::invalid_unsigned_int)
      return;
    const std::string text = dealii::Utilities::MPI::broadcast(comm, message, failed);
    const int         kind = dealii::Utilities::MPI::broadcast(comm, int(failure), failed);
    if (kind == int(RankFailure::input))
      throw InputError(text);
    throw NumericalError(text);
  }
} // namespace greentread

#pragma once

#include <mpi.h>

#include <stdexcept>
#include <string>

/**
 * @file
 * The two kinds of failure GreenTread reports to its users. Both end the
 * program with a message and a non-zero exit; neither leaves a half-written
 * output file behind (see greentread/base/output.h).
 */

namespace greentread
{
  /**
   * @brief Bad input: an unknown parameter, a value out of range, a missing or
   * malformed file, an impossible geometry or an unwritable directory.
   *
   * The message names the parameter or file, the value given and what is
   * allowed.
   */
  class InputError : public std::runtime_error
  {
  public:
    using std::runtime_error::runtime_error;
  };

  /**
   * @brief A numerical failure: a singular or ill-conditioned system, an
   * overflow, a diverging time integration. Raised instead of returning NaN
   * or inf; the message says what went wrong and what to change.
   */
  class NumericalError : public std::runtime_error
  {
  public:
    using std::runtime_error::runtime_error;
  };

  /**
   * @brief Format a number for a user-facing message: shortest form that
   * reads back to the same double.
   */
  std::string
  format_number(double value);

  /**
   * @brief Format a computed quantity for a message: 4 significant digits.
   */
  std::string
  format_short(double value);

  /**
   * @brief Format one number with a printf conversion, e.g. "%.3e", for
   * reports laid out in columns.
   */
  std::string
  format_printf(const char *format, double value);

  /**
   * @brief Throw an InputError naming a parameter unless @p condition holds.
   *
   * @param[in] condition What must be true of the value.
   * @param[in] path      Full parameter path, e.g. "Oscillator/Mass".
   * @param[in] value     The value given, as the user wrote it.
   * @param[in] allowed   What is allowed, with its unit, e.g. "M > 0 kg".
   */
  void
  require_parameter(bool               condition,
                    const std::string &path,
                    double             value,
                    const std::string &allowed);

  /// @copydoc require_parameter
  void
  require_parameter(bool               condition,
                    const std::string &path,
                    const std::string &value,
                    const std::string &allowed);

  /// What one MPI rank has to report, for throw_if_any_rank_failed().
  enum class RankFailure
  {
    none,
    input,
    numerical
  };

  /**
   * @brief Collective on @p comm: if any rank has a failure, every rank
   * throws the lowest failing rank's error (InputError or NumericalError,
   * with its @p message), so that no rank is left waiting in a later
   * collective call.
   */
  void
  throw_if_any_rank_failed(MPI_Comm comm, RankFailure failure, const std::string &message);

  /**
   * @brief Run @p work on every rank of @p comm; an InputError or
   * NumericalError on any rank is thrown on all of them
   * (throw_if_any_rank_failed()).
   */
  template <typename Work>
  void
  collectively(const MPI_Comm comm, Work &&work)
  {
    RankFailure failure = RankFailure::none;
    std::string message;
    try
      {
        work();
      }
    catch (const InputError &e)
      {
        failure = RankFailure::input;
        message = e.what();
      }
    catch (const NumericalError &e)
      {
        failure = RankFailure::numerical;
        message = e.what();
      }
    throw_if_any_rank_failed(comm, failure, message);
  }
} // namespace greentread

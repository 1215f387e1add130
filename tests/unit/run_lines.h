#pragma once

// What the program printed of its rolling runs (analysis/study_run.cc): each
// run starts with a line 'run <name>: V0 = ...' and ends with one that says
// '... steps the contact solve did not converge: <n>, ...'. A run with its
// error bars prints several, so one line saying 0 does not say that every
// run converged: each run's must.

#include <boost/test/unit_test.hpp>

#include <string>

namespace test
{
  /// The runs' lines of a program's screen output. Counted as occurrences,
  /// not as lines: stdout and stderr share the file the tests read, and a
  /// progress line on stderr may end inside a line of stdout.
  struct RunLines
  {
    /// 'run <name>: V0 = ': the runs started.
    unsigned int runs = 0;
    /// 'steps the contact solve did not converge: 0,'.
    unsigned int converged = 0;
    /// 'did not converge: ' and a digit 1 to 9.
    unsigned int failed = 0;
  };

  inline RunLines
  run_lines(const std::string &screen)
  {
    const auto count = [&screen](const std::string &what, const bool nonzero) {
      unsigned int n  = 0;
      std::size_t  at = screen.find(what);
      while (at != std::string::npos)
        {
          const std::size_t next = at + what.size();
          if (!nonzero || (next < screen.size() && screen[next] >= '1' && screen[next] <= '9'))
            ++n;
          at = screen.find(what, next);
        }
      return n;
    };
    RunLines r;
    // The sdof scene's 'm, V0 = ' is not a run's.
    r.runs      = count(": V0 = ", false);
    r.converged = count("steps the contact solve did not converge: 0,", false);
    r.failed    = count("did not converge: ", true);
    return r;
  }

  /// Every run of @p screen converged at every step: as many lines saying 0
  /// failed steps as runs started (at least one), none saying more.
  inline void
  check_every_run_converged(const std::string &screen, const std::string &name)
  {
    const RunLines r = run_lines(screen);
    BOOST_TEST_MESSAGE(name << ": " << r.runs << " runs, " << r.converged
                            << " with every step converged");
    BOOST_TEST(r.runs > 0u, name << ":\n" << screen);
    BOOST_TEST(r.converged == r.runs, name << ":\n" << screen);
    BOOST_TEST(r.failed == 0u, name << ":\n" << screen);
  }
} // namespace test

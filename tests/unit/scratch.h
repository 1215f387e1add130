#pragma once

// A scratch directory of the test's own: under the unit tests' build
// directory (GREENTREAD_SCRATCH_DIR), named after the test, with the process
// id in its name, so that two runs of the suite at once, or two tests, never
// share a file. It is emptied when it is made.

#include <filesystem>
#include <string>

#include <unistd.h>

namespace test
{
  inline std::filesystem::path
  scratch_directory(const std::string &name)
  {
    namespace fs = std::filesystem;
    const fs::path dir =
      fs::path(GREENTREAD_SCRATCH_DIR) / (name + "-" + std::to_string(::getpid()));
    fs::remove_all(dir);
    fs::create_directories(dir);
    return dir;
  }
} // namespace test

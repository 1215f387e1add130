#pragma once

/**
 * @file
 * The revision of the sources the program was built from, taken at build
 * time (cmake/revision.cmake), for the provenance every output and figure
 * records.
 */

namespace greentread
{
  namespace base
  {
    /// `git describe --always --dirty` of the source tree at the last build
    /// ("unknown" outside a git checkout).
    const char *
    git_revision();
  } // namespace base
} // namespace greentread

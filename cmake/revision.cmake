# Writes OUTPUT, a source defining greentread::git_revision(): the revision of
# the source tree SOURCE_DIR (git describe --always --dirty) when the program
# is built, not when CMake configured it. Run at every build by the target
# greentread_revision; the file is rewritten only when the revision changes,
# so an unchanged tree relinks nothing.
execute_process(COMMAND git describe --always --dirty
  WORKING_DIRECTORY "${SOURCE_DIR}"
  OUTPUT_VARIABLE revision
  OUTPUT_STRIP_TRAILING_WHITESPACE ERROR_QUIET)
if(NOT revision)
  set(revision "unknown")
endif()
set(text "// Written by cmake/revision.cmake at build time.\n#include <greentread/base/revision.h>\n\nconst char *\ngreentread::base::git_revision()\n{\n  return \"${revision}\";\n}\n")
include(${CMAKE_CURRENT_LIST_DIR}/write_if_changed.cmake)
write_if_changed("${OUTPUT}" "${text}")

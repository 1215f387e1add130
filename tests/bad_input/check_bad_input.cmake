# Run PROGRAM with ARGS in a fresh WORKDIR, writing to out/ unless ARGS sets
# another output directory (overrides apply in order, the file first), and
# check: exit status 2 (bad input, as the manual's exit codes say; 1 is an
# internal error, 3 a numerical failure), standard error matching EXPECT, nothing left in
# WORKDIR (an empty out/ at most), and the file UNCHANGED, if given, as it
# was: for a case whose output directory lies elsewhere, what it names.
file(REMOVE_RECURSE ${WORKDIR})
file(MAKE_DIRECTORY ${WORKDIR})
if(UNCHANGED)
  file(SHA256 ${UNCHANGED} unchanged_before)
endif()
execute_process(
  COMMAND ${PROGRAM} --set "Output directory=out" ${ARGS}
  WORKING_DIRECTORY ${WORKDIR}
  RESULT_VARIABLE status
  OUTPUT_VARIABLE out
  ERROR_VARIABLE err)
if(status EQUAL 0)
  message(FATAL_ERROR "expected a failure, but greentread succeeded:\n${out}")
endif()
if(NOT status EQUAL 2)
  message(FATAL_ERROR "expected exit status 2 (bad input), got ${status}:\n${err}")
endif()
string(REGEX REPLACE "\n" " " err_line "${err}")
if(NOT err_line MATCHES "${EXPECT}")
  message(FATAL_ERROR "the message does not match '${EXPECT}':\n${err}")
endif()
if(NOT err MATCHES "^greentread: error: ")
  message(FATAL_ERROR "the message does not start with 'greentread: error: ':\n${err}")
endif()
file(GLOB_RECURSE left LIST_DIRECTORIES true ${WORKDIR}/*)
list(REMOVE_ITEM left ${WORKDIR}/out)
if(left)
  message(FATAL_ERROR "output was left behind: ${left}")
endif()
if(UNCHANGED)
  file(SHA256 ${UNCHANGED} unchanged_after)
  if(NOT unchanged_after STREQUAL unchanged_before)
    message(FATAL_ERROR "${UNCHANGED} was changed")
  endif()
endif()
message(STATUS "exit ${status}: ${err}")

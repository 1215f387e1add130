# Run PROGRAM with ARGS in a fresh WORKDIR, writing to out/ unless ARGS sets
# another output directory (overrides apply in order, the file first), and
# check: non-zero exit, standard error matching EXPECT, no file left in out/.
file(REMOVE_RECURSE ${WORKDIR})
file(MAKE_DIRECTORY ${WORKDIR})
execute_process(
  COMMAND ${PROGRAM} --set "Output directory=out" ${ARGS}
  WORKING_DIRECTORY ${WORKDIR}
  RESULT_VARIABLE status
  OUTPUT_VARIABLE out
  ERROR_VARIABLE err)
if(status EQUAL 0)
  message(FATAL_ERROR "expected a failure, but greentread succeeded:\n${out}")
endif()
string(REGEX REPLACE "\n" " " err_line "${err}")
if(NOT err_line MATCHES "${EXPECT}")
  message(FATAL_ERROR "the message does not match '${EXPECT}':\n${err}")
endif()
if(NOT err MATCHES "^greentread: error: ")
  message(FATAL_ERROR "the message does not start with 'greentread: error: ':\n${err}")
endif()
file(GLOB_RECURSE left ${WORKDIR}/out/*)
if(left)
  message(FATAL_ERROR "output was left behind: ${left}")
endif()
message(STATUS "exit ${status}: ${err}")

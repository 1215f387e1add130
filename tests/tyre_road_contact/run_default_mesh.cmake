# Run the main job's scene on default_mesh.prm into WORKDIR (kept: its saved
# stages are the fixture of unit/main_job_output) and check that it ran.
file(REMOVE_RECURSE ${WORKDIR})
execute_process(
  COMMAND ${PROGRAM} ${PRM}
    --set "Output directory=${WORKDIR}"
    --set "Geometry/Geometry file=${GEO}"
  RESULT_VARIABLE status OUTPUT_VARIABLE out ERROR_VARIABLE err)
if(NOT status EQUAL 0)
  message(FATAL_ERROR "the default-mesh pipeline failed (${status}):\n${out}\n${err}")
endif()
include(${CMAKE_CURRENT_LIST_DIR}/every_run_converged.cmake)
every_run_converged("${out}")
# The identified model of this tyre is not passive: the run warns, with the
# figure, and rolls it because the scene allows it (unit/main_job_output
# measures the figure again).
if(NOT err MATCHES "greentread: warning: the identified patch model is not passive: the smallest eigenvalue of -Im g over its largest is (-[0-9.e-]+) at ([0-9]+) Hz")
  message(FATAL_ERROR "no warning that the patch model is not passive:\n${err}")
endif()
file(WRITE ${WORKDIR}/passivity.txt "${CMAKE_MATCH_1} ${CMAKE_MATCH_2}")
message(STATUS "${out}")

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
# Each run prints a line 'run <name>: V0 = ...' as it starts and one with
# 'steps the contact solve did not converge: <n>,' as it ends: every run's
# must say 0.
string(REGEX MATCHALL "run [^ \n]+: V0 = " runs "${out}")
string(REGEX MATCHALL "steps the contact solve did not converge: 0," converged "${out}")
list(LENGTH runs n_runs)
list(LENGTH converged n_converged)
if(n_runs EQUAL 0 OR NOT n_converged EQUAL n_runs OR out MATCHES "did not converge: [1-9]")
  message(FATAL_ERROR "a contact step did not converge: ${n_converged} of ${n_runs} runs "
    "say 'did not converge: 0,':\n${out}")
endif()
# The identified model of this tyre is not passive: the run warns, with the
# figure, and rolls it because the scene allows it (unit/main_job_output
# measures the figure again).
if(NOT err MATCHES "greentread: warning: the identified patch model is not passive: the smallest eigenvalue of -Im g over its largest is (-[0-9.e-]+) at ([0-9]+) Hz")
  message(FATAL_ERROR "no warning that the patch model is not passive:\n${err}")
endif()
file(WRITE ${WORKDIR}/passivity.txt "${CMAKE_MATCH_1} ${CMAKE_MATCH_2}")
message(STATUS "${out}")

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
if(NOT out MATCHES "steps the contact solve did not converge: 0,")
  message(FATAL_ERROR "a contact step did not converge:\n${out}")
endif()
message(STATUS "${out}")

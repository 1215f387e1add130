# green/coarse's receptances (Bloch, node loads) against the full ring, an
# independent solve of all N cells at once, at two of its lines: 0 Hz and
# 100 Hz, the driving point's resonance. Equal to round-off (measured 5.0e-12
# of the largest |g|); the bound, 2e-11, is 4 times that, as round-off
# differs between machines.
file(REMOVE_RECURSE ${WORKDIR})
file(MAKE_DIRECTORY ${WORKDIR})
execute_process(COMMAND ${PROGRAM} ${PRM} --set "Output directory=${WORKDIR}/full"
    --set "Green's functions/Method=full-ring" --set "Green's functions/Maximum frequency=100"
    --set "Green's functions/Frequency step=100"
    --set "Green's functions/Deflection shape frequency=-1"
  WORKING_DIRECTORY ${WORKDIR} RESULT_VARIABLE rc OUTPUT_VARIABLE out ERROR_VARIABLE err)
if(NOT rc EQUAL 0)
  message(FATAL_ERROR "the full-ring run failed (${rc}):\n${out}\n${err}")
endif()
execute_process(COMMAND ${COMPARE} ${COARSE}/green_functions.h5 ${WORKDIR}/full/green_functions.h5
    ${TOLERANCE}
  RESULT_VARIABLE rc OUTPUT_VARIABLE out ERROR_VARIABLE err)
message(STATUS "green/coarse (Bloch) against the full ring: ${out}")
if(NOT rc EQUAL 0)
  message(FATAL_ERROR "green/coarse differs from the full ring by more than ${TOLERANCE}:\n${out}\n${err}")
endif()

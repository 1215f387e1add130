# The tyre-road-contact scene on the coarse tyre of coarse.prm with the patch
# model from the ring's own modes ('Patch model/Source = fe modes'):
# 1. the run writes modal_model.h5, dispersion.csv (its documented header) and
#    its plot, modal_errors.csv, and rolls with every step converged;
# 2. the synthesis against the direct Green's functions that the same run
#    computed (an independent solve per line): E of Eq. (50) within the bound
#    below for every pair, G_r positive semidefinite and -Im g too;
# 3. a second run reuses modal_model.h5 and says so.
# With -DMETHOD=harmonic, the same through the section's harmonics.
file(REMOVE_RECURSE ${WORKDIR})
file(MAKE_DIRECTORY ${WORKDIR})
set(common ${SOURCE_DIR}/coarse.prm --set "Geometry/Geometry file=${GEO}"
    --set "Patch model/Source=fe modes" --set "Output directory=${WORKDIR}/run")
# -DMETHOD=harmonic: the Green's functions and the modes from the section's
# harmonics (which take tributary areas), the rest the same.
if(METHOD)
  list(APPEND common --set "Green's functions/Method=${METHOD}"
    --set "Green's functions/Point load=tributary area")
endif()
execute_process(COMMAND ${PROGRAM} ${common}
  WORKING_DIRECTORY ${WORKDIR} RESULT_VARIABLE status OUTPUT_VARIABLE out ERROR_VARIABLE err)
if(NOT status EQUAL 0)
  message(FATAL_ERROR "the coarse pipeline with fe modes failed (${status}):\n${out}\n${err}")
endif()
message(STATUS "${out}")
foreach(file green_functions.h5 modal_model.h5 modal_errors.csv dispersion.csv dispersion.png
    history_road-A_90kmh.csv spectra.csv)
  if(NOT EXISTS ${WORKDIR}/run/${file})
    message(FATAL_ERROR "the run did not write ${file}")
  endif()
endforeach()
file(STRINGS ${WORKDIR}/run/dispersion.csv header LIMIT_COUNT 1)
if(NOT header STREQUAL "wavenumber,branch,frequency_Hz,damping_ratio")
  message(FATAL_ERROR "dispersion.csv starts with '${header}'")
endif()
if(NOT out MATCHES "steps the contact solve did not converge: 0,"
   OR out MATCHES "did not converge: [1-9]")
  message(FATAL_ERROR "a contact step did not converge")
endif()

# The figures of the synthesis, as the scene prints them.
if(NOT out MATCHES "over the ([0-9]+) pairs: median ([0-9.]+)%, 90th percentile ([0-9.]+)%, largest ([0-9.]+)%")
  message(FATAL_ERROR "no synthesis figures in the output")
endif()
set(worst ${CMAKE_MATCH_4})
if(NOT CMAKE_MATCH_1 EQUAL 144)
  message(FATAL_ERROR "E over ${CMAKE_MATCH_1} pairs, not the 144 of 12 points")
endif()
# Bound: measured largest E on this tyre (see doc/methods/modal.md).
if(worst GREATER ${WORST_BOUND})
  message(FATAL_ERROR "the synthesis' largest E is ${worst}%, above ${WORST_BOUND}%")
endif()
if(NOT out MATCHES "passivity: smallest eigenvalue of -Im g over its largest, over the lines ([-0-9.e+]+); static residual G_r: smallest eigenvalue over its largest ([-0-9.e+]+)")
  message(FATAL_ERROR "no passivity figures in the output")
endif()
foreach(value ${CMAKE_MATCH_1} ${CMAKE_MATCH_2})
  if(value MATCHES "^-" AND NOT value MATCHES "e-1[2-9]$")
    message(FATAL_ERROR "not positive semidefinite: ${value}")
  endif()
endforeach()

execute_process(COMMAND ${PROGRAM} ${common} --set "Rolling/Speeds (kph)=50"
  WORKING_DIRECTORY ${WORKDIR} RESULT_VARIABLE status OUTPUT_VARIABLE out ERROR_VARIABLE err)
if(NOT status EQUAL 0 OR NOT out MATCHES "Reusing [^\n]*modal_model.h5")
  message(FATAL_ERROR "the rerun did not reuse modal_model.h5 (${status}):\n${out}\n${err}")
endif()

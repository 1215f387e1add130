# The tyre-road-contact scene on the coarse tyre of coarse.prm with the patch
# model from the ring's own modes ('Patch model/Source = fe modes'):
# 1. the run writes modal_model.h5, dispersion.csv (its documented header) and
#    its plot, modal_errors.csv, and rolls with every step converged;
# 2. the synthesis against the direct Green's functions that the same run
#    computed (an independent solve per line): E of Eq. (50) within the bound
#    below for every pair, G_r positive semidefinite and -Im g too;
# 3. a second run reuses modal_model.h5 and says so.
file(REMOVE_RECURSE ${WORKDIR})
file(MAKE_DIRECTORY ${WORKDIR})
set(common ${SOURCE_DIR}/coarse.prm --set "Geometry/Geometry file=${GEO}"
    --set "Patch model/Source=fe modes" --set "Output directory=${WORKDIR}/run")
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
include(${CMAKE_CURRENT_LIST_DIR}/every_run_converged.cmake)
every_run_converged("${out}")

# The figures of the synthesis, as the scene prints them. Bound: measured
# largest E on this tyre (see doc/methods/modal.md), 144 pairs of 12 points.
include(${CMAKE_CURRENT_LIST_DIR}/synthesis_figures.cmake)
check_synthesis_figures("${out}" 144 ${WORST_BOUND})

execute_process(COMMAND ${PROGRAM} ${common} --set "Rolling/Speeds (kph)=50"
  WORKING_DIRECTORY ${WORKDIR} RESULT_VARIABLE status OUTPUT_VARIABLE out ERROR_VARIABLE err)
if(NOT status EQUAL 0 OR NOT out MATCHES "Reusing [^\n]*modal_model.h5")
  message(FATAL_ERROR "the rerun did not reuse modal_model.h5 (${status}):\n${out}\n${err}")
endif()

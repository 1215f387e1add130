# The tyre-road-contact scene on the coarse tyre of coarse.prm:
# 1. the whole pipeline runs and writes every output, every step converged;
# 2. the output directory, copied elsewhere and used from another working
#    directory with another speed (50 km/h) and another path to the same .geo file,
#    reuses both saved stages and says so.
# 0. the identified model of this tyre is not passive: with 'Patch
#    model/Allow non-passive = false' the scene refuses to roll it, with the
#    figure and the parameter named, exit 2 and no run's output; coarse.prm
#    allows it, and the run then warns with the figure.
# The first run's patch_model.h5 is the fixture of unit/tyre_contact.
file(REMOVE_RECURSE ${WORKDIR})
file(MAKE_DIRECTORY ${WORKDIR}/elsewhere)

execute_process(
  COMMAND ${PROGRAM} ${SOURCE_DIR}/coarse.prm
    --set "Output directory=${WORKDIR}/first"
    --set "Geometry/Geometry file=${GEO}"
    --set "Patch model/Allow non-passive=false"
  WORKING_DIRECTORY ${WORKDIR}
  RESULT_VARIABLE status OUTPUT_VARIABLE out ERROR_VARIABLE err)
string(REGEX REPLACE "\n" " " err_line "${err}")
if(NOT status EQUAL 2 OR NOT err_line MATCHES "parameter 'Patch model/Allow non-passive' = false: +the +identified +patch +model +is +not +passive: +the +smallest +eigenvalue +of +-Im +g +over +its +largest +is +-[0-9.e-]+ at [0-9]+ Hz")
  message(FATAL_ERROR "a patch model that is not passive was not refused (${status}):\n${out}\n${err}")
endif()
file(GLOB rolled ${WORKDIR}/first/history_* ${WORKDIR}/first/spectr*)
if(rolled)
  message(FATAL_ERROR "the refused run left a run's output: ${rolled}")
endif()

execute_process(
  COMMAND ${PROGRAM} ${SOURCE_DIR}/coarse.prm
    --set "Output directory=${WORKDIR}/first"
    --set "Geometry/Geometry file=${GEO}"
  WORKING_DIRECTORY ${WORKDIR}
  RESULT_VARIABLE status OUTPUT_VARIABLE out ERROR_VARIABLE err)
if(NOT status EQUAL 0)
  message(FATAL_ERROR "the coarse pipeline failed (${status}):\n${out}\n${err}")
endif()
message(STATUS "${out}")
if(NOT err MATCHES "greentread: warning: the identified patch model is not passive: the smallest eigenvalue of -Im g over its largest is -[0-9.e-]+ at [0-9]+ Hz")
  message(FATAL_ERROR "no warning that the patch model is not passive:\n${err}")
endif()
foreach(file green_functions.h5 patch_model.h5 modal_errors.csv
    road_road-A_spectrum.csv road_road-A_spectrum.png road_road-A_texture.png
    history_road-A_90kmh.csv history_road-A_90kmh.png contact_road-A_90kmh.pvd
    map_road-A_90kmh.png spectra.csv rolling_resistance.csv rolling_resistance.png)
  if(NOT EXISTS ${WORKDIR}/first/${file})
    message(FATAL_ERROR "the run did not write ${file}")
  endif()
endforeach()
include(${CMAKE_CURRENT_LIST_DIR}/every_run_converged.cmake)
every_run_converged("${out}")
file(GLOB_RECURSE written ${WORKDIR}/first/*)
foreach(file ${written})
  if(file MATCHES "\\.(csv|vtu)$")
    file(READ ${file} text)
    if(text MATCHES "[^a-z](nan|inf)[^a-z]")
      message(FATAL_ERROR "${file} holds a NaN or inf")
    endif()
  endif()
endforeach()

file(COPY ${WORKDIR}/first/ DESTINATION ${WORKDIR}/copied)
file(COPY ${GEO} DESTINATION ${WORKDIR}/elsewhere)
get_filename_component(geo_name ${GEO} NAME)
execute_process(
  COMMAND ${PROGRAM} ${SOURCE_DIR}/coarse.prm
    --set "Output directory=../copied"
    --set "Geometry/Geometry file=${geo_name}"
    --set "Rolling/Speeds (kph)=50"
  WORKING_DIRECTORY ${WORKDIR}/elsewhere
  RESULT_VARIABLE status OUTPUT_VARIABLE out ERROR_VARIABLE err)
if(NOT status EQUAL 0)
  message(FATAL_ERROR "the rerun failed (${status}):\n${out}\n${err}")
endif()
if(NOT out MATCHES "Reusing [^\n]*green_functions.h5")
  message(FATAL_ERROR "the rerun did not reuse the Green's functions:\n${out}")
endif()
if(NOT out MATCHES "Reusing [^\n]*patch_model.h5")
  message(FATAL_ERROR "the rerun did not reuse the patch model:\n${out}")
endif()
if(NOT EXISTS ${WORKDIR}/copied/history_road-A_50kmh.csv)
  message(FATAL_ERROR "the rerun did not write history_road-A_50kmh.csv")
endif()
message(STATUS "rerun from another directory at 50 km/h:\n${out}")

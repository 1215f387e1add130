# The sound stage of the scene on the stages tyre_road_contact/main_job
# saved, copied from STAGES into WORKDIR: road-A at 70 km/h over 1.1 m, a
# 2 dB standard error target, no force error bars, the sound from 250 to
# 500 Hz on 5 cm boundary elements (13.7 cells to a wavelength at 500 Hz).
# Checked, from what the program prints and writes:
# - the Green's functions and the modes reused, not made again;
# - sound_road-A_70kmh.csv: the four bands for each of the two CPX
#   microphones, the radiated power and the power put in, every band from
#   the low-rate run (76.8 us); each level finite, its total error at least
#   its standard error and each estimate (the mesh's and the harmonics'),
#   and the estimates at most MESH_BOUND and HARMONICS_BOUND dB;
# - energy: in every band the radiated power below the power the forces
#   put in (the two come by independent routes: the boundary element
#   method's far field, and the forces' work on the points' own velocity);
# - the PNG written;
# - a second run of the same scene reuses sound_model.h5, the saved stage,
#   and writes the same bytes in sound_road-A_70kmh.csv.
cmake_minimum_required(VERSION 3.16)
file(REMOVE_RECURSE ${WORKDIR})
file(MAKE_DIRECTORY ${WORKDIR})
file(COPY ${STAGES}/green_functions.h5 ${STAGES}/modal_model.h5 DESTINATION ${WORKDIR})
set(command ${PROGRAM}
    --set "Output directory=${WORKDIR}"
    --set "Geometry/Geometry file=${GEO}"
    --set "Road texture/Roads=road-A"
    --set "Rolling/Speeds (kph)=70"
    --set "Rolling/Distance=1.1"
    --set "Spectra/Standard error target=2"
    --set "Error bars/Estimates="
    --set "Sound/Top band=500"
    --set "Sound/Cell size=0.05")
execute_process(COMMAND ${command} RESULT_VARIABLE status OUTPUT_VARIABLE out ERROR_VARIABLE err)
file(WRITE ${WORKDIR}/screen.txt "${out}${err}")
if(NOT status EQUAL 0)
  message(FATAL_ERROR "the sound stage failed (${status}):\n${out}\n${err}")
endif()
message(STATUS "${out}")

include(${CMAKE_CURRENT_LIST_DIR}/require.cmake)
if(out MATCHES "Stages geometry -> fe -> periodic" OR out MATCHES "[0-9]+ ring modes from")
  message(FATAL_ERROR "the saved stages were made again:\n${out}")
endif()
require("Stage radiation: the sound from 250 to 500 Hz" "the sound stage")
require("sound of road-A at 70 km/h: front " "the sound's summary")

set(file ${WORKDIR}/sound_road-A_70kmh.csv)
if(NOT EXISTS ${file} OR NOT EXISTS ${WORKDIR}/sound_road-A_70kmh.png)
  message(FATAL_ERROR "sound_road-A_70kmh.csv or .png not written")
endif()
file(STRINGS ${file} rows REGEX "^[0-9]")
list(LENGTH rows n_rows)
if(NOT n_rows EQUAL 16)
  message(FATAL_ERROR "${file}: ${n_rows} rows, 16 expected (4 bands, 4 quantities)")
endif()
set(largest_mesh 0)
set(largest_harmonics 0)
foreach(row ${rows})
  # band_Hz,quantity,level_dB,standard_error_dB,bem_mesh_dB,harmonics_dB,total_error_dB,
  # time_step_us
  string(REPLACE "," ";" f "${row}")
  list(GET f 0 band)
  list(GET f 1 quantity)
  list(GET f 2 level)
  list(GET f 3 standard)
  list(GET f 4 mesh)
  list(GET f 5 harmonics)
  list(GET f 6 total)
  list(GET f 7 step)
  if(NOT level MATCHES "^-?[0-9.]+(e[-+]?[0-9]+)?$" OR NOT step EQUAL 76.8)
    message(FATAL_ERROR "${file}: a level not finite, or not from the low-rate run: ${row}")
  endif()
  if(total LESS standard OR total LESS mesh OR total LESS harmonics OR standard LESS 0
     OR mesh LESS 0 OR harmonics LESS 0)
    message(FATAL_ERROR "${file}: the errors do not combine: ${row}")
  endif()
  if(mesh GREATER largest_mesh)
    set(largest_mesh ${mesh})
  endif()
  if(harmonics GREATER largest_harmonics)
    set(largest_harmonics ${harmonics})
  endif()
  set(${quantity}_${band} ${level})
endforeach()
if(largest_mesh GREATER MESH_BOUND OR largest_harmonics GREATER HARMONICS_BOUND)
  message(FATAL_ERROR "${file}: the mesh's estimate reaches ${largest_mesh} dB (bound ${MESH_BOUND}), "
    "the harmonics' ${largest_harmonics} dB (bound ${HARMONICS_BOUND})")
endif()
foreach(band 250 315 400 500)
  if(NOT ${power_${band}} LESS ${input_${band}})
    message(FATAL_ERROR "${file}: at ${band} Hz the radiated power ${power_${band}} dB is not "
      "below the power put in, ${input_${band}} dB")
  endif()
endforeach()
message(STATUS "${file}: 16 rows, the largest estimates ${largest_mesh} dB (mesh) and "
  "${largest_harmonics} dB (harmonics), the power below the input in every band")

# The saved stage: the same scene again reuses it, and writes the same bytes.
file(SHA256 ${file} first_run)
execute_process(COMMAND ${command} RESULT_VARIABLE status OUTPUT_VARIABLE out ERROR_VARIABLE err)
if(NOT status EQUAL 0)
  message(FATAL_ERROR "the second run failed (${status}):\n${out}\n${err}")
endif()
require("Reusing [^\n]*sound_model.h5" "the saved radiation stage")
file(SHA256 ${file} second_run)
if(NOT first_run STREQUAL second_run)
  message(FATAL_ERROR "${file}: the run on the saved stage wrote other bytes")
endif()
message(STATUS "the second run reused sound_model.h5 and wrote the same bytes")

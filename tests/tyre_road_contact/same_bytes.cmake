# The same scene gives the same bytes in every output file whatever the
# thread count: the main job's path (the built-in default scene) on a coarse
# ring, from scratch, once with one thread and once with two
# (DEAL_II_NUM_THREADS). With two, the rolling runs go two at a time and a
# run alone has two threads for its modal update, the stages' sums run on two
# threads, so every place where the thread count could change the order of a
# sum is on the path. Both runs write to the same directory (moved aside
# after each), because the PNGs record the output directory.
#
#   cmake -DPROGRAM=build/greentread -DGEO=geometry/tyre_165_65_r13.geo
#         -DWORKDIR=<dir> -P same_bytes.cmake
#
# Every file of the first run must be in the second with the same bytes, and
# the second must have no other.
file(REMOVE_RECURSE ${WORKDIR})
set(run ${WORKDIR}/run)
foreach(threads 1 2)
  execute_process(
    COMMAND ${CMAKE_COMMAND} -E env DEAL_II_NUM_THREADS=${threads}
      ${PROGRAM}
      --set "Output directory=${run}"
      --set "Geometry/Geometry file=${GEO}"
      --set "Geometry/Mesh size=0.032"
      --set "Geometry/Element degree=2"
      --set "Green's functions/Maximum frequency=2000"
      --set "Green's functions/Frequency step=500"
      --set "Patch model/Mode cutoff=4000"
      --set "Contact grid/Subdivisions=2"
      --set "Road texture/Roads=road-A"
      --set "Rolling/Speeds (kph)=70, 90"
      --set "Rolling/Distance=1.1"
      --set "Spectra/Longest distance=3.3"
    RESULT_VARIABLE status OUTPUT_VARIABLE out ERROR_VARIABLE err)
  file(WRITE ${WORKDIR}/screen_${threads}.txt "${out}${err}")
  if(NOT status EQUAL 0)
    message(FATAL_ERROR "the run with ${threads} thread(s) failed (${status}):\n${out}\n${err}")
  endif()
  file(RENAME ${run} ${WORKDIR}/threads_${threads})
endforeach()

# The second run went the parallel way.
file(READ ${WORKDIR}/screen_2.txt out)
if(NOT out MATCHES "runs, 2 at a time")
  message(FATAL_ERROR "with two threads the runs did not go two at a time: no 'runs, 2 at a "
                      "time' in ${WORKDIR}/screen_2.txt")
endif()

file(GLOB_RECURSE first RELATIVE ${WORKDIR}/threads_1 ${WORKDIR}/threads_1/*)
file(GLOB_RECURSE second RELATIVE ${WORKDIR}/threads_2 ${WORKDIR}/threads_2/*)
list(SORT first)
list(SORT second)
if(NOT first STREQUAL second)
  message(FATAL_ERROR "the two runs wrote different files:\n1 thread: ${first}\n"
                      "2 threads: ${second}")
endif()
set(differ "")
foreach(f IN LISTS first)
  execute_process(COMMAND ${CMAKE_COMMAND} -E compare_files ${WORKDIR}/threads_1/${f}
                          ${WORKDIR}/threads_2/${f} RESULT_VARIABLE same)
  if(NOT same EQUAL 0)
    list(APPEND differ ${f})
  endif()
endforeach()
list(LENGTH first n)
if(differ)
  message(FATAL_ERROR "of ${n} files, these differ between 1 and 2 threads: ${differ}")
endif()
message(STATUS "${n} files, the same bytes with 1 and 2 threads")

# The tyre-green scene with two MPI ranks against one process, the stage
# cache, and 'identify' on a CSV it wrote.
file(REMOVE_RECURSE ${WORKDIR})
file(MAKE_DIRECTORY ${WORKDIR})
set(common
  --set "Geometry/Geometry file=${SOURCE_DIR}/geometry/tyre_165_65_r13.geo"
  --set "Geometry/Mesh size=0.04" --set "Geometry/Number of cells=32"
  --set "Green's functions/Frequency step=50" --set "Green's functions/Points along=4"
  --set "Green's functions/Points across=3" --set "Green's functions/Patch length=0.08"
  --set "Green's functions/Deflection shape frequency=-1"
  --set "Green's functions/Method=bloch")

function(run_checked name)
  execute_process(COMMAND ${ARGN} WORKING_DIRECTORY ${WORKDIR}
    RESULT_VARIABLE rc OUTPUT_VARIABLE out ERROR_VARIABLE err)
  if(NOT rc EQUAL 0)
    message(FATAL_ERROR "${name} failed (${rc}):\n${out}\n${err}")
  endif()
  set(output "${out}" PARENT_SCOPE)
endfunction()

run_checked("serial run" ${PROGRAM} --set "Scene=tyre-green" --set "Output directory=serial" ${common})
run_checked("mpirun -np 2" ${MPIEXEC} -np 2 ${PROGRAM} --set "Scene=tyre-green"
  --set "Output directory=parallel" ${common})
if(NOT output MATCHES "Run time on 2 MPI rank")
  message(FATAL_ERROR "the parallel run did not use 2 ranks:\n${output}")
endif()
# Each line is computed by one rank exactly as in the serial run: identical.
run_checked("compare" ${COMPARE} serial/green_functions.h5 parallel/green_functions.h5 0)
message(STATUS "serial against 2 ranks: ${output}")

# The same parameters again: the saved Green's functions are reused; a
# changed one is recomputed.
run_checked("second run" ${PROGRAM} --set "Scene=tyre-green" --set "Output directory=serial" ${common})
if(NOT output MATCHES "Reusing .*green_functions.h5")
  message(FATAL_ERROR "the second run did not reuse the saved Green's functions:\n${output}")
endif()
run_checked("changed run" ${PROGRAM} --set "Scene=tyre-green" --set "Output directory=serial" ${common}
  --set "Inflation/Pressure=2.2e5")
if(output MATCHES "Reusing")
  message(FATAL_ERROR "a changed pressure reused the old Green's functions:\n${output}")
endif()

# 'identify' reads the driving point's CSV (point 7 = the patch centre): the
# grid as written, and a fit. A point force on one tread node makes the
# driving point mostly a local static compliance, which modes below f_max
# carry poorly: on this coarse ring one mode is kept and E is 0.925. The
# bound, E below 1, is 1.08x that; a fit worse than no model at all fails.
run_checked("identify" ${PROGRAM} ${SOURCE_DIR}/prm/identify.prm --set "Output directory=identify"
  --set "Identification/FRF file=parallel/green_7_7.csv" --set "Print timings=false"
  --set "Identification/Maximum number of modes=20")
if(NOT output MATCHES "lines: 81 from 0 to 4000 Hz \\(df = 50 Hz\\)")
  message(FATAL_ERROR "identify did not read the 81 lines of green_7_7.csv:\n${output}")
endif()
if(NOT output MATCHES "Error E \\(Eq. 50\\): min [0-9.e+-]+, median [0-9.e+-]+, max ([0-9.e+-]+)")
  message(FATAL_ERROR "identify printed no error:\n${output}")
endif()
if(NOT CMAKE_MATCH_1 LESS 1)
  message(FATAL_ERROR "identify fitted green_7_7.csv with E = ${CMAKE_MATCH_1}:\n${output}")
endif()
message(STATUS "identify on green_7_7.csv: E = ${CMAKE_MATCH_1}")

# Under mpirun, every scene but tyre-green is refused on every rank, with a
# message that says which scene uses MPI, and exit status 2, the status of
# bad input (mpirun passes the ranks' status on).
execute_process(COMMAND ${MPIEXEC} -np 2 ${PROGRAM} --set "Scene=sdof"
  --set "Output directory=refused" WORKING_DIRECTORY ${WORKDIR}
  RESULT_VARIABLE rc OUTPUT_VARIABLE out ERROR_VARIABLE err)
if(NOT rc EQUAL 2)
  message(FATAL_ERROR "mpirun -np 2 of the sdof scene exited with ${rc}, not 2:\n${out}\n${err}")
endif()
if(NOT err MATCHES "only 'tyre-green' uses MPI")
  message(FATAL_ERROR "mpirun -np 2 of the sdof scene did not say why it was refused:\n${out}\n${err}")
endif()
file(GLOB_RECURSE left ${WORKDIR}/refused/*)
if(left)
  message(FATAL_ERROR "the refused MPI run left output behind: ${left}")
endif()
message(STATUS "mpirun -np 2 of the sdof scene: refused (${rc})")

# A failure on one rank only reaches every rank, as the same exception with
# the lowest failing rank's message (the rule of the Green's stage's frequency
# loop, throw_if_any_rank_failed).
run_checked("rank_failure" ${MPIEXEC} -np 2 ${RANK_FAILURE})
message(STATUS "a failure on one rank:\n${output}")

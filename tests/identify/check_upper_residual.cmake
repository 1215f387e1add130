# identify/upper_residual against identify/example_frf, both run on the same
# FRF: the upper residual takes the stiffness the modes above 4 kHz leave in
# the band, so E must drop. Read from both runs' output, not from stored
# numbers. Measured: 0.03147 without, 0.01691 with (0.54 of it); the bound,
# 0.75, sits between that and no gain.
foreach(run example_frf upper_residual)
  file(READ ${BINARY_DIR}/${run}.release/output text)
  if(NOT text MATCHES "Error E \\(Eq. 50\\): min ([0-9.e+-]+),")
    message(FATAL_ERROR "identify/${run} printed no E:\n${text}")
  endif()
  set(E_${run} ${CMAKE_MATCH_1})
endforeach()
# E as parts per million, for CMake's integer arithmetic.
foreach(run example_frf upper_residual)
  string(REGEX MATCH "^0\\.([0-9]+)$" digits "${E_${run}}")
  if(NOT digits)
    message(FATAL_ERROR "identify/${run}: E = ${E_${run}} is not a fraction below 1")
  endif()
  string(SUBSTRING "${CMAKE_MATCH_1}000000" 0 6 ppm)
  math(EXPR ppm_${run} "1${ppm} - 1000000")
endforeach()
math(EXPR limit "${ppm_example_frf} * 3 / 4")
message(STATUS "E without the upper residual ${E_example_frf}, with it ${E_upper_residual} "
               "(bound 0.75 of the first)")
if(NOT ppm_upper_residual LESS limit)
  message(FATAL_ERROR "the upper residual did not lower E enough: ${E_upper_residual} against "
                      "${E_example_frf} without it (bound 0.75 of it)")
endif()

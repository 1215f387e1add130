# check_synthesis_figures(OUTPUT PAIRS BOUND): the figures a run of the scene
# with the ring's own modes prints about its synthesis: E of Eq. (50) over
# PAIRS pairs, the largest at most BOUND %, and the patch model passive (the
# smallest eigenvalue of -Im g and of G_r over their largest not negative
# beyond round-off: a negative value passes only with an exponent from e-12
# to e-19).
function(check_synthesis_figures output pairs bound)
  if(NOT output MATCHES "over the ([0-9]+) pairs: median ([0-9.]+)%, 90th percentile ([0-9.]+)%, largest ([0-9.]+)%")
    message(FATAL_ERROR "no synthesis figures in the output")
  endif()
  set(worst ${CMAKE_MATCH_4})
  if(NOT CMAKE_MATCH_1 EQUAL ${pairs})
    message(FATAL_ERROR "E over ${CMAKE_MATCH_1} pairs, not ${pairs}")
  endif()
  if(worst GREATER ${bound})
    message(FATAL_ERROR "the synthesis' largest E is ${worst}%, above ${bound}%")
  endif()
  if(NOT output MATCHES "passivity: smallest eigenvalue of -Im g over its largest, over the lines ([-0-9.e+]+); static residual G_r: smallest eigenvalue over its largest ([-0-9.e+]+)")
    message(FATAL_ERROR "no passivity figures in the output")
  endif()
  foreach(value ${CMAKE_MATCH_1} ${CMAKE_MATCH_2})
    if(value MATCHES "^-" AND NOT value MATCHES "e-1[2-9]$")
      message(FATAL_ERROR "not positive semidefinite: ${value}")
    endif()
  endforeach()
  message(STATUS "synthesis: largest E ${worst}% over ${pairs} pairs")
endfunction()

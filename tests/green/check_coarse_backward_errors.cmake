# green/coarse's solve diagnostics against bounds, where numdiff cannot
# judge them: the backward errors are round-off (4.2e-18 to 5.3e-18 measured
# on the machines so far), which differs from machine to machine, so the
# .output's figures pass numdiff by its absolute tolerance (1e-6) whatever
# they are. A stable LU keeps them near round-off: the bound, 5e-17, is about
# 10x what is measured; a loss of even two digits fails it.
file(READ ${OUTPUT} text)
foreach(pattern "Every solve checked: largest backward error ([0-9.e+-]+)"
                "Deflection shape at [0-9]+ Hz under the unit load of point [0-9]+: largest backward error ([0-9.e+-]+)")
  if(NOT text MATCHES "${pattern}")
    message(FATAL_ERROR "${OUTPUT} has no line matching '${pattern}':\n${text}")
  endif()
  set(value ${CMAKE_MATCH_1})
  # CMake compares numbers as integers or plain decimals: compare the
  # exponent instead (a value below 5e-17 has mantissa x 10^e with e <= -18,
  # or e = -17 and mantissa < 5).
  if(NOT value MATCHES "^([0-9.]+)e-([0-9]+)$")
    message(FATAL_ERROR "backward error '${value}' is not below 1: ${CMAKE_MATCH_0}")
  endif()
  set(mantissa ${CMAKE_MATCH_1})
  set(exponent ${CMAKE_MATCH_2})
  if(exponent LESS 17 OR (exponent EQUAL 17 AND mantissa GREATER_EQUAL 5))
    message(FATAL_ERROR "green/coarse: a backward error of ${value} is above its bound 5e-17")
  endif()
  message(STATUS "backward error ${value} (bound 5e-17)")
endforeach()

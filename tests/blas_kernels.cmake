# greentread --version names OpenBLAS's kernels (base/blas_kernels.h). On a
# processor with AVX2 they must not be Prescott's (SSE3), OpenBLAS's fallback
# for a processor it does not know: the program then runs itself again with
# better ones. A BLAS other than OpenBLAS, or an older processor, passes.
# The user's own OPENBLAS_CORETYPE is kept: with Prescott asked, Prescott.
execute_process(COMMAND ${PROGRAM} --version RESULT_VARIABLE status OUTPUT_VARIABLE out)
if(NOT status EQUAL 0 OR NOT out MATCHES "BLAS (OpenBLAS \\(([A-Za-z0-9]+) kernels\\)|not OpenBLAS)")
  message(FATAL_ERROR "greentread --version does not name its BLAS:\n${out}")
endif()
set(core "${CMAKE_MATCH_2}")
file(READ /proc/cpuinfo cpuinfo)
if(core AND cpuinfo MATCHES " avx2 " AND core STREQUAL "Prescott")
  message(FATAL_ERROR "OpenBLAS runs Prescott's kernels on a processor with AVX2:\n${out}")
endif()
if(core)
  execute_process(COMMAND ${CMAKE_COMMAND} -E env OPENBLAS_CORETYPE=Prescott ${PROGRAM} --version
                  OUTPUT_VARIABLE asked)
  if(NOT asked MATCHES "OpenBLAS \\(Prescott kernels\\)")
    message(FATAL_ERROR "OPENBLAS_CORETYPE=Prescott was not kept:\n${asked}")
  endif()
endif()
message(STATUS "kernels: ${core}")

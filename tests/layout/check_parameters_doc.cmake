# doc/parameters.md must be what the program prints: the parameter reference
# is generated, never written by hand. Fails naming the first differing line
# and the command that brings the file up to date.
execute_process(COMMAND ${PROGRAM} --print-parameters=markdown
  OUTPUT_FILE ${OUT} RESULT_VARIABLE status)
if(NOT status EQUAL 0)
  message(FATAL_ERROR "greentread --print-parameters=markdown failed (exit ${status})")
endif()
file(STRINGS ${DOC} doc)
file(STRINGS ${OUT} generated)
if(NOT doc STREQUAL generated)
  list(LENGTH doc n_doc)
  list(LENGTH generated n_generated)
  set(first "")
  foreach(i RANGE 0 ${n_generated})
    if(i LESS n_doc AND i LESS n_generated)
      list(GET doc ${i} a)
      list(GET generated ${i} b)
      if(NOT a STREQUAL b)
        math(EXPR line "${i} + 1")
        set(first "line ${line}:\n  doc:     ${a}\n  program: ${b}")
        break()
      endif()
    endif()
  endforeach()
  message(FATAL_ERROR "doc/parameters.md is stale (${n_doc} lines; the program prints ${n_generated}); "
    "${first}\nbring it up to date: build/greentread --print-parameters=markdown > doc/parameters.md")
endif()
message(STATUS "doc/parameters.md is the program's own reference")

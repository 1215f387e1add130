# Runs one benchmark and writes its key numbers; with --quick, as ctest's
# benchmark-smoke/<name> runs it, compares them with its folder's
# reference_quick.csv.
#
#   cmake -DPROGRAM=build/benchmarks/<name> -DOUTPUT=<dir> [-DFULL=ON]
#         [-DCONFIG=benchmarks/<name>/reference_quick.cmake
#          [-DREFERENCE=benchmarks/<name>/reference_quick.csv]]
#         -P benchmarks/run_benchmark.cmake
#
# The run (with --quick unless FULL) must exit 0: every benchmark asserts its
# own figures against its reference method (benchmark::Checks). CONFIG, a
# benchmark's reference_quick.cmake, sets
#
#   CSV         the file the run writes in OUTPUT;
#   COLUMNS     the columns of CSV that are key numbers, '|' between them:
#               only numbers of the method (errors, levels, frequencies,
#               counts), never run times;
#   ROWS        (optional) a regular expression that the kept rows match;
#   EXCLUDE_ROWS (optional) one that they do not match;
#   RELATIVE    the relative tolerance of every numeric column;
#   TOLERANCES  (optional) column=relative[@absolute] for the columns that
#               need their own ('|' between them); the absolute one for a
#               figure that may pass through zero.
#
# Those columns of those rows are written to OUTPUT/key_numbers.csv, and with
# REFERENCE compared with it by numdiff column by column (text columns
# exactly). Spaces and commas inside a text field become '_' so that a field
# is one column for numdiff. benchmarks/update_tables.sh writes the same file
# as the table of the benchmark's README.

cmake_minimum_required(VERSION 3.13) # lists keep their empty elements (empty CSV fields)
if(NOT PROGRAM OR NOT OUTPUT)
  message(FATAL_ERROR "run_benchmark.cmake needs -DPROGRAM and -DOUTPUT")
endif()
set(mode --quick)
if(FULL)
  set(mode "")
endif()
execute_process(COMMAND ${PROGRAM} ${mode} --output ${OUTPUT} RESULT_VARIABLE status)
if(NOT status EQUAL 0)
  message(FATAL_ERROR "${PROGRAM} ${mode} failed (${status})")
endif()
if(NOT CONFIG)
  return()
endif()
include(${CONFIG})

if(NOT EXISTS ${OUTPUT}/${CSV})
  message(FATAL_ERROR "${PROGRAM} ${mode} wrote no ${OUTPUT}/${CSV}")
endif()

# fields(<line> <out-var>): the fields of one CSV line, quotes removed, spaces
# and commas inside a field replaced by '_'.
function(fields line out)
  set(previous "")
  while(NOT line STREQUAL previous)
    set(previous "${line}")
    string(REGEX REPLACE "\"([^\",]*),([^\"]*)\"" "\"\\1_\\2\"" line "${line}")
  endwhile()
  string(REPLACE "\"" "" line "${line}")
  string(REPLACE ";" "_" line "${line}")
  string(REPLACE " " "_" line "${line}")
  string(REPLACE "," ";" line "${line}")
  set(${out} "${line}" PARENT_SCOPE)
endfunction()

file(STRINGS ${OUTPUT}/${CSV} lines)
list(FILTER lines EXCLUDE REGEX "^#")
list(POP_FRONT lines header_line)
fields("${header_line}" header)
string(REPLACE "|" ";" columns "${COLUMNS}")
set(indices "")
foreach(column IN LISTS columns)
  list(FIND header "${column}" i)
  if(i LESS 0)
    message(FATAL_ERROR "${CSV} has no column '${column}' (it has: ${header})")
  endif()
  list(APPEND indices ${i})
endforeach()

string(REPLACE ";" "," key "${columns}")
set(key "${key}\n")
foreach(line IN LISTS lines)
  if(line STREQUAL "" OR (ROWS AND NOT line MATCHES "${ROWS}") OR
     (EXCLUDE_ROWS AND line MATCHES "${EXCLUDE_ROWS}"))
    continue()
  endif()
  fields("${line}" row)
  set(kept "")
  foreach(i IN LISTS indices)
    list(GET row ${i} value)
    list(APPEND kept "${value}")
  endforeach()
  string(REPLACE ";" "," kept "${kept}")
  string(APPEND key "${kept}\n")
endforeach()
file(WRITE ${OUTPUT}/key_numbers.csv "${key}")
message(STATUS "Wrote ${OUTPUT}/key_numbers.csv")
if(NOT REFERENCE)
  return()
endif()
find_program(NUMDIFF numdiff)
if(NOT NUMDIFF)
  message(FATAL_ERROR "numdiff was not found (apt-get install numdiff): it compares the key "
                      "numbers with ${REFERENCE}")
endif()

# numdiff's field numbers are the columns', counted from 1.
set(tolerance_args -r ${RELATIVE})
string(REPLACE "|" ";" tolerances "${TOLERANCES}")
foreach(entry IN LISTS tolerances)
  if(NOT entry MATCHES "^([^=]+)=([^@]+)(@(.+))?$")
    message(FATAL_ERROR "TOLERANCES entry '${entry}' is not column=relative[@absolute]")
  endif()
  list(FIND columns "${CMAKE_MATCH_1}" i)
  if(i LESS 0)
    message(FATAL_ERROR "TOLERANCES names '${CMAKE_MATCH_1}', which is not in COLUMNS")
  endif()
  math(EXPR field "${i} + 1")
  list(APPEND tolerance_args -r ${CMAKE_MATCH_2}:${field})
  if(CMAKE_MATCH_4)
    list(APPEND tolerance_args -a ${CMAKE_MATCH_4}:${field})
  endif()
endforeach()

string(REPLACE ";" " " shown "${tolerance_args}")
execute_process(
  COMMAND ${NUMDIFF} -q -s ", \n" ${tolerance_args} ${REFERENCE} ${OUTPUT}/key_numbers.csv
  RESULT_VARIABLE status)
if(NOT status EQUAL 0)
  execute_process(
    COMMAND ${NUMDIFF} -s ", \n" ${tolerance_args} ${REFERENCE} ${OUTPUT}/key_numbers.csv
    OUTPUT_VARIABLE differences)
  message(FATAL_ERROR
    "The key numbers of ${PROGRAM} ${mode} differ from ${REFERENCE} beyond their tolerances "
    "(numdiff ${shown}):\n${differences}\n"
    "If the change is meant, check it and accept it with:\n"
    "  cp ${OUTPUT}/key_numbers.csv ${REFERENCE}")
endif()
message(STATUS "The key numbers (${COLUMNS}) agree with ${REFERENCE} (numdiff ${shown})")

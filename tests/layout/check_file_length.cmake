# No C++ source of the project is over 600 lines (CONTRIBUTING.md: a file
# that grows past it is split where its work divides). Run as
#   cmake -DTOP=<source dir> -P check_file_length.cmake
# and it fails naming every file over the limit, with its length.
cmake_policy(SET CMP0007 NEW)
set(limit 600)
file(GLOB_RECURSE files
  ${TOP}/source/*.cc ${TOP}/include/*.h ${TOP}/tests/*.cc ${TOP}/tests/*.h
  ${TOP}/benchmarks/*.cc ${TOP}/benchmarks/*.h)
set(long "")
list(LENGTH files n_files)
foreach(file IN LISTS files)
  # The newlines, not file(STRINGS), which drops empty lines.
  file(READ ${file} text)
  string(REGEX MATCHALL "\n" newlines "${text}")
  list(LENGTH newlines n)
  if(n GREATER limit)
    file(RELATIVE_PATH relative ${TOP} ${file})
    string(APPEND long "\n  ${relative}: ${n} lines")
  endif()
endforeach()
if(long)
  message(FATAL_ERROR "files over ${limit} lines (split them where their work divides):${long}")
endif()
message(STATUS "${n_files} C++ files, none over ${limit} lines")

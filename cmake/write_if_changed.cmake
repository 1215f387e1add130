# write_if_changed(FILE TEXT): writes TEXT to FILE unless FILE holds it
# already, so that what depends on FILE is not rebuilt for nothing. Included
# by the scripts that generate sources at build time.
function(write_if_changed file text)
  set(old "")
  if(EXISTS "${file}")
    file(READ "${file}" old)
  endif()
  if(NOT old STREQUAL text)
    file(WRITE "${file}" "${text}")
  endif()
endfunction()

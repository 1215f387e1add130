# Writes OUTPUT, a header defining GREENTREAD_<NAME>_SOURCES_DIGEST: the SHA-256
# of the sources listed in FILES (separated by '|'), in order. Run at build
# time by the target <name>_sources_digest, so an edit to any of them changes
# the key of the saved stage output, and no other edit does.
string(REPLACE "|" ";" files "${FILES}")
set(all "")
foreach(f IN LISTS files)
  file(SHA256 "${f}" h)
  string(APPEND all "${h}")
endforeach()
string(SHA256 digest "${all}")
set(text "#pragma once\n#define GREENTREAD_${NAME}_SOURCES_DIGEST \"${digest}\"\n")
include(${CMAKE_CURRENT_LIST_DIR}/write_if_changed.cmake)
write_if_changed("${OUTPUT}" "${text}")

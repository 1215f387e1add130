# require(<pattern> <what>): the screen output in the caller's variable 'out'
# must match <pattern>; otherwise the test fails, saying <what>.
function(require pattern what)
  if(NOT out MATCHES "${pattern}")
    message(FATAL_ERROR "${what}: no '${pattern}' in the output")
  endif()
endfunction()

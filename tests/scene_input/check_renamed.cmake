# The old spellings of renamed parameters still work for one release, with a
# warning that names both spellings, and give the same results as the new
# ones. Run with -DPROGRAM=<greentread> -DWORKDIR=<scratch folder>.
file(REMOVE_RECURSE ${WORKDIR})
file(MAKE_DIRECTORY ${WORKDIR})

function(run name expect_status)
  execute_process(COMMAND ${PROGRAM} --set "Print timings=false" ${ARGN}
    WORKING_DIRECTORY ${WORKDIR} RESULT_VARIABLE status OUTPUT_VARIABLE out ERROR_VARIABLE err)
  if(NOT status EQUAL expect_status)
    message(FATAL_ERROR "${name}: exit ${status}, expected ${expect_status}:\n${out}\n${err}")
  endif()
  set(${name}_err "${err}" PARENT_SCOPE)
endfunction()

function(expect name regex)
  string(REGEX REPLACE "\n" " " line "${${name}_err}")
  if(NOT line MATCHES "${regex}")
    message(FATAL_ERROR "${name}: standard error does not match '${regex}':\n${${name}_err}")
  endif()
endfunction()

# 1. The 1-DoF scene at 0.1 m/s, once with the old name in m/s and once with
#    the new one in km/h: the same history, and a warning for the old one.
run(old_speed 0 --set "Scene=sdof" --set "Output directory=old" --set "Oscillator/Speed=0.1")
run(new_speed 0 --set "Scene=sdof" --set "Output directory=new" --set "Oscillator/Speed (kph)=0.36")
expect(old_speed "greentread: warning: parameter 'Oscillator/Speed' is deprecated: it was read as 'Oscillator/Speed \\(kph\\)' = 0.36; use that name")
if(new_speed_err MATCHES "warning")
  message(FATAL_ERROR "the new name warned:\n${new_speed_err}")
endif()
file(GLOB results RELATIVE ${WORKDIR}/new ${WORKDIR}/new/*.csv)
if(NOT results)
  message(FATAL_ERROR "the 1-DoF scene wrote no CSV file in ${WORKDIR}/new")
endif()
foreach(f IN LISTS results)
  # Every line but the comments and the run time.
  file(STRINGS ${WORKDIR}/old/${f} a REGEX "^[^#]")
  file(STRINGS ${WORKDIR}/new/${f} b REGEX "^[^#]")
  list(FILTER a EXCLUDE REGEX "^run_time,")
  list(FILTER b EXCLUDE REGEX "^run_time,")
  if(NOT a STREQUAL b)
    message(FATAL_ERROR "${f} differs between the old and the new speed parameter")
  endif()
endforeach()
list(LENGTH results n)

# 2. The other renames: each old name reaches its new entry (its range check
#    names both), and setting both spellings is refused.
run(old_speeds 2 --set "Rolling/Speeds=-50")
expect(old_speeds "parameter 'Rolling/Speeds' = -50 \\(the old spelling of 'Rolling/Speeds \\(kph\\)' = -50\\) is not allowed")
run(old_amplitude 2 --set "Road texture/Sinusoid amplitude=1")
expect(old_amplitude "parameter 'Road texture/Sinusoid amplitude' = 1 \\(the old spelling of 'Road/Sinusoid/Amplitude' = 1\\) is not allowed; allowed: \\[a finite number in \\[0, 0.05\\], in m\\]")
run(old_wavelength 2 --set "Road texture/Sinusoid wavelength=100")
expect(old_wavelength "the old spelling of 'Road/Sinusoid/Wavelength' = 100\\) is not allowed")
run(both 2 --set "Road texture/Sinusoid amplitude=0.001" --set "Road/Sinusoid/Amplitude=0.002")
expect(both "parameters 'Road texture/Sinusoid amplitude' = 0.001 and 'Road/Sinusoid/Amplitude' = 0.002 are both set")

# 3. The old scene names: read as the new ones, with a warning (then a bad
#    value stops the run before anything is computed).
run(old_scene 2 --set "Scene=tire-cell" --set "Geometry/Geometry file=no_such.geo")
expect(old_scene "greentread: warning: scene 'tire-cell' is deprecated: it was read as 'tyre-cell'.*parameter 'Geometry/Geometry file' = no_such.geo: no such file")
message(STATUS "old and new names agree on ${n} result files; every old spelling warns")

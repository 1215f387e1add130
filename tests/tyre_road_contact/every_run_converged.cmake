# every_run_converged(<screen output>): each run prints a line
# 'run <name>: V0 = ...' as it starts and one with 'steps the contact solve
# did not converge: <n>,' as it ends; there must be at least one run, and
# every run's line must say 0 (the same rule as tests/unit/run_lines.h).
function(every_run_converged out)
  string(REGEX MATCHALL "run [^ \n]+: V0 = " runs "${out}")
  string(REGEX MATCHALL "steps the contact solve did not converge: 0," converged "${out}")
  list(LENGTH runs n_runs)
  list(LENGTH converged n_converged)
  if(n_runs EQUAL 0 OR NOT n_converged EQUAL n_runs OR out MATCHES "did not converge: [1-9]")
    message(FATAL_ERROR "a contact step did not converge: ${n_converged} of ${n_runs} runs "
      "say 'did not converge: 0,':\n${out}")
  endif()
endfunction()

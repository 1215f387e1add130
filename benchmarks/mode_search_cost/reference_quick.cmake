# Key numbers of mode_search_cost --quick (run_benchmark.cmake): for 1 to 4
# slices and each wavenumber, the modes found below 3 kHz (a count: exact)
# and their frequencies' largest difference from one slice's, which is the
# search's tolerance at work: up to 1.7e-11 here, and the program's own
# check is 1e-10. Absolute 5e-11 (3 times it) fails a slicing that loses
# accuracy. The solves and the Krylov dimensions are left out: they follow
# the convergence test, which round-off can tip by a restart.
set(CSV mode_search_cost.csv)
set(COLUMNS "slices|k|modes|difference_vs_one_slice")
set(RELATIVE 0)
set(TOLERANCES "difference_vs_one_slice=0@5e-11")

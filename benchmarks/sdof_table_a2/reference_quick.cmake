# Key numbers of sdof_table_a2 --quick (run_benchmark.cmake): each method's
# size (N_g or N_m) and its largest error against the exact solution.
# Runs, and 1 against 2 threads, give the same numbers to every printed digit;
# the methods differ from each other by 4.5e-6 relative (modal-paper against
# modal-recursive on the first row), so 1e-6 keeps them apart and leaves the
# round-off of another processor or compiler (1e-12 and below) through. The
# 10 us row's errors are round-off (1e-21 m): absolute 1e-15 m passes those.
set(CSV table_a2.csv)
set(COLUMNS "dt|n_steps|method|size|max_u_error")
set(RELATIVE 1e-6)
set(TOLERANCES "max_u_error=1e-6@1e-15")

# Key numbers of modal_update_cost --quick (run_benchmark.cmake): for each
# number of modes, the largest difference between the modal-recursive update
# and the direct convolution of the same Green's function on the same loads.
# It is round-off, 8e-15 to 3.4e-14 here: absolute 1e-13 (3 times the
# largest) passes another processor's round-off and fails a recursion that
# has stopped being exact (a wrong factor moves it by percents).
set(CSV modal_update_cost.csv)
set(COLUMNS "n_modes|difference")
set(RELATIVE 0)
set(TOLERANCES "difference=0@1e-13")

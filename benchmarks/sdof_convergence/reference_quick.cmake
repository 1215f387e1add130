# Key numbers of sdof_convergence --quick (run_benchmark.cmake): each
# configuration's largest error against the exact solution and its largest
# penetration inside a step, at each dt. Runs, and 1 against 2 threads, give
# the same numbers to every printed digit. They are printed to 6 digits, so a
# round-off change of another processor can move the last one (up to 1e-5
# relative); 1e-4 allows that. A change of a law or of a method's order moves
# these errors by far more: modal-paper and direct differ by 1.3e-4 at 1 ms,
# and halving the order would move the 37 us errors by two orders of magnitude.
set(CSV sdof_convergence.csv)
set(COLUMNS "configuration|dt|max_u_error|max_penetration_inside_steps")
set(RELATIVE 1e-4)

# Key numbers of rolling_contact --quick (run_benchmark.cmake): each run's
# distance and steps, and the modal-recursive run's largest stress
# difference from the direct convolution's on the same road (relative to the
# largest stress), which is round-off: 3.5e-14 here. Absolute 1e-13 (3 times
# it) passes another processor's round-off. The band-level difference is
# left out: the --quick record is too short for bands (the program prints
# nan for it, by design).
set(CSV rolling_contact.csv)
set(COLUMNS "method|distance_m|steps|max_rel_stress_difference")
set(RELATIVE 0)
set(TOLERANCES "max_rel_stress_difference=0@1e-13")

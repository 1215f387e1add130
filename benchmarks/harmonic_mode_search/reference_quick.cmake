# Key numbers of harmonic_mode_search --quick (run_benchmark.cmake): the
# number of modes below 4 kHz that each solver finds on the quadratic 8 mm
# section at harmonics 0 and 40 (74 and 46). They must match exactly: they are
# the section's spectrum, which a change of its mesh, materials or assembly
# moves, and every solver must find them all (the program also checks each
# count against the inertia's). The residuals and the frequency differences
# between solvers are round-off, bounded by the program's own check, and the
# times are not compared.
set(CSV harmonic_mode_search.csv)
set(COLUMNS "harmonic|solver|modes")
set(RELATIVE 0)

# Key numbers of identification --quick (run_benchmark.cmake): the FRFs, how
# many were identified (the rest by reciprocity), and E of Eq. (50) over them
# (min, median, 95th percentile, max). The largest pole error is round-off
# (2.4e-10) and is bounded by the program's own check, so it is not compared.
# Runs, and 1 against 2 threads, give the same numbers to every printed digit
# (12). E comes out of least squares and eigenvalue solves, whose round-off
# moves with the processor's vector width; 1e-3 of E leaves that through and
# fails on a fit that changes (a mode more or less moves E by percents).
set(CSV identification.csv)
set(COLUMNS "frfs|identified|E_min|E_median|E_p95|E_max")
set(RELATIVE 1e-3)

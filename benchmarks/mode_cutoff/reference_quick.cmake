# Key numbers of mode_cutoff --quick (run_benchmark.cmake): on the tests'
# coarse tyre, at the 2.5 and 5 kHz cut-offs, the modes kept and E of Eq. (50)
# against the direct lines (median, 90th percentile, worst, worst driving
# point). Passivity and G_r's definiteness are round-off (-2e-16, -1e-14) and
# bounded by the program's own check, so they are not compared. Printed to 6
# digits: 1e-4 of E allows a last-digit change from another processor's
# round-off; one mode more or less, or a change of the residual's fit, moves E
# by far more (the two cut-offs differ sevenfold). The mode counts must match.
set(CSV mode_cutoff.csv)
set(COLUMNS "cutoff_hz|modes|median|p90|worst|driving_worst")
set(RELATIVE 1e-4)
set(TOLERANCES "modes=0")

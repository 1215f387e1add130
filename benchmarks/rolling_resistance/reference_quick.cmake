# Key numbers of rolling_resistance.sh --quick (run_benchmark.cmake): on
# road-A and road-B at 70 km/h over 1.2 m (the coarse ring), at 2, 1 and 1/2
# of the scene's step, the rolling-resistance coefficient, its standard error,
# its change to the next finer step, the order the three steps show, each
# step's distance from the extrapolated limit, and the scene's time step
# error bar on its step. The runs are deterministic (the same bytes at any
# thread count), so these are a reproduction. The scene prints six
# significant digits, one unit of the last being 1e-6 to 1e-5 of the value:
# 1e-5 is that unit, which another processor's round-off may flip (on an AMD
# EPYC of family 26 the standard error of road-B at half the step read
# 3.64817e-4 against the reference's 3.64818e-4, made on family 25, 2.7e-6
# apart), and it still fails a
# meter that moved by a step's work (about 1e-4 of the record's); the order
# and the distance are compared to their printed digits. Never the times per
# step.
set(CSV rolling_resistance.csv)
set(COLUMNS "road|factor|coefficient|coefficient_se|change_from_finer|observed_order|from_limit_percent|step_error")
set(RELATIVE 1e-5)
set(TOLERANCES "change_from_finer=1e-5@1e-12|observed_order=0@0.002|from_limit_percent=0@0.02")

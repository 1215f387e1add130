# Key numbers of contact_grid_study.sh --quick (run_benchmark.cmake): on
# road-A at 90 km/h over 1.2 m (the coarse ring), for 1, 2 and 4 contact
# rectangles per Green's-function rectangle and the rule 'point' on 1 and 2,
# the points in contact (least and most, %), the mean force, and the largest
# band-level difference of the stress and of the force to the next finer grid
# and to the finest (dB; 'none' where the row has no such grid), the study's
# convergence figures (3 to 21 dB on so coarse a ring). Four runs here
# differed by up to 4e-6 dB (the FFT plans were measured then, so round-off
# varied with the load; runs now give the same bytes, and the bound is a
# margin for another processor's round-off) and not in the counts and forces,
# which the runs print to 3 or 4 digits; 1e-5 dB bounds the differences within
# about 2.5 times that, and 1e-3 of the force is its last printed digit.
set(CSV contact_grid_study.csv)
set(COLUMNS "grid|rule|points|road|contact_min_pct|contact_max_pct|mean_force_N|stress_to_next_dB|stress_to_finest_dB|force_to_next_dB|force_to_finest_dB")
set(ROWS "^grids,")
set(RELATIVE 0)
set(TOLERANCES "mean_force_N=1e-3|stress_to_next_dB=0@1e-5|stress_to_finest_dB=0@1e-5|force_to_next_dB=0@1e-5|force_to_finest_dB=0@1e-5")

# Key numbers of patch_update_cost --quick (run_benchmark.cmake): for each
# size and form, the memory and floating-point work per step (counts, exact)
# and the difference from the double-precision form. The single-precision
# form's difference (1.2e-7 and 2.3e-7 here) is float round-off, which moves
# with the order of the sums (the processor's vector width): relative 1
# allows a factor 2 and fails a form that is wrong (percents). The full
# form's difference is double round-off (2.5e-15): absolute 1e-14.
set(CSV patch_update_cost.csv)
set(COLUMNS "points|shape_rows|form|block_steps|mb_per_step|gflop_per_step|difference")
set(RELATIVE 1e-12)
set(TOLERANCES "difference=1@1e-14")

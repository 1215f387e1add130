# Key numbers of contact_studies.sh --quick (run_benchmark.cmake): on the
# coarse ring, the time-step study's largest band-level differences from the
# reference step (bands to 1 kHz and all bands) and its steps not converged;
# and for each case, the points in contact (least and most, %), the mean force
# and its steps not converged. Two runs here differed by up to 3e-6 dB in the
# differences (the FFT plans were measured then, so round-off varied with the
# load; runs now give the same bytes, and the bound is a margin for another
# processor's round-off) and not in the counts and forces, which the runs
# print to 3 or 4 digits; 1e-5 dB bounds the differences within about 3 times
# that (the smallest is 0.008 dB), and 1e-3 of a force is its last printed
# digit.
set(CSV contact_studies.csv)
set(COLUMNS "table|label|road_samples_per_step|steps_not_converged|difference_to_1kHz_dB|difference_all_bands_dB|top_band_Hz|contact_min_pct|contact_max_pct|mean_force_N|static_force_N")
set(RELATIVE 0)
set(TOLERANCES "difference_to_1kHz_dB=0@1e-5|difference_all_bands_dB=0@1e-5|mean_force_N=1e-3|static_force_N=1e-3")

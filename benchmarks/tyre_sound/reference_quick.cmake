# Key numbers of tyre_sound --quick (run_benchmark.cmake): the levels [dB] at
# the two CPX microphones and the power level of the main job's tyre for
# white-noise forces at its points, per band, on the coarse and the fine
# mesh and with twice the harmonics. They are printed to 6 digits; the
# solution's round-off on another processor moves them by far less than
# 0.01 dB, the absolute tolerance. A change of the kernel, the quadrature, the
# geometry or the modes moves them by more: the finer mesh alone moves them
# by up to 0.9 dB.
set(CSV tyre_sound.csv)
set(COLUMNS "band_Hz|quantity|coarse_dB|fine_dB|coarse_2x_harmonics_dB")
set(RELATIVE 1e-4)
set(TOLERANCES "coarse_dB=1e-4@0.01|fine_dB=1e-4@0.01|coarse_2x_harmonics_dB=1e-4@0.01")

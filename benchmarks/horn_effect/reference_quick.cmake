# Key numbers of horn_effect --quick (run_benchmark.cmake): the tyre's
# amplification [dB] of a source on the road before its contact patch, on
# the coarse and the fine mesh, per band, distance and direction. They are
# printed to 6 digits; the solution's round-off on another processor moves
# them by far less than 0.01 dB, which is the absolute tolerance (some pass
# near 0 dB). A change of the kernel, the quadrature or the geometry moves
# them by more: the finer mesh alone moves them by up to 0.26 dB.
set(CSV horn_effect.csv)
set(COLUMNS "frequency|distance|direction|coarse|fine")
set(RELATIVE 1e-4)
set(TOLERANCES "coarse=1e-3@0.01|fine=1e-3@0.01")

# Key numbers of harmonic_convergence --quick (run_benchmark.cmake): the
# static centre driving point and its transfers (g, m/N) of the quadratic
# 8 mm and 4 mm sections, and each one's difference from the 4 mm one. Runs
# give the same numbers to every printed digit (6); 1e-4 allows a last-digit
# change from another processor's round-off, while the two sections differ by
# 3.5% to 12% and a change of the element, the harmonics or the loads moves g by
# more than 1e-3. The static imaginary parts are 0 and so is the finer
# section's difference from itself: absolute tolerances pass their round-off.
set(CSV harmonic_convergence.csv)
set(COLUMNS "series|mesh_size|degree|frequency|function|re|im|relative_difference_from_finest")
set(RELATIVE 1e-4)
set(TOLERANCES "im=1e-4@1e-15|relative_difference_from_finest=1e-4@1e-9")

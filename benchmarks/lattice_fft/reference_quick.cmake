# Key numbers of lattice_fft --quick (run_benchmark.cmake): for each grid and
# plan, the product's largest difference from the dense product L x and
# whether two products gave the same bytes. The differences are round-off
# (measured 3e-16 to 1e-15, moving with the plan FFTW builds for this
# processor); relative 3 with an absolute 3e-15 holds them within a few
# units of round-off and fails an error of the method (1e-2 for an index off
# by one). The planning and product times are not compared.
set(CSV lattice_fft.csv)
set(COLUMNS "nx|ny|plans|difference_from_dense|same_bytes_twice")
set(RELATIVE 0)
set(TOLERANCES "difference_from_dense=3@3e-15")

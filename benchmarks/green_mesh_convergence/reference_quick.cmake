# Key numbers of green_mesh_convergence --quick (run_benchmark.cmake): part
# 1's three uniform levels (4, 2, 1 cm) at 0 and 1 kHz, the centre driving
# point and its two transfers: the cells' DoFs, g (real and imaginary parts,
# um/N) and its difference from the finest level. Runs give the same numbers
# to every printed digit (6). A round-off change of another processor can move
# the last digit (up to 1e-5 relative), so 1e-4 of g; the levels differ by 30%
# to 90%, and a change of the element or of the loads moves g by more than
# 1e-3. The imaginary parts at 0 Hz and the finest level's difference from
# itself are round-off (1e-13, 0): absolute 1e-9 passes those.
set(CSV green_mesh_convergence.csv)
set(COLUMNS "mesh_size|n_cells|crown_refinement|cell_dofs|frequency_Hz|function|re_um_per_N|im_um_per_N|difference_from_finest")
set(RELATIVE 1e-4)
set(TOLERANCES "im_um_per_N=1e-4@1e-9|difference_from_finest=1e-4@1e-9")

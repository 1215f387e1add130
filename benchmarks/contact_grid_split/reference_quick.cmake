# Key numbers of contact_grid_split --quick (run_benchmark.cmake): on the 20 mm
# section, the centre driving point and its transfers (um/N) of the finite
# elements' 10 x 12 rectangles, of the 5 x 6 split with the layer and of the
# spread without it, and the worst driving point's and the whole matrix's
# difference from the finite elements. Runs give the same numbers to every
# printed digit (6); 1e-4 allows a last-digit change from another processor's
# round-off, while a change of the split or of the layer moves them by
# percents (the two coarse models differ by 50%). The finite elements' own
# differences are 0: absolute 1e-9 passes their round-off.
set(CSV contact_grid_split.csv)
set(COLUMNS "mesh_size|model|driving_um_per_N|along_x_um_per_N|across_y_um_per_N|worst_driving_difference|matrix_difference")
set(RELATIVE 1e-4)
set(TOLERANCES "worst_driving_difference=1e-4@1e-9|matrix_difference=1e-4@1e-9")

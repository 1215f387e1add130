# Key numbers of tread_pattern.sh --quick (run_benchmark.cmake): on road-A at
# 70 km/h over 1.2 m at 3 road samples per step (the coarse ring), at 480 and
# 1920 contact points, the largest force band-level difference (100 Hz to
# 5 kHz) from the 1920-point grid, patterned and slick, and between the
# patterned and the slick tyre; on 1920 points, the largest move of the
# patterned tyre's force band levels from its finite blocks on their 4 mm
# mesh to their 6 mm and 2.67 mm meshes and to the endless layer, and the
# scene's error bar of the blocks' mesh on 4 mm (rms over the bands from
# 250 Hz). The runs are deterministic (the same bytes
# at any thread count), so the numbers are a reproduction, not a
# measurement with a spread: 0.01 dB leaves room for another libm and still
# fails a pattern moved by a contact rectangle (which moves them by tenths
# of a dB and more). Never the times per step.
set(CSV tread_pattern.csv)
set(COLUMNS "points|patterned_grid_dB|slick_grid_dB|pattern_effect_dB|blocks|blocks_dB")
set(RELATIVE 0)
set(TOLERANCES "patterned_grid_dB=0@0.01|slick_grid_dB=0@0.01|pattern_effect_dB=0@0.01|blocks_dB=0@0.01")

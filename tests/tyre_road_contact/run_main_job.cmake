# The main job's own path, end to end: the program with its built-in default
# scene and every default of the main job (the harmonic ring and its
# quartic section, tributary areas, the ring's own modes, the contact grid
# at 8 subdivisions, projected CG), on one road, one speed and a short
# distance: a 5 um sinusoid of 40 mm at 90 km/h under 3000 N, where the
# contact is sustained, with its multi-rate spectra (the bands to 1 kHz from
# a low-rate run as long as a 2 dB target needs, a quarter of the default
# 1 dB's). WORKDIR is kept: its saved stages are the fixture of
# unit/main_job_path. Checked here, from what the run prints:
# - the route: the harmonic ring, the ring's modes, 7680 contact points by
#   projected CG, every step converged;
# - the synthesis' E of Eq. (50) against the run's own direct lines, every
#   pair (bound WORST_BOUND, %);
# - the patch model passive (its smallest eigenvalue of -Im g over its
#   largest not negative beyond round-off);
# - the error bars: the runs at half the step, on half the subdivisions,
#   with the modes to 6 kHz and on the section twice as coarse (its own
#   Green's functions and modes), and their summary.
# unit/main_job_path checks the outputs against physics.
file(REMOVE_RECURSE ${WORKDIR})
execute_process(
  COMMAND ${PROGRAM}
    --set "Output directory=${WORKDIR}"
    --set "Geometry/Geometry file=${GEO}"
    --set "Road texture/Roads=sinusoid"
    --set "Road/Sinusoid/Amplitude=0.000005"
    --set "Road/Sinusoid/Wavelength=0.04"
    --set "Rolling/Speeds (kph)=90"
    --set "Rolling/Static load=3000"
    --set "Rolling/Distance=1.1"
    --set "Spectra/Standard error target=2"
  RESULT_VARIABLE status OUTPUT_VARIABLE out ERROR_VARIABLE err)
file(WRITE ${WORKDIR}/screen.txt "${out}${err}")
if(NOT status EQUAL 0)
  message(FATAL_ERROR "the main job's path failed (${status}):\n${out}\n${err}")
endif()
message(STATUS "${out}")

include(${CMAKE_CURRENT_LIST_DIR}/require.cmake)
require("harmonic ring: the section's [0-9]+ unknowns per harmonic \\(degree 4\\)" "not the harmonic ring on its quartic section")
require("Stage modal: the ring's own modes" "not the ring's own modes")
require("= 7680 points, rectangles 0.750 x 0.833 mm" "not the contact grid of 8 subdivisions")
# The candidate-set solver's line (the whole grid's and pivoting's say
# otherwise), and no grid solved by either of those.
require("the contact solved by projected CG on the candidate points \\(matrix-free\\) \\('Contact grid/Solver' = auto\\)"
        "not the projected CG solver on the candidate points")
if(out MATCHES "the contact solved by (block principal pivoting|projected CG on the whole grid)")
  message(FATAL_ERROR "a contact grid not solved by projected CG on the candidate points:\n${out}")
endif()
include(${CMAKE_CURRENT_LIST_DIR}/every_run_converged.cmake)
every_run_converged("${out}")
require("run sinusoid_90kmh_low-rate: V0 = 90 km/h, dt = 76.8 us, [0-9.]+ m, [0-9]+ steps, modal-recursive, for the bands up to 1000 Hz"
        "not the multi-rate spectra (a low-rate run at 76.8 us for the bands to 1 kHz)")
# Each run rolls on to its bands' standard errors (Spectra/Extend runs): the
# run at the scene's step misses 2 dB over its 1.1 m and stops at its
# longest, 3 times its plan (floor(3.3 m / 0.384 mm) steps), and says so.
require("sinusoid_90kmh: extended to [0-9., m]+ for the standard error target \\('Spectra/Extend runs'\\): 3.3 m, 8593 steps \\(its longest"
        "the run at the scene's step did not roll on to its standard errors, to 3 times its plan")
require("sinusoid at 90 km/h, stress: largest [0-9.]+ dB; above the target in the [0-9, ]+ Hz bands; a run at the scene's step of [0-9.]+ m would meet it \\(the run stopped at its longest"
        "the bands still above the target at the run's longest not named")
# Under 3000 N on 60% of the points the coarse step rings (the total force's
# standard deviation 660 N against 56 N at the scene's step): the check of
# the low-rate run against the run at the scene's step must refuse its bands.
require("Warning: sinusoid at 90 km/h: the low-rate run \\(76.8 us, 'Spectra/Low-band time step'\\) disagrees with the run at the scene's step"
        "the low-rate run's ringing bands were used")

# E over the 14,400 pairs of 120 points, and passivity.
require("the mode cut-off's error bar: the [0-9]+ modes to 6000 Hz \\('Error bars/Coarser mode cutoff'\\)"
        "no coarser mode cut-off for the error bars")
require("run sinusoid_90kmh_finer_time_step: V0 = 90 km/h, dt = 7.68 us"
        "no run at half the step for the error bars")
require("run sinusoid_90kmh_coarser_contact_grid: V0 = 90 km/h, dt = 15.36 us"
        "no run on the coarser grid for the error bars")
require("run sinusoid_90kmh_coarser_mode_cutoff: V0 = 90 km/h, dt = 15.36 us"
        "no run with the coarser cut-off for the error bars")
require("The ring section's error bar: the section at 16 mm \\('Geometry/Mesh size' doubled\\)"
        "no coarser section for the error bars")
require("run sinusoid_90kmh_coarser_ring_section: V0 = 90 km/h, dt = 15.36 us"
        "no run on the coarser section for the error bars")
require("Error bars from 250 Hz .*sinusoid at 90 km/h, stress: largest [0-9.]+ dB"
        "no summary of the error bars")

include(${CMAKE_CURRENT_LIST_DIR}/synthesis_figures.cmake)
check_synthesis_figures("${out}" 14400 ${WORST_BOUND})

#!/usr/bin/env bash
# Set up GreenTread on a Debian 12 machine and either run the default scene
# or the whole test suite.
#
#   bash scripts/setup.sh first  # install, build the program, run the 1-DoF scene (seconds)
#   bash scripts/setup.sh run    # install, build, run the built-in default scene
#   bash scripts/setup.sh test   # install, build, run every test through ctest
#   bash scripts/setup.sh build  # install and build only
#
# Environment: BUILD_DIR (default: build), JOBS (default: number of cores).
set -euo pipefail

mode="${1:-run}"
case "$mode" in
  first|run|test|build) ;;
  *) echo "setup.sh: mode '$mode' is not one of first, run, test, build" >&2
     echo "usage: bash scripts/setup.sh first|run|test|build" >&2; exit 2 ;;
esac

top="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
build_dir="${BUILD_DIR:-$top/build}"
jobs="${JOBS:-$(nproc)}"

# Everything GreenTread needs, as Debian 12 packages.
packages=(
  g++ make cmake git perl
  libdeal.ii-dev        # deal.II 9.4 (with Trilinos, UMFPACK, MPI)
  libeigen3-dev         # Eigen 3.4
  libboost-test-dev     # Boost.Test for tests/unit
  libgmsh-dev gmsh      # gmsh API for the tyre section
  calculix-ccx          # independent check of the tyre model (tests/unit/test_calculix.cc)
  numdiff               # deal.II-style regression tests
  gnuplot-nox           # PNG plots
  openmpi-bin           # mpirun: the tyre-green scene and its MPI test
  libsuitesparse-dev    # UMFPACK headers: the full-ring reference solve
  libfftw3-dev          # FFTW 3: the tread's layer on fine contact grids
  libopenblas0-serial   # an optimised serial BLAS under UMFPACK (30% faster full-ring solves)
  libspectra-dev        # Spectra: shift-invert Lanczos for the section's harmonic modes
  libsiconos-numerics-dev # Siconos' LCP solvers: the reference of tests/unit/test_lcp.cc
  libminizip-dev        # minizip: X3P road files are zip archives
  libssl-dev            # OpenSSL's libcrypto: the MD5 sums X3P files carry
  clang-format          # the code's layout, checked by scripts/check_format.sh in CI
)

missing=()
for p in "${packages[@]}"; do
  if ! dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed"; then
    missing+=("$p")
  fi
done

if (( ${#missing[@]} )); then
  echo "== installing: ${missing[*]}"
  sudo=""
  if [[ $(id -u) -ne 0 ]]; then sudo="sudo"; fi
  $sudo apt-get update -qq
  DEBIAN_FRONTEND=noninteractive $sudo apt-get install -y -qq --no-install-recommends "${missing[@]}"
else
  echo "== all packages are installed"
fi

echo "== configuring in $build_dir (Release)"
mkdir -p "$build_dir"
cmake -S "$top" -B "$build_dir" -DCMAKE_BUILD_TYPE=Release > "$build_dir/configure.log" 2>&1 || {
  cat "$build_dir/configure.log"; exit 1; }
# The scenes need the program, and the worked example of
# doc/getting-started.md the tool that writes its road; the tests need
# everything.
echo "== building with $jobs jobs"
case "$mode" in
  first|run) cmake --build "$build_dir" -j "$jobs" --target greentread make_example_road ;;
  *)         cmake --build "$build_dir" -j "$jobs" ;;
esac

case "$mode" in
  first)
    echo "== running the 1-DoF scene (the paper's Section 3), writing to output/sdof_kinematic/"
    cd "$top"
    "$build_dir/greentread" prm/sdof_kinematic.prm --set "Output directory=output/sdof_kinematic"
    echo "== next: bash scripts/setup.sh run (the main job), or see doc/getting-started.md"
    ;;
  run)
    echo "== running the built-in default scene, the main job (tyre on road-A and road-B, 50-90 km/h)"
    echo "   (the same as greentread prm/tyre_road_contact.prm, writing to output/)"
    cd "$top"
    "$build_dir/greentread"
    ;;
  test)
    echo "== running the test suite"
    # Test executables are built on demand by ctest (deal.II test macros);
    # build them here in parallel first.
    cmake --build "$build_dir" -j "$jobs" --target greentread_tests
    cd "$build_dir"
    ctest --output-on-failure -j "$jobs"
    ;;
  build) ;;
esac

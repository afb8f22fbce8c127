#!/usr/bin/env bash
# Installs what is missing, builds everything with the tests and runs them; exits with the
# status of ctest, and in Release of the Python module's tests (pytest, python/tests) as well.
#
#   bash scripts/test.sh                the Release suite, in build/ (the README's command)
#   bash scripts/test.sh --assertions   the suite with CGAL's assertions and preconditions on
#                                       (optimised, without NDEBUG), in build-assertions/; the
#                                       example programs and the Mesh_3 tests are left out
#   bash scripts/test.sh --sanitize     the suite under AddressSanitizer and UndefinedBehaviorSanitizer
#                                       with CGAL's assertions and preconditions on as well (what
#                                       CI runs after the Release suite), in build-sanitize/; the
#                                       examples and the Mesh_3 tests are left out
#
# Every option of the build is set explicitly at each run, so that what ran before in the same
# build directory (scripts/demo.sh configures build/ without tests and meshing) changes nothing.
# Extra arguments go to cmake after those, e.g. `bash scripts/test.sh -DSFE_BUILD_MESHING=OFF`.
set -euo pipefail
# shellcheck source-path=SCRIPTDIR source=common.sh
source "$(dirname "${BASH_SOURCE[0]}")/common.sh"
cd "$SFE_ROOT"

mode=release
python_packages=()
case "${1:-}" in
  --assertions|--sanitize) mode="${1#--}"; shift ;;
esac

# Every test program instantiates the whole pipeline, so each one costs its own compile: the
# test files that, together, run every stage, reader, writer, kernel and execution tag of the
# library (SFE_COVERING_TESTS in test/Sharp_feature_extraction/CMakeLists.txt) are built as one
# program of one translation unit, test_covering, which compiles the pipeline once.
build_options=(-DSFE_BUILD_EXAMPLES=ON -DSFE_BUILD_TESTS=ON -DSFE_BUILD_BENCHMARK=OFF -DSFE_TESTS_AS_ONE_PROGRAM=ON)
case "$mode" in
  release)
    build_options+=(-DSFE_BUILD_MESHING=ON)
    # The Python module, for Debian's python3, and its tests after ctest (Release only).
    build_options+=(-DSFE_BUILD_PYTHON=ON -DPython_EXECUTABLE="$SFE_PYTHON")
    python_packages=("${SFE_PYTHON_PACKAGES[@]}")
    ;;
  assertions)
    SFE_BUILD_DIR="$SFE_ROOT/build-assertions"
    # -O2 keeps the suite within CI's time (at -O0 single tests take 30-45 s); no NDEBUG, so
    # CGAL_assertion and CGAL_precondition are checked.
    # The examples are left out (no test runs them; the Release run builds them), and so are
    # the Mesh_3 tests: their translation unit alone takes over 5 minutes and 5 GB to compile.
    build_options+=(-DSFE_BUILD_EXAMPLES=OFF -DSFE_BUILD_MESHING=OFF -DSFE_BUILD_PYTHON=OFF
                    -DCMAKE_BUILD_TYPE=Assertions -DCMAKE_CXX_FLAGS_ASSERTIONS=-O2)
    ;;
  sanitize)
    SFE_BUILD_DIR="$SFE_ROOT/build-sanitize"
    # One build for both checks CI needs beyond Release: no NDEBUG, so CGAL_assertion and
    # CGAL_precondition are checked under the sanitizers, and a separate assertions build
    # (7 more translation units to compile) is not needed.
    # Compiling weighs more than running here: test_bad_input.cpp takes 196 s of CPU to compile
    # at -O1 -g1, 315 s at -O2 -g1 and 253 s at -O1 -g, and 38 s to run its tests at -O1.
    # Hence -O1 and -g1 (line tables only: the reports keep file and line).
    # The Mesh_3 tests are left out (one translation unit of ~3.6 GB and minutes), and so
    # are the examples (no test runs them; the Release run builds them).
    # Only test_covering is built and run (each program's compile costs about 290 s of CPU
    # here). test_extract_sharp_features is left out: it checks the accuracy of the default
    # call on analytic shapes, the same code that test_stages and test_kernels_and_determinism
    # run on the cube, the capped cylinder and the boxes, exact and noisy, and test_bad_input
    # on planes and degenerate clouds; under the sanitizers it takes 205 s of CPU to run,
    # besides its compile.
    sanitized_programs=(test_covering)
    sanitizers="-fsanitize=address,undefined -fno-sanitize-recover=all -fno-omit-frame-pointer"
    build_options+=(-DSFE_BUILD_EXAMPLES=OFF -DSFE_BUILD_MESHING=OFF -DSFE_BUILD_PYTHON=OFF -DCMAKE_BUILD_TYPE=Sanitize
                    "-DCMAKE_CXX_FLAGS_SANITIZE=-O1 -g1 $sanitizers"
                    "-DCMAKE_EXE_LINKER_FLAGS_SANITIZE=$sanitizers")
    # Any finding ends the test process with a non-zero status, so ctest counts it as failed:
    # -fno-sanitize-recover and halt_on_error for UBSan, abort_on_error for ASan, and
    # LeakSanitizer's exit status for a leak.
    export ASAN_OPTIONS="detect_leaks=1:abort_on_error=1:strict_string_checks=1"
    export UBSAN_OPTIONS="print_stacktrace=1:halt_on_error=1"
    ;;
esac

install_missing_packages "${SFE_PACKAGES[@]}" "${python_packages[@]}"
ctest_selection=()
if [ "$mode" = sanitize ]; then
  # Only the program test_covering is built and run (see above).
  sfe_log "configuring into $SFE_BUILD_DIR"
  cmake -S "$SFE_ROOT" -B "$SFE_BUILD_DIR" "${build_options[@]}" "$@"
  cmake --build "$SFE_BUILD_DIR" -j "$SFE_JOBS" --target "${sanitized_programs[@]}"
  # The tests carry their program's name as label (test/Sharp_feature_extraction/CMakeLists.txt).
  ctest_selection=(-L "^($(IFS='|'; printf '%s' "${sanitized_programs[*]}"))\$")
else
  configure_and_build "${build_options[@]}" "$@"
fi

# The assertions are what these builds check: an NDEBUG or CGAL_NDEBUG brought in from outside
# (CXXFLAGS, an extra argument) must not switch them off silently.
if [ "$mode" != release ] && grep -qsE -- "-D(CGAL_)?NDEBUG" "$SFE_BUILD_DIR"/test/Sharp_feature_extraction/CMakeFiles/*/flags.make; then
  sfe_die "NDEBUG or CGAL_NDEBUG is defined in $SFE_BUILD_DIR: CGAL's assertions would not be checked"
fi

# The meshing tests must be there whenever meshing is on: a cached option once dropped them
# silently (scripts/demo.sh, then this script, in one checkout).
meshing_on="$(sed -n 's/^SFE_BUILD_MESHING:BOOL=//p' "$SFE_BUILD_DIR/CMakeCache.txt")"
# The list is captured first: with pipefail, grep -q closing the pipe early would fail ctest.
registered_tests="$(ctest --test-dir "$SFE_BUILD_DIR" --show-only=json-v1)"
if [ "$meshing_on" = ON ] && ! grep -q test_meshing_with_features <<< "$registered_tests"; then
  sfe_die "SFE_BUILD_MESHING is ON in $SFE_BUILD_DIR but no meshing test is registered"
fi

status=0
# --no-tests=error: a build that lost its tests must not pass.
ctest --test-dir "$SFE_BUILD_DIR" --output-on-failure --no-tests=error -j "$SFE_JOBS" \
  "${ctest_selection[@]}" || status=$?

# The Python module's tests, on the module and the program of this build, whenever the module
# is built (an extra argument can switch it off). No bytecode caches in the source tree.
python_on="$(sed -n 's/^SFE_BUILD_PYTHON:BOOL=//p' "$SFE_BUILD_DIR/CMakeCache.txt")"
if [ "$mode" = release ] && [ "$python_on" = ON ]; then
  sfe_log "running the Python module's tests"
  python_status=0
  PYTHONPATH="$SFE_BUILD_DIR/python" PYTHONDONTWRITEBYTECODE=1 \
    SFE_EXTRACT_PROGRAM="$SFE_BUILD_DIR/examples/Sharp_feature_extraction/extract_sharp_features" \
    "$SFE_PYTHON" -m pytest -p no:cacheprovider -q "$SFE_ROOT/python/tests" || python_status=$?
  [ "$status" -ne 0 ] || status="$python_status"
fi
exit "$status"

#!/usr/bin/env bash
# Benchmark of sharp feature extraction: accuracy, robustness and speed against ground truth
# creases of CAD meshes and against CGAL's VCM, written up in one report.
#
#   scripts/bench.sh            full run (about 80 min on 2 cores): benchmark/results/REPORT.md
#   scripts/bench.sh --quick    smoke run (under 5 min once built): out/bench_quick/report/REPORT.md
#
# Options:
#   --quick          fewer parts, sizes and configurations; VCM at its fixed default setting
#   --data DIR       where clouds' results, ground truth and pictures go (default out/bench or
#                    out/bench_quick); it is emptied first: everything is regenerated
#   --report DIR     where REPORT.md and its PNGs go (default benchmark/results, or
#                    out/bench_quick/report with --quick)
#   --build DIR      build directory (default out/build-bench)
#   --only-scanner   only the scanner-like inputs (step 5b): rows in DATA/scanner.jsonl and their
#                    report section in DATA/scanner.md (default DATA out/bench_scanner, or
#                    out/bench_scanner_quick with --quick); REPORT.md is left alone
#   --no-meshing     full run without step 7: meshing/MESHING.md keeps its last run (which
#                    scripts/bench_meshing.sh regenerates on its own)
#
# Installs the Debian packages it needs (when missing), builds the benchmark programs with
# -DSFE_BUILD_BENCHMARK=ON, and then, each configuration in its own process:
#   1. ground truth of each part (sfe_ground_truth) and a self-test of the scoring;
#   2. the VCM sweep of R, r and threshold on fandisk at 100k points (full run only);
#   3. every part x cloud variant: our pipeline (sfe_bench_run) and VCM (sfe_vcm_run), and
#      fandisk at 5% noise, the heaviest noise of the paper's Fig. 12 (ours only, with a picture);
#   4. scaling on fandisk from 50k to 2M points;
#   5. speed: fandisk at 500k points with 1 and 2 threads (noise 0 and 0.5%), and 10M points;
#   5a. density: pinion and rotor at as many points as fandisk's speed rows, 0.5% noise (beside
#      their accuracy rows and fandisk's speed row: the same noise on a denser cloud);
#   5b. scanner-like inputs: fandisk and a square scanned by the simulated scanner
#      (benchmark/Sharp_feature_extraction/scan_simulation.h) with the defects of real files;
#   6. the report (benchmark/Sharp_feature_extraction/make_report.py);
#   7. full run only: feature-protected meshing with and without the curves
#      (scripts/bench_meshing.sh, which writes benchmark/results/meshing/MESHING.md).
set -euo pipefail

ROOT="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
cd "$ROOT"

QUICK=0
ONLY_SCANNER=0
NO_MESHING=0
DATA=""
REPORT=""
BUILD="$ROOT/out/build-bench"
while [ $# -gt 0 ]; do
  case "$1" in
    --quick) QUICK=1 ;;
    --data) DATA="$2"; shift ;;
    --report) REPORT="$2"; shift ;;
    --build) BUILD="$2"; shift ;;
    --only-scanner) ONLY_SCANNER=1 ;;
    --no-meshing) NO_MESHING=1 ;;
    -h|--help) sed -n '2,29p' "$0"; exit 0 ;;
    *) echo "bench.sh: unknown option $1" >&2; exit 2 ;;
  esac
  shift
done
# The scanner rows alone go elsewhere by default: DATA is emptied first.
if [ "$ONLY_SCANNER" = 1 ]; then
  DATA="${DATA:-$ROOT/out/bench_scanner$([ "$QUICK" = 0 ] || echo _quick)}"
fi
if [ "$QUICK" = 1 ]; then
  DATA="${DATA:-$ROOT/out/bench_quick}"
  REPORT="${REPORT:-$ROOT/out/bench_quick/report}"
else
  DATA="${DATA:-$ROOT/out/bench}"
  REPORT="${REPORT:-$ROOT/benchmark/results}"
fi
case "$DATA" in /*) ;; *) DATA="$ROOT/$DATA" ;; esac
case "$REPORT" in /*) ;; *) REPORT="$ROOT/$REPORT" ;; esac
case "$BUILD" in /*) ;; *) BUILD="$ROOT/$BUILD" ;; esac

PYTHON=/usr/bin/python3 # Debian's, with Debian's matplotlib (a pyenv python may shadow it)
START_SECONDS=$SECONDS
log() { printf '[bench %4ds] %s\n' "$((SECONDS - START_SECONDS))" "$*"; }

# ------------------------------------------------------------------------------------------
# Packages, meshes, build. scripts/common.sh (shared with demo.sh and test.sh) provides
# install_missing_packages and fetch_cgal_mesh; the fallbacks below stand in when it is absent.
# ------------------------------------------------------------------------------------------
if [ -f "$ROOT/scripts/common.sh" ]; then
  # shellcheck source=/dev/null
  source "$ROOT/scripts/common.sh"
fi

# libcgal-demo (CGAL's sample meshes) is not listed: fetch_cgal_mesh unpacks it into out/cache
# when it is not installed.
BENCH_PACKAGES="build-essential cmake libcgal-dev libeigen3-dev libboost-dev libtbb-dev \
libgmp-dev libmpfr-dev python3 python3-matplotlib python3-numpy python3-pil"
if ! declare -F install_missing_packages >/dev/null; then
  install_missing_packages() { # fallback when scripts/common.sh is absent
    local missing=() p sudo=""
    for p in "$@"; do
      dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed" || missing+=("$p")
    done
    [ ${#missing[@]} -eq 0 ] && return 0
    [ "$(id -u)" = 0 ] || sudo="sudo"
    $sudo apt-get update -qq
    DEBIAN_FRONTEND=noninteractive $sudo apt-get install -y -qq "${missing[@]}" >/dev/null
  }
fi
if ! declare -F fetch_cgal_mesh >/dev/null; then
  fetch_cgal_mesh() { # fallback when scripts/common.sh is absent: needs libcgal-demo installed
    local out="$ROOT/out/meshes/$1.off"
    if [ ! -s "$out" ]; then
      mkdir -p "$(dirname "$out")"
      tar -xzf /usr/share/doc/libcgal-dev/data.tar.gz -O "data/meshes/$1.off" >"$out.part"
      mv "$out.part" "$out"
    fi
    printf '%s\n' "$out"
  }
fi

# shellcheck disable=SC2086
install_missing_packages $BENCH_PACKAGES

MESHES="$ROOT/out/meshes"
mkdir -p "$MESHES"

# The meshing benchmark needs two example programs (one of them includes Mesh_3: slow to build).
MESHING=$([ "$QUICK" = 1 ] || [ "$ONLY_SCANNER" = 1 ] || [ "$NO_MESHING" = 1 ] && echo 0 || echo 1)
TARGETS=(sfe_ground_truth sfe_scoring_selftest sfe_vcm_run sfe_bench_run)
[ "$MESHING" = 1 ] && TARGETS+=(mesh_with_sharp_features measure_mesh_against_truth)
if [ "$ONLY_SCANNER" = 1 ]; then TARGETS=(sfe_ground_truth sfe_bench_run); fi
log "building the benchmark programs in $BUILD"
cmake -S "$ROOT" -B "$BUILD" -DCMAKE_BUILD_TYPE=Release -DSFE_BUILD_BENCHMARK=ON \
  -DSFE_BUILD_EXAMPLES="$([ "$MESHING" = 1 ] && echo ON || echo OFF)" -DSFE_BUILD_MESHING=ON \
  -DSFE_BUILD_TESTS=OFF >"$BUILD.cmake.log" 2>&1 ||
  { cat "$BUILD.cmake.log"; exit 1; }
nice cmake --build "$BUILD" -j2 --target "${TARGETS[@]}"
BIN="$BUILD/benchmark/Sharp_feature_extraction"
MAKE_REPORT="$ROOT/benchmark/Sharp_feature_extraction/make_report.py"

# ------------------------------------------------------------------------------------------
# What is measured.
# ------------------------------------------------------------------------------------------
# Angle of the ground truth's sharp edges, per part (30 degrees unless stated).
truth_angle() { case "$1" in anchor_dense|couplingdown) echo 40 ;; *) echo 30 ;; esac; }
# Cloud variants: name:noise:outliers:denser (noise and outliers as fractions of dB / of N).
# Noise 2% is judged at eps = 1% dB (its noise band is 4% dB thick).
NOISE_VARIANTS="noise0:0:0:1 noise0.25:0.0025:0:1 noise0.5:0.005:0:1 noise1:0.01:0:1 noise2:0.02:0:1"
# The heaviest noise of the paper's Fig. 12 (5% of dB), on fandisk only, for its picture.
HEAVY_NOISE=0.05
OTHER_VARIANTS="denser5:0:0:5 outliers1:0:0.01:1 outliers5:0:0.05:1"
# VCM sweep (fractions of dB for R and r), on fandisk at 100k points at each noise level; the
# setting with the best mean point-F1 at eps 0.5% over the noise levels is used everywhere.
SWEEP_R="0.01,0.02,0.04"
SWEEP_r="0,0.005,0.01"
SWEEP_THRESHOLD="0.02,0.04,0.06,0.08,0.12,0.16,0.2,0.25,0.3,0.35,0.4"
# The setting the quick run uses without sweeping (the full run's choice on this machine).
VCM_DEFAULT="0.01 0.01 0.3"
VCM_TIMEOUT=600 # seconds: VCM runs longer than this (large N) are skipped and reported so

if [ "$QUICK" = 1 ]; then
  PARTS="fandisk part rotor"
  CONTROLS="itemb"
  POINTS=50000
  VARIANTS="noise0:0:0:1 noise0.5:0.005:0:1"
  CONTROL_VARIANTS="noise0:0:0:1"
  SCALING_SIZES="50000 100000"
  SPEED_POINTS=100000
  DENSITY_PARTS="rotor"
  LARGE_POINTS=""
  SCAN_RETURNS=50000
  SCAN_DUPLICATES=500000
  SCAN_LARGE=1000000
  DO_SWEEP=0
  REPEAT_CHECK=0
else
  PARTS="fandisk anchor joint part pinion rotor spool u cross"
  CONTROLS="itemb"
  POINTS=100000
  VARIANTS="$NOISE_VARIANTS $OTHER_VARIANTS"
  CONTROL_VARIANTS="$VARIANTS"
  SCALING_SIZES="50000 100000 200000 500000 1000000 2000000"
  SPEED_POINTS=500000
  DENSITY_PARTS="pinion rotor"
  LARGE_POINTS=10000000
  SCAN_RETURNS=100000
  SCAN_DUPLICATES=1000000
  SCAN_LARGE=10000000
  DO_SWEEP=1
  REPEAT_CHECK=1
fi
SEED=1

# ------------------------------------------------------------------------------------------
# Run.
# ------------------------------------------------------------------------------------------
log "regenerating $DATA from scratch"
LOAD_AT_START="$(cut -d' ' -f1-3 /proc/loadavg)"
rm -rf "$DATA"
mkdir -p "$DATA/truth" "$DATA/pictures" "$DATA/curves" "$DATA/logs"

# Runs one configuration in its own process, stderr to the log. A failure or a time-out is
# recorded as a row with a status (the report lists it) and does not stop the benchmark.
# Returns the command's exit code (124: timed out).
run_row() { # FILE LABEL METHOD COMMAND...
  local file="$1" label="$2" method="$3"; shift 3
  local errors="$DATA/logs/${label}_$method.err" status=0
  nice "$@" --label "$label" --output "$file" 2>"$errors" || status=$?
  if [ "$status" != 0 ]; then
    local what=failed
    [ "$status" = 124 ] && what=timeout
    log "  $what (exit $status): $label $method (see $errors)"
    printf '{"label": "%s", "method": "%s", "status": "%s", "exit_code": %d}\n' \
      "$label" "$method" "$what" "$status" >>"$file"
  fi
  return 0
}

# Scanner-like inputs: fandisk scanned from 4 viewpoints (SCAN_RETURNS returns) as the
# reference, then one defect of real scans per row, and a square scanned from one viewpoint.
# What each row should give is stated in make_report.py (SCANNER_ROWS) and checked there.
scanner_rows() {
  local rows="$DATA/scanner.jsonl"
  local fandisk=(--mesh "$MESHES/fandisk.off" --truth "$DATA/truth/fandisk" --seed "$SEED" --scan-views 4)
  # The square z = 0: its border is no crease, so its truth is empty.
  local plane="$DATA/truth/scan_plane"
  printf 'OFF\n4 2 0\n0 0 0\n1 0 0\n1 1 0\n0 1 0\n3 0 1 2\n3 0 2 3\n' >"$plane.off"
  : >"$plane.polylines.txt"
  : >"$plane.corners.xyz"
  echo 1.4142135623730951 >"$plane.diagonal"
  local square=(--mesh "$plane.off" --truth "$plane" --seed "$SEED" --scan-views 1 --points "$SCAN_RETURNS")
  scan_row() { # NAME OPTIONS...
    local name="$1"; shift
    log "  scanner_$name"
    run_row "$rows" "scanner_$name" ours "$BIN/sfe_bench_run" "$@"
  }
  log "scanner-like inputs: fandisk scanned from 4 viewpoints ($SCAN_RETURNS returns), a scanned square, $SCAN_LARGE returns"
  scan_row reference "${fandisk[@]}" --points "$SCAN_RETURNS"
  scan_row range_noise "${fandisk[@]}" --points "$SCAN_RETURNS" --noise 0.005
  scan_row offset_1e6 "${fandisk[@]}" --points "$SCAN_RETURNS" --offset 1e6
  scan_row offset_1e8 "${fandisk[@]}" --points "$SCAN_RETURNS" --offset 1e8
  scan_row lines_4 "${fandisk[@]}" --points "$SCAN_RETURNS" --scan-lines 4
  scan_row lines_8 "${fandisk[@]}" --points "$SCAN_RETURNS" --scan-lines 8
  scan_row misregistered "${fandisk[@]}" --points "$SCAN_RETURNS" --misregistration 0.001
  scan_row window_2 "${fandisk[@]}" --points "$SCAN_RETURNS" --scan-window 2
  scan_row no_returns "${fandisk[@]}" --points "$SCAN_RETURNS" --scan-window 2 --no-returns 1
  scan_row duplicates "${fandisk[@]}" --points "$SCAN_RETURNS" --duplicates "$SCAN_DUPLICATES"
  scan_row distinct "${fandisk[@]}" --points "$((SCAN_RETURNS + SCAN_DUPLICATES))"
  scan_row plane "${square[@]}"
  scan_row plane_noise "${square[@]}" --noise 0.005
  scan_row large "${fandisk[@]}" --points "$SCAN_LARGE"
}

if [ "$ONLY_SCANNER" = 1 ]; then
  [ -s "$MESHES/fandisk.off" ] || fetch_cgal_mesh fandisk >/dev/null
  "$BIN/sfe_ground_truth" --mesh "$MESHES/fandisk.off" --prefix "$DATA/truth/fandisk" --angle "$(truth_angle fandisk)" \
    --label fandisk --output "$DATA/truth.jsonl"
  scanner_rows
  "$PYTHON" "$MAKE_REPORT" --scanner "$DATA/scanner.jsonl" >"$DATA/scanner.md"
  log "done in $((SECONDS - START_SECONDS)) s: $DATA/scanner.md"
  exit 0
fi

log "ground truth"
for part in $PARTS $CONTROLS; do
  [ -s "$MESHES/$part.off" ] || fetch_cgal_mesh "$part" >/dev/null
  "$BIN/sfe_ground_truth" --mesh "$MESHES/$part.off" --prefix "$DATA/truth/$part" \
    --angle "$(truth_angle "$part")" --label "$part" --output "$DATA/truth.jsonl" \
    --picture "$DATA/pictures/truth_$part.png"
done
"$BIN/sfe_scoring_selftest" >"$DATA/logs/selftest_cube.txt"
"$BIN/sfe_scoring_selftest" --truth "$DATA/truth/fandisk" >"$DATA/logs/selftest_fandisk.txt"
log "scoring self-test: $(tail -1 "$DATA/logs/selftest_cube.txt") (cube), $(tail -1 "$DATA/logs/selftest_fandisk.txt") (fandisk)"

if [ "$DO_SWEEP" = 1 ]; then
  log "VCM sweep on fandisk, 100k points: R {$SWEEP_R} x r {$SWEEP_r} x threshold {$SWEEP_THRESHOLD}"
  for variant in $NOISE_VARIANTS; do
    IFS=: read -r name noise outliers denser <<<"$variant"
    log "  sweep $name"
    run_row "$DATA/sweep.jsonl" "sweep_$name" vcm "$BIN/sfe_vcm_run" --mesh "$MESHES/fandisk.off" \
      --truth "$DATA/truth/fandisk" --points 100000 --noise "$noise" --outliers "$outliers" \
      --denser "$denser" --seed "$SEED" --R "$SWEEP_R" --r "$SWEEP_r" --threshold "$SWEEP_THRESHOLD"
  done
  read -r VCM_R VCM_r VCM_T <<<"$("$PYTHON" "$MAKE_REPORT" --choose-vcm "$DATA/sweep.jsonl")"
else
  read -r VCM_R VCM_r VCM_T <<<"$VCM_DEFAULT"
fi
log "VCM setting: R = $VCM_R dB, r = $VCM_r dB, threshold = $VCM_T"
echo "$VCM_R $VCM_r $VCM_T" >"$DATA/vcm_setting.txt"

log "accuracy and robustness: $POINTS points, parts: $PARTS, controls: $CONTROLS"
for part in $PARTS $CONTROLS; do
  variants="$VARIANTS"
  case " $CONTROLS " in *" $part "*) variants="$CONTROL_VARIANTS" ;; esac
  for variant in $variants; do
    IFS=: read -r name noise outliers denser <<<"$variant"
    label="${part}_${name}"
    cloud=(--mesh "$MESHES/$part.off" --truth "$DATA/truth/$part" --points "$POINTS" --noise "$noise"
           --outliers "$outliers" --denser "$denser" --seed "$SEED")
    extra=(--save-curves "$DATA/curves/$label.polylines.txt")
    if [ "$part" = fandisk ]; then extra+=(--picture "$DATA/pictures/curves_$label.png"); fi
    log "  $label"
    run_row "$DATA/accuracy.jsonl" "$label" ours "$BIN/sfe_bench_run" "${cloud[@]}" "${extra[@]}"
    run_row "$DATA/accuracy.jsonl" "$label" vcm timeout "$VCM_TIMEOUT" "$BIN/sfe_vcm_run" "${cloud[@]}" \
      --R "$VCM_R" --r "$VCM_r" --threshold "$VCM_T"
  done
done

if [ "$QUICK" = 0 ]; then
  log "heavy noise: fandisk at $HEAVY_NOISE dB noise (the paper's Fig. 12)"
  run_row "$DATA/heavy.jsonl" "fandisk_noise5" ours "$BIN/sfe_bench_run" --mesh "$MESHES/fandisk.off" \
    --truth "$DATA/truth/fandisk" --points "$POINTS" --noise "$HEAVY_NOISE" --seed "$SEED" \
    --save-curves "$DATA/curves/fandisk_noise5.polylines.txt" --picture "$DATA/pictures/curves_fandisk_noise5.png"
fi

if [ "$REPEAT_CHECK" = 1 ]; then
  log "repeatability: fandisk noise 0.5% once more"
  run_row "$DATA/repeat.jsonl" "fandisk_noise0.5" ours "$BIN/sfe_bench_run" --mesh "$MESHES/fandisk.off" \
    --truth "$DATA/truth/fandisk" --points "$POINTS" --noise 0.005 --seed "$SEED"
fi

log "scaling on fandisk: $SCALING_SIZES points"
VCM_SKIP=0
for n in $SCALING_SIZES; do
  cloud=(--mesh "$MESHES/fandisk.off" --truth "$DATA/truth/fandisk" --points "$n" --seed "$SEED")
  log "  ours, $n points"
  run_row "$DATA/scaling.jsonl" "scaling_$n" ours "$BIN/sfe_bench_run" "${cloud[@]}" --stage-memory 1
  if [ "$VCM_SKIP" = 1 ]; then
    printf '{"label": "scaling_%s", "method": "vcm", "points": %s, "status": "skipped"}\n' "$n" "$n" \
      >>"$DATA/scaling.jsonl"
    continue
  fi
  log "  VCM, $n points"
  run_row "$DATA/scaling.jsonl" "scaling_$n" vcm timeout "$VCM_TIMEOUT" "$BIN/sfe_vcm_run" "${cloud[@]}" \
    --R "$VCM_R" --r "$VCM_r" --threshold "$VCM_T"
  if tail -1 "$DATA/scaling.jsonl" | grep -q '"status": "timeout"'; then
    log "  VCM took more than $VCM_TIMEOUT s at $n points: skipped for the larger sizes"
    VCM_SKIP=1
  fi
done

log "speed: fandisk at $SPEED_POINTS points with 1 and 2 threads${LARGE_POINTS:+, and $LARGE_POINTS points}"
for variant in noise0:0 noise0.5:0.005; do
  IFS=: read -r name noise <<<"$variant"
  cloud=(--mesh "$MESHES/fandisk.off" --truth "$DATA/truth/fandisk" --points "$SPEED_POINTS" --noise "$noise"
         --seed "$SEED")
  for threads in 1 2; do
    log "  ours, $name, $threads thread(s)"
    run_row "$DATA/speed.jsonl" "speed_${name}_${SPEED_POINTS}" ours "$BIN/sfe_bench_run" "${cloud[@]}" \
      --threads "$threads" --save-curves "$DATA/curves/speed_${name}_t$threads.polylines.txt"
  done
  if cmp -s "$DATA/curves/speed_${name}_t1.polylines.txt" "$DATA/curves/speed_${name}_t2.polylines.txt"; then
    echo "speed_${name}_${SPEED_POINTS} identical" >>"$DATA/speed_threads.txt"
  else
    echo "speed_${name}_${SPEED_POINTS} DIFFERENT" >>"$DATA/speed_threads.txt"
  fi
  log "  VCM, $name"
  run_row "$DATA/speed.jsonl" "speed_${name}_${SPEED_POINTS}" vcm timeout "$VCM_TIMEOUT" "$BIN/sfe_vcm_run" \
    "${cloud[@]}" --R "$VCM_R" --r "$VCM_r" --threshold "$VCM_T"
done
if [ -n "$LARGE_POINTS" ]; then
  log "  ours, $LARGE_POINTS points, 2 threads"
  run_row "$DATA/speed.jsonl" "speed_noise0_$LARGE_POINTS" ours "$BIN/sfe_bench_run" --mesh "$MESHES/fandisk.off" \
    --truth "$DATA/truth/fandisk" --points "$LARGE_POINTS" --noise 0 --seed "$SEED" --threads 2
fi

# The same noise as the accuracy rows' noise0.5 variant on a denser cloud: the scales follow the
# noise, so the curves should be at least as good. Fandisk's row is its speed row above.
log "density: $DENSITY_PARTS at $SPEED_POINTS points, noise 0.5%, 2 threads"
for part in $DENSITY_PARTS; do
  run_row "$DATA/density.jsonl" "density_${part}_noise0.5" ours "$BIN/sfe_bench_run" --mesh "$MESHES/$part.off" \
    --truth "$DATA/truth/$part" --points "$SPEED_POINTS" --noise 0.005 --seed "$SEED" --threads 2 --patches 0
done

scanner_rows

# The machine and the commands, for the report.
{
  echo "cpu: $(lscpu | sed -n 's/^Model name: *//p' | head -1)"
  echo "cores: $(nproc)"
  echo "memory: $(free -g | awk '/^Mem:/ {print $2}') GiB"
  echo "os: $(. /etc/os-release && echo "$PRETTY_NAME")"
  echo "compiler: $(c++ --version | head -1)"
  echo "cgal: $(dpkg-query -W -f='${Version}' libcgal-dev)"
  echo "tbb: $(dpkg-query -W -f='${Version}' libtbb-dev)"
  echo "eigen: $(dpkg-query -W -f='${Version}' libeigen3-dev)"
  echo "commit: $(git -C "$ROOT" rev-parse --short HEAD 2>/dev/null || echo none)$(git -C "$ROOT" diff --quiet 2>/dev/null || echo ' (with local changes)')"
  echo "date: $(date -u '+%Y-%m-%d %H:%M UTC')"
  echo "mode: $([ "$QUICK" = 1 ] && echo quick || echo full)"
  echo "load average (1/5/15 min) at start: $LOAD_AT_START"
  echo "load average (1/5/15 min) at end: $(cut -d' ' -f1-3 /proc/loadavg)"
  echo "seconds: $((SECONDS - START_SECONDS))"
} >"$DATA/machine.txt"

log "report: $REPORT/REPORT.md"
mkdir -p "$REPORT"
"$PYTHON" "$MAKE_REPORT" --data "$DATA" --report "$REPORT" $([ "$QUICK" = 1 ] && echo --quick)

if [ "$MESHING" = 1 ]; then
  log "feature-protected meshing: scripts/bench_meshing.sh (log: $DATA/logs/meshing.log)"
  "$ROOT/scripts/bench_meshing.sh" --build "$BUILD" --work "$DATA/meshing" --time-limit 600 >"$DATA/logs/meshing.log" 2>&1 ||
    log "  the meshing benchmark failed: see $DATA/logs/meshing.log"
fi
log "done in $((SECONDS - START_SECONDS)) s"

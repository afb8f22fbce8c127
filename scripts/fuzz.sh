#!/usr/bin/env bash
# Builds the libFuzzer targets (test/Sharp_feature_extraction/fuzz, clang with AddressSanitizer,
# UndefinedBehaviorSanitizer and CGAL's assertions on) into out/fuzz and runs each for SECONDS:
#
#   bash scripts/fuzz.sh SECONDS [TARGET...]     # default: every target
#
# Targets: fuzz_read_polylines, fuzz_read_xyz, fuzz_read_ply, fuzz_read_off, fuzz_read_las (the
# readers of the package and of its program), fuzz_extract_sharp_features (the whole pipeline)
# and fuzz_decompress_point_cloud (the decoder of the point-cloud coder, over OpenJPEG).
# Each starts from its seeds in test/Sharp_feature_extraction/fuzz/corpus/TARGET and grows a
# corpus of its own in out/fuzz/corpus/TARGET, kept between runs. Runs SFE_FUZZ_PARALLEL targets
# at once (default 2), each under `nice -n 10`. Exits non-zero if any target found a crash, a
# sanitizer report, a leak, a timeout or an out-of-memory: the input that caused it is in
# out/fuzz/artifacts/TARGET/, and `out/fuzz/build/TARGET FILE` replays it.
set -euo pipefail
source "$(dirname "${BASH_SOURCE[0]}")/common.sh"

usage="usage: bash scripts/fuzz.sh SECONDS [TARGET...]"
[ "$#" -ge 1 ] || sfe_die "$usage"
seconds="$1"
shift
[[ "$seconds" =~ ^[1-9][0-9]*$ ]] || sfe_die "SECONDS must be a positive integer ($usage)"
all_targets=(fuzz_read_polylines fuzz_read_xyz fuzz_read_ply fuzz_read_off fuzz_read_las
             fuzz_extract_sharp_features fuzz_decompress_point_cloud)
targets=("$@")
[ "${#targets[@]}" -gt 0 ] || targets=("${all_targets[@]}")
for target in "${targets[@]}"; do
  [[ " ${all_targets[*]} " == *" $target "* ]] || sfe_die "unknown target '$target' (one of: ${all_targets[*]})"
done
parallel="${SFE_FUZZ_PARALLEL:-2}"
# A reader takes milliseconds on the inputs the fuzzer makes: a minute is a hang. The pipeline
# is about 100 times slower with the sanitizers and assertions than in Release (box volume, 300
# points: 31 s against 0.24 s, 4000 points: 4.9 s in Release): ten minutes is a hang there.
reader_timeout_seconds=60
pipeline_timeout_seconds=600
# libFuzzer's default memory limit; the targets need far less.
rss_limit_mb=2048

install_missing_packages build-essential cmake libcgal-dev libeigen3-dev libboost-dev libtbb-dev \
  pkg-config libopenjp2-7-dev clang libclang-rt-14-dev

fuzz_source="$SFE_ROOT/test/Sharp_feature_extraction/fuzz"
fuzz_out="$SFE_OUT_DIR/fuzz"
build="$fuzz_out/build"
mkdir -p "$fuzz_out"
sfe_log "building the fuzz targets into $build"
cmake -S "$fuzz_source" -B "$build" -DCMAKE_CXX_COMPILER=clang++ > "$fuzz_out/configure.log" 2>&1 ||
  { cat "$fuzz_out/configure.log" >&2; sfe_die "configuring the fuzz targets failed"; }
nice -n 10 cmake --build "$build" -j "$SFE_JOBS" --target "${targets[@]}"

export ASAN_OPTIONS="${ASAN_OPTIONS:-detect_leaks=1}"
export UBSAN_OPTIONS="${UBSAN_OPTIONS:-print_stacktrace=1}"

run_target() {
  local target="$1" corpus="$fuzz_out/corpus/$1" artifacts="$fuzz_out/artifacts/$1"
  mkdir -p "$corpus" "$artifacts"
  local timeout_seconds="$reader_timeout_seconds"
  [ "$target" != fuzz_extract_sharp_features ] || timeout_seconds="$pipeline_timeout_seconds"
  local options=(-max_total_time="$seconds" -timeout="$timeout_seconds" -rss_limit_mb="$rss_limit_mb"
                 -print_final_stats=1 -artifact_prefix="$artifacts/")
  [ "$target" != fuzz_read_ply ] || options+=(-dict="$fuzz_source/ply.dict")
  [ "$target" != fuzz_read_las ] || options+=(-dict="$fuzz_source/las.dict")
  # New inputs go to the first corpus directory; the seeds in the repository are only read.
  local status=0
  nice -n 10 "$build/$target" "${options[@]}" "$corpus" "$fuzz_source/corpus/$target" \
    > "$fuzz_out/$target.log" 2>&1 || status=$?
  echo "$status" > "$fuzz_out/$target.status"
}

sfe_log "running ${targets[*]} for $seconds s each, $parallel at once (logs: $fuzz_out/TARGET.log)"
running=0
for target in "${targets[@]}"; do
  rm -f "$fuzz_out/$target.status"
  if [ "$running" -ge "$parallel" ]; then
    wait -n
    running=$((running - 1))
  fi
  run_target "$target" &
  running=$((running + 1))
done
wait

failed=()
for target in "${targets[@]}"; do
  status="$(cat "$fuzz_out/$target.status")"
  log="$fuzz_out/$target.log"
  runs="$(sed -n 's/^Done \([0-9]*\) runs in \([0-9]*\) second.*/\1 runs in \2 s/p' "$log" | tail -n 1)"
  if [ "$status" -eq 0 ]; then
    printf '%-30s ok      %s\n' "$target" "${runs:-?}"
  else
    failed+=("$target")
    finding="$(grep -m 1 -E '^(==[0-9]+==ERROR|SUMMARY|.*runtime error|.*property violated|.*CGAL ERROR)' "$log" || true)"
    printf '%-30s FAILED  (exit %s) %s\n' "$target" "$status" "${finding:-see $log}"
    ls "$fuzz_out/artifacts/$target" | sed "s|^|    input: $fuzz_out/artifacts/$target/|"
  fi
done
[ "${#failed[@]}" -eq 0 ] || sfe_die "${#failed[@]} fuzz target(s) found a fault: ${failed[*]} (logs in $fuzz_out)"
sfe_log "no finding in ${#targets[@]} target(s) after $seconds s each"

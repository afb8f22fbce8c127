#!/usr/bin/env bash
# Surface patches benchmark (issue 14): segment_into_patches() on the curves of the default call,
# on the 9 parts at noise 0, 0.5% and 1% of dB and with 5% outliers, scored against the faces of
# the meshes (mean IoU, adjusted Rand index, patch counts; benchmark/Sharp_feature_extraction/
# patch_scoring.h). Writes benchmark/results/patches/PATCHES.md and its pictures (the rows and
# the raw pictures: out/bench_patches/). About 10 minutes on 2 cores once built.
#
#   scripts/bench_patches.sh [--build DIR] [--parts "fandisk pinion"] [--seeds "1 2"]
#                            [--points 100000] [--pictures "fandisk pinion"]
#
# Builds sfe_ground_truth and sfe_bench_run (-DSFE_BUILD_BENCHMARK=ON) in DIR (default
# out/build-bench, as scripts/bench.sh), fetches the meshes into out/meshes. One run per process.
set -euo pipefail

root="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
# shellcheck source=/dev/null
source "$root/scripts/common.sh"
build="$root/out/build-bench"
parts="fandisk anchor joint part pinion rotor spool u cross"
seeds="1 2"
points=100000
pictures="fandisk pinion"
while [ $# -gt 0 ]; do
  case "$1" in
    --build) build="$2"; shift 2 ;;
    --parts) parts="$2"; shift 2 ;;
    --seeds) seeds="$2"; shift 2 ;;
    --points) points="$2"; shift 2 ;;
    --pictures) pictures="$2"; shift 2 ;;
    -h|--help) sed -n '2,13p' "$0"; exit 0 ;;
    *) echo "bench_patches.sh: unknown argument $1 (see --help)" >&2; exit 1 ;;
  esac
done
case "$build" in /*) ;; *) build="$root/$build" ;; esac

# Cloud variants, as in scripts/bench.sh: name:noise:outliers (fractions of dB / of N).
variants="noise0:0:0 noise0.5:0.005:0 noise1:0.01:0 outliers5:0:0.05"
# The pictures are of the first seed.
picture_seed="${seeds%% *}"

work="$root/out/bench_patches"
page="$root/benchmark/results/patches"
rm -rf "$work"
mkdir -p "$work/truth" "$work/logs" "$work/pictures" "$page"
rm -f "$page"/*.png

sfe_log "building sfe_ground_truth and sfe_bench_run in $build"
cmake -S "$root" -B "$build" -DCMAKE_BUILD_TYPE=Release -DSFE_BUILD_BENCHMARK=ON >"$work/logs/cmake.log" 2>&1 ||
  { cat "$work/logs/cmake.log"; exit 1; }
nice cmake --build "$build" -j"$SFE_JOBS" --target sfe_ground_truth sfe_bench_run
bin="$build/benchmark/Sharp_feature_extraction"

rows="$work/patches.jsonl"
for part in $parts; do
  mesh="$(fetch_cgal_mesh "$part")"
  "$bin/sfe_ground_truth" --mesh "$mesh" --prefix "$work/truth/$part" --angle 30 --label "$part" \
    --output "$work/truth.jsonl"
  for variant in $variants; do
    IFS=: read -r name noise outliers <<<"$variant"
    for seed in $seeds; do
      label="${part}_${name}"
      extra=()
      if [ "$seed" = "$picture_seed" ] && [[ " $pictures " == *" $part "* ]]; then
        extra=(--patch-picture "$work/pictures/${label}.png")
      fi
      sfe_log "$label seed $seed"
      nice "$bin/sfe_bench_run" --mesh "$mesh" --truth "$work/truth/$part" --points "$points" --noise "$noise" \
        --outliers "$outliers" --seed "$seed" --label "$label" --output "$rows" "${extra[@]}" \
        2>"$work/logs/${label}_$seed.err" ||
        printf '{"label": "%s", "seed": %s, "status": "failed"}\n' "$label" "$seed" >>"$rows"
    done
  done
done
"$SFE_PYTHON" "$root/benchmark/Sharp_feature_extraction/patches_page.py" "$rows" --pictures-dir "$work/pictures" \
  --pictured "$pictures" --output-dir "$page"
sfe_log "benchmark/results/patches/PATCHES.md"

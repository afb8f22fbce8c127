#!/usr/bin/env bash
# Benchmark of `python3 -m sharp_features` distributed with dask: writes
# benchmark/results/dask/DASK.md from the runs below (rows in out/bench_dask/*.json).
#
#   bash scripts/bench_dask.sh [--scene-points N] [--skip-scene] [--build DIR]
#
# --build: the build directory (default out/build-dask, configured with the Python module and
# the examples when new); only sample_mesh_surface, extract_sharp_features and sharp_features
# are built.
# 1. fandisk, 500,000 points (noise 0), as LAS: the extract_sharp_features program, the module
#    untiled, tiled in this process (--tiles 4) and on a LocalCluster of 2 worker processes
#    (--workers 2, 4 tiles; also 2 and 8 tiles); the curves of 4 tiles in process and on the
#    workers are compared byte for byte.
# 2. a synthetic CAD-like scene of N points (default 20,000,000; make_scene.py: a grid of
#    rotated copies of the nine sample parts at 250,000 points each, as LAS) on 2 workers with
#    --tiles 16. --skip-scene leaves it out (it takes minutes and about 2 GB of disk).
# Each run is one process, timed by /usr/bin/time (wall clock and the client's peak memory);
# the module reports each pass's time and every worker's peak memory (getrusage) as JSON.
# The machine is shared: the report states the load average seen at the start of each run.
set -euo pipefail
# shellcheck source-path=SCRIPTDIR source=common.sh
source "$(dirname "${BASH_SOURCE[0]}")/common.sh"
cd "$SFE_ROOT"

scene_points=20000000
skip_scene=0
build="$SFE_OUT_DIR/build-dask"
while [ $# -gt 0 ]; do
  case "$1" in
    --scene-points) scene_points="$2"; shift ;;
    --skip-scene) skip_scene=1 ;;
    --build) build="$2"; shift ;;
    -h|--help) sed -n '2,20p' "$0"; exit 0 ;;
    *) sfe_die "unknown option $1 (see --help)" ;;
  esac
  shift
done
# Points per copy of a part in the scene, and the parts (CGAL's sample meshes).
copy_points=250000
parts=(fandisk anchor joint part pinion rotor spool u cross)
# Tiles of the scene run: about 1.3 million points each with 20M points, so that a worker
# holds a few hundred MB at most.
scene_tiles=16

install_missing_packages "${SFE_PACKAGES[@]}" "${SFE_PYTHON_PACKAGES[@]}" time
work="$SFE_OUT_DIR/bench_dask"
results="$SFE_ROOT/benchmark/results/dask"
mkdir -p "$work" "$results"
sfe_log "building into $build"
# An existing build directory keeps its options (it must have the Python module and the examples).
[ -f "$build/CMakeCache.txt" ] ||
  cmake -S "$SFE_ROOT" -B "$build" -DCMAKE_BUILD_TYPE=Release -DSFE_BUILD_EXAMPLES=ON -DSFE_BUILD_TESTS=OFF \
    -DSFE_BUILD_BENCHMARK=OFF -DSFE_BUILD_MESHING=OFF -DSFE_BUILD_PYTHON=ON -DPython_EXECUTABLE="$SFE_PYTHON" > /dev/null
cmake --build "$build" -j "$SFE_JOBS" --target sample_mesh_surface extract_sharp_features sharp_features
bin="$build/examples/Sharp_feature_extraction"
export PYTHONPATH="$build/python" PYTHONDONTWRITEBYTECODE=1

# run NAME COMMAND...: runs COMMAND under /usr/bin/time into $work/NAME.time, after noting the
# load average in $work/NAME.load.
run() {
  local name="$1"
  shift
  cut -d ' ' -f 1 /proc/loadavg > "$work/$name.load"
  sfe_log "$name: $*"
  /usr/bin/time -f "%e %M" -o "$work/$name.time" "$@"
}

to_las() { "$SFE_PYTHON" -c 'import sys, sharp_features as s; s.write_las(sys.argv[2], s.read_point_cloud(sys.argv[1]))' "$@"; }

fandisk="$work/fandisk_500k"
if [ ! -s "$fandisk.las" ]; then
  "$bin/sample_mesh_surface" "$(fetch_cgal_mesh fandisk)" -o "$fandisk.xyz" -n 500000 --seed 1
  to_las "$fandisk.xyz" "$fandisk.las"
fi
module=("$SFE_PYTHON" -m sharp_features --quiet)
run fandisk_program "$bin/extract_sharp_features" "$fandisk.las" -o "$work/fandisk_program.txt" --quiet
run fandisk_untiled "${module[@]}" "$fandisk.las" -o "$work/fandisk_untiled.txt" --report "$work/fandisk_untiled.json"
run fandisk_tiled "${module[@]}" "$fandisk.las" -o "$work/fandisk_tiled.txt" --tiles 4 \
  --report "$work/fandisk_tiled.json"
run fandisk_workers "${module[@]}" "$fandisk.las" -o "$work/fandisk_workers.txt" --workers 2 --tiles 4 \
  --report "$work/fandisk_workers.json"
# Other tile counts: the halos' share against the size of a tile.
for tiles in 2 8; do
  run "fandisk_workers_${tiles}_tiles" "${module[@]}" "$fandisk.las" -o "$work/fandisk_workers_${tiles}_tiles.txt" \
    --workers 2 --tiles "$tiles" --report "$work/fandisk_workers_${tiles}_tiles.json"
done

if [ "$skip_scene" = 0 ]; then
  scene="$work/scene_${scene_points}.las"
  if [ ! -s "$scene" ]; then
    meshes=()
    for part in "${parts[@]}"; do
      meshes+=("$(fetch_cgal_mesh "$part")")
      [ -s "$work/samples/$part.xyz" ] ||
        { mkdir -p "$work/samples"; "$bin/sample_mesh_surface" "${meshes[-1]}" -o "$work/samples/$part.xyz" -n "$copy_points" --seed 1; }
    done
    "$SFE_PYTHON" "$SFE_ROOT/benchmark/Sharp_feature_extraction/dask/make_scene.py" "$scene" \
      --points "$scene_points" --samples "$work/samples" "${meshes[@]}"
  fi
  run scene_workers "${module[@]}" "$scene" -o "$work/scene_workers.txt" --workers 2 --tiles "$scene_tiles" \
    --report "$work/scene_workers.json"
fi

"$SFE_PYTHON" "$SFE_ROOT/benchmark/Sharp_feature_extraction/dask/make_report.py" "$work" "$results/DASK.md"
sfe_log "wrote $results/DASK.md"

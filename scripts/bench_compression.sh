#!/usr/bin/env bash
# Benchmark of the point-cloud coder (compress_point_cloud): rate-distortion curves of the
# traditional and the guided height-field partitions, written up in
# benchmark/results/compression/ (README.md, rate_distortion.png, decoded pictures, CSVs).
#
#   bash scripts/bench_compression.sh       about 15 min on 2 cores once built
#
# Clouds: fandisk at 200,000 points (the paper's size, seeds 1 and 2) and part (seed 1),
# sampled uniformly without noise (sample_mesh_surface). Each is coded with grids of 1, 2 and 4
# times its sampling spacing (coarser grids reach lower rates), every quantizer step of
# `compress_point_cloud --rate-distortion`, the distortion measured to the mesh itself.
# Pictures: fandisk seed 1 decoded at 0.08 and 0.11 bits per point (the rates of the paper's
# Fig. 11) on the coarsest grid, guided; the traditional partition at its lowest rates; both
# partitions (the paper's Fig. 10), on the finest grid.
set -euo pipefail
source "$(dirname "${BASH_SOURCE[0]}")/common.sh"

install_missing_packages
install_missing_packages python3-matplotlib python3-pil
BUILD="$SFE_OUT_DIR/build-compression"
DATA="$SFE_OUT_DIR/compression"
RESULTS="$SFE_ROOT/benchmark/results/compression"
mkdir -p "$DATA" "$RESULTS"
cmake -S "$SFE_ROOT" -B "$BUILD" -DCMAKE_BUILD_TYPE=Release -DSFE_BUILD_TESTS=OFF -DSFE_BUILD_MESHING=OFF \
  -DSFE_BUILD_PYTHON=OFF > "$DATA/configure.log"
cmake --build "$BUILD" -j "$SFE_JOBS" --target compress_point_cloud sample_mesh_surface render_feature_curves
bin="$BUILD/examples/Sharp_feature_extraction"

# 200k points: the size of the paper's Fig. 11.
points=200000
grid_scales=(1 2 4)
csvs=()
for cloud in fandisk:1 fandisk:2 part:1; do
  mesh_name="${cloud%%:*}"
  seed="${cloud##*:}"
  mesh="$(fetch_cgal_mesh "$mesh_name")"
  name="${mesh_name}_200k_s${seed}"
  "$bin/sample_mesh_surface" "$mesh" -o "$DATA/$name.xyz" -n "$points" --seed "$seed" > /dev/null
  csv="$RESULTS/$name.csv"
  echo "partition,step,bpp,rms,grid_scale" > "$csv"
  for scale in "${grid_scales[@]}"; do
    sfe_log "$name, grid $scale x spacing"
    "$bin/compress_point_cloud" "$DATA/$name.xyz" --rate-distortion "$DATA/${name}_g$scale.csv" \
      --grid-scale "$scale" --reference-mesh "$mesh" > "$DATA/${name}_g$scale.log"
    tail -n +2 "$DATA/${name}_g$scale.csv" | sed "s/\$/,$scale/" >> "$csv"
  done
  csvs+=("$csv")
done

# Decoded pictures of fandisk seed 1 on the coarsest grid.
pictures=()
picture() { # PARTITION BPP
  local stem="$DATA/fandisk_$1_$2"
  "$bin/compress_point_cloud" "$DATA/fandisk_200k_s1.xyz" -o "$stem.sfeh" --bpp "$2" --partition "$1" \
    --grid-scale "${grid_scales[-1]}"
  "$bin/compress_point_cloud" --decode "$stem.sfeh" -o "$stem.xyz"
  "$bin/render_feature_curves" "$stem.xyz" -o "$RESULTS/fandisk_$1_$2bpp.png" --width 800 --height 400
  pictures+=("$RESULTS/fandisk_$1_$2bpp.png")
}
picture guided 0.08
picture guided 0.11
picture traditional 0.13
picture traditional 0.2
"$bin/render_feature_curves" "$DATA/fandisk_200k_s1.xyz" -o "$RESULTS/fandisk_original.png" --width 800 --height 400
pictures+=("$RESULTS/fandisk_original.png")
for partition in traditional guided; do
  "$bin/compress_point_cloud" "$DATA/fandisk_200k_s1.xyz" -o "$DATA/fandisk_$partition.sfeh" --bpp 1 \
    --partition "$partition" --partition-labels "$DATA/fandisk_$partition.labels.txt"
  "$bin/render_feature_curves" "$DATA/fandisk_200k_s1.xyz" --patches "$DATA/fandisk_$partition.labels.txt" \
    -o "$RESULTS/fandisk_partition_$partition.png" --width 800 --height 400
  pictures+=("$RESULTS/fandisk_partition_$partition.png")
done
/usr/bin/python3 "$SFE_ROOT/benchmark/Sharp_feature_extraction/compression_report.py" --shrink "${pictures[@]}"

/usr/bin/python3 "$SFE_ROOT/benchmark/Sharp_feature_extraction/compression_report.py" "$RESULTS" "${csvs[@]}" \
  > "$RESULTS/table.md"
sfe_log "wrote $RESULTS (table.md, rate_distortion.png, pictures)"

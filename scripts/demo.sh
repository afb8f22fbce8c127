#!/usr/bin/env bash
# From nothing to a picture: installs what is missing, builds the examples, samples CGAL's
# fandisk mesh with 100k points, extracts its sharp feature curves and renders them.
# Everything it makes goes to out/ (git-ignored).
set -euo pipefail
# shellcheck source-path=SCRIPTDIR source=common.sh
source "$(dirname "${BASH_SOURCE[0]}")/common.sh"
cd "$SFE_ROOT"

install_missing_packages "${SFE_PACKAGES[@]}"
configure_and_build -DSFE_BUILD_TESTS=OFF -DSFE_BUILD_MESHING=OFF -DSFE_BUILD_PYTHON=OFF

bin="$SFE_BUILD_DIR/examples/Sharp_feature_extraction"
mesh="$(fetch_cgal_mesh fandisk)"
cloud=out/fandisk_100k.xyz
curves=out/fandisk.polylines.txt
features=out/fandisk_features.ply
picture=out/fandisk_features.png
patches=out/fandisk.patches.txt
patch_picture=out/fandisk_patches.png

sfe_log "sampling 100k points on $mesh"
"$bin/sample_mesh_surface" "$mesh" -o "$cloud" -n 100000 --seed 1
sfe_log "extracting sharp features"
"$bin/extract_sharp_features" "$cloud" -o "$curves" --ply "$features" --patches "$patches"
sfe_log "rendering"
"$bin/render_feature_curves" "$cloud" --polylines "$curves" -o "$picture"
"$bin/render_feature_curves" "$cloud" --polylines "$curves" --patches "$patches" -o "$patch_picture"

cat << SUMMARY

Demo outputs (in $SFE_ROOT):
  input mesh       $mesh
  point cloud      $cloud
  feature curves   $curves   (one polyline per line: n x1 y1 z1 ... xn yn zn)
  feature points   $features
  picture          $picture
  surface patches  $patches   (one label per point, -1: none)
  patch picture    $patch_picture
SUMMARY

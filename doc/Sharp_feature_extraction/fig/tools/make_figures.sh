#!/usr/bin/env bash
# Regenerates the manual's figures, doc/Sharp_feature_extraction/fig/*.png, from the demo's
# cloud: 100,000 points sampled on CGAL's fandisk (run `bash scripts/demo.sh` first, which
# writes out/fandisk_100k.xyz). Builds its tools into build-figures/ (git-ignored).
set -euo pipefail
fig="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
root="$(cd "$fig/../../.." && pwd)"
build="$root/build-figures"
cloud="$root/out/fandisk_100k.xyz"
[ -s "$cloud" ] || { echo "make_figures.sh: $cloud is missing; run bash scripts/demo.sh first" >&2; exit 1; }

cmake -S "$fig/tools" -B "$build" -DCMAKE_BUILD_TYPE=Release >/dev/null
cmake --build "$build" -j "$(nproc)" --target dump_stage_points render_feature_curves >/dev/null
render="$build/sfe/examples/Sharp_feature_extraction/render_feature_curves"
work="$build/work"
mkdir -p "$work"

"$build/dump_stage_points" "$cloud" "$work/fandisk"

# Both views of the cloud with its curves.
"$render" "$cloud" --polylines "$work/fandisk_final.polylines.txt" -o "$work/fandisk_features.png" \
  --width 1000 --height 500
python3 "$fig/tools/png_panels.py" recompress "$work/fandisk_features.png" "$fig/fandisk_features.png"

# The first view of each stage, side by side.
for stage in candidates projected smoothed; do
  "$render" "$work/fandisk_$stage.xyz" -o "$work/$stage.png" --width 800 --height 400
done
"$render" "$work/fandisk_smoothed.xyz" --polylines "$work/fandisk_final.polylines.txt" \
  -o "$work/curves.png" --width 800 --height 400
python3 "$fig/tools/png_panels.py" panels "$fig/pipeline_stages.png" 40 360 \
  "$work/candidates.png" "$work/projected.png" "$work/smoothed.png" "$work/curves.png"
ls -l "$fig"/*.png

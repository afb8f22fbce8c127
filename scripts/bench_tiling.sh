#!/usr/bin/env bash
# Tiled extraction benchmark: each cloud untiled and in tiles (sfe_bench_run --tiles), scored
# against the truth, and compared vertex for vertex (sfe_tiled_vs_untiled); writes benchmark/results/tiling/table.md (the rows: out/bench_tiling/).
#
#   scripts/bench_tiling.sh [--build DIR] [--parts "fandisk anchor"] [--seeds "1 2"]
#                           [--tiles "8 27"] [--points 500000]
#
# Needs the benchmark built (-DSFE_BUILD_BENCHMARK=ON) and the meshes and truth of scripts/bench.sh
# (out/meshes, out/truth). One run per process, so that the peak RSS is the run's.
set -euo pipefail

root="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
build="$root/build"
parts="fandisk anchor"
seeds="1 2"
tiles="8 27"
points=500000
while [ $# -gt 0 ]; do
  case "$1" in
    --build) build="$2"; shift 2 ;;
    --parts) parts="$2"; shift 2 ;;
    --seeds) seeds="$2"; shift 2 ;;
    --tiles) tiles="$2"; shift 2 ;;
    --points) points="$2"; shift 2 ;;
    -h|--help) sed -n '2,10p' "$0"; exit 0 ;;
    *) echo "bench_tiling.sh: unknown argument $1 (see --help)" >&2; exit 1 ;;
  esac
done

run="$build/benchmark/Sharp_feature_extraction/sfe_bench_run"
compare="$build/benchmark/Sharp_feature_extraction/sfe_tiled_vs_untiled"
[ -x "$compare" ] || { echo "bench_tiling.sh: $compare not built" >&2; exit 1; }
[ -x "$run" ] || { echo "bench_tiling.sh: $run not built (-DSFE_BUILD_BENCHMARK=ON, or --build DIR)" >&2; exit 1; }
work="$root/out/bench_tiling"
mkdir -p "$work" "$root/benchmark/results/tiling"
rows="$work/tiling.jsonl"
identity="$work/identity.jsonl"
rm -f "$rows" "$identity"
for part in $parts; do
  for seed in $seeds; do
    for t in 0 $tiles; do
      echo "==> $part seed $seed tiles $t" >&2
      "$run" --mesh "$root/out/meshes/$part.off" --truth "$root/out/truth/$part" --points "$points" --noise 0 \
        --seed "$seed" --patches 0 --tiles "$t" --output "$rows"
      if [ "$t" != 0 ]; then
        "$compare" --mesh "$root/out/meshes/$part.off" --points "$points" --noise 0 --seed "$seed" --tiles "$t" \
          --output "$identity"
      fi
    done
  done
done
/usr/bin/python3 "$root/benchmark/Sharp_feature_extraction/tiling_table.py" "$rows" "$identity" > "$root/benchmark/results/tiling/table.md"
echo "==> benchmark/results/tiling/table.md" >&2

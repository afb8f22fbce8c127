#!/usr/bin/env bash
# Meshing benchmark: feature-protected meshing vs the same pipeline without features.
#
# For every part and noise level: sample the true mesh, run mesh_with_sharp_features with and
# without features, measure both outputs against the true mesh (measure_mesh_against_truth),
# render them with the same cameras, and write benchmark/results/meshing/MESHING.md.
#
#   scripts/bench_meshing.sh [--build DIR] [--parts "fandisk anchor joint part"]
#                            [--noises "0 0.005"] [--seeds "1 2 3 4 5"] [--points 100000]
#                            [--true-curves] [--work DIR] [--time-limit SEC] [--resume] [--report]
#
# --seeds: one independently drawn cloud per seed and case (the sampler's seed), so that a
# failure on one draw of the same part and noise cannot hide behind a lucky one. The table has
# one row per run and a summary per part, noise and run over the seeds (valid count, medians).
#
# Exit status 2 when a run did not give a valid mesh (closed, manifold, free of self-intersections,
# Mesh_3 not stopped): each is named on stderr after the report is written.
#
# --resume keeps the clouds and runs already in the work directory (an interrupted benchmark, or
# more parts added to a finished one) and runs only the missing ones; the report covers all.
# --report runs nothing: it writes the report of the runs already in the work directory (a run
# not there is reported as failed).
#
# --true-curves adds a third run per case, protecting the true creases instead of the
# extracted ones (the best the meshing can do with perfect curves). When the library's
# extract_sharp_features() is not built in, the "features" run uses the true curves and the
# report says so.
set -euo pipefail

root="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
build="$root/build"
parts="fandisk anchor joint part"
noises="0 0.005"
seeds="1 2 3 4 5"
points=100000
true_curves=0
time_limit=1800
work=""
resume=0
report_only=0
while [ $# -gt 0 ]; do
  case "$1" in
    --build) build="$2"; shift 2 ;;
    --parts) parts="$2"; shift 2 ;;
    --noises) noises="$2"; shift 2 ;;
    --seeds) seeds="$2"; shift 2 ;;
    --points) points="$2"; shift 2 ;;
    --true-curves) true_curves=1; shift ;;
    --work) work="$2"; shift 2 ;;
    --time-limit) time_limit="$2"; shift 2 ;;
    --resume) resume=1; shift ;;
    --report) report_only=1; resume=1; shift ;;
    -h|--help) sed -n '2,30p' "$0"; exit 0 ;;
    *) echo "bench_meshing.sh: unknown argument $1 (see --help)" >&2; exit 1 ;;
  esac
done

find_program() {
  local found
  found="$(find "$build" -type f -name "$1" -perm -u+x 2>/dev/null | head -n 1)"
  if [ -z "$found" ]; then
    echo "bench_meshing.sh: $1 not found under $build (build it: mesh_with_sharp_features with" \
         "-DSFE_BUILD_MESHING=ON, measure_mesh_against_truth with -DSFE_BUILD_BENCHMARK=ON; or pass --build DIR)" >&2
    exit 1
  fi
  echo "$found"
}
mesher="$(find_program mesh_with_sharp_features)"
measure="$(find_program measure_mesh_against_truth)"

work="${work:-$build/meshing_work}"
results="$root/benchmark/results/meshing"
mkdir -p "$work" "$results"

# CGAL's sample meshes, from libcgal-demo (fetched into out/ when it is not installed)
# shellcheck source=scripts/common.sh
source "$root/scripts/common.sh"
data="$SFE_OUT_DIR/meshes"
for part in $parts; do
  fetch_cgal_mesh "$part" > /dev/null
done

# does this build extract curves itself?
extraction=1
probe_dir="$work/probe"
mkdir -p "$probe_dir"
printf '0 0 0\n1 0 0\n0 1 0\n' > "$probe_dir/tiny.xyz"
if "$mesher" --quiet "$probe_dir/tiny.xyz" "$probe_dir/out" 2>&1 | grep -q "no extract_sharp_features"; then
  extraction=0
fi

value() { grep "^$1=" "$2" | head -n 1 | cut -d= -f2; }

run_case() { # part noise seed variant -> stats + measures in $work/<part>_<noise>_s<seed>_<variant>.*
  local part="$1" noise="$2" seed="$3" variant="$4"
  local base="$work/${part}_${noise}_s${seed}_${variant}"
  local cloud="$work/${part}_${noise}_s${seed}.xyz"
  local args=(--quiet --time-limit "$time_limit" --stats "$base.stats")
  case "$variant" in
    plain) args+=(--no-features) ;;
    features) [ "$extraction" = 1 ] || args+=(--curves "$work/${part}_true_curves.txt") ;;
    true) args+=(--curves "$work/${part}_true_curves.txt") ;;
  esac
  # .status is written last: a run interrupted before it is run again
  [ "$resume" = 1 ] && [ -f "$base.status" ] && return 0
  [ "$report_only" = 1 ] && return 0
  rm -f "$base.off" "$base.stats" "$base.measure" "$base.status"
  echo "  $part noise $noise seed $seed: $variant" >&2
  local status=0
  "$mesher" "${args[@]}" "$cloud" "$base" > "$base.log" 2>&1 || status=$?
  if [ ! -f "$base.off" ] || [ "$status" = 1 ]; then
    echo "    failed (status $status): $(tail -n 1 "$base.log")" >&2
    echo "$status" > "$base.status"
    return 1
  fi
  "$measure" --truth "$data/$part.off" --mesh "$base.off" > "$base.measure"
  if [ "$noise" = 0 ] && [ "$seed" = "$first_seed" ]; then
    "$measure" --truth "$data/$part.off" --mesh "$base.off" --render "$results/${part}_${variant}" > /dev/null
  fi
  echo "$status" > "$base.status"
}

# a run gave a closed, manifold, self-intersection free mesh and Mesh_3 was not stopped
valid_run() { # base
  [ -f "$1.measure" ] && [ "$(value closed "$1.measure")" = 1 ] && [ "$(value manifold "$1.measure")" = 1 ] &&
    [ "$(value self_intersecting "$1.measure")" = 0 ] && [ "$(value stopped "$1.stats")" = 0 ]
}

row() { # part noise seed variant
  local base="$work/${1}_${2}_s${3}_${4}" m s
  m="$base.measure"; s="$base.stats"
  if [ ! -f "$m" ]; then
    echo "| $1 | $2 | $3 | $4 | failed: $(tail -n 1 "$base.log" 2>/dev/null | tr '|' '/' | cut -c1-120) | | | | | | | | | |"
    return
  fi
  local valid="yes"
  valid_run "$base" || valid="NO"
  [ "$(value stopped "$s")" = 1 ] && valid="NO (stopped)"
  awk -v part="$1" -v noise="$2" -v seed="$3" -v variant="$4" -v valid="$valid" \
      -v tri="$(value triangles "$m")" -v mean="$(value mean_distance "$m")" -v max="$(value max_distance "$m")" \
      -v bmean="$(value band_mean_distance "$m")" -v bmax="$(value band_max_distance "$m")" \
      -v bnorm="$(value band_normal_angle "$m")" -v tru="$(value crease_true_angle "$m")" \
      -v reach="$(value crease_reached_angle "$m")" -v err="$(value crease_angle_error "$m")" \
      -v w10="$(value crease_within_10 "$m")" -v t="$(value seconds_total "$s")" \
      -v tm="$(value seconds_meshing "$s")" 'BEGIN {
    printf "| %s | %s | %s | %s | %d | %.2e | %.2e | %.2e | %.2e | %.1f | %.1f / %.1f | %.1f | %.0f%% | %.0f (%.0f) | %s |\n",
      part, noise, seed, variant, tri, mean, max, bmean, bmax, bnorm, reach, tru, err, 100 * w10, t, tm, valid }'
}

first_seed="${seeds%% *}"
variants="plain features"
[ "$true_curves" = 1 ] && [ "$extraction" = 1 ] && variants="$variants true"

# one line per part, noise and run over the seeds: valid runs, then medians over the valid ones
summary_row() { # part noise variant
  local seed base valid=0 total=0 times="" bands="" tris=""
  for seed in $seeds; do
    base="$work/${1}_${2}_s${seed}_${3}"
    total=$((total + 1))
    valid_run "$base" || continue
    valid=$((valid + 1))
    times="$times $(value seconds_total "$base.stats")"
    bands="$bands $(value band_mean_distance "$base.measure")"
    tris="$tris $(value triangles "$base.measure")"
  done
  median() { echo "$1" | tr ' ' '\n' | grep . | sort -g | awk '{v[NR] = $1} END {if(NR) print v[int((NR + 1) / 2)]; else print "-"}'; }
  echo "| $1 | $2 | $3 | $valid / $total | $(median "$times") | $(median "$bands") | $(median "$tris") |"
}

declare -a cases=()
for part in $parts; do
  [ -f "$data/$part.off" ] || { echo "bench_meshing.sh: no true mesh $data/$part.off" >&2; exit 1; }
  "$measure" --truth "$data/$part.off" --true-curves-to "$work/${part}_true_curves.txt"
  "$measure" --truth "$data/$part.off" --render "$results/${part}_truth"
  for noise in $noises; do
    for seed in $seeds; do
      [ "$resume" = 1 ] && { [ -f "$work/${part}_${noise}_s${seed}.xyz" ] || [ "$report_only" = 1 ]; } ||
      "$measure" --truth "$data/$part.off" --sample-to "$work/${part}_${noise}_s${seed}.xyz" --points "$points" \
                 --noise "$noise" --seed "$seed"
      for variant in $variants; do
        run_case "$part" "$noise" "$seed" "$variant" || true
        cases+=("$part $noise $seed $variant")
      done
    done
  done
done

{
  echo "# Feature-protected meshing: with and without the feature curves"
  echo
  echo "Generated by \`scripts/bench_meshing.sh\` on $(date -u +%Y-%m-%d) ($(nproc) cores)."
  echo "Input: $points points sampled uniformly on each CGAL sample mesh, one independent draw per seed"
  echo "(seeds: $seeds); noise: radius of a uniform ball,"
  echo "fraction of the bounding-box diagonal dB. Pipeline: jet normals oriented along the sheets of the"
  echo "surface (a minimum spanning tree that does not cross thin walls), Poisson implicit function,"
  echo "Mesh_3 (facet size 3s, facet distance 0.1s, edge size 3s, angle 25; s = the extraction's spacing / 1.6,"
  echo "about the mean distance to the 6 nearest neighbours), manifold."
  echo "*plain*: \`--no-features\`; *features*: curves protected, two-sided normals near the curves,"
  echo "implicit function sharpened near the curves where both sides of the crease could be fitted,"
  echo "every protected vertex moved onto the implicit surface (a curve that is not on it is dropped)."
  if [ "$extraction" = 0 ]; then
    echo
    echo "**This build has no \`extract_sharp_features()\`: the *features* rows use the TRUE creases"
    echo "(from the true mesh, with their normals) instead of extracted curves.**"
  fi
  [ "$true_curves" = 1 ] && [ "$extraction" = 1 ] && echo && echo "*true*: the true creases instead of the extracted curves."
  echo
  echo "Distances are fractions of dB, from 200k area-uniform samples of the output mesh (max also"
  echo "over its vertices) to the true mesh. Band: samples within 2% dB of a true crease (a true mesh"
  echo "edge whose facet normals differ by more than 30 degrees). Normal: mean angle between the"
  echo "output facet normal and the nearest true facet normal, in the band. Crease angle: turning"
  echo "angle between the output normals found 0.5% dB into each of the two faces, against the true"
  echo "angle, averaged along the true creases away from corners; error: mean |reached - true|."
  echo "Time: total seconds (Mesh_3 alone in parentheses). Valid: closed, manifold, no self-intersection,"
  echo "and Mesh_3 not stopped (by the time limit, or by the vertex limit of 2 per input point that catches a"
  echo "runaway refinement)."
  echo
  echo "## Over the seeds"
  echo
  echo "Valid: runs that gave a closed, manifold, self-intersection free mesh, of all runs; medians over"
  echo "the valid runs (time in seconds, crease-band mean distance in dB, triangles)."
  echo
  echo "| part | noise | run | valid | median time s | median band mean | median triangles |"
  echo "|---|---|---|---|---|---|---|"
  for part in $parts; do
    for noise in $noises; do
      for variant in $variants; do
        summary_row "$part" "$noise" "$variant"
      done
    done
  done
  echo
  echo "## Every run"
  echo
  echo "| part | noise | seed | run | triangles | mean dist | max dist | band mean | band max | band normal (deg) | crease angle reached / true | angle error | within 10 deg | time s | valid |"
  echo "|---|---|---|---|---|---|---|---|---|---|---|---|---|---|---|"
  for c in "${cases[@]}"; do
    # shellcheck disable=SC2086
    row $c
  done
  echo
  echo "## Against the acceptance criteria"
  echo
  echo "(first seed, $first_seed)"
  echo
  for part in $parts; do
    for noise in $noises; do
      p="$work/${part}_${noise}_s${first_seed}_plain.measure"; f="$work/${part}_${noise}_s${first_seed}_features.measure"
      [ -f "$p" ] && [ -f "$f" ] || continue
      awk -v part="$part" -v noise="$noise" -v bp="$(value band_mean_distance "$p")" -v bf="$(value band_mean_distance "$f")" \
          -v tp="$(value triangles "$p")" -v tf="$(value triangles "$f")" -v ef="$(value crease_angle_error "$f")" \
          -v ep="$(value crease_angle_error "$p")" 'BEGIN {
        printf "- %s, noise %s: crease-band error %.2fx lower with features (needs >= 3); crease angle error %.1f deg with, %.1f without (needs <= 10 on fandisk at noise 0); triangles %d with, %d without (%s)\n",
          part, noise, (bf > 0 ? bp / bf : 0), ef, ep, tf, tp, (tf <= tp ? "not larger" : "LARGER") }'
    done
  done
  echo
  echo "## Pictures"
  echo
  echo "Same cameras for every mesh of a part: \`<part>_<run>_full.png\` and a close-up of a long crease"
  echo "\`<part>_<run>_closeup.png\` (runs: truth, plain, features), noise 0, first seed."
  echo
  for part in $parts; do
    echo "- $part: ![truth](${part}_truth_closeup.png) ![plain](${part}_plain_closeup.png) ![features](${part}_features_closeup.png)"
  done
} > "$results/MESHING.md"
echo "wrote $results/MESHING.md" >&2

# every run must give a valid mesh: an invalid one fails the benchmark, so that it cannot regress silently
invalid=0
for c in "${cases[@]}"; do
  read -r part noise seed variant <<< "$c"
  valid_run "$work/${part}_${noise}_s${seed}_${variant}" || {
    invalid=$((invalid + 1))
    echo "bench_meshing.sh: invalid: $part noise $noise seed $seed $variant" >&2
  }
done
echo "bench_meshing.sh: $((${#cases[@]} - invalid)) of ${#cases[@]} runs valid" >&2
[ "$invalid" = 0 ] || exit 2

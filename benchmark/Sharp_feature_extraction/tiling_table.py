"""JSON lines of sfe_bench_run (untiled and --tiles T runs of the same clouds) and of
sfe_tiled_vs_untiled -> the markdown tables of benchmark/results/tiling/README.md: each tiled run
against the untiled run of its cloud, scored, then vertex for vertex.

    python3 tiling_table.py rows.jsonl identity.jsonl > table.md
"""

import json
import sys

# The issue's targets: F1 within this of the untiled run, at most this many more curves.
F1_TOLERANCE = 0.005
CURVE_EXCESS = 0.10


def identity_table(path):
    rows = [json.loads(line) for line in open(path) if line.strip()]
    print()
    print("| part | seed | tiles | smoothed edge points identical | corners identical | curves | curve vertices identical |")
    print("|---|---|---|---|---|---|---|")
    for r in rows:
        print(f"| {r['mesh'].removesuffix('.off')} | {r['seed']} | {r['tiles']:.0f} "
              f"| {r['edge_points_identical']}/{r['edge_points_untiled']} ({r['edge_points_tiled']} tiled) "
              f"| {r['corners_identical']}/{r['corners_untiled']} | {r['curves_tiled']}/{r['curves_untiled']} "
              f"| {r['vertices_identical']}/{r['vertices_untiled']} ({r['vertices_tiled']} tiled) |")


def main(path, identity_path):
    rows = [json.loads(line) for line in open(path) if line.strip()]
    untiled = {(r["mesh"], r["seed"]): r for r in rows if r["tiles"] == 0}
    print("| part | seed | tiles | curves (untiled) | F1@0.5% (untiled) | dF1 | curve excess | time s (untiled) "
          "| peak RSS MB (untiled) | heap peak MB (untiled) | targets |")
    print("|---|---|---|---|---|---|---|---|---|---|---|")
    for r in rows:
        if r["tiles"] == 0:
            continue
        u = untiled[(r["mesh"], r["seed"])]
        d_f1 = r["ours_f1@0.5"] - u["ours_f1@0.5"]
        excess = r["ours_curves"] / u["ours_curves"] - 1
        met = abs(d_f1) <= F1_TOLERANCE and excess <= CURVE_EXCESS
        print(f"| {r['mesh'].removesuffix('.off')} | {r['seed']} | {r['tiles']} | {r['ours_curves']} ({u['ours_curves']}) "
              f"| {r['ours_f1@0.5']:.4f} ({u['ours_f1@0.5']:.4f}) | {d_f1:+.4f} | {excess:+.0%} "
              f"| {r['time_wall']:.1f} ({u['time_wall']:.1f}) | {r['rss_peak_mb']:.0f} ({u['rss_peak_mb']:.0f}) "
              f"| {r['heap_peak_mb']:.0f} ({u['heap_peak_mb']:.0f}) | {'met' if met else 'MISSED'} |")


    identity_table(identity_path)


if __name__ == "__main__":
    main(sys.argv[1], sys.argv[2])

#!/usr/bin/env python3
"""Writes the dask benchmark's report (markdown) from the runs of scripts/bench_dask.sh.

    make_report.py WORK_DIR OUT.md

WORK_DIR holds, per run NAME: NAME.time (/usr/bin/time: wall seconds, peak RSS in KB of the
client process), NAME.load (load average at its start), NAME.json (the module's --report)
and the curves NAME.txt; fandisk_program is the extract_sharp_features program.
"""

import json
import pathlib
import sys

MB = 2**20
# The extrapolation's target: a billion points, on machines like this one (2 cores, so 2
# worker processes each).
TARGET_POINTS = 10**9
WORKERS_PER_MACHINE = 2
MACHINES = (1, 4, 16, 64)
RUNS = [("fandisk_program", "fandisk 500k, extract_sharp_features program (reference)"),
        ("fandisk_untiled", "fandisk 500k, module untiled, in process"),
        ("fandisk_tiled", "fandisk 500k, module tiled (4 tiles), in process"),
        ("fandisk_workers", "fandisk 500k, LocalCluster of 2 workers (4 tiles)"),
        ("fandisk_workers_2_tiles", "fandisk 500k, LocalCluster of 2 workers (2 tiles)"),
        ("fandisk_workers_8_tiles", "fandisk 500k, LocalCluster of 2 workers (8 tiles)"),
        ("scene_workers", "synthetic scene, LocalCluster of 2 workers")]
PASSES = ["bounds", "binning", "scales", "halos", "extraction", "stitching"]


def load(work, name):
    if not (work / f"{name}.time").exists():
        return None
    wall, peak_kb = (work / f"{name}.time").read_text().split()[-2:]
    run = {"wall": float(wall), "client_rss": int(peak_kb) * 1024, "load": (work / f"{name}.load").read_text().strip()}
    if (work / f"{name}.json").exists():
        run.update(json.loads((work / f"{name}.json").read_text()))
    return run


def worker_memory(run):
    peaks = [v for k, v in run.get("peak_memory", {}).items() if not k.startswith("client")]
    return " / ".join(f"{v / MB:.0f}" for v in sorted(peaks)) if peaks else "-"


def table(work):
    lines = ["| run | points | tiles (with points / grid) | points read by the tiles | wall (s) | " + " | ".join(PASSES) +
             " | peak RSS per worker (MB) | client peak RSS (MB) | wall us per point | load at start |",
             "|---" * (9 + len(PASSES)) + "|"]
    for name, title in RUNS:
        run = load(work, name)
        if run is None:
            continue
        # The program writes no report: its input is that of the module's untiled run.
        points = run.get("points") or load(work, name.split("_")[0] + "_untiled")["points"]
        tiles = f"{run['tiles_with_points']} / {run['tiles']}" if "tiles" in run else "-"
        read = f"{run['extracted_points'] / points:.2f} x" if run.get("extracted_points") else "-"
        seconds = [f"{run['seconds'][p]:.2f}" if p in run.get("seconds", {}) else "-" for p in PASSES]
        lines.append(f"| {title} | {points:,} | {tiles} | {read} | {run['wall']:.1f} | " + " | ".join(seconds) +
                     f" | {worker_memory(run)} | {run['client_rss'] / MB:.0f} | {1e6 * run['wall'] / points:.2f} | "
                     f"{run['load']} |")
    return lines


def cpu_table(work):
    lines = ["| run | " + " | ".join(PASSES[1:]) + " | client peak RSS after the scales (MB) |",
             "|---" * (len(PASSES) + 1) + "|"]
    for name, title in RUNS:
        run = load(work, name)
        if run is None or "cpu_seconds" not in run:
            continue
        seconds = [f"{run['cpu_seconds'][p]:.2f}" for p in PASSES[1:]]
        after_scales = run["peak_memory"].get("client after the scales", 0) / MB
        lines.append(f"| {title} | " + " | ".join(seconds) + f" | {after_scales:.0f} |")
    return lines


def same_curves(work, a, b):
    first, second = work / f"{a}.txt", work / f"{b}.txt"
    if not (first.exists() and second.exists()):
        return "not run"
    same = first.read_bytes() == second.read_bytes()
    return f"{'identical' if same else 'DIFFERENT'} ({len(first.read_text().splitlines())} curves)"


def extrapolation(run):
    """Time of TARGET_POINTS on N machines from one run's per-point CPU costs, which the other
    jobs on this machine do not inflate: the three passes over the points run on every core
    at once (CPU seconds per point of their tasks), the stitching on the client's one core
    (CPU seconds per point), the scales once (CPU seconds, on one tile whatever the cloud)."""
    points = run["points"]
    parallel = sum(run["cpu_seconds"][p] for p in ("binning", "halos", "extraction")) / points
    serial = run["cpu_seconds"]["stitching"] / points
    fixed = run["cpu_seconds"]["scales"]
    lines = [f"Per-point CPU cost measured on this run ({points:,} points): "
             f"{1e6 * parallel:.2f} us per point in the binning, halo and extraction passes, "
             f"{1e6 * serial:.3f} us per point of stitching on the client, {fixed:.1f} s for the scales.", "",
             f"| machines ({WORKERS_PER_MACHINE} cores, {WORKERS_PER_MACHINE} workers each) | passes (h) | "
             "stitching (h) | total (h) |",
             "|---|---|---|---|"]
    for machines in MACHINES:
        passes = TARGET_POINTS * parallel / (machines * WORKERS_PER_MACHINE) / 3600
        stitching = TARGET_POINTS * serial / 3600
        lines.append(f"| {machines} | {passes:.2f} | {stitching:.2f} | {passes + stitching + fixed / 3600:.2f} |")
    gathered = run["peak_memory"]["client"] - run["peak_memory"]["client after the scales"]
    lines += ["", f"Memory: a worker's peak stays that of one tile (above). The client's grows with the cloud: "
                  f"{gathered / MB:.0f} MB more after gathering the tiles' results and stitching them than after the "
                  f"scales, {gathered / points:.0f} bytes per point, hence about {TARGET_POINTS * gathered / points / 2**30:.0f} "
                  f"GB for {TARGET_POINTS:.0e} points on one client: the stitching, not the passes, bounds the size."]
    return lines


def main():
    work, out = pathlib.Path(sys.argv[1]), pathlib.Path(sys.argv[2])
    lines = ["# `python3 -m sharp_features` on dask.distributed", "",
             "Produced by `bash scripts/bench_dask.sh` (rows: out/bench_dask/*.json and *.time). Inputs are LAS files "
             "written by our writer; noise 0. Machine: 2 cores shared with other jobs (the load average at the start of "
             "each run is given: above 0 means contention).", "",
             *table(work), "",
             "CPU seconds of each pass (all the tasks' threads, summed over the workers; the client's for the scales "
             "and the stitching): what the passes cost whatever else runs on the machine.", "",
             *cpu_table(work), "",
             "Wall: the whole process, imports and the cluster's start included (/usr/bin/time). Pass times: the "
             "module's own (--report). Peak RSS per worker: getrusage in each worker process after its last task. "
             "Client: the process that reads nothing but the most populated tile (scales) and the tiles' results.", "",
             f"Curves, tiled in process vs 2 workers: {same_curves(work, 'fandisk_tiled', 'fandisk_workers')}; "
             f"module untiled vs the program: {same_curves(work, 'fandisk_untiled', 'fandisk_program')}.", "",
             "Points read by the tiles: every tile reads its core and its halo (tile_halo_width of the scales), so the "
             "extraction costs this multiple of the points. On fandisk at 500k points the halo is a sizeable part of a "
             "tile (more tiles, more halo: compare 2, 4 and 8 tiles); on the scene, whose tiles hold 0.3 to 2 million "
             "points, it is a few percent. Tiling pays when a cloud does not fit one process, not on 500k points.", ""]
    best = load(work, "scene_workers") or load(work, "fandisk_workers")
    if best is not None and "cpu_seconds" in best:
        lines += [f"## Extrapolation to {TARGET_POINTS:.0e} points", "", *extrapolation(best), "",
                  "Assumes the tiles stay the size measured here (so each worker's peak memory stays as above), "
                  "a file system shared by all machines that keeps up (binning reads the LAS once and writes 24 bytes "
                  "per point, the halo pass rereads them) and a stitching cost linear in the points (it is linear in "
                  "the tiles' curves, which grow with the surface, not the density)."]
    out.write_text("\n".join(lines) + "\n")


if __name__ == "__main__":
    main()

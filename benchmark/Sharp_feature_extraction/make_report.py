#!/usr/bin/python3
# Copyright (c) 2026 The Sharp_feature_extraction authors.
# SPDX-License-Identifier: LGPL-3.0-or-later
"""Turns the rows measured by scripts/bench.sh into REPORT.md and its PNG figures.

    make_report.py --data out/bench --report benchmark/results [--quick]
    make_report.py --choose-vcm out/bench/sweep.jsonl      # prints "R r threshold"
    make_report.py --scanner out/bench/scanner.jsonl       # prints the scanner-like inputs section

Every number in the report comes from the JSON lines in --data (one line per measured
configuration, written by sfe_ground_truth, sfe_bench_run and sfe_vcm_run); nothing is typed in
by hand except the expected ground-truth counts of BENCHMARK_DATA.md, which the report checks.
Needs Debian's python3-matplotlib and python3-pil.
"""

import argparse
import json
import math
import os
import sys

# Curve and corner counts of the ground truth, measured independently (BENCHMARK_DATA.md).
EXPECTED_TRUTH = {
    "fandisk": (34, 22), "anchor": (32, 14), "joint": (22, 12), "part": (5, 2), "pinion": (122, 80),
    "rotor": (9, 0), "spool": (11, 0), "u": (24, 16), "cross": (36, 24), "star": (36, 14),
    "oblong": (52, 28), "dragknob": (4, 0), "cube-meshed": (12, 8), "itemb": (0, 0),
    "anchor_dense": (41, 22), "couplingdown": (59, 6),
}
CONTROLS = {"itemb"}
NOISE_VARIANTS = ["noise0", "noise0.25", "noise0.5", "noise1", "noise2"]
VARIANT_TITLES = {
    "noise0": "noise 0", "noise0.25": "noise 0.25%", "noise0.5": "noise 0.5%", "noise1": "noise 1%",
    "noise2": "noise 2%", "noise5": "noise 5%",
    "denser5": "one half 5x denser", "outliers1": "1% outliers", "outliers5": "5% outliers",
}
MAX_PNG_BYTES = 300 * 1024
# Peak RSS per point that a cloud of 10M points must stay within (the memory target).
MEMORY_TARGET_BYTES_PER_POINT = 300
# Scanner-like inputs (scripts/bench.sh, scanner_rows): each row, what it is, and what it should
# give, as text and as a test of the row against the rows of the section (by name). F1 and
# recall at eps = 0.5% dB. "reference" is fandisk scanned from 4 viewpoints without defect.


def _f1(row):
    return row.get("ours_f1@0.5") or 0.0


def _as_reference(name, f1_tolerance, curve_fraction=0):
    """F1 within `f1_tolerance` of row `name`, and its curve count within `curve_fraction` of it."""
    def check(row, rows):
        ref = rows.get(name)
        return None if ref is None else (
            abs(row.get("ours_curves", 0) - ref.get("ours_curves", 0)) <= curve_fraction * ref.get("ours_curves", 0)
            and abs(_f1(row) - _f1(ref)) <= f1_tolerance)
    return check


SCANNER_ROWS = [
    ("reference", "fandisk, 4 viewpoints, even ray grid", "F1 >= 0.98 (uniform sample of 100k points: 0.996)",
     lambda r, rows: _f1(r) >= 0.98),
    ("range_noise", "range noise 0.5% dB along the rays", "F1 >= 0.94 (uniform sample, 0.5% noise in a ball: 0.964)",
     lambda r, rows: _f1(r) >= 0.94),
    ("offset_1e6", "georeferenced: every coordinate + 1e6", "F1 within 0.001 of the reference, curves within 10%",
     _as_reference("reference", 0.001, 0.1)),
    ("offset_1e8", "georeferenced: every coordinate + 1e8", "F1 within 0.001 of the reference, curves within 10%",
     _as_reference("reference", 0.001, 0.1)),
    ("lines_4", "scan lines 4x farther apart than the points on a line", "F1 within 0.01 of the reference",
     lambda r, rows: "reference" in rows and _f1(r) >= _f1(rows["reference"]) - 0.01),
    ("lines_8", "scan lines 8x farther apart than the points on a line", "F1 within 0.01 of the reference",
     lambda r, rows: "reference" in rows and _f1(r) >= _f1(rows["reference"]) - 0.01),
    ("misregistered", "last view shifted by 0.1% dB (doubled surface)",
     "F1 within 0.02 of the reference, at most 10% more curves",
     lambda r, rows: "reference" in rows and _f1(r) >= _f1(rows["reference"]) - 0.02
     and r.get("ours_curves", 0) <= 1.1 * rows["reference"].get("ours_curves", 0)),
    ("window_2", "ray grid twice as wide as the object, misses dropped", "F1 within 0.01 of the reference",
     lambda r, rows: "reference" in rows and _f1(r) >= _f1(rows["reference"]) - 0.01),
    ("no_returns", "the same, misses written as (0,0,0)", "the curve count of window_2, F1 within 0.002",
     _as_reference("window_2", 0.002)),
    ("duplicates", "the reference's returns + exact duplicates", "the reference's curve count, F1 within 0.005, "
     "time no more than the distinct cloud of the same size",
     lambda r, rows: None if "distinct" not in rows or "reference" not in rows else
     _as_reference("reference", 0.005)(r, rows) and r["time_total"] <= rows["distinct"]["time_total"]),
    ("distinct", "fandisk scanned with as many distinct returns", "F1 >= 0.98", lambda r, rows: _f1(r) >= 0.98),
    ("plane", "a square scanned from 1 viewpoint", "no curve", lambda r, rows: r.get("ours_curves") == 0),
    ("plane_noise", "the same, range noise 0.5% dB", "no curve", lambda r, rows: r.get("ours_curves") == 0),
    ("large", "fandisk, 4 viewpoints, large", f"peak RSS <= {MEMORY_TARGET_BYTES_PER_POINT} B per point, F1 >= 0.98",
     lambda r, rows: r["rss_peak_mb"] * 1048576 / r["cloud_size"] <= MEMORY_TARGET_BYTES_PER_POINT and _f1(r) >= 0.98),
]


# ------------------------------------------------------------------------------------------
# Reading the rows
# ------------------------------------------------------------------------------------------

def read_rows(path):
    rows = []
    if os.path.exists(path):
        with open(path) as f:
            for line in f:
                line = line.strip()
                if line:
                    rows.append(json.loads(line))
    return rows


def split_label(label):
    """'fandisk_noise0.5' -> ('fandisk', 'noise0.5'); part names may contain '_' or '-'."""
    part, _, variant = label.rpartition("_")
    return part, variant


def point_f1(row, prefix, eps="0.5"):
    p, c = row.get(f"{prefix}_precision@{eps}"), row.get(f"{prefix}_coverage@{eps}")
    if p is None or c is None or p + c == 0:
        return 0.0
    return 2 * p * c / (p + c)


def choose_vcm(sweep_rows):
    """The (R, r, threshold) with the best mean point-F1 at eps 0.5% over the swept clouds."""
    scores = {}
    for row in sweep_rows:
        if row.get("status"):
            continue
        key = (row["vcm_R"], row["vcm_r"], row["vcm_threshold"])
        scores.setdefault(key, []).append(point_f1(row, "vcm"))
    count = max(len(v) for v in scores.values())
    complete = {k: sum(v) / len(v) for k, v in scores.items() if len(v) == count}
    best = max(complete, key=lambda k: (complete[k], -k[0], -k[1]))
    return best, complete


# ------------------------------------------------------------------------------------------
# Formatting
# ------------------------------------------------------------------------------------------

def fmt(value, digits=3):
    if value is None:
        return "-"
    if isinstance(value, bool):
        return "yes" if value else "no"
    if isinstance(value, int):
        return str(value)
    if isinstance(value, float) and (math.isnan(value) or math.isinf(value)):
        return "-"
    return f"{value:.{digits}f}"


def pct(value, digits=3):
    """A fraction of dB shown in percent of dB."""
    return "-" if value is None else f"{100 * value:.{digits}f}"


def secs(value):
    if value is None:
        return "-"
    return f"{value:.2f}" if value < 10 else f"{value:.1f}"


def write_density_section(w, accuracy_rows, speed_rows, density_rows):
    """Section 7c: each part's 0.5%-noise accuracy row beside the same noise on a denser cloud
    (fandisk's speed row with 2 threads, the density rows of the other parts)."""
    dense = {split_label(r["label"][len("density_"):])[0]: r for r in density_rows if not r.get("status")}
    speed = next((r for r in speed_rows if r.get("method") == "ours" and not r.get("status")
                  and r.get("noise") == 0.005 and r.get("threads") == 2), None)
    if speed:
        dense["fandisk"] = speed
    sparse = {split_label(r["label"])[0]: r for r in accuracy_rows
              if r.get("method") == "ours" and not r.get("status") and split_label(r["label"])[1] == "noise0.5"}
    parts = [p for p in sorted(dense) if p in sparse]
    if not parts:
        return
    w("## 7c. Density: the same noise on a denser cloud\n")
    w("Noise 0.5% dB, default call, seed 1: each part's row of section 3 beside a cloud of the same "
      "noise with more points. The scales follow the noise, so the denser cloud should give curves "
      "at least as good; the change is in the last column.\n")
    rows = []
    for part in parts:
        before, after = sparse[part], dense[part]
        for r in (before, after):
            radius = r.get("scale_growth_radius")
            rows.append([part, f"{r['points']:,}", fmt(r.get("scale_candidate_neighbors")),
                         fmt(r.get("scale_search_fraction"), 2),
                         fmt(radius / r["scale_noise"], 1) if radius and r.get("scale_noise") else "-",
                         fmt(r.get("ours_f1@0.5")),
                         f"{r.get('ours_corners_found@0.5', '-')} / {r.get('ours_true_corners', '-')}",
                         fmt(r.get("ours_pieces_per_true_curve@1"), 2), secs(r.get("time_total")),
                         "" if r is before else
                         f"F1 {after['ours_f1@0.5'] - before['ours_f1@0.5']:+.3f}, corners "
                         f"{after['ours_corners_found@0.5'] - before['ours_corners_found@0.5']:+d}"])
    w(table(["part", "points", "stage-1 neighbours", "search fraction (means)", "stage-1 radius / noise",
             "F1 0.5%", "corners found 0.5%", "pieces per found curve 1%", "time (s)", "denser - sparser"], rows))
    w("\nThe stage-1 neighbours are points, or means of points where the search fraction is below 1 "
      "(see the manual's scale table); their radius (the median, which is also the growth radius of "
      "stage 4) is given in units of the measured noise: the noise alone should set it. Fandisk's "
      "denser row is its 2-thread speed row (section 7b, patches included in its run), the others "
      "ran with 2 threads and without patches.\n")


def table(header, rows):
    lines = ["| " + " | ".join(header) + " |", "|" + "|".join("---" for _ in header) + "|"]
    for r in rows:
        lines.append("| " + " | ".join(str(c) for c in r) + " |")
    return "\n".join(lines)


# ------------------------------------------------------------------------------------------
# Figures
# ------------------------------------------------------------------------------------------

def save_small_png(image, path):
    """Saves a PIL image as an optimized PNG, quantizing or shrinking it until < 300 KB."""
    from PIL import Image
    image = image.convert("RGB")
    for attempt in range(6):
        candidate = image if attempt == 0 else image.quantize(colors=256, method=Image.MEDIANCUT)
        if attempt >= 2:
            scale = 0.85 ** (attempt - 1)
            smaller = image.resize((int(image.width * scale), int(image.height * scale)), Image.LANCZOS)
            candidate = smaller.quantize(colors=256, method=Image.MEDIANCUT)
        candidate.save(path, optimize=True)
        if os.path.getsize(path) < MAX_PNG_BYTES:
            return
    raise RuntimeError(f"{path} stays above {MAX_PNG_BYTES} bytes")


def save_figure(fig, path):
    import io
    from PIL import Image
    buffer = io.BytesIO()
    fig.savefig(buffer, format="png", dpi=90, bbox_inches="tight")
    buffer.seek(0)
    save_small_png(Image.open(buffer), path)


def picture_grid(paths_and_titles, columns, path, width):
    """Pastes renderer pictures into a grid with a title above each, scaled to `width` pixels."""
    from PIL import Image, ImageDraw
    images = [(Image.open(p).convert("RGB"), t) for p, t in paths_and_titles if os.path.exists(p)]
    if not images:
        return False
    w, h = images[0][0].size
    title_height = 28
    rows = (len(images) + columns - 1) // columns
    grid = Image.new("RGB", (w * columns, (h + title_height) * rows), "white")
    draw = ImageDraw.Draw(grid)
    font = None
    try:
        from PIL import ImageFont
        import matplotlib.font_manager
        font = ImageFont.truetype(matplotlib.font_manager.findfont("DejaVu Sans"), 22)
    except Exception:
        pass
    for i, (im, title) in enumerate(images):
        x, y = (i % columns) * w, (i // columns) * (h + title_height)
        grid.paste(im, (x, y + title_height))
        draw.text((x + 10, y + 2), title, fill=(0, 0, 0), font=font)
    scale = width / grid.width
    grid = grid.resize((width, int(grid.height * scale)), Image.LANCZOS)
    save_small_png(grid, path)
    return True


def plot_accuracy_vs_noise(ours, vcm, parts, path, eps="0.5"):
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    columns = min(4, len(parts))
    rows = (len(parts) + columns - 1) // columns
    fig, axes = plt.subplots(rows, columns, figsize=(3.2 * columns, 2.7 * rows), squeeze=False, sharey=True)
    for ax in axes.flat[len(parts):]:
        ax.axis("off")
    for ax, part in zip(axes.flat, parts):
        noises, series = [], {k: [] for k in ("rec", "prec", "vcov", "vprec")}
        for variant in NOISE_VARIANTS:
            o, v = ours.get((part, variant)), vcm.get((part, variant))
            if o is None or v is None:
                continue
            noises.append(100 * o["noise"])
            series["rec"].append(o.get(f"ours_recall@{eps}"))
            series["prec"].append(o.get(f"ours_precision@{eps}"))
            series["vcov"].append(v.get(f"vcm_coverage@{eps}"))
            series["vprec"].append(v.get(f"vcm_precision@{eps}"))
        ax.plot(noises, series["rec"], "o-", color="tab:blue", label="ours: recall (curves)")
        ax.plot(noises, series["prec"], "s--", color="tab:blue", label="ours: precision (curves)")
        ax.plot(noises, series["vcov"], "o-", color="tab:orange", label="VCM: coverage (points)")
        ax.plot(noises, series["vprec"], "s--", color="tab:orange", label="VCM: precision (points)")
        ax.set_title(part)
        ax.set_ylim(-0.02, 1.02)
        ax.grid(alpha=0.3)
        ax.set_xlabel("noise (% of dB)")
    for ax in axes[:, 0]:
        ax.set_ylabel(f"at eps = {eps}% dB")
    handles, labels = axes.flat[0].get_legend_handles_labels()
    fig.tight_layout()
    fig.legend(handles, labels, loc="upper center", ncol=4, bbox_to_anchor=(0.5, 0.0))
    save_figure(fig, path)
    plt.close(fig)


def plot_scaling(ours_rows, vcm_rows, path):
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    fig, (ax_time, ax_memory) = plt.subplots(1, 2, figsize=(10, 4))
    n = [r["points"] for r in ours_rows]
    ax_time.loglog(n, [r["time_total"] for r in ours_rows], "o-", color="tab:blue", lw=2.5, label="ours, total")
    for stage, style in (("context", "-"), ("candidates", ":"), ("projection", "--"), ("smoothing", "-."),
                         ("growing", ":"), ("completion", "--")):
        values = [max(r.get(f"time_{stage}", 0), 1e-3) for r in ours_rows]
        ax_time.loglog(n, values, style, color="tab:blue", alpha=0.6, lw=1, label=f"ours, {stage}")
    if vcm_rows:
        ax_time.loglog([r["points"] for r in vcm_rows], [r["time_total"] for r in vcm_rows], "s-",
                       color="tab:orange", lw=2.5, label="CGAL VCM")
    ax_time.set_xlabel("points")
    ax_time.set_ylabel("wall time (s)")
    ax_time.set_title("time vs N (fandisk)")
    ax_time.grid(True, which="both", alpha=0.3)
    ax_time.legend(fontsize=7)
    ax_memory.loglog(n, [r["rss_peak_mb"] for r in ours_rows], "o-", color="tab:blue", label="ours, process peak RSS")
    ax_memory.loglog(n, [r["heap_peak_mb"] for r in ours_rows], "o--", color="tab:blue", alpha=0.6,
                     label="ours, heap peak of the run")
    if vcm_rows:
        ax_memory.loglog([r["points"] for r in vcm_rows], [r["rss_peak_mb"] for r in vcm_rows], "s-",
                         color="tab:orange", label="VCM, process peak RSS")
    ax_memory.set_xlabel("points")
    ax_memory.set_ylabel("MB")
    ax_memory.set_title("peak memory vs N")
    ax_memory.grid(True, which="both", alpha=0.3)
    ax_memory.legend(fontsize=7)
    fig.tight_layout()
    save_figure(fig, path)
    plt.close(fig)


# ------------------------------------------------------------------------------------------
# The report
# ------------------------------------------------------------------------------------------

ACCURACY_FIELDS = ["ours_recall@0.5", "ours_precision@0.5", "ours_f1@0.5", "ours_recall@1", "ours_precision@1",
                   "ours_f1@1", "ours_mean_dist", "ours_rms_dist", "ours_max_dist", "ours_curves", "ours_corners",
                   "ours_corners_found@0.5", "ours_corners_found@1", "ours_pieces_per_true_curve@1",
                   "candidates_count", "projected_count", "smoothed_count", "smoothed_precision@0.5",
                   "smoothed_coverage@0.5"]


def scanner_section(rows):
    """The report section of the scanner-like inputs, from their rows (labels scanner_NAME)."""
    by_name = {r["label"][len("scanner_"):]: r for r in rows if not r.get("status")}
    failed = {r["label"][len("scanner_"):]: r["status"] for r in rows if r.get("status")}
    table_rows, met = [], 0
    for name, what, expectation, check in SCANNER_ROWS:
        r = by_name.get(name)
        if r is None:
            if name in failed:
                table_rows.append([name, what, expectation, f"**{failed[name]}**"] + ["-"] * 8)
            continue
        ok = check(r, by_name)
        met += ok is True
        table_rows.append([name, what, expectation, "yes" if ok else ("-" if ok is None else "**no**"),
                           f"{r['cloud_size']:,}", f"{r.get('ours_curves')} / {r.get('ours_true_curves')}",
                           fmt(r.get("ours_f1@0.5")), fmt(r.get("ours_recall@0.5")), fmt(r.get("ours_precision@0.5")),
                           f"{r.get('ours_corners_found@0.5', '-')} / {r.get('ours_true_corners')}",
                           secs(r.get("time_total")), fmt(r["rss_peak_mb"] * 1048576 / r["cloud_size"], 0)])
    out = ["## 12. Scanner-like inputs\n",
           "Clouds as range scanners write them, from the scan simulation of "
           "`benchmark/Sharp_feature_extraction/scan_simulation.h`: rays from viewpoints around the mesh (the "
           "vertices of a regular tetrahedron, 1.5 dB from the centre), each returning the first surface it hits "
           "(occlusion), none beyond 80 degrees of incidence; then one defect of real files per row. Default "
           "call, all cores; F1, recall and precision of the curves at eps = 0.5% dB (the square has no true "
           "crease: only its curve count means something). Each row states what it should give, and whether it "
           f"does: {met} of {len(table_rows)} rows meet their expectation.\n",
           table(["row", "cloud", "expected", "met", "points", "curves / true", "F1", "recall", "precision",
                  "corners found / true", "time (s)", "peak RSS B per point"], table_rows),
           "\nPoints: the cloud as given to the library (returns, (0,0,0) points and duplicates included). Peak "
           "RSS: the whole process (the scan, the cloud, the ground truth and the scoring included).\n"]
    return "\n".join(out)


def machine_info(data):
    info = {}
    path = os.path.join(data, "machine.txt")
    if os.path.exists(path):
        for line in open(path):
            key, _, value = line.partition(":")
            info[key.strip()] = value.strip()
    return info


def write_report(data, report, quick):
    os.makedirs(report, exist_ok=True)
    truth_rows = read_rows(os.path.join(data, "truth.jsonl"))
    sweep_rows = read_rows(os.path.join(data, "sweep.jsonl"))
    accuracy_rows = read_rows(os.path.join(data, "accuracy.jsonl"))
    scaling_rows = read_rows(os.path.join(data, "scaling.jsonl"))
    repeat_rows = read_rows(os.path.join(data, "repeat.jsonl"))
    speed_rows = read_rows(os.path.join(data, "speed.jsonl"))
    scanner_rows = read_rows(os.path.join(data, "scanner.jsonl"))
    heavy_rows = read_rows(os.path.join(data, "heavy.jsonl"))
    density_rows = read_rows(os.path.join(data, "density.jsonl"))
    machine = machine_info(data)
    vcm_setting = open(os.path.join(data, "vcm_setting.txt")).read().split()

    failures = [r for r in accuracy_rows + scaling_rows + sweep_rows + repeat_rows + speed_rows + scanner_rows + heavy_rows
                + density_rows
                if r.get("status") in ("failed", "timeout")]
    ours, vcm = {}, {}
    for r in accuracy_rows:
        if r.get("status"):
            continue
        key = split_label(r["label"])
        (ours if r["method"] == "ours" else vcm)[key] = r
    parts = []
    for r in truth_rows:
        if r["label"] not in CONTROLS:
            parts.append(r["label"])
    controls = [r["label"] for r in truth_rows if r["label"] in CONTROLS]
    variants = []
    for r in accuracy_rows:
        if "label" in r:
            v = split_label(r["label"])[1]
            if v not in variants:
                variants.append(v)
    points = next((r["points"] for r in accuracy_rows if "points" in r), None)

    out = []
    w = out.append
    w("# Sharp feature extraction: benchmark report\n")
    w(f"Generated by `scripts/bench.sh{' --quick' if quick else ''}` on {machine.get('date', '?')} "
      f"in {int(machine.get('seconds', '0')) // 60} min; every figure below is read from the rows that run "
      "measured (`make_report.py` writes this file; do not edit it by hand). "
      + ("**Quick run**: fewer parts, sizes and variants, VCM at its fixed setting; the full report is "
         "`benchmark/results/REPORT.md`.\n" if quick else "\n"))

    # Headline.
    w("## Headline\n")
    headline = []
    for variant in ("noise0", "noise0.5"):
        o, v = ours.get(("fandisk", variant)), vcm.get(("fandisk", variant))
        if o and v:
            headline.append([f"fandisk, {points // 1000}k points, {VARIANT_TITLES[variant]}",
                             fmt(o.get("ours_recall@0.5")), fmt(o.get("ours_precision@0.5")), fmt(o.get("ours_f1@0.5")),
                             f"{o.get('ours_curves')} / {o.get('ours_true_curves')}", secs(o.get("time_total")),
                             fmt(v.get("vcm_precision@0.5")), fmt(v.get("vcm_coverage@0.5")), secs(v.get("time_total"))])
    if headline:
        w(table(["cloud", "ours: recall", "ours: precision", "ours: F1", "ours: curves / true", "ours: time (s)",
                 "VCM: point precision", "VCM: coverage", "VCM: time (s)"], headline))
        w("\nRecall, precision and coverage at eps = 0.5% of the bounding-box diagonal dB. Ours are curves "
          "(length within eps of the true creases); VCM labels points and makes no curves. Both ran on the "
          f"same cloud, VCM with {'the fixed setting' if not sweep_rows else 'its best setting of the sweep below'} "
          f"(R = {vcm_setting[0]} dB, r = {vcm_setting[1]} dB, threshold = {vcm_setting[2]}). Times are wall "
          "clock on a 2-core machine shared with other work: they vary from run to run, accuracy does not.\n")
    else:
        w("No fandisk rows: see Failures.\n")

    # Machine and commands.
    w("## Machine and commands\n")
    w(table(["", ""], [[k, v] for k, v in machine.items() if k not in ("seconds",)]))
    w("\nRegenerate everything (Debian packages, build, ground truth, clouds, runs, this report and its "
      "figures) from scratch with\n")
    w("```\nscripts/bench.sh            # full: this report, about 1.5 h on 2 cores\n"
      "scripts/bench.sh --quick    # smoke run, < 5 min once built: out/bench_quick/report/REPORT.md\n```\n")
    w("Each configuration runs in its own process (`sfe_bench_run` for ours with default parameters "
      "only and `CGAL::Parallel_if_available_tag`, `sfe_vcm_run` for VCM, single-threaded as CGAL 5.5 "
      "implements it), so its peak memory is its own. Rows: `out/bench*/accuracy.jsonl`, `sweep.jsonl`, "
      "`scaling.jsonl`.\n")

    # Definitions.
    w("## What is measured\n")
    w("- **Ground truth**: mesh edges whose two face normals differ by more than 30 degrees, chained into "
      "curves that break where the number of sharp edges at a vertex is not 2; corners are the vertices with "
      "3 or more (`sfe_ground_truth`).\n"
      f"- **Clouds**: {points} points drawn uniformly (area-weighted, seed 1) on the mesh "
      "(`sfe_utilities::sample_triangle_soup`), moved by uniform noise in a ball of radius L x dB; "
      "variants with one half (x above the box centre) 5x denser, and with 1% or 5% extra outliers "
      "uniform in the bounding box. dB is the mesh's bounding-box diagonal.\n"
      "- **Curve metrics** (ours): both curve sets resampled every 0.025% dB, distances exact to "
      "segments (AABB tree). Recall = fraction of true crease length within eps of our curves; precision = "
      "fraction of our curve length within eps of a true crease; F1 their harmonic mean; mean / RMS / max "
      "distance of our curves to the truth (length-weighted, in % of dB). Corners found = true corners with a "
      "distinct corner of ours within eps (greedy closest-first matching). Pieces per true curve = mean, over "
      "the true curves we find, of how many of our curves follow it for at least 3 eps (or half its length).\n"
      "- **Point metrics** (VCM labels, and ours at each stage: candidate points, RMLS-projected edge and "
      "corner points, smoothed points): precision = fraction of the points within eps of a true crease; "
      "coverage = fraction of true crease length with a point within eps; mean distance to the truth.\n"
      "- **Time**: ours from `result.timings` (per stage, wall clock); VCM = `compute_vcm` + labelling. "
      "**Memory**: process peak RSS (getrusage) and the heap peak of the run (bytes allocated through "
      "operator new, counted by the benchmark).\n"
      "- eps = 0.5% and 1% of dB. Default parameters only: no per-model tuning.\n")

    # Ground truth.
    w("## 1. Ground truth\n")
    gt = []
    for r in truth_rows:
        expected = EXPECTED_TRUTH.get(r["label"])
        ok = expected is None or (r["curves"], r["corners"]) == expected
        gt.append([r["label"], r["angle"], r["vertices"], r["faces"], fmt(r["diagonal"]), r["curves"], r["closed_curves"],
                   r["corners"], r["dangling_ends"], fmt(r["length"], 2),
                   ("yes" if ok else f"**NO** (expected {expected[0]} / {expected[1]})") if expected else "-"])
    w(table(["part", "angle", "vertices", "faces", "dB", "curves", "closed", "corners", "fading ends",
             "length / dB", "counts as in BENCHMARK_DATA.md"], gt))
    if picture_grid([(os.path.join(data, "pictures", f"truth_{r['label']}.png"), r["label"]) for r in truth_rows],
                    2, os.path.join(report, "truth.png"), 1100):
        w("\n![ground truth](truth.png)\n\n*Ground-truth curves (one colour each) and corners (dots) over a "
          "sampling of each mesh, two opposite views. Checked by eye: every curve is a crease; the facet "
          "lines of curved faces (e.g. fandisk's rounded top, under 30 degrees) are not curves.*\n")

    # VCM sweep.
    w("## 2. The peer: CGAL's VCM and its sweep\n")
    if sweep_rows:
        best, mean_f1 = choose_vcm(sweep_rows)
        settings = sorted({(r["vcm_R"], r["vcm_r"]) for r in sweep_rows if not r.get("status")})
        thresholds = sorted({r["vcm_threshold"] for r in sweep_rows if not r.get("status")})
        w(f"`compute_vcm(points, cov, R, r)` then `vcm_is_on_feature_edge(cov[i], threshold)`, on fandisk at "
          f"100k points at each noise level. Sweep: R in {{{', '.join(fmt(s, 3) for s in sorted({s[0] for s in settings}))}}} dB, "
          f"r in {{{', '.join(fmt(s, 3) for s in sorted({s[1] for s in settings}))}}} dB, threshold in "
          f"{{{', '.join(fmt(t, 2) for t in thresholds)}}} ({len(settings) * len(thresholds)} settings). "
          "The setting with the best point F1 (harmonic mean of point precision and coverage at eps 0.5% dB) "
          f"averaged over the noise levels is used for every VCM row: **R = {best[0]} dB, r = {best[1]} dB, "
          f"threshold = {best[2]}** (mean F1 {fmt(mean_f1[best])}).\n")
        rows = []
        for variant in NOISE_VARIANTS:
            vrows = [r for r in sweep_rows if not r.get("status") and split_label(r["label"])[1] == variant]
            if not vrows:
                continue
            top = max(vrows, key=lambda r: point_f1(r, "vcm"))
            chosen = next((r for r in vrows if (r["vcm_R"], r["vcm_r"], r["vcm_threshold"]) == best), None)
            rows.append([VARIANT_TITLES[variant],
                         f"{top['vcm_R']} / {top['vcm_r']} / {top['vcm_threshold']}", fmt(top["vcm_precision@0.5"]),
                         fmt(top["vcm_coverage@0.5"]), fmt(point_f1(top, "vcm")),
                         fmt(chosen["vcm_precision@0.5"]) if chosen else "-", fmt(chosen["vcm_coverage@0.5"]) if chosen else "-",
                         fmt(point_f1(chosen, "vcm")) if chosen else "-", secs(chosen["time_vcm"]) if chosen else "-"])
        w(table(["fandisk 100k", "best R / r / threshold here", "precision", "coverage", "F1",
                 "chosen: precision", "chosen: coverage", "chosen: F1", "chosen: time (s)"], rows))
        w("\n<details><summary>Whole sweep (point precision / coverage at eps 0.5% dB)</summary>\n")
        header = ["R / r / threshold"] + [VARIANT_TITLES[v] for v in NOISE_VARIANTS]
        rows = []
        for (R, r) in settings:
            for t in thresholds:
                cells = [f"{R} / {r} / {t}"]
                for variant in NOISE_VARIANTS:
                    m = next((x for x in sweep_rows if not x.get("status") and split_label(x["label"])[1] == variant
                              and (x["vcm_R"], x["vcm_r"], x["vcm_threshold"]) == (R, r, t)), None)
                    cells.append(f"{fmt(m['vcm_precision@0.5'], 2)} / {fmt(m['vcm_coverage@0.5'], 2)}" if m else "-")
                rows.append(cells)
        w(table(header, rows))
        w("\n</details>\n")
    else:
        w(f"No sweep in this run: VCM at the full run's setting R = {vcm_setting[0]} dB, r = {vcm_setting[1]} dB, "
          f"threshold = {vcm_setting[2]}.\n")

    # Accuracy of our curves.
    w(f"## 3. Accuracy of our curves ({points // 1000}k points)\n")
    rows = []
    for part in parts:
        for variant in variants:
            o = ours.get((part, variant))
            if not o:
                continue
            rows.append([part, VARIANT_TITLES.get(variant, variant),
                         fmt(o.get("ours_recall@0.5")), fmt(o.get("ours_precision@0.5")), f"**{fmt(o.get('ours_f1@0.5'))}**",
                         fmt(o.get("ours_recall@1")), fmt(o.get("ours_precision@1")), fmt(o.get("ours_f1@1")),
                         pct(o.get("ours_mean_dist")), pct(o.get("ours_rms_dist")), pct(o.get("ours_max_dist"), 2),
                         secs(o.get("time_total"))])
    w(table(["part", "cloud", "recall 0.5%", "precision 0.5%", "F1 0.5%", "recall 1%", "precision 1%", "F1 1%",
             "mean dist (% dB)", "RMS dist", "max dist", "time (s)"], rows))
    w("\nStructure of the curve network (at eps = 1% dB unless stated):\n")
    rows = []
    for part in parts:
        for variant in variants:
            o = ours.get((part, variant))
            if not o:
                continue
            rows.append([part, VARIANT_TITLES.get(variant, variant), f"{o.get('ours_curves')} / {o.get('ours_true_curves')}",
                         fmt(o["ours_curves"] / o["ours_true_curves"], 2) if o.get("ours_true_curves") else "-",
                         fmt(o.get("ours_pieces_per_true_curve@1"), 2),
                         f"{o.get('ours_true_curves_half_recalled@1')} / {o.get('ours_true_curves')}",
                         f"{o.get('ours_corners_found@0.5')} / {o.get('ours_corners_found@1')} / {o.get('ours_true_corners')}",
                         o.get("ours_corners"),
                         f"{fmt(o.get('grown_f1@0.5'))} / {o.get('grown_curves')}"])
    w(table(["part", "cloud", "curves / true", "curves per true curve", "pieces per found true curve",
             "true curves >= half recalled", "corners found 0.5% / 1% / true", "our corners",
             "before completion: F1 0.5% / curves"], rows))

    # Points: ours per stage vs VCM.
    w(f"\n## 4. Feature points: ours at each stage vs VCM (eps = 0.5% dB)\n")
    w("Cells are precision / coverage. Times: ours = all five stages, VCM = compute_vcm + labelling.\n")
    rows = []
    for part in parts:
        for variant in variants:
            o, v = ours.get((part, variant)), vcm.get((part, variant))
            if not o and not v:
                continue
            cell = lambda r, p: f"{fmt(r.get(p + '_precision@0.5'), 2)} / {fmt(r.get(p + '_coverage@0.5'), 2)}" if r else "-"
            rows.append([part, VARIANT_TITLES.get(variant, variant), cell(o, "candidates"), cell(o, "projected"),
                         cell(o, "smoothed"), cell(v, "vcm"),
                         f"{pct(o.get('smoothed_mean_dist'))} / {pct(v.get('vcm_mean_dist')) if v else '-'}" if o else "-",
                         f"{o.get('smoothed_count') if o else '-'} / {v.get('vcm_count') if v else '-'}",
                         f"{secs(o.get('time_total')) if o else '-'} / {secs(v.get('time_total')) if v else '-'}",
                         fmt(o["time_total"] / v["time_total"], 2) if o and v and v.get("time_total") else "-"])
    w(table(["part", "cloud", "ours: candidates", "ours: projected", "ours: smoothed", "VCM labelled",
             "mean dist (% dB) smoothed / VCM", "points smoothed / VCM", "time (s) ours / VCM", "time ratio"], rows))

    # Robustness summary.
    w("\n## 5. Robustness: mean over the parts\n")
    rows = []
    for variant in variants:
        os_ = [ours[(p, variant)] for p in parts if (p, variant) in ours]
        vs = [vcm[(p, variant)] for p in parts if (p, variant) in vcm]
        if not os_:
            continue
        mean = lambda xs: sum(xs) / len(xs) if xs else None
        rows.append([VARIANT_TITLES.get(variant, variant), len(os_),
                     fmt(mean([r.get("ours_recall@0.5", 0) for r in os_])), fmt(mean([r.get("ours_precision@0.5", 0) for r in os_])),
                     fmt(mean([r.get("ours_f1@0.5", 0) for r in os_])), fmt(mean([r.get("ours_f1@1", 0) for r in os_])),
                     fmt(mean([point_f1(r, "smoothed") for r in os_])), fmt(mean([point_f1(r, "vcm") for r in vs])),
                     fmt(mean([r.get("vcm_precision@0.5", 0) for r in vs])), fmt(mean([r.get("vcm_coverage@0.5", 0) for r in vs])),
                     secs(mean([r["time_total"] for r in os_])), secs(mean([r["time_total"] for r in vs]))])
    w(table(["cloud", "parts", "ours: recall 0.5%", "ours: precision 0.5%", "ours: F1 0.5%", "ours: F1 1%",
             "ours smoothed points: F1 0.5%", "VCM points: F1 0.5%", "VCM: precision", "VCM: coverage",
             "ours: mean time (s)", "VCM: mean time (s)"], rows))
    if any((p, v) in ours and (p, v) in vcm for p in parts for v in NOISE_VARIANTS):
        plot_accuracy_vs_noise(ours, vcm, parts, os.path.join(report, "accuracy_vs_noise.png"))
        w("\n![recall and precision vs noise](accuracy_vs_noise.png)\n\n*Per part, at eps = 0.5% dB: our curves' "
          "recall and precision, and VCM's labelled points' coverage and precision, against the noise radius.*\n")

    # Negative control.
    w("## 6. Negative control: a smooth part without creases\n")
    rows = []
    for part in controls:
        for variant in variants:
            o, v = ours.get((part, variant)), vcm.get((part, variant))
            if not o and not v:
                continue
            rows.append([part, VARIANT_TITLES.get(variant, variant), o.get("ours_curves") if o else "-",
                         fmt(o.get("ours_length"), 3) if o else "-", o.get("ours_corners") if o else "-",
                         o.get("candidates_count") if o else "-", o.get("smoothed_count") if o else "-",
                         v.get("vcm_count") if v else "-"])
    w(table(["part", "cloud", "our curves", "our curve length / dB", "our corners", "candidates", "smoothed points",
             "VCM labelled points"], rows))
    w("\nEverything found here is false: the ideal row is all zeros.\n")

    # Scaling.
    w("## 7. Scaling on fandisk (noise 0)\n")
    s_ours = sorted([r for r in scaling_rows if r.get("method") == "ours" and not r.get("status")], key=lambda r: r["points"])
    s_vcm = sorted([r for r in scaling_rows if r.get("method") == "vcm" and not r.get("status")], key=lambda r: r["points"])
    vcm_by_n = {r["points"]: r for r in s_vcm}
    vcm_status = {int(r["label"].split("_")[-1]): r["status"] for r in scaling_rows
                  if r.get("method") == "vcm" and r.get("status")}
    rows = []
    for r in s_ours:
        v = vcm_by_n.get(r["points"])
        vtime = secs(v["time_total"]) if v else vcm_status.get(r["points"], "-")
        rows.append([f"{r['points']:,}", secs(r["time_candidates"] + r.get("time_context", 0)), secs(r["time_projection"]), secs(r["time_smoothing"]),
                     secs(r["time_growing"]), secs(r["time_completion"]), f"**{secs(r['time_total'])}**", vtime,
                     fmt(r["time_total"] / v["time_total"], 2) if v else "-",
                     " / ".join(fmt(r.get(f"heap_{s}_mb"), 0) for s in ("candidates", "projection", "smoothing", "growing", "completion")),
                     fmt(r["heap_peak_mb"], 0), fmt(r["rss_peak_mb"], 0), fmt(v["rss_peak_mb"], 0) if v else "-",
                     fmt(r.get("ours_f1@0.5"))])
    w(table(["points", "context + candidates (s)", "projection", "smoothing", "growing", "completion", "ours total", "VCM (s)",
             "ours / VCM", "heap per stage (MB)", "heap, whole run (MB)", "ours peak RSS (MB)", "VCM peak RSS (MB)",
             "ours F1 0.5%"], rows))
    w("\nHeap per stage: peak bytes allocated through operator new while that stage alone runs, above what "
      "was allocated before it (a second pass that runs the five stage functions one after another). "
      "Peak RSS: whole process (cloud, ground truth and scoring included).")
    if vcm_status:
        w("\nVCM: " + ", ".join(f"{n:,} points {s}" for n, s in sorted(vcm_status.items())) +
          " (a VCM run is stopped after 10 minutes and larger sizes are then skipped).")
    w("\n")
    if s_ours:
        plot_scaling(s_ours, s_vcm, os.path.join(report, "scaling.png"))
        w("![time and memory vs N](scaling.png)\n")

    # Speed.
    if speed_rows:
        w("## 7b. Speed: fandisk, 1 and 2 threads\n")
        vcm_speed = {r["label"]: r for r in speed_rows if r.get("method") == "vcm" and not r.get("status")}
        rows = []
        for r in speed_rows:
            if r.get("method") != "ours" or r.get("status"):
                continue
            v = vcm_speed.get(r["label"])
            rows.append([f"{r['points']:,}", pct(r.get("noise", 0), 2), r.get("threads") or "all",
                         secs(r["time_candidates"] + r.get("time_context", 0)), secs(r["time_projection"]), secs(r["time_smoothing"]),
                         secs(r["time_growing"]), secs(r["time_completion"]), f"**{secs(r['time_total'])}**",
                         fmt(r["time_total"] / r["points"] * 1e6, 2),
                         secs(v["time_total"]) if v else "-",
                         fmt(v["time_total"] / r["time_total"], 1) if v else "-",
                         fmt(r["heap_peak_mb"] * 1048576 / r["points"], 0),
                         fmt(r["rss_peak_mb"] * 1048576 / r["points"], 0),
                         fmt(r.get("ours_f1@0.5"))])
        w(table(["points", "noise (% dB)", "threads", "context + candidates (s)", "projection", "smoothing", "growing",
                 "completion", "ours total", "us per point", "VCM (s)", "VCM / ours", "heap B per point",
                 "peak RSS B per point", "ours F1 0.5%"], rows))
        same_path = os.path.join(data, "speed_threads.txt")
        if os.path.exists(same_path):
            w("\nCurves with 1 and 2 threads, compared byte for byte: " +
              "; ".join(line.strip() for line in open(same_path) if line.strip()) + ".")
        w("\nVCM runs single-threaded (CGAL 5.5). Heap: bytes allocated by the pipeline through operator new "
          "at its peak; peak RSS: the whole process (the cloud itself, 24 bytes per point, the ground truth "
          "and the scoring included).\n")

    # Density.
    write_density_section(w, accuracy_rows, speed_rows, density_rows)

    # Pictures.
    w("## 8. Our curves on fandisk\n")
    pictures = [(os.path.join(data, "pictures", f"curves_fandisk_{v}.png"), f"{VARIANT_TITLES[v]}")
                for v in variants if os.path.exists(os.path.join(data, "pictures", f"curves_fandisk_{v}.png"))]
    if picture_grid(pictures, 2, os.path.join(report, "fandisk_curves.png"), 1100):
        w(f"![our curves on fandisk](fandisk_curves.png)\n\n*Our curves (one colour each) and corners (dots) on "
          f"the {points // 1000}k-point fandisk cloud, default parameters, for each cloud variant.*\n")

    # Heavy noise, at the levels of the paper's Fig. 12.
    heavy = next((r for r in heavy_rows if not r.get("status")), None)
    if heavy:
        w("## 8b. Heavy noise: fandisk at the noise levels of the paper's Fig. 12\n")
        pictures = [(os.path.join(data, "pictures", f"curves_fandisk_{v}.png"), VARIANT_TITLES[v])
                    for v in ("noise1", "noise2", "noise5")]
        if picture_grid(pictures, 3, os.path.join(report, "fandisk_heavy_noise.png"), 1500):
            w("![our curves on fandisk under heavy noise](fandisk_heavy_noise.png)\n")
        w(f"*Our curves on the {points // 1000}k-point fandisk cloud with uniform noise in a ball of radius 1%, 2% "
          "and 5% of dB, default call.* The paper's Fig. 12 shows its curves on the Quarter Piston with uniform "
          "shifts of length up to 1% and 5% of dB: smooth feature lines at both levels, which completion fails to "
          "connect fully only at the higher one. "
          f"Ours at 5%: {heavy.get('ours_curves')} curves, {fmt(heavy.get('ours_length'), 2)} of "
          f"{fmt(heavy.get('ours_true_length'), 2)} units of true crease length, F1 {fmt(heavy.get('ours_f1@1'))} at "
          f"eps = 1% dB, in {secs(heavy['time_total'])} s.")
        part = os.path.splitext(os.path.basename(heavy["mesh"]))[0]
        diagonal = next((r["diagonal"] for r in truth_rows if r["label"] == part), None)
        if diagonal and heavy.get("scale_spacing"):
            # Uniform noise in a ball of radius rho has an RMS of rho / sqrt(5) along any direction.
            normal_rms = heavy["noise"] * diagonal / math.sqrt(5)
            w(f" There the noise band is {fmt(2 * heavy['noise'] * 100, 0)}% dB thick, and the noise along the normal "
              f"has an RMS of {fmt(normal_rms / heavy['scale_spacing'], 1)} spacings, but the noise estimate (from "
              f"the residuals of jets fitted to neighbourhoods widened towards 5 noise scales, at most 400 points: "
              f"at this noise they still lie inside the band and absorb it) "
              f"is {fmt(heavy['scale_noise'] / heavy['scale_spacing'], 2)} spacings. The neighbourhoods grown from "
              f"it hold {heavy['scale_candidate_neighbors']} and {heavy['scale_rmls_neighbors']} "
              f"{'means' if heavy.get('scale_search_fraction', 1) < 1 else 'points'}, about as "
              "wide as the band: the fits see a slab, not a surface (issue 11).")
        w("\n")

    # Repeatability.
    if repeat_rows:
        w("## 9. Repeatability\n")
        rows = []
        for r in repeat_rows:
            if r.get("status"):
                continue
            first = ours.get(split_label(r["label"]))
            same = [f for f in ACCURACY_FIELDS if first is not None and first.get(f) == r.get(f)]
            differ = [f for f in ACCURACY_FIELDS if first is not None and first.get(f) != r.get(f)]
            rows.append([r["label"], f"{len(same)} / {len(ACCURACY_FIELDS)}", ", ".join(differ) or "none",
                         f"{secs(first['time_total']) if first else '-'} / {secs(r['time_total'])}"])
        w(table(["configuration run twice", "accuracy figures identical", "differing", "times (s)"], rows))
        w("\nThe clouds depend only on the seed; accuracy figures must repeat exactly, times vary.\n")

    # Meshing (written after this report by scripts/bench_meshing.sh, full run only).
    if not quick:
        w("## 10. Feature-protected meshing\n")
        w("The last step of `scripts/bench.sh` runs `scripts/bench_meshing.sh`: each part is sampled "
          "(100k points, noise 0 and 0.5% dB), meshed by `mesh_with_sharp_features` with and without "
          "the extracted curves as Mesh_3 features, and both meshes are measured against the true mesh "
          "(distances, crease band, crease angles, triangle count, validity) and rendered with the same "
          "cameras. Tables and pictures: [meshing/MESHING.md](meshing/MESHING.md).\n")
        w("## 11. Surface patches\n")
        w("`scripts/bench_patches.sh` (run on its own, about 10 min) segments each part into the surface "
          "patches that its curves enclose (`CGAL::segment_into_patches()`, default call), at noise 0, 0.5% and "
          "1% and with 5% outliers, and scores them against the faces of the mesh (mean IoU, adjusted Rand "
          "index, patch counts). Tables and pictures: [patches/PATCHES.md](patches/PATCHES.md).\n")

    if scanner_rows:
        w(scanner_section(scanner_rows))

    # Self-test and failures.
    w("## Checks\n")
    for name in ("selftest_cube", "selftest_fandisk"):
        path = os.path.join(data, "logs", f"{name}.txt")
        if os.path.exists(path):
            lines = open(path).read().strip().splitlines()
            w(f"- Scoring self-test ({name.split('_')[1]}): {lines[-1] if lines else 'no output'} "
              "(perfect, shifted, partial, split and spurious fake curves with known scores).")
    if failures:
        w("- **Failed or timed-out runs**:\n")
        w(table(["label", "method", "status", "exit code"],
                [[f.get("label"), f.get("method"), f.get("status"), f.get("exit_code")] for f in failures]))
    else:
        w("- No run failed or timed out.")
    w("")

    with open(os.path.join(report, "REPORT.md"), "w") as f:
        f.write("\n".join(out))


def main():
    parser = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("--data")
    parser.add_argument("--report")
    parser.add_argument("--quick", action="store_true")
    parser.add_argument("--choose-vcm", metavar="SWEEP_JSONL")
    parser.add_argument("--scanner", metavar="SCANNER_JSONL", help="print the scanner-like inputs section alone")
    args = parser.parse_args()
    if args.choose_vcm:
        best, _ = choose_vcm(read_rows(args.choose_vcm))
        print(*best)
        return
    if args.scanner:
        print(scanner_section(read_rows(args.scanner)))
        return
    if not args.data or not args.report:
        parser.error("--data and --report are required")
    write_report(args.data, args.report, args.quick)


if __name__ == "__main__":
    sys.exit(main())

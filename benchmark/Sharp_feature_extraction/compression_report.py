#!/usr/bin/python3
"""Rate-distortion report of the point-cloud coder (scripts/bench_compression.sh).

    compression_report.py OUT_DIR NAME.csv...
    compression_report.py --shrink PICTURE.png...    (re-saves them as small optimized PNGs)

Each CSV holds rows partition,step,bpp,rms,grid_scale: those of `compress_point_cloud
--rate-distortion` (rms in bounding-box diagonals) for grids of grid_scale times the sampling
spacing. Writes OUT_DIR/rate_distortion.png (PSNR = 20 log10(1 / rms) dB against bits per
point, one panel per cloud, one curve per partition and grid) and prints a markdown table: for
every guided rate inside the traditional range of the same grid, the traditional rms at that
rate (interpolated linearly in log-rate) and the ratio guided / traditional.
"""
import csv
import math
import os
import sys

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402

# The target: guided rms at most this fraction of the traditional rms at the same rate.
TARGET_RATIO = 0.8


def read_curves(path):
    """{(partition, grid_scale): [(bpp, rms, step)] by rate}."""
    curves = {}
    with open(path) as f:
        for row in csv.DictReader(f):
            key = (row["partition"], row["grid_scale"])
            curves.setdefault(key, []).append((float(row["bpp"]), float(row["rms"]), float(row["step"])))
    for points in curves.values():
        points.sort()
    return curves


def interpolate_log_rate(curve, bpp):
    """The rms of `curve` at `bpp`, linear in log(bpp); None outside its range."""
    for (b0, r0, _), (b1, r1, _) in zip(curve, curve[1:]):
        if b0 <= bpp <= b1:
            t = 0 if b1 == b0 else (math.log(bpp) - math.log(b0)) / (math.log(b1) - math.log(b0))
            return r0 + t * (r1 - r0)
    return None


def shrink(paths):
    """The renderer writes uncompressed PNGs: palette of 64 colours, optimized (about 10 times smaller)."""
    from PIL import Image
    for path in paths:
        Image.open(path).convert("RGB").quantize(colors=64).save(path, optimize=True)


def main():
    if sys.argv[1] == "--shrink":
        shrink(sys.argv[2:])
        return
    out_dir, paths = sys.argv[1], sys.argv[2:]
    figure, axes = plt.subplots(1, len(paths), figsize=(5 * len(paths), 4), squeeze=False)
    print("| cloud | grid | guided bpp | guided rms (PSNR dB) | traditional rms at that rate (PSNR dB) | ratio | <= %.1f |"
          % TARGET_RATIO)
    print("|---|---|---|---|---|---|---|")
    met = compared = 0
    for panel, path in zip(axes[0], paths):
        name = os.path.splitext(os.path.basename(path))[0]
        curves = read_curves(path)
        scales = sorted({scale for _, scale in curves}, key=float)
        for scale in scales:
            for partition, style in (("traditional", "o-"), ("guided", "s--")):
                c = curves.get((partition, scale), [])
                panel.plot([b for b, _, _ in c], [20 * math.log10(1 / r) for _, r, _ in c], style,
                           label="%s, grid %s" % (partition, scale), markersize=3)
            for bpp, rms, _ in curves.get(("guided", scale), []):
                reference = interpolate_log_rate(curves.get(("traditional", scale), []), bpp)
                if reference is None:
                    continue
                ratio = rms / reference
                compared += 1
                met += ratio <= TARGET_RATIO
                print("| %s | %s | %.3f | %.3g (%.1f) | %.3g (%.1f) | %.2f | %s |" % (
                    name, scale, bpp, rms, 20 * math.log10(1 / rms), reference, 20 * math.log10(1 / reference),
                    ratio, "yes" if ratio <= TARGET_RATIO else "no"))
        panel.set_xscale("log")
        panel.set_xlabel("bits per input point")
        panel.set_ylabel("PSNR = 20 log10(dB / rms) [dB]")
        panel.set_title(name)
        panel.grid(True, which="both", alpha=0.3)
        panel.legend(fontsize=7)
    print("\n%d of %d guided rates inside the traditional range meet the target." % (met, compared))
    figure.tight_layout()
    figure.savefig(os.path.join(out_dir, "rate_distortion.png"), dpi=90)


if __name__ == "__main__":
    main()

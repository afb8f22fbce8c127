"""python3 -m sharp_features: a point cloud file in, sharp feature curves out.

    python3 -m sharp_features INPUT -o OUT.polylines.txt [--workers K | --scheduler ADDRESS] [--tiles N]

Without --workers, --scheduler or --tiles: the whole cloud in this process, untiled, the same
curves as the extract_sharp_features program (any of its formats: .xyz, .ply, .off, .las).
With --tiles N: tiled (sharp_features.tiling), in this process. With --workers K: tiled on a
dask.distributed LocalCluster of K worker processes on 127.0.0.1; with --scheduler ADDRESS, on
an existing cluster whose workers can read the input and the work directory. Tiled runs stream
.las and .ply inputs: no process holds the whole cloud. A progress bar is drawn on a terminal.
"""

import argparse
import contextlib
import dataclasses
import json
import logging
import os
import pathlib
import sys
import tempfile
import time

from . import _point_files
from . import _sharp_features
from . import tiling

PROGRAM = "python3 -m sharp_features"
# Tiles per worker when --tiles is not given: two keep a worker busy while the largest tile
# of another finishes, and keep each tile a fraction of what one process would hold.
TILES_PER_WORKER = 2
# Progress steps of the untiled bar: the extraction reports fractions of 1.
PROGRESS_STEPS = 1000

# The options of the extract_sharp_features program, and the keyword of extract() each sets.
OVERRIDES = [
    ("--candidate-neighbors", "candidate_neighbors", int, "stage-1 neighbourhood size"),
    ("--rmls-neighbors", "rmls_neighbors", int, "stage-2 neighbourhood size"),
    ("--threshold", "threshold_distance", float, "stage-1 residual threshold (distance)"),
    ("--rmls-tolerance", "rmls_tolerance", float, "stage-2 residual tolerance (distance)"),
    ("--sharpness-angle", "sharpness_angle", float, "smallest angle between the normals of two surfaces"),
    ("--corner-radius", "corner_radius", float, "corner points closer than this are one corner"),
    ("--growth-radius", "growth_radius", float, "polyline growing radius"),
    ("--completion-distance", "completion_distance", float, "largest gap bridged by completion"),
    ("--smoothing-passes", "number_of_iterations", int, "stage-3 passes"),
]


def parse_arguments(argv):
    parser = argparse.ArgumentParser(prog=PROGRAM, description=__doc__.split("\n\n")[0])
    parser.add_argument("input", help="point cloud: .xyz, .ply, .off or .las (tiled runs: .las or .ply)")
    parser.add_argument("-o", "--output", required=True, help="curves in Mesh_3's polyline format")
    cluster = parser.add_mutually_exclusive_group()
    cluster.add_argument("--workers", type=int, metavar="K", help="start a LocalCluster of K worker processes")
    cluster.add_argument("--scheduler", metavar="ADDRESS", help="use the dask cluster of this scheduler")
    parser.add_argument("--tiles", type=int, metavar="N",
                        help=f"at least N tiles (default with a cluster: {TILES_PER_WORKER} per worker)")
    parser.add_argument("--work-dir", type=pathlib.Path,
                        help="directory of the tile files, kept (default: a temporary one beside OUTPUT)")
    parser.add_argument("--threads", type=int,
                        help="threads per extraction (default: all cores, shared among the workers of --workers)")
    parser.add_argument("--report", type=pathlib.Path, help="also write what was measured as JSON")
    parser.add_argument("--quiet", action="store_true", help="no progress bar and no summary")
    for option, keyword, kind, description in OVERRIDES:
        parser.add_argument(option, dest=keyword, type=kind, help=description)
    arguments = parser.parse_args(argv)
    for name in ("workers", "tiles", "threads"):
        value = getattr(arguments, name)
        if value is not None and value < 1:
            parser.error(f"--{name} must be at least 1")
    return arguments


def show_progress(arguments):
    return not arguments.quiet and sys.stderr.isatty()


def progress_bars(arguments):
    """The tiled passes' bars: tqdm on a terminal, nothing otherwise."""
    if not show_progress(arguments):
        return tiling.no_progress_bar
    from tqdm import tqdm

    return lambda description, total: tqdm(total=total, desc=description, unit="task", file=sys.stderr)


def extraction_parameters(arguments):
    parameters = {keyword: getattr(arguments, keyword) for _, keyword, _, _ in OVERRIDES}
    parameters = {k: v for k, v in parameters.items() if v is not None}
    if arguments.threads is not None:
        parameters["threads"] = arguments.threads
    elif arguments.workers is not None:
        # The workers of a LocalCluster share this machine's cores.
        parameters["threads"] = max(1, (os.cpu_count() or 1) // arguments.workers)
    return parameters


def run_untiled(arguments, parameters):
    points = _point_files.read_point_cloud(arguments.input)
    if len(points) == 0:
        raise ValueError(f"'{arguments.input}' contains no points")
    if not show_progress(arguments):
        return _sharp_features.extract(points, **parameters), {"points": len(points)}
    from tqdm import tqdm

    with tqdm(total=PROGRESS_STEPS, desc="extracting", file=sys.stderr) as bar:
        result = _sharp_features.extract(points, progress=lambda f: bar.update(int(f * PROGRESS_STEPS) - bar.n),
                                         **parameters)
    return result, {"points": len(points)}


@contextlib.contextmanager
def executor_for(arguments):
    """The executor of the tiled passes: this process, a new LocalCluster or a scheduler's."""
    if arguments.workers is None and arguments.scheduler is None:
        yield tiling.Executor()
        return
    from distributed import Client, LocalCluster

    if arguments.scheduler is not None:
        with Client(arguments.scheduler) as client:
            yield tiling.DaskExecutor(client)
        return
    with LocalCluster(n_workers=arguments.workers, threads_per_worker=1, processes=True, host="127.0.0.1",
                      dashboard_address=None, silence_logs=logging.ERROR) as cluster, Client(cluster) as client:
        yield tiling.DaskExecutor(client)


def run_tiled(arguments, parameters):
    with executor_for(arguments) as executor, contextlib.ExitStack() as stack:
        work_dir = arguments.work_dir
        if work_dir is None:
            parent = pathlib.Path(arguments.output).resolve().parent
            work_dir = pathlib.Path(stack.enter_context(tempfile.TemporaryDirectory(prefix=".sharp_features_tiles_",
                                                                                    dir=parent)))
        else:
            work_dir.mkdir(parents=True, exist_ok=True)
            if any(work_dir.iterdir()):
                raise ValueError(f"the work directory '{work_dir}' is not empty")
        tiles = arguments.tiles or TILES_PER_WORKER * executor.workers
        run = tiling.TiledRun(progress_bar=progress_bars(arguments))
        result = tiling.extract_file_tiled(arguments.input, tiles, work_dir, executor, parameters, run)
        report = dataclasses.asdict(run)
        del report["progress_bar"]
        report["workers"] = executor.workers
        return result, report


def summary(result, report, seconds):
    lines = [f"points            {report['points']}",
             f"curves            {len(result.polylines)}",
             f"corners           {len(result.corners)}"]
    if "tiles" in report:
        lines.append(f"tiles             {report['tiles_with_points']} with points of {report['tiles']}, "
                     f"halo {report['halo_width']:.6g} (tiles read {report['extracted_points']} points), "
                     f"largest {report['largest_tile_points']} points")
        lines.append("time [s]          " + ", ".join(f"{k} {v:.2f}" for k, v in report["seconds"].items()))
        memory = ", ".join(f"{k} {v / 2**20:.0f}" for k, v in sorted(report["peak_memory"].items()))
        lines.append(f"peak memory [MB]  {memory}")
    lines.append(f"total [s]         {seconds:.2f}")
    return "\n".join(lines)


def main(argv=None):
    arguments = parse_arguments(argv)
    parameters = extraction_parameters(arguments)
    started = time.perf_counter()
    try:
        tiled = arguments.tiles is not None or arguments.workers is not None or arguments.scheduler is not None
        if tiled and pathlib.Path(arguments.input).suffix.lower() not in (".las", ".ply"):
            raise ValueError(f"tiled runs stream .las and .ply files, not '{arguments.input}'")
        result, report = (run_tiled if tiled else run_untiled)(arguments, parameters)
        result.write_polylines(arguments.output)
    except (OSError, ValueError, TypeError, _sharp_features.Cancelled) as error:
        print(f"{PROGRAM}: {error}", file=sys.stderr)
        return 1
    seconds = time.perf_counter() - started
    report["total_seconds"] = seconds
    if arguments.report is not None:
        arguments.report.write_text(json.dumps(report, indent=2) + "\n")
    if not arguments.quiet:
        print(summary(result, report, seconds))
    return 0


if __name__ == "__main__":
    sys.exit(main())

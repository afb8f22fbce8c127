"""Tiled extraction of a point cloud file that no process holds whole.

The cloud's bounding box is cut into a grid of tiles (`TileGrid`). Three passes of tasks,
which an `Executor` runs in this process or on a dask.distributed cluster:

1. binning: each task streams a range of the input file (`PointReader`) and appends every
   point to the file of its tile (its core box), `core_T/part_R.f64` (float64 x, y, z rows);
2. halos: once the scales are estimated on the most populated tile (a whole tile keeps the
   sampling density, which the scales follow), each task reads one tile's files and appends
   every point that lies within the halo width of another tile's core box to that tile's
   `halo_T/from_S.f64`: each point ends up in every tile whose core plus halo contains it;
3. extraction: each task reads one tile's core and halo files and calls `extract_tile`.

The client stitches the tiles' results (`stitch_tiles`). A task holds at most one tile and
one chunk of the input; the files live in a work directory that every worker can read (the
same machine, or a shared file system).
"""

import contextlib
import dataclasses
import itertools
import math
import os
import pathlib
import resource
import time

import numpy as np

from . import _point_files
from . import _sharp_features

# Points decoded per read of the input: 24 MB of float64, small beside a tile.
CHUNK_POINTS = 1 << 20
# Binning tasks per worker: two let a worker start its second range while the slowest first
# range still runs, without cutting the file into ranges too small to amortise a task.
BINNING_TASKS_PER_WORKER = 2
# The keywords of python3 -m sharp_features that each tiled function takes (the others refuse
# the rest): the scales are estimated once, the tiles run stages 1 to 3, the stitching stage 5.
SCALE_KEYWORDS = {"candidate_neighbors", "rmls_neighbors", "threshold_distance", "rmls_tolerance", "corner_radius",
                  "growth_radius", "completion_distance", "degree_fitting", "threads"}
HALO_KEYWORDS = {"number_of_iterations"}
TILE_KEYWORDS = {"degree_fitting", "sharpness_angle", "number_of_iterations", "threads"}
STITCH_KEYWORDS = {"maximum_angle", "number_of_relaxation_steps"}


def keywords_among(parameters, accepted):
    return {k: v for k, v in parameters.items() if k in accepted}


@dataclasses.dataclass(frozen=True)
class TileGrid:
    """A grid of `counts` tiles, of `size` each, from `low`: tile (i, j, k) has the half-open
    core box [low + (i, j, k) * size, low + (i + 1, j + 1, k + 1) * size), whose faces on the
    border of the grid are pushed to infinity (as extract_tiled's are), so that every point has
    a tile even where a LAS header's bounds are too small. Tiles are numbered
    i + counts[0] * (j + counts[1] * k)."""

    low: tuple
    size: tuple
    counts: tuple

    @classmethod
    def covering(cls, low, high, tiles):
        """The grid of at least `tiles` tiles over the box [low, high]: the side of the tiles
        that is the longest is halved (in count, doubled) until there are enough, so that
        tiles stay close to cubes whatever the shape of the box."""
        low, high = np.asarray(low, dtype=float), np.asarray(high, dtype=float)
        counts = [1, 1, 1]
        while math.prod(counts) < tiles:
            axis = max(range(3), key=lambda a: (high[a] - low[a]) / counts[a])
            counts[axis] += 1
        # An axis without extent (a planar cloud) has one tile, of any size: its faces are infinite.
        size = np.where(high > low, (high - low) / counts, 1.0)
        return cls(tuple(low.tolist()), tuple(size.tolist()), tuple(counts))

    @property
    def tile_count(self):
        return math.prod(self.counts)

    def _cells(self, points, shift=0.0):
        """Per axis, the tile index of each point moved by `shift`, clamped to the grid."""
        cells = np.floor((points + shift - np.asarray(self.low)) / np.asarray(self.size)).astype(np.int64)
        return np.clip(cells, 0, np.asarray(self.counts) - 1)

    def _flat(self, cells):
        return cells[:, 0] + self.counts[0] * (cells[:, 1] + self.counts[1] * cells[:, 2])

    def tile_of(self, points):
        """The tile that owns each point (points outside the grid go to the nearest tile)."""
        return self._flat(self._cells(points))

    def core_box(self, tile):
        """(box_min, box_max) of the core of `tile`, as lists of three floats (infinite on the
        border of the grid)."""
        cell = (tile % self.counts[0], (tile // self.counts[0]) % self.counts[1], tile // (self.counts[0] * self.counts[1]))
        box_min = [-math.inf if c == 0 else self.low[a] + c * self.size[a] for a, c in enumerate(cell)]
        box_max = [math.inf if c + 1 == self.counts[a] else self.low[a] + (c + 1) * self.size[a]
                   for a, c in enumerate(cell)]
        return box_min, box_max

    def halo_tiles(self, points, halo):
        """Pairs (point indices, tile) for every tile other than its own whose core box, grown
        by `halo` along each axis, contains a point."""
        first, last = self._cells(points, -halo), self._cells(points, halo)
        own = self.tile_of(points)
        span = int(np.max(last - first)) + 1 if len(points) else 0
        for offset in itertools.product(range(span), repeat=3):
            cells = first + np.asarray(offset)
            inside = np.all(cells <= last, axis=1)
            tiles = self._flat(cells)
            for tile in np.unique(tiles[inside & (tiles != own)]):
                yield np.flatnonzero(inside & (tiles == tile)), int(tile)


def peak_memory_bytes():
    """The peak resident memory of this process so far (Linux reports kilobytes)."""
    return resource.getrusage(resource.RUSAGE_SELF).ru_maxrss * 1024


@dataclasses.dataclass
class TaskReport:
    """What every task returns besides its result: which process ran it, that process's peak
    memory so far, and the CPU time of the task (all its threads): unlike the wall time, it
    does not grow when other jobs share the machine."""

    process: str
    peak_memory: int
    cpu_seconds: float

    @classmethod
    def here(cls, cpu_started):
        """The report of a task that started when time.process_time() was `cpu_started`."""
        return cls(f"{os.uname().nodename}:{os.getpid()}", peak_memory_bytes(), time.process_time() - cpu_started)


def _append(path, points):
    path.parent.mkdir(parents=True, exist_ok=True)
    with open(path, "ab") as f:
        points.tofile(f)


def _read_rows(path):
    return np.fromfile(path, dtype=np.float64).reshape(-1, 3)


def read_tile_files(directory):
    """The points of every .f64 file of `directory` (sorted by name), as one (N, 3) array."""
    files = sorted(pathlib.Path(directory).glob("*.f64"))
    if not files:
        return np.empty((0, 3))
    return np.concatenate([_read_rows(f) for f in files])


def bin_range(source, first, count, grid, work_dir, part):
    """Binning task: appends points `first` to `first + count` of `source` to the files of
    their tiles, `work_dir/core_T/part_<part>.f64`. Returns (per-tile point counts, TaskReport)."""
    cpu_started = time.process_time()
    reader = _point_files.PointReader(source)
    if first:
        reader.seek(first)
    counts = np.zeros(grid.tile_count, dtype=np.int64)
    remaining = count
    while remaining > 0:
        chunk = reader.read(min(CHUNK_POINTS, remaining))
        if len(chunk) == 0:
            raise ValueError(f"'{source}' ends {remaining} points before the count of its header")
        remaining -= len(chunk)
        tiles = grid.tile_of(chunk)
        order = np.argsort(tiles, kind="stable")
        present, starts = np.unique(tiles[order], return_index=True)
        for tile, rows in zip(present, np.split(order, starts[1:])):
            points = chunk[rows]
            _append(pathlib.Path(work_dir) / f"core_{tile}" / f"part_{part:06d}.f64", points)
            counts[tile] += len(points)
    return counts, TaskReport.here(cpu_started)


def write_halos(tile, grid, halo, work_dir):
    """Halo task: appends every point of `tile`'s core that another tile needs (within `halo`
    of its core box) to `work_dir/halo_<other>/from_<tile>.f64`. Returns TaskReport."""
    cpu_started = time.process_time()
    points = read_tile_files(pathlib.Path(work_dir) / f"core_{tile}")
    for rows, other in grid.halo_tiles(points, halo):
        _append(pathlib.Path(work_dir) / f"halo_{other}" / f"from_{tile:06d}.f64", points[rows])
    return TaskReport.here(cpu_started)


def extract_tile_files(tile, box_min, box_max, scales, work_dir, parameters):
    """Extraction task: `extract_tile` on the core and halo points of `tile`. Returns
    (TileResult, number of points read, TaskReport)."""
    cpu_started = time.process_time()
    work_dir = pathlib.Path(work_dir)
    points = np.concatenate([read_tile_files(work_dir / f"core_{tile}"), read_tile_files(work_dir / f"halo_{tile}")])
    # The order of the files depends on how the input was cut into binning ranges, hence on the
    # number of workers; sorted, a tile's points are the same array whatever ran the passes.
    points = points[np.lexsort(points.T[::-1])]
    result = _sharp_features.extract_tile(points, box_min, box_max, scales, **keywords_among(parameters, TILE_KEYWORDS))
    return result, len(points), TaskReport.here(cpu_started)


class Executor:
    """Runs the tasks of a pass in this process, one after the other."""

    workers = 1

    def map(self, function, arguments, progress):
        """`function(*a)` for each tuple `a` of `arguments`, results in the same order;
        `progress()` is called once per finished task."""
        results = []
        for a in arguments:
            results.append(function(*a))
            progress()
        return results


class DaskExecutor(Executor):
    """Runs the tasks of a pass on the workers of a dask.distributed client."""

    def __init__(self, client):
        self.client = client
        self.workers = max(1, len(client.scheduler_info()["workers"]))

    def map(self, function, arguments, progress):
        from distributed import as_completed

        futures = [self.client.submit(function, *a, pure=False) for a in arguments]
        for _ in as_completed(futures):
            progress()
        return self.client.gather(futures)


@dataclasses.dataclass
class TiledRun:
    """What a tiled extraction measured, for the summary and the benchmark."""

    points: int = 0
    tiles: int = 0
    tiles_with_points: int = 0
    halo_width: float = 0.0
    largest_tile_points: int = 0
    # Points the extraction tasks read, halos included: above `points` by the halos' share.
    extracted_points: int = 0
    seconds: dict = dataclasses.field(default_factory=dict)  # pass -> wall seconds
    cpu_seconds: dict = dataclasses.field(default_factory=dict)  # pass -> CPU seconds of its tasks
    peak_memory: dict = dataclasses.field(default_factory=dict)  # process -> bytes

    # Makes a context manager with an `update()` method, called once per finished task, from
    # (description, number of tasks): a tqdm bar, or `no_progress_bar`.
    progress_bar: object = None

    def run_pass(self, executor, name, function, arguments):
        """The tasks `function(*a)` of one pass, timed; their TaskReports recorded."""
        started = time.perf_counter()
        with (self.progress_bar or no_progress_bar)(name, len(arguments)) as bar:
            results = executor.map(function, arguments, bar.update)
        self.seconds[name] = time.perf_counter() - started
        reports = [r if isinstance(r, TaskReport) else r[-1] for r in results]
        self.cpu_seconds[name] = sum(r.cpu_seconds for r in reports)
        for r in reports:
            self.peak_memory[r.process] = max(self.peak_memory.get(r.process, 0), r.peak_memory)
        return results


class _NoBar:
    def update(self, n=1):
        pass


def no_progress_bar(description, total):
    """A progress bar that shows nothing."""
    return contextlib.nullcontext(_NoBar())


def binning_ranges(reader, workers):
    """(first, count) ranges of the input for the binning tasks: one per PLY file (its records
    cannot be located without reading them), several per worker for LAS."""
    if reader.format != "las":
        return [(0, reader.count)]
    ranges = max(1, min(BINNING_TASKS_PER_WORKER * workers, math.ceil(reader.count / CHUNK_POINTS)))
    step = math.ceil(reader.count / ranges)
    return [(first, min(step, reader.count - first)) for first in range(0, reader.count, step)]


def bin_file(source, tiles, work_dir, executor, run):
    """Pass 1: the grid of at least `tiles` tiles over the LAS or PLY file `source`, and its
    points binned into `work_dir/core_T/`. Returns (grid, the binning tasks' results)."""
    started = time.perf_counter()
    reader = _point_files.PointReader(source)
    run.points = reader.count
    bounds = reader.bounds or _bounds_by_reading(reader)
    grid = TileGrid.covering(bounds[0], bounds[1], tiles)
    run.tiles = grid.tile_count
    ranges = binning_ranges(reader, executor.workers)
    run.seconds["bounds"] = time.perf_counter() - started
    binned = run.run_pass(executor, "binning", bin_range,
                          [(str(source), first, count, grid, str(work_dir), part)
                           for part, (first, count) in enumerate(ranges)])
    return grid, binned


def spread_halos(grid, occupied, halo, work_dir, executor, run):
    """Pass 2: the points of the `occupied` tiles that other tiles need, into their halos."""
    run.halo_width = halo
    run.run_pass(executor, "halos", write_halos, [(t, grid, halo, str(work_dir)) for t in occupied])


def extract_file_tiled(source, tiles, work_dir, executor, parameters, run):
    """Tiled extraction of the LAS or PLY file `source` with at least `tiles` tiles: the three
    passes, the scales estimated on the most populated tile between the first two, and the
    tiles stitched. Returns the Result; `run` (a TiledRun) receives what was measured."""
    work_dir = pathlib.Path(work_dir)
    grid, binned = bin_file(source, tiles, work_dir, executor, run)
    counts = sum(b[0] for b in binned)

    started, cpu_started = time.perf_counter(), time.process_time()
    largest = int(np.argmax(counts))
    run.largest_tile_points = int(counts[largest])
    scales = _sharp_features.estimate_scales(read_tile_files(work_dir / f"core_{largest}"),
                                             **keywords_among(parameters, SCALE_KEYWORDS))
    run.seconds["scales"], run.cpu_seconds["scales"] = time.perf_counter() - started, time.process_time() - cpu_started
    run.peak_memory["client after the scales"] = peak_memory_bytes()

    occupied = [int(t) for t in np.flatnonzero(counts)]
    run.tiles_with_points = len(occupied)
    spread_halos(grid, occupied, _sharp_features.tile_halo_width(scales, **keywords_among(parameters, HALO_KEYWORDS)),
                 work_dir, executor, run)
    extracted = run.run_pass(executor, "extraction", extract_tile_files,
                             [(t, *grid.core_box(t), scales, str(work_dir), parameters) for t in occupied])
    run.extracted_points = sum(e[1] for e in extracted)

    started, cpu_started = time.perf_counter(), time.process_time()
    result = _sharp_features.stitch_tiles([e[0] for e in extracted], **keywords_among(parameters, STITCH_KEYWORDS))
    run.seconds["stitching"] = time.perf_counter() - started
    run.cpu_seconds["stitching"] = time.process_time() - cpu_started
    run.peak_memory["client"] = peak_memory_bytes()
    return result


def _bounds_by_reading(reader):
    """The bounding box of the points of `reader`, read a chunk at a time (PLY headers have
    none); leaves the reader at its end."""
    low, high = np.full(3, np.inf), np.full(3, -np.inf)
    while len(chunk := reader.read(CHUNK_POINTS)):
        low, high = np.minimum(low, chunk.min(axis=0)), np.maximum(high, chunk.max(axis=0))
    if not np.all(low <= high):
        raise ValueError("the file holds no points")
    return low, high

"""python3 -m sharp_features and its tiled passes (sharp_features.tiling): the binning and
halo passes put every point in the files of exactly the tiles whose core plus halo contains
it; a dask LocalCluster of 2 worker processes on 127.0.0.1 bins the same points and extracts
the same curves as this process, through the API and through the module's --scheduler; the
untiled run writes the extract_sharp_features program's curves; bad inputs end the program
with one line."""

import logging
import os
import subprocess
import sys

import numpy as np
import pytest

import sharp_features
from sharp_features import tiling

# Tiles of the test cube: 2 x 2 x 1, so that every tile has neighbours along two axes.
TILES = 4
# A halo of a tenth of the cube's side: every tile then has points of three others.
HALO = 0.1


def rows(points):
    """The rows of `points` as a set of tuples (the tile files hold them in any order)."""
    return set(map(tuple, np.asarray(points).tolist()))


@pytest.fixture(scope="module")
def cube_las(tmp_path_factory, cube):
    path = tmp_path_factory.mktemp("cloud") / "cube.las"
    sharp_features.write_las(path, cube)
    return path


@pytest.fixture(scope="module")
def client():
    """A dask.distributed LocalCluster of 2 worker processes on the loopback interface."""
    distributed = pytest.importorskip("distributed")
    with distributed.LocalCluster(n_workers=2, threads_per_worker=1, processes=True, host="127.0.0.1",
                                  dashboard_address=None, silence_logs=logging.ERROR) as cluster:
        with distributed.Client(cluster) as c:
            yield c


def bin_with_halos(source, executor, work_dir):
    run = tiling.TiledRun()
    grid, binned = tiling.bin_file(source, TILES, work_dir, executor, run)
    occupied = [int(t) for t in np.flatnonzero(sum(b[0] for b in binned))]
    tiling.spread_halos(grid, occupied, HALO, work_dir, executor, run)
    return grid, binned, occupied, run


def tile_contents(work_dir, occupied):
    return {t: (rows(tiling.read_tile_files(work_dir / f"core_{t}")), rows(tiling.read_tile_files(work_dir / f"halo_{t}")))
            for t in occupied}


def test_the_grid_splits_the_longest_side_until_there_are_enough_tiles():
    assert tiling.TileGrid.covering([0, 0, 0], [4, 2, 1], 2).counts == (2, 1, 1)
    assert tiling.TileGrid.covering([0, 0, 0], [4, 2, 1], 8).counts == (4, 2, 1)
    assert tiling.TileGrid.covering([0, 0, 0], [1, 1, 1], 5).counts == (2, 2, 2)
    assert tiling.TileGrid.covering([0, 0, 0], [0, 0, 0], 1).counts == (1, 1, 1)


def test_each_point_is_in_its_tile_and_in_the_halo_of_every_tile_whose_grown_box_holds_it(cube_las, tmp_path):
    grid, _, occupied, run = bin_with_halos(cube_las, tiling.Executor(), tmp_path)
    points = sharp_features.read_point_cloud(cube_las)
    assert run.points == len(points) and grid.tile_count == TILES and len(occupied) == TILES
    contents = tile_contents(tmp_path, occupied)
    assert sum(len(core) for core, _ in contents.values()) == len(points)
    for t, (core, halo) in contents.items():
        low, high = (np.asarray(b) for b in grid.core_box(t))
        in_core = np.all((points >= low) & (points < high), axis=1)
        in_grown = np.all((points >= low - HALO) & (points < high + HALO), axis=1)
        assert core == rows(points[in_core])
        assert halo == rows(points[in_grown & ~in_core])
        assert halo, "every tile of the cube has neighbours within the halo"


def test_a_cluster_of_two_worker_processes_bins_the_same_points_as_this_process(cube_las, tmp_path, client):
    here, there = tmp_path / "here", tmp_path / "there"
    _, _, occupied, _ = bin_with_halos(cube_las, tiling.Executor(), here)
    _, _, occupied_there, run = bin_with_halos(cube_las, tiling.DaskExecutor(client), there)
    assert occupied_there == occupied
    assert tile_contents(there, occupied) == tile_contents(here, occupied)
    workers = [p for p in run.peak_memory if p != "client"]
    assert len(workers) == 2 and all(str(os.getpid()) not in p for p in workers), "the tasks ran in the workers"


def test_two_worker_processes_extract_the_same_curves_as_this_process(cube_las, tmp_path, client, monkeypatch):
    # Small binning ranges, so that the workers bin the cube in several (in this process: 2 ranges;
    # on the cluster: 4), and the tile files hold their points in other orders.
    monkeypatch.setattr(tiling, "CHUNK_POINTS", 1000)
    here = tiling.extract_file_tiled(cube_las, TILES, tmp_path / "here", tiling.Executor(), {}, tiling.TiledRun())
    run = tiling.TiledRun()
    there = tiling.extract_file_tiled(cube_las, TILES, tmp_path / "there", tiling.DaskExecutor(client), {}, run)
    assert len(list((tmp_path / "there" / "core_0").iterdir())) > len(list((tmp_path / "here" / "core_0").iterdir()))
    assert len(here.polylines) == 12 and len(here.corners) == 8
    assert len(there.polylines) == len(here.polylines)
    assert all(np.array_equal(a, b) for a, b in zip(there.polylines, here.polylines))
    assert np.array_equal(there.corners, here.corners)


def test_a_binary_ply_input_is_streamed_and_tiled(cube, tmp_path):
    path = tmp_path / "cube.ply"
    header = f"ply\nformat binary_little_endian 1.0\nelement vertex {len(cube)}\n" \
             "property double x\nproperty double y\nproperty double z\nend_header\n"
    path.write_bytes(header.encode() + cube.astype("<f8").tobytes())
    run = tiling.TiledRun()
    result = tiling.extract_file_tiled(path, TILES, tmp_path / "tiles", tiling.Executor(), {}, run)
    assert (run.points, run.tiles) == (len(cube), TILES)
    assert (len(result.polylines), len(result.corners)) == (12, 8)


def run_module(*arguments):
    return subprocess.run([sys.executable, "-m", "sharp_features", *map(str, arguments)], capture_output=True,
                          text=True, env=dict(os.environ, PYTHONDONTWRITEBYTECODE="1"))


def test_the_untiled_module_writes_the_programs_curves(cube_las, extract_program, tmp_path):
    module, program = tmp_path / "module.polylines.txt", tmp_path / "program.polylines.txt"
    assert run_module(cube_las, "-o", module, "--quiet").returncode == 0
    subprocess.run([extract_program, cube_las, "-o", program, "--quiet"], check=True)
    assert module.read_text() == program.read_text()
    assert len(module.read_text().splitlines()) == 12


def test_the_module_on_a_scheduler_writes_the_curves_of_the_module_tiled_in_process(cube_las, client, tmp_path):
    here, there = tmp_path / "here.polylines.txt", tmp_path / "there.polylines.txt"
    assert run_module(cube_las, "-o", here, "--tiles", TILES, "--quiet").returncode == 0
    done = run_module(cube_las, "-o", there, "--scheduler", client.scheduler.address, "--tiles", TILES,
                      "--work-dir", tmp_path / "tiles", "--report", tmp_path / "report.json")
    assert done.returncode == 0, done.stderr
    assert there.read_text() == here.read_text()
    assert "tiles             4 with points of 4" in done.stdout
    assert len(list((tmp_path / "tiles").glob("core_*"))) == TILES, "--work-dir keeps the tile files"


@pytest.mark.parametrize("arguments, message", [
    (["missing.las"], "No such file or directory"),
    (["cloud.xyz", "--tiles", "2"], "tiled runs stream .las and .ply files"),
    (["bad.las"], "not a LAS file"),
])
def test_bad_inputs_end_the_module_with_one_line(tmp_path, arguments, message):
    (tmp_path / "cloud.xyz").write_text("0 0 0\n")
    (tmp_path / "bad.las").write_bytes(b"LASX" + bytes(400))
    done = run_module(*[tmp_path / a if a.endswith(("las", "xyz")) else a for a in arguments],
                      "-o", tmp_path / "out.txt")
    assert done.returncode == 1
    assert message in done.stderr and done.stderr.count("\n") == 1

"""Tiled extraction from Python: estimate_scales(), tile_halo_width(), extract_tile() (its result
pickled, as Dask sends it), stitch_tiles() and extract_tiled() give the curves of extract() run
with the tiled threshold, in any order of the tiles."""

import pickle

import numpy as np
import pytest

import sharp_features


def same_curves(a, b):
    """Whether two results have exactly the same polylines and corners (in the same order: the
    stitched curves come in the order of the untiled run's)."""
    return (len(a.polylines) == len(b.polylines)
            and all(np.array_equal(p, q) for p, q in zip(a.polylines, b.polylines))
            and np.array_equal(a.corners, b.corners))


def sorted_curves(result):
    """The polylines as sorted tuples of vertices (order and direction left out)."""
    return sorted(tuple(sorted(map(tuple, p))) for p in result.polylines)


# Noise on the test cube, in its units: on exact planes a tile without its halo would fit the same
# planes as the whole cloud, and these tests would not see a missing halo.
NOISE = 0.002
NOISE_SEED = 2


@pytest.fixture(scope="module")
def noisy_cube(cube):
    return cube + np.random.default_rng(NOISE_SEED).uniform(-NOISE, NOISE, size=cube.shape)


@pytest.fixture(scope="module")
def scales(noisy_cube):
    return sharp_features.estimate_scales(noisy_cube)


@pytest.fixture(scope="module")
def untiled(noisy_cube, scales):
    return sharp_features.extract(noisy_cube, threshold_distance=scales["residual_threshold"])


def slabs(points, scales, count, halo=None):
    """The cube cut into `count` slabs along x, each extracted with `halo` (default: the tile
    halo width) and pickled."""
    if halo is None:
        halo = sharp_features.tile_halo_width(scales)
    cuts = np.concatenate(([-np.inf], np.linspace(-0.5, 0.5, count + 1)[1:-1], [np.inf]))
    tiles = []
    for low, high in zip(cuts[:-1], cuts[1:]):
        inside = (points[:, 0] >= low - halo) & (points[:, 0] < high + halo)
        tile = sharp_features.extract_tile(points[inside], (low, -np.inf, -np.inf), (high, np.inf, np.inf), scales)
        tiles.append(pickle.loads(pickle.dumps(tile)))
    return tiles


def test_the_scales_carry_the_tiled_threshold(scales):
    assert scales["residual_threshold"] > 0
    assert sharp_features.tile_halo_width(scales) > scales["candidate_radius"]
    assert sharp_features.tile_halo_width(scales, number_of_iterations=0) < sharp_features.tile_halo_width(scales)


def test_pickled_tiles_stitch_into_the_untiled_curves_in_any_order(noisy_cube, scales, untiled):
    tiles = slabs(noisy_cube, scales, 3)
    assert sum(len(t.state["edge_points"]) for t in tiles) > 0
    forward = sharp_features.stitch_tiles(tiles)
    backward = sharp_features.stitch_tiles(tiles[::-1])
    assert same_curves(forward, backward)
    assert sorted_curves(forward) == sorted_curves(untiled)
    assert len(forward.polylines) == 12 and forward.corners.shape == (8, 3)


def test_without_the_halo_the_stitched_curves_differ(noisy_cube, scales, untiled):
    assert sorted_curves(sharp_features.stitch_tiles(slabs(noisy_cube, scales, 3, halo=0))) != sorted_curves(untiled)


def test_extract_tiled_gives_the_untiled_curves(noisy_cube, untiled):
    tiled = sharp_features.extract_tiled(noisy_cube, tiles=8, threads=1)
    assert sorted_curves(tiled) == sorted_curves(untiled)
    assert tiled.patches.shape == (0,)


def test_a_tile_state_round_trips_exactly(cube, scales):
    tile = slabs(cube, scales, 2)[0]
    copy = pickle.loads(pickle.dumps(tile))
    for key, value in tile.state.items():
        if isinstance(value, np.ndarray):
            assert np.array_equal(value, copy.state[key]), key
        else:
            assert value == copy.state[key], key


def test_bad_tiles_and_keywords_are_rejected(cube, scales):
    with pytest.raises(ValueError):
        sharp_features.extract_tile(cube, (0, 0, 0), (0, 1, 1), scales)
    with pytest.raises(TypeError, match="extract_tile"):
        sharp_features.extract_tile(cube, (0, 0, 0), (1, 1, 1), scales, growth_radius=0.1)
    with pytest.raises(ValueError, match="scales"):
        sharp_features.tile_halo_width({"spacing": 1.0})
    for name, value in (("sampled_fraction", 0.0), ("sampled_fraction", 1.5), ("search_fraction", 0.0),
                        ("search_fraction", 1.5), ("growth_radius", float("nan")), ("spacing", -1.0)):
        with pytest.raises(ValueError, match="scales." + name):
            sharp_features.tile_halo_width(dict(scales, **{name: value}))
    tile = slabs(cube, scales, 2)[0]
    with pytest.raises(ValueError, match="overlap"):
        sharp_features.stitch_tiles([tile, tile])
    with pytest.raises(TypeError):
        sharp_features.stitch_tiles([tile, "not a tile"])


def test_progress_reaches_one_and_cancels(cube, scales):
    values = []
    sharp_features.extract_tile(cube, (-np.inf,) * 3, (np.inf,) * 3, scales, progress=values.append)
    assert values and values[-1] == 1.0 and values == sorted(values)
    with pytest.raises(sharp_features.Cancelled):
        sharp_features.extract_tiled(cube, tiles=2, progress=lambda x: x < 0.5)

"""sharp_features.extract(): inputs, parameters, threads, progress and cancellation."""

import os
import signal
import threading
import tracemalloc

import numpy as np
import pytest

import sharp_features
from conftest import sample_cube_surface

CUBE_EDGES = 12
CUBE_CORNERS = 8


def same_curves(a, b):
    """Whether two results have exactly the same polylines, normals and corners."""
    return (len(a.polylines) == len(b.polylines)
            and all(np.array_equal(p, q) for p, q in zip(a.polylines, b.polylines))
            and all(np.array_equal(m, n) for m, n in zip(a.normals, b.normals))
            and np.array_equal(a.corners, b.corners))


@pytest.fixture(scope="module")
def cube_result(cube):
    return sharp_features.extract(cube)


def test_a_sampled_cube_yields_its_12_edges_and_8_corners(cube_result):
    assert len(cube_result.polylines) == CUBE_EDGES
    assert cube_result.corners.shape == (CUBE_CORNERS, 3)


def test_float32_and_non_contiguous_arrays_give_the_curves_of_the_float64_array(cube, cube_result):
    fortran_order = np.asfortranarray(cube)
    interleaved = np.empty((len(cube), 6))
    interleaved[:, ::2] = cube
    strided = interleaved[:, ::2]
    assert not strided.flags.c_contiguous and not fortran_order.flags.c_contiguous
    assert same_curves(sharp_features.extract(fortran_order), cube_result)
    assert same_curves(sharp_features.extract(strided), cube_result)
    single = cube.astype(np.float32)
    assert same_curves(sharp_features.extract(single), sharp_features.extract(single.astype(np.float64)))


# Enough points that a copy of the array outweighs the arrays of the result.
COPY_CHECK_POINTS = 50_000


def numpy_memory_peak(function, *args):
    """The peak of the memory allocated by NumPy (which tracemalloc follows) while
    `function(*args)` runs; the library's own allocations are not counted."""
    tracemalloc.start()
    try:
        base = tracemalloc.get_traced_memory()[0]
        function(*args)
        return tracemalloc.get_traced_memory()[1] - base
    finally:
        tracemalloc.stop()


def test_a_c_contiguous_float64_array_is_read_in_place_and_others_are_converted_once():
    points = sample_cube_surface(COPY_CHECK_POINTS, seed=3)
    # The result holds one int64 patch label per point (Result.patches): a third of the points.
    labels = len(points) * np.dtype(np.int64).itemsize
    assert numpy_memory_peak(sharp_features.extract, points) < labels + points.nbytes / 4
    fortran_order = np.asfortranarray(points)
    assert points.nbytes + labels <= numpy_memory_peak(sharp_features.extract, fortran_order) < 2 * points.nbytes + labels


def test_a_list_of_triples_is_an_array(cube, cube_result):
    assert same_curves(sharp_features.extract(cube.tolist()), cube_result)


def test_the_number_of_threads_does_not_change_the_curves(cube, cube_result):
    assert same_curves(sharp_features.extract(cube, threads=1), cube_result)
    with pytest.raises(ValueError, match="threads"):
        sharp_features.extract(cube, threads=0)


def test_a_given_scale_replaces_the_derived_one(cube, cube_result):
    corner_radius = 0.5 * cube_result.scales["corner_radius"]
    result = sharp_features.extract(cube, corner_radius=corner_radius, candidate_neighbors=40)
    assert result.scales["corner_radius"] == corner_radius
    assert result.scales["candidate_neighbors"] == 40


def test_none_and_the_documented_defaults_give_the_default_curves(cube, cube_result):
    defaults = dict(degree_fitting=2, threshold_distance=-1, sharpness_angle=25, number_of_iterations=3,
                    maximum_angle=30, number_of_relaxation_steps=2, candidate_neighbors=0, rmls_neighbors=0,
                    rmls_tolerance=0, corner_radius=0, growth_radius=0, completion_distance=0)
    assert same_curves(sharp_features.extract(cube, **defaults), cube_result)
    assert same_curves(sharp_features.extract(cube, **{name: None for name in defaults}), cube_result)


def test_an_unknown_keyword_raises_type_error(cube):
    with pytest.raises(TypeError, match="unexpected keyword argument 'sharpness'"):
        sharp_features.extract(cube, sharpness=30)
    with pytest.raises(TypeError):
        sharp_features.extract(cube, 4)


def test_a_value_of_the_wrong_type_raises_type_error(cube):
    with pytest.raises(TypeError, match="number_of_iterations must be an integer"):
        sharp_features.extract(cube, number_of_iterations=2.5)
    with pytest.raises(TypeError, match="sharpness_angle must be a number"):
        sharp_features.extract(cube, sharpness_angle="30")
    with pytest.raises(TypeError, match="points"):
        sharp_features.extract("cube.xyz")


def test_a_parameter_out_of_range_raises_the_librarys_value_error(cube):
    with pytest.raises(ValueError, match="sharpness_angle must be in \\(0, 90\\) degrees"):
        sharp_features.extract(cube, sharpness_angle=95)
    with pytest.raises(ValueError, match="degree_fitting must be 1 or 2"):
        sharp_features.extract(cube, degree_fitting=3)
    with pytest.raises(ValueError, match="growth_radius must be a finite, non-negative distance"):
        sharp_features.extract(cube, growth_radius=float("nan"))
    with pytest.raises(ValueError, match="rmls_neighbors must be an integer in \\[0, "):
        sharp_features.extract(cube, rmls_neighbors=-1)


@pytest.mark.parametrize("value", [np.nan, np.inf])
def test_a_non_finite_coordinate_raises_value_error(cube, value):
    points = cube.copy()
    points[17, 2] = value
    with pytest.raises(ValueError, match="input point 17 has a non-finite coordinate"):
        sharp_features.extract(points)


@pytest.mark.parametrize("shape", [(100, 2), (100, 4), (300,), (10, 10, 3)])
def test_points_of_another_shape_raise_value_error(shape):
    with pytest.raises(ValueError, match="points must have shape \\(N, 3\\)"):
        sharp_features.extract(np.zeros(shape))


def test_too_few_points_yield_no_curves():
    result = sharp_features.extract(np.zeros((0, 3)))
    assert result.polylines == [] and result.corners.shape == (0, 3)


def test_progress_receives_increasing_fractions_up_to_1(cube):
    fractions = []
    sharp_features.extract(cube, progress=fractions.append)
    assert fractions and fractions == sorted(fractions)
    assert 0 <= fractions[0] and fractions[-1] == 1


def test_progress_returning_false_cancels(cube):
    fractions = []

    def half_way(fraction):
        fractions.append(fraction)
        return fraction < 0.5

    with pytest.raises(sharp_features.Cancelled):
        sharp_features.extract(cube, progress=half_way)
    assert fractions[-1] >= 0.5 and fractions[-2] < 0.5


def test_an_exception_in_progress_propagates(cube):
    def failing(fraction):
        raise ZeroDivisionError("from progress")

    with pytest.raises(ZeroDivisionError, match="from progress"):
        sharp_features.extract(cube, progress=failing)
    with pytest.raises(TypeError, match="progress must be callable"):
        sharp_features.extract(cube, progress=1)


@pytest.fixture
def python_handles_ctrl_c():
    """Python's own SIGINT handler, whatever this process inherited: a shell starts background
    jobs with SIGINT ignored, and Python then installs no handler of its own."""
    inherited = signal.signal(signal.SIGINT, signal.default_int_handler)
    yield
    signal.signal(signal.SIGINT, inherited)


def test_ctrl_c_in_progress_cancels(cube, python_handles_ctrl_c):
    calls = []

    def interrupted(fraction):
        calls.append(fraction)
        signal.raise_signal(signal.SIGINT)
        return True

    with pytest.raises(KeyboardInterrupt):
        sharp_features.extract(cube, progress=interrupted)
    assert len(calls) == 1


# Enough points that one thread takes about a second: the interrupt arrives while it computes.
INTERRUPTED_CLOUD_POINTS = 150_000
INTERRUPT_DELAY = 0.1  # seconds


def test_ctrl_c_cancels_without_progress_function(python_handles_ctrl_c):
    points = sample_cube_surface(INTERRUPTED_CLOUD_POINTS, seed=2)
    interrupt = threading.Timer(INTERRUPT_DELAY, os.kill, (os.getpid(), signal.SIGINT))
    interrupt.start()
    try:
        with pytest.raises(KeyboardInterrupt):
            sharp_features.extract(points, threads=1)
    finally:
        interrupt.cancel()
        interrupt.join()

"""Shared fixtures of the tests of the Python module sharp_features.

The module is imported from PYTHONPATH (scripts/test.sh puts build/python there). The tests
that compare with the command-line program find it through the environment variable
SFE_EXTRACT_PROGRAM (scripts/test.sh sets it), otherwise in build/, and are skipped without it.
"""

import os
import pathlib

import numpy as np
import pytest

REPOSITORY = pathlib.Path(__file__).resolve().parents[2]
DEFAULT_PROGRAM = REPOSITORY / "build" / "examples" / "Sharp_feature_extraction" / "extract_sharp_features"

# The cube every test runs on: enough points for the default scales to find its 12 edges and
# 8 corners, few enough for a fraction of a second per extraction.
CUBE_POINTS = 6000
CUBE_SEED = 1


def sample_cube_surface(count, seed):
    """`count` points drawn uniformly on the surface of the cube [-0.5, 0.5]^3 (an (N, 3)
    C-contiguous float64 array); the same `seed` gives the same points."""
    rng = np.random.default_rng(seed)
    points = rng.uniform(-0.5, 0.5, size=(count, 3))
    face_axis = rng.integers(0, 3, size=count)
    points[np.arange(count), face_axis] = rng.choice([-0.5, 0.5], size=count)
    return points


@pytest.fixture(scope="session")
def cube():
    """The points of the test cube (do not modify them)."""
    return sample_cube_surface(CUBE_POINTS, CUBE_SEED)


@pytest.fixture(scope="session")
def extract_program():
    """Path of the extract_sharp_features program built with the module."""
    program = pathlib.Path(os.environ.get("SFE_EXTRACT_PROGRAM", DEFAULT_PROGRAM))
    if not program.is_file():
        pytest.skip(f"the program extract_sharp_features is not built ({program}); set SFE_EXTRACT_PROGRAM")
    return program

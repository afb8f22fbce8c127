"""sharp_features.Result: its arrays, and its writers, whose files equal those of the
extract_sharp_features program on the same cloud."""

import pathlib
import subprocess

import numpy as np
import pytest

import sharp_features

SCALES = {"spacing", "noise", "candidate_neighbors", "candidate_radius", "rmls_neighbors", "residual_threshold",
          "rmls_tolerance", "corner_radius", "growth_radius", "completion_distance", "sampled_fraction",
          "search_fraction"}
TIMINGS = {"context", "candidates", "projection", "smoothing", "growing", "completion", "total"}


@pytest.fixture(scope="module")
def cube_result(cube):
    return sharp_features.extract(cube)


def test_each_polyline_has_one_pair_of_unit_normals_per_vertex(cube_result):
    assert len(cube_result.normals) == len(cube_result.polylines)
    for points, normals in zip(cube_result.polylines, cube_result.normals):
        assert points.dtype == np.float64 and points.ndim == 2 and points.shape[1] == 3
        assert normals.shape == (len(points), 2, 3)
        assert np.allclose(np.linalg.norm(normals, axis=2), 1)


def test_each_corner_is_the_exact_end_point_of_its_incident_polylines(cube_result):
    assert len(cube_result.corner_polylines) == len(cube_result.corners)
    for corner, incident in zip(cube_result.corners, cube_result.corner_polylines):
        assert len(incident) > 0
        for i in incident:
            ends = cube_result.polylines[i][[0, -1]]
            assert any(np.array_equal(corner, end) for end in ends)


def test_scales_and_timings_are_reported_by_name(cube_result):
    assert set(cube_result.scales) == SCALES
    assert all(value > 0 for name, value in cube_result.scales.items() if name != "noise")
    assert set(cube_result.timings) == TIMINGS
    assert cube_result.timings["total"] == pytest.approx(sum(v for k, v in cube_result.timings.items() if k != "total"))
    assert repr(cube_result) == "<sharp_features.Result: 12 polylines, 8 corners>"


def test_the_polylines_file_reads_back_as_the_polylines(cube_result, tmp_path):
    path = tmp_path / "cube.polylines.txt"
    cube_result.write_polylines(path)
    lines = path.read_text().splitlines()
    assert len(lines) == len(cube_result.polylines)
    for line, points in zip(lines, cube_result.polylines):
        numbers = line.split()
        assert int(numbers[0]) == len(points)
        assert np.array_equal(np.array(numbers[1:], dtype=np.float64).reshape(-1, 3), points)


def test_writing_to_a_missing_directory_raises_os_error(cube_result, tmp_path):
    with pytest.raises(OSError, match="cannot write"):
        cube_result.write_polylines(tmp_path / "missing" / "cube.polylines.txt")
    with pytest.raises(OSError, match="cannot write"):
        cube_result.write_ply(str(tmp_path / "missing" / "cube.ply"))


# Parameters of the comparison with the program: its option and the keyword of extract().
OVERRIDES = {
    "defaults": ([], {}),
    "overrides": (["--sharpness-angle", "30", "--growth-radius", "0.09", "--smoothing-passes", "2",
                   "--candidate-neighbors", "30"],
                  dict(sharpness_angle=30, growth_radius=0.09, number_of_iterations=2, candidate_neighbors=30)),
}


@pytest.mark.parametrize("case", sorted(OVERRIDES))
def test_the_files_equal_those_of_the_program_byte_for_byte(cube, extract_program, tmp_path, case):
    options, keywords = OVERRIDES[case]
    cloud = tmp_path / "cube.xyz"
    np.savetxt(cloud, cube, fmt="%.17g")  # 17 significant digits: the program reads the same doubles
    program_output = {"polylines": tmp_path / "program.polylines.txt", "ply": tmp_path / "program.ply"}
    subprocess.run([str(extract_program), str(cloud), "-o", str(program_output["polylines"]),
                    "--ply", str(program_output["ply"]), "--quiet", *options], check=True)

    result = sharp_features.extract(cube, **keywords)
    result.write_polylines(tmp_path / "module.polylines.txt")
    result.write_ply(tmp_path / "module.ply")
    assert len(result.polylines) > 0
    assert (tmp_path / "module.polylines.txt").read_bytes() == program_output["polylines"].read_bytes()
    assert (tmp_path / "module.ply").read_bytes() == program_output["ply"].read_bytes()


def test_the_programs_ply_with_patches_colours_every_point_by_its_patch(cube, extract_program, tmp_path):
    cloud = tmp_path / "cube.xyz"
    np.savetxt(cloud, cube, fmt="%.17g")
    ply, labels_file = tmp_path / "cube.ply", tmp_path / "cube.labels.txt"
    subprocess.run([str(extract_program), str(cloud), "-o", str(tmp_path / "cube.polylines.txt"), "--ply", str(ply),
                    "--patches", str(labels_file), "--quiet"], check=True)
    labels = np.loadtxt(labels_file, dtype=np.int64)
    lines = ply.read_text().splitlines()
    header = lines[:lines.index("end_header")]
    assert header[-7:-3] == ["property int patch", "property uchar red", "property uchar green", "property uchar blue"]
    vertices = int(next(line for line in header if line.startswith("element vertex")).split()[2])
    rows = np.array([line.split() for line in lines[len(header) + 1:len(header) + 1 + vertices]], dtype=float)
    # The curve vertices first (black, in no patch), then the points in input order.
    points = rows[-len(cube):]
    assert np.all(rows[:-len(cube), 11] == -1) and np.all(rows[:-len(cube), 12:] == 0)
    assert np.array_equal(points[:, :3], cube)
    assert np.array_equal(points[:, 11].astype(np.int64), labels)
    colour_of = {}
    for label, colour in zip(labels, map(tuple, points[:, 12:])):
        assert colour_of.setdefault(label, colour) == colour  # one colour per patch
    assert len(set(colour_of.values())) == len(colour_of)  # a different one for each
    assert colour_of.get(-1, (128, 128, 128)) == (128, 128, 128)  # grey for no patch


def test_every_point_is_in_the_patch_of_its_cube_face(cube, cube_result):
    patches = cube_result.patches
    assert patches.shape == (len(cube),) and patches.dtype == np.int64
    # The face of each point: the axis and sign of its coordinate at +-0.5.
    axis = np.argmax(np.abs(cube), axis=1)
    face = 2 * axis + (cube[np.arange(len(cube)), axis] > 0)
    agree = 0
    majority = set()
    for f in range(6):
        labels, counts = np.unique(patches[face == f], return_counts=True)
        agree += counts.max()
        majority.add(labels[np.argmax(counts)])
    assert len(set(patches[patches >= 0])) == 6
    assert len(majority) == 6
    assert agree >= 0.99 * len(cube)

"""The point cloud files of sharp_features: write_las and PointReader (LAS 1.2 to 1.4, point
formats 0 to 10, chunks, seek), PLY streaming, read_point_cloud, and bad files rejected with
ValueError saying why."""

import struct

import numpy as np
import pytest

import sharp_features

# The first LAS minor version of each point format 0 to 10 (LAS 1.4 R15, table of formats).
FIRST_MINOR_VERSION = [2, 2, 2, 2, 3, 3, 4, 4, 4, 4, 4]
# Byte offsets in the LAS header: minor version, point format.
VERSION_MINOR_AT, POINT_FORMAT_AT = 25, 104


@pytest.fixture(scope="module")
def points():
    """A few hundred points at georeferenced coordinates (hundreds of km, sub-metre detail)."""
    rng = np.random.default_rng(7)
    return rng.uniform([500000, 4000000, 100], [501000, 4001000, 200], size=(300, 3))


def quantum(points):
    """The writer's step: the half extent over 2^30 (see write_LAS_points.h)."""
    return np.max(np.ptp(points, axis=0)) / 2 / 2**30


def read_in_chunks(path, chunk):
    reader = sharp_features.PointReader(path)
    chunks = []
    while len(part := reader.read(chunk)):
        chunks.append(part)
    return np.concatenate(chunks)


@pytest.mark.parametrize("point_format", range(11))
def test_las_of_every_format_and_version_reads_back_within_half_a_step(points, point_format, tmp_path):
    for minor in range(FIRST_MINOR_VERSION[point_format], 5):
        path = tmp_path / f"f{point_format}_v{minor}.las"
        sharp_features.write_las(path, points, version_minor=minor, point_format=point_format, extra_bytes=3)
        data = path.read_bytes()
        assert (data[VERSION_MINOR_AT], data[POINT_FORMAT_AT]) == (minor, point_format)
        reader = sharp_features.PointReader(path)
        assert (reader.format, reader.count) == ("las", len(points))
        np.testing.assert_allclose(reader.bounds, [points.min(axis=0), points.max(axis=0)], rtol=0, atol=0)
        read = read_in_chunks(path, 64)
        assert read.shape == points.shape and read.dtype == np.float64
        assert np.max(np.abs(read - points)) <= quantum(points) / 2 * (1 + 1e-9)


def test_las_chunks_and_seek_give_the_same_points_as_a_whole_read(points, tmp_path):
    path = tmp_path / "cloud.las"
    sharp_features.write_las(path, points)
    whole = sharp_features.read_point_cloud(path)
    assert np.array_equal(read_in_chunks(path, 1), whole)
    assert np.array_equal(read_in_chunks(path, 7), whole)
    reader = sharp_features.PointReader(path)
    reader.seek(250)
    assert np.array_equal(reader.read(1000), whole[250:])
    assert len(reader.read(1000)) == 0


def test_binary_ply_streams_in_chunks(points, tmp_path):
    path = tmp_path / "cloud.ply"
    header = f"ply\nformat binary_little_endian 1.0\nelement vertex {len(points)}\n" \
             "property double x\nproperty double y\nproperty double z\nproperty uchar red\nend_header\n"
    body = b"".join(struct.pack("<3dB", *p, 200) for p in points)
    path.write_bytes(header.encode() + body)
    reader = sharp_features.PointReader(path)
    assert (reader.format, reader.count, reader.bounds) == ("ply", len(points), None)
    assert np.array_equal(read_in_chunks(path, 7), points)
    assert np.array_equal(sharp_features.read_point_cloud(path), points)
    with pytest.raises(ValueError, match="LAS"):
        reader.seek(3)
    path.write_bytes(header.encode() + body[:-5])
    with pytest.raises(ValueError, match="truncated"):
        read_in_chunks(path, 100)


@pytest.mark.parametrize("patch, message", [
    ({0: b"LASX"}, "not a LAS file"),
    ({VERSION_MINOR_AT: b"\x01"}, "LAS version 1.1 is not supported"),
    ({POINT_FORMAT_AT: b"\x83"}, r"compressed LAS \(LAZ\)"),
    ({POINT_FORMAT_AT: b"\x07"}, "point format 7 does not exist in version 1.2"),
])
def test_bad_las_headers_raise_value_error_saying_why(points, tmp_path, patch, message):
    path = tmp_path / "bad.las"
    sharp_features.write_las(path, points)
    data = bytearray(path.read_bytes())
    for at, value in patch.items():
        data[at:at + len(value)] = value
    path.write_bytes(bytes(data))
    with pytest.raises(ValueError, match=message):
        sharp_features.PointReader(path)
    with pytest.raises(ValueError, match=message):
        sharp_features.read_point_cloud(path)


def test_a_truncated_las_file_raises_value_error_when_its_end_is_read(points, tmp_path):
    path = tmp_path / "truncated.las"
    sharp_features.write_las(path, points)
    path.write_bytes(path.read_bytes()[:-1])
    reader = sharp_features.PointReader(path)
    assert len(reader.read(len(points) - 1)) == len(points) - 1
    with pytest.raises(ValueError, match="ends after 299 of the 300 points"):
        reader.read(10)


def test_other_files_are_rejected_with_the_reason(tmp_path):
    with pytest.raises(FileNotFoundError):
        sharp_features.PointReader(tmp_path / "missing.las")
    (tmp_path / "cloud.xyz").write_text("0 0 0\n")
    with pytest.raises(ValueError, match="streams .las and .ply"):
        sharp_features.PointReader(tmp_path / "cloud.xyz")
    with pytest.raises(ValueError, match="point format 11 does not exist"):
        sharp_features.write_las(tmp_path / "x.las", np.zeros((1, 3)), point_format=11)
    with pytest.raises(ValueError, match="not finite"):
        sharp_features.write_las(tmp_path / "x.las", np.array([[0, 0, np.nan]]))

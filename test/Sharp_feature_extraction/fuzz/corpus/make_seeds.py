#!/usr/bin/env python3
"""Writes the binary seeds of the fuzz corpus (the text seeds are plain files beside this one).

  python3 make_seeds.py   # from this directory; rewrites the files below, byte for byte

- fuzz_read_ply/binary_{little,big}_endian.ply: the same two vertices, with integer-typed x and y,
  a float z, a property before x, an element with a list before the vertices and a face after.
- fuzz_read_las/*.las: small LAS files, one per version 1.2, 1.3 and 1.4, with point formats 0,
  4 (with extra bytes), 6 (with a variable length record) and 10; three points each.
- fuzz_extract_sharp_features/*.bin: inputs of fuzz_extract_sharp_features.cpp. Its
  FuzzedDataProvider reads each number from the end of the input, little endian, in the order of
  decode(); `pipeline_seed` lays them out that way.

Not written here: fuzz_decompress_point_cloud/fandisk_600.sfeh, a bitstream of the point-cloud
coder (`compress_point_cloud fandisk_600.xyz -o fandisk_600.sfeh --bpp 8 --partition traditional`,
the cloud from `sample_mesh_surface fandisk.off -n 600 --seed 3`).
"""
import struct

MAX_U64 = 2**64 - 1


def ply(fmt, endian):
    header = ("ply\nformat %s 1.0\nelement material 1\nproperty list uchar int ids\n"
              "element vertex 2\nproperty double nx\nproperty int x\nproperty float z\nproperty short y\n"
              "element face 1\nproperty list uchar int vertex_indices\nend_header\n" % fmt).encode()
    body = struct.pack(endian + "B3i", 3, 7, 8, 9)
    for x, y, z in [(1, -2, 3.25), (-4, 5, 0.125)]:
        body += struct.pack(endian + "difh", 0.5, x, z, y)
    return header + body + struct.pack(endian + "B2i", 2, 0, 1)


# Public header size of LAS 1.2, 1.3, 1.4 and record size of point formats 0 to 10 (LAS 1.4 R15).
LAS_HEADER_SIZE = {2: 227, 3: 235, 4: 375}
LAS_RECORD_SIZE = [20, 28, 26, 34, 57, 63, 30, 36, 38, 59, 67]
LAS_VLR_HEADER_SIZE = 54


def las(minor, point_format, extra_bytes=0, vlr_payload=0):
    points = [(0, 0, 0), (1000, -2000, 3000), (-7, 8, 2**31 - 1)]
    header_size = LAS_HEADER_SIZE[minor]
    vlrs = b""
    if vlr_payload:
        vlrs = struct.pack("<H16sHH32s", 0, b"seed", 1, vlr_payload, b"") + bytes(vlr_payload)
    record = LAS_RECORD_SIZE[point_format] + extra_bytes
    legacy_count = len(points) if point_format < 6 else 0
    header = (b"LASF" + bytes(20) + bytes([1, minor]) + bytes(64) + struct.pack("<HHHII", 1, 2026, header_size,
              header_size + len(vlrs), 1 if vlrs else 0) + struct.pack("<BHI", point_format, record, legacy_count)
              + bytes(20) + struct.pack("<3d", 0.01, 0.01, 0.001) + struct.pack("<3d", 500000.0, 4e6, 0.0)
              + struct.pack("<6d", 1, 0, 1, 0, 1, 0))
    header += bytes(header_size - len(header))
    if minor == 4:  # the 64-bit point count, at byte 247
        header = header[:247] + struct.pack("<Q", len(points)) + header[255:]
    body = b"".join(struct.pack("<3i", *p) + bytes(record - 12) for p in points)
    return header + vlrs + body


LAS_SEEDS = {"v12_format0": las(2, 0), "v13_format4_extra": las(3, 4, extra_bytes=3),
             "v14_format6_vlr": las(4, 6, vlr_payload=10), "v14_format10": las(4, 10)}


def number(value, size):
    return value.to_bytes(size, "little")


def probability(p):
    return number(int(p * MAX_U64), 8)


SHAPES = ["none", "cube", "plane", "segment", "wedge", "box", "sphere", "one_point"]


def pipeline_seed(shape, n, seed=1, noise_exponent=-30, wedge_angle=1.5, scale_exponent=None,
                  offset_exponent=None, grid_exponent=None, copies=None, cluster=None,
                  overrides=None, raw_points=()):
    chunks = [number(SHAPES.index(shape), 1), number(n, 2), number(seed, 4),
              number(noise_exponent + 30, 1), probability((wedge_angle - 0.01) / 3.12)]
    flags = 0
    optional = []
    for bit, value, encode in [(1, scale_exponent, lambda v: number(v + 1100, 2)),
                               (2, offset_exponent, lambda v: number(v, 1)),
                               (4, grid_exponent, lambda v: number(v, 1)),
                               (8, copies, lambda v: number(v - 2, 1)),
                               (16, cluster, lambda v: number(v - 1, 2))]:
        if value is not None:
            flags |= bit
            optional.append(encode(value))
    chunks += [number(flags, 1)] + optional
    if overrides is None:
        chunks.append(number(0, 1))
    else:
        candidate_neighbors, rmls_neighbors, sharpness_angle = overrides
        chunks += [number(1, 1), number(candidate_neighbors, 1), number(rmls_neighbors, 1),
                   probability((sharpness_angle - 1) / 88)]
    for point in raw_points:
        for c in point:
            chunks.append(struct.pack("<d", c))
    return b"".join(reversed(chunks))


NAN, INF = float("nan"), float("inf")
PIPELINE_SEEDS = {
    "cube_600": pipeline_seed("cube", 600),
    "cube_noisy_overrides": pipeline_seed("cube", 400, seed=2, noise_exponent=-9, overrides=(12, 30, 40)),
    "wedge_500": pipeline_seed("wedge", 500, wedge_angle=1.2, noise_exponent=-12),
    "plane_grid": pipeline_seed("plane", 300, grid_exponent=4),
    "segment_repeated": pipeline_seed("segment", 100, copies=4),
    "sphere_tiny": pipeline_seed("sphere", 400, noise_exponent=-8, scale_exponent=-1000),
    "box_georeferenced": pipeline_seed("box", 300, offset_exponent=40),
    "one_point_cluster": pipeline_seed("one_point", 20, cluster=3000),
    "empty": pipeline_seed("none", 0),
    "raw_nan_inf": pipeline_seed("none", 0, raw_points=[(0, 0, 0), (1, NAN, 0), (0, 1, INF), (5e-324, 1e308, -0.0)]),
}

if __name__ == "__main__":
    for name, endian in [("little", "<"), ("big", ">")]:
        with open("fuzz_read_ply/binary_%s_endian.ply" % name, "wb") as f:
            f.write(ply("binary_%s_endian" % name, endian))
    for name, data in LAS_SEEDS.items():
        with open("fuzz_read_las/%s.las" % name, "wb") as f:
            f.write(data)
    for name, data in PIPELINE_SEEDS.items():
        with open("fuzz_extract_sharp_features/%s.bin" % name, "wb") as f:
            f.write(data)

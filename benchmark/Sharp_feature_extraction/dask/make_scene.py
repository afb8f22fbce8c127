#!/usr/bin/env python3
"""A large synthetic CAD-like scene, written as LAS: a grid of rotated copies of sampled parts.

    make_scene.py OUT.las --points N --samples DIR PART.off... [--seed S]

Each PART.off (a CGAL sample mesh) comes with DIR/PART.xyz, points sampled uniformly on its
surface (scripts/bench_dask.sh runs sample_mesh_surface for that). Each part is scaled to unit
surface area, so that copies of different parts with the same number of points have the same
sampling density (the tiled run estimates its scales on one tile and applies them to all). The
copies (each with all the points of its part's sample) cycle through the parts, each rotated at
random and placed in its cell of a cubic grid spaced 1.5 times the largest part's diameter,
until N points; the file is written by sharp_features'
write_las. The scene is generated at run time and never committed (hundreds of MB).
"""

import argparse
import math
import pathlib
import sys

import numpy as np

import sharp_features

# Cells of the grid are this many times the largest part's extent: copies never touch, and
# the gaps stay small beside a copy (the scene is mostly surface, like a real site).
CELL_PER_EXTENT = 1.5


def mesh_area(path):
    """The surface area of an OFF mesh (polygons fanned into triangles)."""
    tokens = [line.split("#")[0] for line in pathlib.Path(path).read_text().splitlines()]
    numbers = " ".join(tokens).split()
    if not numbers or not numbers[0].endswith("OFF"):
        raise ValueError(f"{path}: not an OFF file")
    vertices, faces = int(numbers[1]), int(numbers[2])
    position = 4
    xyz = np.array(numbers[position:position + 3 * vertices], dtype=float).reshape(-1, 3)
    position += 3 * vertices
    area = 0.0
    for _ in range(faces):
        size = int(numbers[position])
        corners = xyz[np.array(numbers[position + 1:position + 1 + size], dtype=int)]
        position += 1 + size
        edges = np.cross(corners[1:-1] - corners[0], corners[2:] - corners[0])
        area += 0.5 * np.linalg.norm(edges, axis=1).sum()
    return area


def random_rotation(rng):
    """A uniformly random rotation matrix (QR of a Gaussian matrix, signs fixed)."""
    q, r = np.linalg.qr(rng.normal(size=(3, 3)))
    q *= np.sign(np.diag(r))
    return q if np.linalg.det(q) > 0 else -q


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("output", type=pathlib.Path)
    parser.add_argument("--points", type=int, required=True)
    parser.add_argument("--samples", type=pathlib.Path, required=True)
    parser.add_argument("--seed", type=int, default=1)
    parser.add_argument("parts", nargs="+", type=pathlib.Path)
    arguments = parser.parse_args()
    rng = np.random.default_rng(arguments.seed)
    parts = []
    for mesh in arguments.parts:
        points = np.loadtxt(arguments.samples / (mesh.stem + ".xyz"))[:, :3]
        points = (points - points.mean(axis=0)) / math.sqrt(mesh_area(mesh))
        parts.append(points)
    copies = math.ceil(arguments.points / len(parts[0]))
    cell = CELL_PER_EXTENT * max(np.max(np.linalg.norm(p, axis=1)) * 2 for p in parts)
    side = math.ceil(copies ** (1 / 3))
    scene = np.empty((arguments.points, 3))
    written = 0
    for copy in range(copies):
        points = parts[copy % len(parts)] @ random_rotation(rng).T
        cell_index = np.array([copy % side, (copy // side) % side, copy // (side * side)])
        count = min(len(points), arguments.points - written)
        scene[written:written + count] = points[:count] + cell * cell_index
        written += count
    sharp_features.write_las(arguments.output, scene)
    print(f"{arguments.output}: {written} points, {copies} copies of {len(parts)} parts, "
          f"grid {side}^3 of cells {cell:.3g}", file=sys.stderr)


if __name__ == "__main__":
    main()

#!/usr/bin/env python3
"""Writes the fuzz harnesses' seed corpus from the project's fixtures:
make_seeds.py FIXTURES OUT

OUT/mesh_reader: every mesh of FIXTURES with the harness's format byte in front (0 .off, 1 .obj,
2 .stl, 3 .ply); OUT/polygons: every hlr-polygons/1 document; OUT/draw: a few tiny scenes in
the draw harness's byte layout (view, vertex count, 2 bytes per grid vertex, 4 per face)."""
import pathlib
import sys

FORMATS = {".off": 0, ".obj": 1, ".stl": 2, ".ply": 3}
VIEWS = ["front", "back", "top", "bottom", "left", "right", "iso"]


def grid_vertex(x, y, z):
    bits = x | (y << 2) | (z << 4)
    return bytes([bits & 0xFF, bits >> 8])


def draw_seed(view, vertices, faces):
    """faces: tuples of 3 or 4 vertex indices (a quad's 4th corner comes first in its record)."""
    out = bytes([VIEWS.index(view), len(vertices) - 3])
    for v in vertices:
        out += grid_vertex(*v)
    for f in faces:
        out += bytes([0, f[0], f[1], f[2]]) if len(f) == 3 else bytes([1 | (f[3] << 1), f[0], f[1], f[2]])
    return out


def draw_seeds():
    cube = [(0, 0, 0), (2, 0, 0), (2, 2, 0), (0, 2, 0), (0, 0, 2), (2, 0, 2), (2, 2, 2), (0, 2, 2)]
    cube_faces = [(0, 2, 1), (0, 3, 2), (4, 5, 6), (4, 6, 7), (0, 1, 5), (0, 5, 4),
                  (1, 2, 6), (1, 6, 5), (2, 3, 7), (2, 7, 6), (3, 0, 4), (3, 4, 7)]
    yield "cube_iso", draw_seed("iso", cube, cube_faces)
    yield "cube_front", draw_seed("front", cube, cube_faces)
    crossing = [(0, 0, 1), (3, 0, 1), (0, 3, 1), (1, 1, 0), (1, 1, 3), (3, 3, 2)]
    yield "penetrating_iso", draw_seed("iso", crossing, [(0, 1, 2), (3, 4, 5)])
    coplanar = [(0, 0, 0), (3, 0, 0), (3, 3, 0), (0, 3, 0), (1, 1, 0), (2, 1, 0), (2, 2, 0)]
    yield "coplanar_top", draw_seed("top", coplanar, [(0, 1, 2), (0, 2, 3), (4, 5, 6)])


def main():
    fixtures, out = pathlib.Path(sys.argv[1]), pathlib.Path(sys.argv[2])
    for harness in ("mesh_reader", "polygons", "draw"):
        (out / harness).mkdir(parents=True, exist_ok=True)
    count = 0
    for path in sorted(fixtures.rglob("*")):
        suffix = path.suffix.lower()
        if suffix in FORMATS and path.is_file():
            name = "_".join(path.relative_to(fixtures).parts)
            (out / "mesh_reader" / name).write_bytes(bytes([FORMATS[suffix]]) + path.read_bytes())
            count += 1
        elif suffix == ".json" and b"hlr-polygons/1" in path.read_bytes():
            (out / "polygons" / path.name).write_bytes(path.read_bytes())
            count += 1
    for name, data in draw_seeds():
        (out / "draw" / name).write_bytes(data)
        count += 1
    print(f"make_seeds: {count} seeds in {out}")


if __name__ == "__main__":
    main()

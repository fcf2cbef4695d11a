#!/usr/bin/env python3
"""Writes a closed torus mesh of 2 * U * V triangles (default 1,000,000) for the
scale measurement of spec/numerics.md ("Meshes at scale"), and a scene that
renders it:

    python3 tests/gen_big_mesh.py OUT_DIR [--u U] [--v V] [--ply]

OUT_DIR/torus.obj (or torus.ply, binary little-endian, with --ply) holds U x V
vertices on a torus of radii 2 and 0.75, each grid cell cut into two triangles
wound outward; OUT_DIR/torus.scene reads it.  Coordinates are written with 17
significant digits, so the mesh is closed to the bit: every edge is shared by
exactly two triangles and consecutive rings share their vertices by index.
"""
import math
import os
import struct
import sys


def torus(u_count, v_count):
    """Vertices and triangles of the torus grid (indices 0-based)."""
    big, small = 2.0, 0.75
    verts = []
    for i in range(u_count):
        a = 2 * math.pi * i / u_count
        for j in range(v_count):
            b = 2 * math.pi * j / v_count
            r = big + small * math.cos(b)
            verts.append((r * math.cos(a), small * math.sin(b), r * math.sin(a)))
    tris = []
    for i in range(u_count):
        i1 = (i + 1) % u_count
        for j in range(v_count):
            j1 = (j + 1) % v_count
            a, b = i * v_count + j, i1 * v_count + j
            c, d = i1 * v_count + j1, i * v_count + j1
            tris.append((a, d, c))
            tris.append((a, c, b))
    return verts, tris


def write_obj(path, verts, tris):
    with open(path, "w") as f:
        f.write("# closed torus, %d triangles (tests/gen_big_mesh.py)\n" % len(tris))
        f.write("".join("v %.17g %.17g %.17g\n" % v for v in verts))
        f.write("".join("f %d %d %d\n" % (a + 1, b + 1, c + 1) for a, b, c in tris))


def write_ply(path, verts, tris):
    with open(path, "wb") as f:
        f.write(b"ply\nformat binary_little_endian 1.0\ncomment tests/gen_big_mesh.py\n")
        f.write(b"element vertex %d\nproperty double x\nproperty double y\nproperty double z\n" % len(verts))
        f.write(b"element face %d\nproperty list uchar int vertex_indices\nend_header\n" % len(tris))
        f.write(b"".join(struct.pack("<3d", *v) for v in verts))
        f.write(b"".join(struct.pack("<B3i", 3, *t) for t in tris))


def main(argv):
    args = argv[1:]
    if not args or args[0].startswith("-"):
        sys.exit(__doc__)
    out, u_count, v_count, ply = args[0], 1000, 500, "--ply" in args
    if "--u" in args:
        u_count = int(args[args.index("--u") + 1])
    if "--v" in args:
        v_count = int(args[args.index("--v") + 1])
    os.makedirs(out, exist_ok=True)
    verts, tris = torus(u_count, v_count)
    name = "torus.ply" if ply else "torus.obj"
    (write_ply if ply else write_obj)(os.path.join(out, name), verts, tris)
    with open(os.path.join(out, "torus.scene"), "w") as f:
        f.write("# %d triangles: tests/gen_big_mesh.py\n" % len(tris))
        f.write("image  { width 320 height 240 }\n")
        f.write("camera { perspective eye [0, 5, 6] look_at [0, 0, 0] up [0, 1, 0] fov 45 }\n")
        f.write("ambient { color 0.1 }\n")
        f.write("distant_light { direction [-1, -2, -1] power 0.9 }\n")
        f.write('mesh { file "%s" material { Kd [0.7, 0.5, 0.3] } }\n' % name)


if __name__ == "__main__":
    main(sys.argv)

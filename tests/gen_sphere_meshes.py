#!/usr/bin/env python3
"""Writes the smooth sphere meshes of the shadow terminator measurement
(spec/shading.md, [SHADE-TERMINATOR-1]; `make terminator`,
scenes/terminator.scene):

    python3 tests/gen_sphere_meshes.py        # from the repository root

scenes/models/sphere_UxV.obj for U x V = 12x8, 24x16, 48x32: a unit sphere
cut into U slices around the y axis and V bands from pole to pole (quads,
triangle fans at the poles), wound outward, each vertex with its exact unit
normal (the sphere's), so the interpolated normals are as good as a mesh can
give and only the facets' positions are coarse.
"""
import math

SIZES = ((12, 8), (24, 16), (48, 32))


def write(u_count, v_count):
    path = "scenes/models/sphere_%dx%d.obj" % (u_count, v_count)
    lines = ["# A smooth unit sphere, %d slices x %d bands, exact vertex normals." % (u_count, v_count),
             "# Written by tests/gen_sphere_meshes.py for the shadow terminator measurement."]
    rings = []
    for j in range(1, v_count):
        b = math.pi * j / v_count
        ring = []
        for i in range(u_count):
            a = 2 * math.pi * i / u_count
            ring.append((math.sin(b) * math.cos(a), math.cos(b), -math.sin(b) * math.sin(a)))
        rings.append(ring)
    points = [p for ring in rings for p in ring] + [(0.0, 1.0, 0.0), (0.0, -1.0, 0.0)]
    for p in points:
        lines.append("v %r %r %r" % p)
    for p in points:
        lines.append("vn %r %r %r" % p)
    top, bottom = len(points) - 1, len(points)  # the poles, 1-based

    def k(j, i):
        return j * u_count + (i % u_count) + 1

    for i in range(u_count):
        lines.append("f %d//%d %d//%d %d//%d" % (top, top, k(0, i), k(0, i), k(0, i + 1), k(0, i + 1)))
        for j in range(v_count - 2):
            c = (k(j, i), k(j + 1, i), k(j + 1, i + 1), k(j, i + 1))
            lines.append("f " + " ".join("%d//%d" % (q, q) for q in c))
        last = v_count - 2
        lines.append("f %d//%d %d//%d %d//%d" % (bottom, bottom, k(last, i + 1), k(last, i + 1), k(last, i), k(last, i)))
    with open(path, "w") as f:
        f.write("\n".join(lines) + "\n")


if __name__ == "__main__":
    for size in SIZES:
        write(*size)

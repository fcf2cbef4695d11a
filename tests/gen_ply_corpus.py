#!/usr/bin/env python3
"""Writes the PLY test corpus (tests/check_ply.c, spec/language.md section 8):

    python3 tests/gen_ply_corpus.py        # from the repository root

tests/ply/uvsphere.obj and uvsphere_{ascii,le,be}.ply: one smooth mesh (a UV
sphere of 8 x 6 cells: quads, triangle fans at the poles, unit vertex
normals) in OBJ and in the three PLY encodings, with the same numbers: every
coordinate is a float32 value, written in text with the digits that give
that very value back (Python repr), so all four files
describe the same doubles and must render the same image.  The PLY files add
what a reader must skip: colour properties of every integer type, a texture
coordinate list on the faces, an element of its own with a property of every
scalar type.

tests/bad/inc/*.ply: binary files for the error corpus (tests/bad/ply-*).
"""
import math
import struct

U, V = 8, 6


def f32(x):
    return struct.unpack("<f", struct.pack("<f", x))[0]


def sphere():
    verts, norms = [], []
    for j in range(1, V):
        b = math.pi * j / V
        for i in range(U):
            a = 2 * math.pi * i / U
            n = (math.sin(b) * math.cos(a), math.cos(b), math.sin(b) * math.sin(a))
            verts.append(tuple(f32(c * 1.5) for c in n))
            norms.append(tuple(f32(c) for c in n))
    verts += [(0.0, 1.5, 0.0), (0.0, -1.5, 0.0)]
    norms += [(0.0, 1.0, 0.0), (0.0, -1.0, 0.0)]
    top, bottom = len(verts) - 2, len(verts) - 1
    faces = []
    for i in range(U):
        i1 = (i + 1) % U
        faces.append((top, i1, i))
        for j in range(V - 2):
            a, b = j * U + i, j * U + i1
            faces.append((a, b, b + U, a + U))
        last = (V - 2) * U
        faces.append((bottom, last + i, last + i1))
    return verts, norms, faces


def g(x):
    return repr(x)


def write_obj(path, verts, norms, faces):
    with open(path, "w") as f:
        f.write("# A UV sphere of 8 x 6 cells, smooth (tests/gen_ply_corpus.py).\n")
        for v in verts:
            f.write("v %s\n" % " ".join(map(g, v)))
        for n in norms:
            f.write("vn %s\n" % " ".join(map(g, n)))
        for face in faces:
            f.write("f %s\n" % " ".join("%d//%d" % (k + 1, k + 1) for k in face))


HEADER = """ply
format {fmt} 1.0
comment A UV sphere of 8 x 6 cells (tests/gen_ply_corpus.py)
obj_info the same numbers as uvsphere.obj
element vertex {nv}
property float x
property float y
property float z
property uchar red
property short green
property uint blue
property float nx
property float ny
property float nz
element face {nf}
property list uchar int vertex_indices
property list int float texcoord
element extra 2
property char c
property ushort us
property int i
property double d
property list ushort double values
end_header
"""

EXTRA = [(-5, 65000, -70000, 0.25, [1.5, 2.5]), (7, 1, 2, -1e300, [])]


def write_ply(path, fmt, verts, norms, faces):
    head = HEADER.format(fmt=fmt, nv=len(verts), nf=len(faces)).encode()
    if fmt == "ascii":
        lines = []
        for k, (v, n) in enumerate(zip(verts, norms)):
            lines.append("%s %d %d %d %s" % (" ".join(map(g, v)), k % 256, -k, 70000 + k, " ".join(map(g, n))))
        for face in faces:
            lines.append("%d %s 2 0.5 0.25" % (len(face), " ".join(map(str, face))))
        for c, us, i, d, vals in EXTRA:
            lines.append("%d %d %d %r %d %s" % (c, us, i, d, len(vals), " ".join(map(repr, vals))))
        body = ("\n".join(lines) + "\n").encode()
    else:
        e = "<" if fmt == "binary_little_endian" else ">"
        parts = []
        for k, (v, n) in enumerate(zip(verts, norms)):
            parts.append(struct.pack(e + "3fBhI3f", *v, k % 256, -k, 70000 + k, *n))
        for face in faces:
            parts.append(struct.pack(e + "B%di" % len(face), len(face), *face))
            parts.append(struct.pack(e + "i2f", 2, 0.5, 0.25))
        for c, us, i, d, vals in EXTRA:
            parts.append(struct.pack(e + "bHidH%dd" % len(vals), c, us, i, d, len(vals), *vals))
        body = b"".join(parts)
    with open(path, "wb") as f:
        f.write(head + body)


def write_bad():
    tri = b"element vertex 3\nproperty float x\nproperty float y\nproperty float z\n" \
          b"element face 1\nproperty list uchar int vertex_indices\nend_header\n"
    verts = struct.pack("<9f", 0, 0, 0, 1, 0, 0, 0, 1, 0)
    with open("tests/bad/inc/truncated.ply", "wb") as f:
        f.write(b"ply\nformat binary_little_endian 1.0\n" + tri + verts + struct.pack("<Bi", 3, 0))
    with open("tests/bad/inc/index_range.ply", "wb") as f:
        f.write(b"ply\nformat binary_big_endian 1.0\n" + tri + struct.pack(">9f", 0, 0, 0, 1, 0, 0, 0, 1, 0) +
                struct.pack(">B3i", 3, 0, 1, 7))
    with open("tests/bad/inc/list_count.ply", "wb") as f:
        f.write(b"ply\nformat binary_little_endian 1.0\n" + tri + verts + struct.pack("<B", 200) + b"\0" * 12)
    with open("tests/bad/inc/nan.ply", "wb") as f:
        f.write(b"ply\nformat binary_little_endian 1.0\n" + tri + struct.pack("<9f", 0, 0, 0, 1, float("nan"), 0, 0, 1, 0) +
                struct.pack("<B3i", 3, 0, 1, 2))


def main():
    verts, norms, faces = sphere()
    write_obj("tests/ply/uvsphere.obj", verts, norms, faces)
    for name, fmt in (("ascii", "ascii"), ("le", "binary_little_endian"), ("be", "binary_big_endian")):
        write_ply("tests/ply/uvsphere_%s.ply" % name, fmt, verts, norms, faces)
    write_bad()


if __name__ == "__main__":
    main()

#!/usr/bin/env python3
"""kit_check.py KIT NAME IMAGE.pfm - checks a picture against a refray
conformance kit without refray: Python's standard library only, PFM only.
It is the rule of spec/conformance.md [KIT-RULE-1] written out, the worked
example of "checking without refray"; exit 0 pass, 1 fail."""
import json
import struct
import sys


def read_pfm(path):
    """(width, height, rows from the top, each 3 floats a pixel)."""
    with open(path, "rb") as f:
        kind, size, scale = f.readline(), f.readline(), f.readline()
        w, h = map(int, size.split())
        n = 3 if kind.strip() == b"PF" else 1
        order = "<" if float(scale) < 0 else ">"
        data = struct.unpack(order + "f" * (w * h * n), f.read(4 * w * h * n))
    rows = [data[y * w * n:(y + 1) * w * n] for y in range(h)][::-1]  # PFM rows run bottom to top
    return w, h, [[r[x * n + c % n] for x in range(w) for c in range(3)] for r in rows]


def read_pgm(path):
    """The mask's bytes, row by row from the top: 255 excluded, 0 compared."""
    with open(path, "rb") as f:
        _magic, w, h, _maxval, pixels = f.read().split(maxsplit=4)
    return pixels[:int(w) * int(h)]


def main(kit, name, image):
    scene = next(s for s in json.load(open(kit + "/manifest.json"))["scenes"] if s["name"] == name)
    w, h, exact = read_pfm(kit + "/" + scene["files"]["exact_pfm"])
    ow, oh, out = read_pfm(image)
    if (ow, oh) != (w, h):
        print(f"{name}: the image is {ow}x{oh}, the exact image {w}x{h}")
        return 1
    mask = read_pgm(kit + "/" + scene["files"]["mask_pgm"])
    rel, ab = scene["tolerance"]["relative"], scene["tolerance"]["absolute"]
    over = compared = 0
    for y in range(h):
        for x in range(w):
            if mask[y * w + x]:
                continue
            compared += 1
            e, o = exact[y][3 * x:3 * x + 3], out[y][3 * x:3 * x + 3]
            # "not <=" so that a NaN fails too
            over += any(not abs(o[c] - e[c]) <= rel * abs(e[c]) + ab for c in range(3))
    print(f"{name}: {over} of {compared} pixels over")
    return 0 if over == 0 and compared > 0 else 1


if __name__ == "__main__":
    sys.exit(main(*sys.argv[1:4]))

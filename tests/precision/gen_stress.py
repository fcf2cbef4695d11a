#!/usr/bin/env python3
"""Writes the stress scenes of scenes/stress/ whose numbers are computed
(critical angles, a Phong lobe 1e-3 rad off its peak, a refracted path's
target) and the OBJ meshes the watertightness cases sweep.  Run from the
repository root: python3 tests/precision/gen_stress.py.  The output is
committed; tests/test_stability.c re-derives every property in long double
from the loaded scene, so a number written here only has to be close."""
import math

D = "scenes/stress/"


def write(name, text):
    with open(D + name, "w") as f:
        f.write(text)


def fmt(v):
    return "[" + ", ".join(repr(float(x)) for x in v) + "]"


def critical(name, sign):
    # Camera inside a glass box (ior 1.5) looking up at its top face y = 0 at
    # theta = theta_c + sign * 1e-12 from the face normal.
    th = math.asin(1 / 1.5) + sign * 1e-12
    d = (math.sin(th), math.cos(th), 0.0)
    eye = (0.0, -1.0, 0.0)
    side = "below" if sign < 0 else "above"
    result = ("refracts: the ray leaves just above the face and sees the background, "
              "pixel = t * 0.5 = 0.5" if sign < 0 else
              "is totally reflected, and so at every later face: the ray is trapped until "
              "max_depth and the pixel is the local colour 0")
    write(name, f"""# Stress: incidence 1e-12 rad {side} the critical angle asin(1/1.5), from
# inside a glass box (ior 1.5, t 1, Kd 0) through its top face.  Written by
# tests/precision/gen_stress.py.
# Must hold: the camera ray {result}.
image  {{ width 1 height 1 background 0.5 max_depth 6 }}
camera {{ perspective eye {fmt(eye)} look_at {fmt([eye[i] + d[i] for i in range(3)])} up [0, 0, 1] fov 1 }}
box {{ from [-10, -10, -10] to [10, 0, 10] material {{ Kd 0 t 1 ior 1.5 }} }}
""")


def rot(v, axis, ang):
    # Rodrigues' rotation of v about the unit axis.
    c, s = math.cos(ang), math.sin(ang)
    k = axis
    kv = sum(k[i] * v[i] for i in range(3))
    kxv = (k[1] * v[2] - k[2] * v[1], k[2] * v[0] - k[0] * v[2], k[0] * v[1] - k[1] * v[0])
    return [v[i] * c + kxv[i] * s + k[i] * kv * (1 - c) for i in range(3)]


def unit(v):
    n = math.sqrt(sum(x * x for x in v))
    return [x / n for x in v]


def phong_off():
    # A plane through the origin with a generic normal, viewed along it; the
    # light's mirror direction R is 1e-3 rad from V, so the lobe with
    # n = 1e6 is about exp(-0.5).
    n = unit([1, 2, 3])
    axis = unit([n[1] * 1 - n[2] * 0, n[2] * 0.3 - n[0] * 1, n[0] * 0 - n[1] * 0.3])
    r = rot(n, axis, 1e-3)            # R, the mirror of L about N
    l = [2 * sum(n[i] * r[i] for i in range(3)) * n[i] - r[i] for i in range(3)]
    write("phong_n1e6_off.scene", f"""# Stress: Phong exponent 1e6, 1e-3 rad off the peak, in a frame along no
# axis (normal [1, 2, 3]).  The lobe is cos^1e6(1e-3) = exp(-0.5): an error of
# one ulp in V.R is an error of 1e6 ulps in the lobe.  Written by
# tests/precision/gen_stress.py.
# Must hold: the pixel is Kd*Ia + Kd*E*(N.L) + Ks*E*(V.R)^n with N, L, V from
# the loaded scene, to 1e-9 relative (spec/numerics.md has the measured error).
image  {{ width 1 height 1 background 0 }}
camera {{ orthographic eye {fmt([10 * x for x in n])} look_at [0, 0, 0] up [0, 0, 1] width 1 }}
ambient {{ color 0.1 }}
distant_light {{ direction {fmt([-x for x in l])} power 1 }}
plane {{ point [0, 0, 0] normal [1, 2, 3] material {{ Kd 0.25 Ks 0.5 n 1e6 }} }}
""")


def touching_inside():
    # Camera inside box A (ior 1.5, z in [-1, 0]) looking at the shared face
    # z = 0 with sin(theta) = 0.7: A -> air would be total internal
    # reflection (0.7 > 1/1.5) but A -> B (ior 1.4) refracts to sin = 0.75.
    # The ray then leaves B through its side x = 1 into air; a small target
    # ball sits 10 units along that exit ray.
    s1 = 0.7
    eye = [-0.5, 0.0, -0.5]
    d1 = [s1, 0.0, math.sqrt(1 - s1 * s1)]
    t = -eye[2] / d1[2]
    p1 = [eye[i] + t * d1[i] for i in range(3)]
    s2 = 1.5 * s1 / 1.4
    d2 = [s2, 0.0, math.sqrt(1 - s2 * s2)]
    t = (1 - p1[0]) / d2[0]
    p2 = [p1[i] + t * d2[i] for i in range(3)]
    # leaving through x = 1: the part along the face (z) scales by 1.4/1
    sz = 1.4 * d2[2]
    d3 = [math.sqrt(1 - sz * sz), 0.0, sz]
    target = [p2[i] + 10 * d3[i] for i in range(3)]
    write("touching_glass_camera_inside.scene", f"""# Stress: the camera inside glass box A (ior 1.5) that touches box B (ior 1.4)
# along the face z = 0.  The camera ray meets the shared face at sin = 0.7:
# it must bend 1.5 -> 1.4 (to sin 0.75), not 1.5 -> air (total internal
# reflection) nor through an air gap.  It then leaves B through the face
# x = 1 and travels to a small red ball placed on the exit ray computed by
# Snell's law (tests/precision/gen_stress.py).
# Must hold: the pixel is the ball's ambient colour [1, 0, 0] exactly (every
# crossing has t = 1 and Kd 0).
image  {{ width 1 height 1 background 0.5 max_depth 6 }}
camera {{ perspective eye {fmt(eye)} look_at {fmt([eye[i] + d1[i] for i in range(3)])} up [0, 1, 0] fov 1 }}
ambient {{ color 1 }}
box {{ from [-1, -1, -1] to [1, 1, 0] material {{ Kd 0 t 1 ior 1.5 }} }}
box {{ from [-1, -1, 0] to [1, 1, 1] material {{ Kd 0 t 1 ior 1.4 }} }}
sphere {{ center {fmt(target)} radius 0.2 material {{ Kd [1, 0, 0] }} }}
""")


def refract(d, n, n1, n2):
    # d unit, n unit facing against d; returns the refracted unit vector.
    c = -sum(d[i] * n[i] for i in range(3))
    eta = n1 / n2
    k = 1 - eta * eta * (1 - c * c)
    assert k > 0, "total internal reflection"
    return unit([eta * d[i] + (eta * c - math.sqrt(k)) * n[i] for i in range(3)])


def sphere_exit(o, d, r):
    # o inside the sphere of radius r at the origin: the exit point.
    b = sum(o[i] * d[i] for i in range(3))
    c = sum(x * x for x in o) - r * r
    t = -b + math.sqrt(b * b - c)
    return [o[i] + t * d[i] for i in range(3)]


def nested_inside():
    # Camera inside glass ball A (radius 1, ior 1.3) inside glass ball B
    # (radius 2, ior 1.6), both centred at the origin.  Leaving A the ray
    # goes 1.3 -> 1.6 (into B, not into air); leaving B, 1.6 -> 1.
    eye = [0.6, 0.1, 0.0]
    d1 = unit([0.3, 0.2, 1.0])
    p1 = sphere_exit(eye, d1, 1.0)
    d2 = refract(d1, [-x for x in unit(p1)], 1.3, 1.6)
    p2 = sphere_exit(p1, d2, 2.0)
    d3 = refract(d2, [-x for x in unit(p2)], 1.6, 1.0)
    target = [p2[i] + 10 * d3[i] for i in range(3)]
    write("camera_inside_nested_glass.scene", f"""# Stress: the camera inside a glass ball (ior 1.3) that is itself inside a
# larger glass ball (ior 1.6).  The camera ray starts with both on its
# medium stack: leaving the inner ball it bends 1.3 -> 1.6, leaving the outer
# one 1.6 -> 1.  A small red ball sits on the exit ray computed by Snell's
# law (tests/precision/gen_stress.py).
# Must hold: the pixel is the red ball's ambient colour [1, 0, 0] exactly.
image  {{ width 1 height 1 background 0.5 max_depth 6 }}
camera {{ perspective eye {fmt(eye)} look_at {fmt([eye[i] + d1[i] for i in range(3)])} up [0, 1, 0] fov 1 }}
ambient {{ color 1 }}
sphere {{ center [0, 0, 0] radius 2 material {{ Kd 0 t 1 ior 1.6 }} }}
sphere {{ center [0, 0, 0] radius 1 material {{ Kd 0 t 1 ior 1.3 }} }}
sphere {{ center {fmt(target)} radius 0.2 material {{ Kd [1, 0, 0] }} }}
""")


def obj(name, verts, faces, comment):
    with open(D + name, "w") as f:
        f.write("# " + comment + "\n# Written by tests/precision/gen_stress.py.\n")
        for v in verts:
            f.write("v %r %r %r\n" % tuple(float(x) for x in v))
        for t in faces:
            f.write("f %d %d %d\n" % tuple(i + 1 for i in t))


def icosphere(levels):
    g = (1 + math.sqrt(5)) / 2
    v = [unit(p) for p in [(-1, g, 0), (1, g, 0), (-1, -g, 0), (1, -g, 0), (0, -1, g), (0, 1, g),
                           (0, -1, -g), (0, 1, -g), (g, 0, -1), (g, 0, 1), (-g, 0, -1), (-g, 0, 1)]]
    f = [(0, 11, 5), (0, 5, 1), (0, 1, 7), (0, 7, 10), (0, 10, 11), (1, 5, 9), (5, 11, 4), (11, 10, 2),
         (10, 7, 6), (7, 1, 8), (3, 9, 4), (3, 4, 2), (3, 2, 6), (3, 6, 8), (3, 8, 9), (4, 9, 5),
         (2, 4, 11), (6, 2, 10), (8, 6, 7), (9, 8, 1)]
    for _ in range(levels):
        mid = {}

        def m(a, b):
            key = (min(a, b), max(a, b))
            if key not in mid:
                v.append(unit([(v[a][i] + v[b][i]) / 2 for i in range(3)]))
                mid[key] = len(v) - 1
            return mid[key]
        nf = []
        for a, b, c in f:
            ab, bc, ca = m(a, b), m(b, c), m(c, a)
            nf += [(a, ab, ca), (b, bc, ab), (c, ca, bc), (ab, bc, ca)]
        f = nf
    return v, f


def meshes():
    v, f = icosphere(3)
    obj("geosphere.obj", v, f, "A closed icosphere of 1280 triangles (radius 1), for the watertightness sweep.")
    h = 1e-8
    obj("thin_strip.obj", [(0, 0, 0), (1, 0, 0), (1, h, 0), (0, h, 0)], [(0, 1, 2), (0, 2, 3)],
        "A 1 x 1e-8 rectangle cut along its diagonal: two triangles of aspect 1e8.")
    n = 64
    fan = [(0.0, 0.0, 0.0)] + [(math.cos(k * 1e-8), math.sin(k * 1e-8), 0.0) for k in range(n + 1)]
    obj("thin_fan.obj", fan, [(0, k, k + 1) for k in range(1, n + 1)],
        "A fan of 64 triangles 1e-8 rad wide around the origin (aspect 1e8).")


def main():
    critical("critical_below.scene", -1)
    critical("critical_above.scene", +1)
    phong_off()
    touching_inside()
    nested_inside()
    meshes()


main()

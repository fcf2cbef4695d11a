#!/usr/bin/env python3
"""mitsuba3.py - a refray JSON scene (spec/json.md) rendered by Mitsuba 3.

    mitsuba3.py SCENE.json OUT.exr     render with Mitsuba's scalar_rgb variant
    mitsuba3.py --dry-run SCENE.json   print the decision and the Mitsuba scenes
                                      as JSON; needs neither Mitsuba nor numpy

The adapter of `refray conform` for Mitsuba 3 (spec/crosscheck.md, section 5):

    refray conform --kit build/kit --format exr --downsample manifest \\
        --cmd '/abs/venv/bin/python /abs/tests/conform/mitsuba3.py {json} {out}'

OUT is a 32-bit float EXR of (k width) x (k height) pixels with one sample at
each pixel's centre, so its pixel centres are refray's k x k sample points
and --downsample manifest averages them into refray's pixels.

Exit status: 0 rendered; 69 the scene's model is not Mitsuba's ("model not
expressible: REASON; ..." on stderr); 64 usage; 65 not a refray scene; 66 no
such file.

Why this works: refray's image is linear in its lights, its ambient light
and its background, so it is the sum of one Mitsuba render per light (the
`direct` integrator on twosided diffuse surfaces, nothing else glowing)
and one render of the ambient term (every surface an area emitter of
radiance Kd * Ia, the background a `constant` emitter, mirrors `conductor`s
of reflectance Ks, the `path` integrator to refray's max_depth).  One light
per render keeps every render deterministic: with several emitters Mitsuba
picks one at random per sample.
"""
import json
import math
import sys

EXIT_USAGE, EXIT_DATA, EXIT_NO_INPUT, EXIT_NOT_EXPRESSIBLE = 64, 65, 66, 69

FAR = 1e6               # how far a plane reaches (refray's are infinite)
FAR_CLIP = 1e7          # Mitsuba's default (1e4) would cut rays near a horizon


def sub(a, b):
    return [x - y for x, y in zip(a, b)]


def add(a, b):
    return [x + y for x, y in zip(a, b)]


def mul(a, s):
    return [x * s for x in a]


def dot(a, b):
    return sum(x * y for x, y in zip(a, b))


def frame(n):
    """Two unit tangents completing unit n (Duff et al. 2017, as refray's disk
    lights; spec/json.md [JSON-SAMPLES-1])."""
    sign = math.copysign(1.0, n[2])
    a = -1.0 / (sign + n[2])
    b = n[0] * n[1] * a
    return ([1.0 + sign * n[0] * n[0] * a, sign * b, -sign * n[0]],
            [b, sign + n[1] * n[1] * a, -n[1]])


def columns(*cols):
    """The 4 x 4 affine matrix (row lists) whose columns are the three axes
    and the origin given."""
    return [[c[i] for c in cols] for i in range(3)] + [[0.0, 0.0, 0.0, 1.0]]


def rgb(v):
    return {'type': 'rgb', 'value': list(v)}


def reasons(doc):
    """Why Mitsuba cannot draw refray's model of this scene: a list of
    sentences ("lights 0, 1: falloff linear (...)"), empty when it can."""
    found = {}  # (what, why) -> [index, ...], in order of discovery

    def note(what, index, why):
        found.setdefault((what, why), []).append(str(index))
    for i, light in enumerate(doc['lights']):
        if light['kind'] == 'distant':
            continue
        if light['falloff'] != 'inverse_square':
            note("light", i, "falloff %s (Mitsuba's lights fall off as 1/d^2)" % light['falloff'])
        elif light['d0'] != 0:
            note("light", i, "falloff E/(d + d0)^2 with d0 > 0 (Mitsuba's: E/d^2)")
    for i in sorted({p['material'] for p in doc['primitives']}):
        m = doc['materials'][i]
        if m['t'] > 0:
            note("material", i, "transparency t (refray: (1 - t) body colour + t straight or refracted ray, no "
                 "Fresnel term, shadows times t; Mitsuba: Fresnel dielectrics, opaque shadows)")
        elif max(m['Ks']) > 0 and doc['lights']:
            note("material", i, "Phong highlight Ks I max(0, V.R)^n (Mitsuba 3 has no Phong BSDF)")
    mirrors = doc['image']['max_depth'] > 1 and any(max(m['Ks']) > 0 for m in doc['materials'])
    for i, p in enumerate(doc['primitives']):
        if p['kind'] in ('cone', 'torus'):
            note("primitive", i, "Mitsuba 3 has no %s shape (a mesh is another surface)" % p['kind'])
        elif p['kind'] in ('triangle', 'mesh') or p['transform'] is not None:
            note("primitive", i, "triangles, meshes and transforms are not translated by this adapter "
                 "(no analytic scene has one)")
        elif p.get('open') or (p['kind'] == 'disk' and mirrors):
            note("primitive", i, "a sheet whose far side a ray may see (an open cylinder's inside, a disk "
                 "in a mirror), where Mitsuba's one-sided area emitter (the ambient term here) is dark")
    return ["%s%s %s: %s" % (what, "s" if len(idx) > 1 else "", ", ".join(idx), why)
            for (what, why), idx in found.items()]


def sensor(doc, k):
    """Mitsuba's camera for refray's basis: look_at's frame is (left, up,
    forward), left = -right; one sample at each pixel centre."""
    cam, image = doc['camera'], doc['image']
    b = cam['basis']
    left = mul(b['right'], -1.0)
    s = {'type': cam['projection'], 'far_clip': FAR_CLIP,
         'sampler': {'type': 'stratified', 'jitter': False, 'sample_count': 1},
         'film': {'type': 'hdrfilm', 'width': k * image['width'], 'height': k * image['height'],
                  'rfilter': {'type': 'box'}, 'pixel_format': 'rgb', 'component_format': 'float32'}}
    if cam['projection'] == 'perspective':
        s.update(fov=cam['fov'], fov_axis='x', to_world=columns(left, b['up'], b['forward'], cam['eye']))
    else:
        # Mitsuba's orthographic view spans [-1, 1] across: scale it to half the width.
        half = 0.5 * cam['width']
        s['to_world'] = columns(mul(left, half), mul(b['up'], half), b['forward'], cam['eye'])
    return s


def facing_eye(doc, n, p):
    """n or -n, whichever points from p to the camera's side (Mitsuba's area
    emitters shine on the side of the normal only)."""
    return n if dot(n, sub(doc['camera']['eye'], p)) >= 0 else mul(n, -1.0)


def plane_tiles(centre, n, near):
    """An infinite plane as rectangles: a square of half-side `near` about
    `centre` and rings around it, each 4 times wider, out to FAR.  Mitsuba
    places a hit by its float position across the whole rectangle (about
    1e-7 of the rectangle's size), so one large rectangle would move near
    hits; here a hit is off by less than 1e-6 of its distance from the
    centre.  Neighbours overlap by 1e-6 of their size, leaving no crack."""
    t1, t2 = frame(n)

    def rect(x0, x1, y0, y1):
        e = 1e-6 * max(x1 - x0, y1 - y0)
        middle = add(centre, add(mul(t1, 0.5 * (x0 + x1)), mul(t2, 0.5 * (y0 + y1))))
        return {'type': 'rectangle',
                'to_world': columns(mul(t1, 0.5 * (x1 - x0) + e), mul(t2, 0.5 * (y1 - y0) + e), n, middle)}
    a = near
    tiles = [rect(-a, a, -a, a)]
    while a < FAR:
        b = 4 * a
        tiles += [rect(-b, b, a, b), rect(-b, b, -b, -a), rect(-b, -a, -a, a), rect(a, b, -a, a)]
        a = b
    return tiles


def disk_shape(centre, n, radius):
    t1, t2 = frame(n)
    return {'type': 'disk', 'to_world': columns(mul(t1, radius), mul(t2, radius), n, centre)}


def shapes(doc, p):
    """The Mitsuba shapes of primitive p, without BSDF.  Their normals face
    the eye where it matters: Mitsuba's area emitters shine on that side only."""
    kind = p['kind']
    eye = doc['camera']['eye']
    if kind == 'sphere':
        inside = dot(sub(eye, p['center']), sub(eye, p['center'])) < p['radius'] ** 2
        return [{'type': 'sphere', 'center': p['center'], 'radius': p['radius'], 'flip_normals': inside}]
    if kind == 'plane':
        # Centred where the eye's perpendicular meets the plane.
        n = facing_eye(doc, p['normal'], p['point'])
        height = dot(sub(eye, p['point']), n)
        return plane_tiles(sub(eye, mul(n, height)), n, max(height, 1e-3))
    if kind == 'disk':
        return [disk_shape(p['center'], facing_eye(doc, p['normal'], p['center']), p['radius'])]
    if kind == 'box':
        c = mul(add(p['from'], p['to']), 0.5)
        h = mul(sub(p['to'], p['from']), 0.5)
        inside = all(abs(e - m) < r for e, m, r in zip(eye, c, h))
        return [{'type': 'cube', 'to_world': columns([h[0], 0, 0], [0, h[1], 0], [0, 0, h[2]], c),
                 'flip_normals': inside}]
    if kind == 'cylinder':
        axis = sub(p['to'], p['from'])
        axis = mul(axis, 1.0 / math.sqrt(dot(axis, axis)))
        return [{'type': 'cylinder', 'p0': p['from'], 'p1': p['to'], 'radius': p['radius']},
                disk_shape(p['from'], mul(axis, -1.0), p['radius']),
                disk_shape(p['to'], axis, p['radius'])]
    raise AssertionError(kind)  # reasons() refused every other kind


def concentric(s, t):
    """Shirley and Chiu's map of [0,1]^2 onto the unit disk, as refray's."""
    a, b = 2.0 * s - 1.0, 2.0 * t - 1.0
    if a == 0 and b == 0:
        return 0.0, 0.0
    if abs(a) > abs(b):
        r, phi = a, (math.pi / 4) * (b / a)
    else:
        r, phi = b, math.pi / 2 - (math.pi / 4) * (a / b)
    return r * math.cos(phi), r * math.sin(phi)


def emitters(light):
    """Mitsuba emitters for a refray light.  A point light of intensity pi E on
    a diffuse BSDF of reflectance Kd gives Kd E cos / d^2, refray's term (the
    BSDF is Kd / pi); a directional one of irradiance pi E gives Kd E cos.  A
    distributed light becomes its samples as point lights at the centres of
    their grid cells, where refray jitters them (spec/crosscheck.md)."""
    kind = light['kind']
    if kind == 'distant':
        return [{'type': 'directional', 'direction': light['direction'],
                 'irradiance': rgb(mul(light['power'], math.pi))}]
    if kind == 'point':
        return [{'type': 'point', 'position': light['position'], 'intensity': rgb(mul(light['power'], math.pi))}]
    grid = light['sampling']['grid']
    intensity = rgb(mul(light['sampling']['sample_power'], math.pi))
    out = []
    for row in range(grid['rows']):
        for col in range(grid['cols']):
            s, t = (col + 0.5) / grid['cols'], (row + 0.5) / grid['rows']
            if kind == 'rectangle':
                p = add(light['corner'], add(mul(light['edge_u'], s), mul(light['edge_v'], t)))
            else:
                x, y = concentric(s, t)
                f = light['sampling']['frame']
                p = add(light['center'], add(mul(f['t1'], x * light['radius']), mul(f['t2'], y * light['radius'])))
            out.append({'type': 'point', 'position': p, 'intensity': intensity})
    return out


def plan(doc):
    """The renders whose sum is refray's image: 'ambient', a scene, and
    'lit', a scene rendered once with each of 'lights' added."""
    k = doc['camera']['pixel_samples']['k']
    depth = doc['image']['max_depth']
    ia = doc['ambient']
    ambient = {'type': 'scene', 'sensor': sensor(doc, k),
               'integrator': {'type': 'path', 'max_depth': depth, 'rr_depth': depth + 1}}
    lit = {'type': 'scene', 'sensor': sensor(doc, k),
           'integrator': {'type': 'direct', 'emitter_samples': 1, 'bsdf_samples': 0}}
    if any(doc['image']['background']):
        ambient['background'] = {'type': 'constant', 'radiance': rgb(doc['image']['background'])}
    for i, p in enumerate(doc['primitives']):
        m = doc['materials'][p['material']]
        for j, shape in enumerate(shapes(doc, p)):
            name = 'shape%d_%d' % (i, j)
            lit[name] = dict(shape, bsdf={'type': 'twosided', 'side': {'type': 'diffuse', 'reflectance': rgb(m['Kd'])}})
            if max(m['Ks']) > 0 and depth > 1:
                # refray's mirror ray weighted Ks: a perfect conductor ('none') scaled by Ks.
                bsdf = {'type': 'twosided', 'side': {'type': 'conductor', 'material': 'none',
                                                     'specular_reflectance': rgb(m['Ks'])}}
            else:
                bsdf = {'type': 'diffuse', 'reflectance': rgb([0, 0, 0])}
            ambient[name] = dict(shape, bsdf=bsdf)
            glow = [kd * a for kd, a in zip(m['Kd'], ia)]
            if any(glow):
                ambient[name]['emitter'] = {'type': 'area', 'radiance': rgb(glow)}
    return {'ambient': ambient, 'lit': lit, 'lights': [e for light in doc['lights'] for e in emitters(light)]}


def to_mitsuba(value, mi):
    """The plan's plain values with every 4 x 4 'to_world' as a Mitsuba transform."""
    if isinstance(value, dict):
        return {key: mi.ScalarTransform4f(v) if key == 'to_world' else to_mitsuba(v, mi) for key, v in value.items()}
    return value


def render(doc, out):
    import mitsuba as mi
    import numpy as np
    mi.set_variant('scalar_rgb')
    p = plan(doc)
    image = np.array(mi.render(mi.load_dict(to_mitsuba(p['ambient'], mi))), dtype=np.float64)
    lit = to_mitsuba(p['lit'], mi)
    for light in p['lights']:
        image += np.array(mi.render(mi.load_dict(dict(lit, light=light))), dtype=np.float64)
    mi.Bitmap(image[:, :, :3].astype(np.float32)).write(out)


def fail(status, message):
    print("mitsuba3.py: " + message, file=sys.stderr)
    sys.exit(status)


def main(argv):
    dry = argv[:1] == ['--dry-run']
    args = argv[1:] if dry else argv
    if len(args) != (1 if dry else 2):
        fail(EXIT_USAGE, "usage: mitsuba3.py SCENE.json OUT.exr | mitsuba3.py --dry-run SCENE.json")
    try:
        with open(args[0]) as f:
            doc = json.load(f)
        if doc['format']['name'] != 'refray-scene':
            raise ValueError("not a refray scene")
    except OSError as e:
        fail(EXIT_NO_INPUT, "%s: %s" % (args[0], e.strerror))
    except (ValueError, KeyError, TypeError) as e:
        fail(EXIT_DATA, "%s: not a refray JSON scene (spec/json.md): %s" % (args[0], e))
    why = reasons(doc)
    if dry:
        print(json.dumps({'expressible': not why, 'reasons': why, 'plan': None if why else plan(doc)}, indent=1))
    if why:
        fail(EXIT_NOT_EXPRESSIBLE, "model not expressible: " + "; ".join(why))
    if not dry:
        render(doc, args[1])


if __name__ == '__main__':
    main(sys.argv[1:])

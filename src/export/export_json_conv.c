/*
 * export_json_conv.c - the "conventions" header of an exported scene: what
 * a reader needs to compute refray's image from the model without reading
 * refray's source (spec/json.md has the same text with its reasons; spec/
 * shading.md the model).  The numbers of the sampling rule come from the
 * constants the renderer uses (base/sampler.h, render/render.h,
 * render/trace.h), so the header cannot drift from the renderer; a test
 * recomputes light samples from it (tests/check_json.c).  JSON=1 only.
 */
#include "base/sampler.h"
#include "export/export_json_impl.h"
#include "render/render.h"

static void text(export_json_build *b, json_t *obj, const char *key, const char *value)
{
    export_json_set(b, obj, key, json_string(value));
}

static json_t *falloffs(export_json_build *b)
{
    json_t *f = json_object();
    text(b, f, "linear", "E / (d + d0)");
    text(b, f, "inverse_square", "E / (d + d0)^2, computed as (E / (d + d0)) / (d + d0)");
    text(b, f, "none", "E");
    text(b, f, "terms", "E: the power of the light, or of one sample of a distributed light (its power / samples); "
                        "d: the distance from the light (sample) to the shaded point; distant lights have falloff "
                        "none");
    return f;
}

static json_t *material(export_json_build *b)
{
    json_t *m = json_object();
    text(b, m, "Kd", "diffuse reflectivity per channel, in [0, 1]; weights the ambient and the diffuse light");
    text(b, m, "Ks", "specular coefficient per channel, in [0, 1]; weights the Phong highlight and the mirror ray "
                     "alike (there is no separate mirror colour)");
    text(b, m, "n", "Phong exponent, >= 0: the highlight is Ks I max(0, V.R)^n, which is 0 where V.R <= 0 even for "
                    "n = 0");
    text(b, m, "t", "transparency in [0, 1]: 0 opaque, 1 clear; the transmitted ray is weighted by t and the body "
                    "colour (ambient and diffuse) by 1 - t; highlights are not weighted");
    text(b, m, "ior", "index of refraction of the inside of a solid (sphere, box, mesh), > 0; a sheet (plane, "
                      "disk, triangle) has no inside and passes the transmitted ray straight on");
    return m;
}

/* The loader checks a document's constants against scene.h's copies. */
typedef char same_key_constants[RENDER_PIXEL_SALT == SCENE_JSON_PIXEL_SALT && TRACE_KEY_MIRROR == SCENE_JSON_KEY_MIRROR &&
                                        TRACE_KEY_REFRACT == SCENE_JSON_KEY_TRANSMITTED &&
                                        TRACE_KEY_LIGHT == SCENE_JSON_KEY_LIGHT
                                    ? 1
                                    : -1];

static json_t *constants(export_json_build *b)
{
    json_t *c = json_object();
    export_json_set(b, c, "gamma", export_json_hex(SAMPLER_GAMMA));
    export_json_set(b, c, "mul1", export_json_hex(SAMPLER_MUL1));
    export_json_set(b, c, "mul2", export_json_hex(SAMPLER_MUL2));
    export_json_set(b, c, "shift1", json_integer(SAMPLER_SHIFT1));
    export_json_set(b, c, "shift2", json_integer(SAMPLER_SHIFT2));
    export_json_set(b, c, "shift3", json_integer(SAMPLER_SHIFT3));
    export_json_set(b, c, "pixel_salt", export_json_hex(RENDER_PIXEL_SALT));
    export_json_set(b, c, "mirror", json_integer(TRACE_KEY_MIRROR));
    export_json_set(b, c, "transmitted", json_integer(TRACE_KEY_REFRACT));
    export_json_set(b, c, "light", export_json_hex(TRACE_KEY_LIGHT));
    return c;
}

static json_t *light_samples(export_json_build *b)
{
    json_t *l = json_object();
    text(b, l, "model", "a distributed light is `samples` point sources, each of power power / samples "
                        "(sampling.sample_power) and the light's falloff and d0; sample j sits in cell (row, "
                        "column) = (j / cols, j % cols) (integer division) of a rows x cols grid over the light's "
                        "unit square (s, t), jittered in the cell by (u1, u2) in [0, 1): a new jitter for every "
                        "shaded point, a deterministic function of the ray that hit it");
    text(b, l, "grid", "rows = the largest divisor of samples that is <= floor(sqrt(samples)); cols = samples / rows "
                       "(sampling.grid)");
    text(b, l, "cell", "s = (column + u1) / cols, t = (row + u2) / rows");
    text(b, l, "rectangle", "point = corner + (edge_u * s + edge_v * t)");
    text(b, l, "disk", "(x, y) = concentric(s, t); point = center + (t1 * (x * radius) + t2 * (y * radius)); "
                       "concentric: a = 2 s - 1, b = 2 t - 1; (0, 0) if a = b = 0; else if |a| > |b|: r = a, phi = "
                       "(pi / 4) * (b / a); else r = b, phi = pi / 2 - (pi / 4) * (a / b); (x, y) = (r cos phi, r "
                       "sin phi) (Shirley and Chiu 1997); t1, t2: sampling.frame");
    text(b, l, "frame", "for the disk's normal n: sign = copysign(1, n.z), a = -1 / (sign + n.z), b = n.x n.y a; t1 = "
                        "(1 + sign n.x^2 a, sign b, -sign n.x), t2 = (b, sign + n.y^2 a, -n.y) (Duff et al. 2017)");
    text(b, l, "jitter", "sample j of the light at index i of `lights`, at a hit of a ray with key K: L = key(K, "
                         "light + i); u1 = uniform(key(L, 2 j)), u2 = uniform(key(L, 2 j + 1))");
    text(b, l, "ray_keys", "camera sample (a, b) of pixel (i, j) of an image `width` pixels wide with a k x k grid: "
                           "K = key(key(j * width + i, pixel_salt), b * k + a); the rays spawned at a hit of a ray "
                           "with key K: key(K, mirror) for the mirror ray, key(K, transmitted) for the transmitted "
                           "ray (refracted, straight through a sheet, or mirrored on total internal reflection); "
                           "shadow rays draw nothing");
    text(b, l, "key", "key(k, c) = mix(k xor mix(c))");
    text(b, l, "mix", "on unsigned 64-bit words, arithmetic modulo 2^64: z = z + gamma; z = (z xor (z >> shift1)) "
                      "* mul1; z = (z xor (z >> shift2)) * mul2; return z xor (z >> shift3) (the SplitMix64 "
                      "finaliser)");
    text(b, l, "uniform", "uniform(k) = (mix(k) >> 11) * 2^-53, a double in [0, 1)");
    export_json_set(b, l, "constants", constants(b));
    return l;
}

json_t *export_json_conventions(export_json_build *b)
{
    json_t *c = json_object();
    text(b, c, "spec", "spec/json.md; the shading model: spec/shading.md");
    text(b, c, "numbers", "IEEE 754 doubles, written with 17 significant digits: read back with a correctly "
                          "rounding parser they are the doubles refray uses, bit for bit; every formula below is "
                          "evaluated in double, left to right as written");
    text(b, c, "coordinates", "right-handed world coordinates; the camera looks along forward with right = forward x "
                              "up");
    text(b, c, "colour", "linear RGB: every colour is three linear values, every formula works channel by "
                         "channel; no gamma in the model");
    text(b, c, "shading", "colour of a hit of a ray of direction D and depth d: C = (1 - t) B + H + [d < max_depth] "
                          "(Ks C(M) + t C(T)); B = Kd Ia + sum_i S_i Kd I_i (N.L_i); H = sum_i S_i Ks I_i max(0, "
                          "V.R_i)^n; the sums run over the point lights, distant lights and samples of distributed "
                          "lights with N.L_i > 0; Ia = ambient; I_i = falloff of light i at distance d_i; L_i the "
                          "unit vector to the light (for a distant light, -direction); V = -D; N the shading normal "
                          "turned toward V; R_i = 2 (N.L_i) N - L_i; S_i the product of t of every surface between "
                          "the point and the light; M = D - 2 (N.D) N; T the transmitted direction (spec/shading.md "
                          "[SHADE-HIT-1])");
    text(b, c, "depth", "camera rays have depth 1; the mirror and transmitted rays of a hit of depth d have depth d + "
                        "1 and are traced only while d < max_depth: max_depth 1 means camera rays only; past "
                        "max_depth the local colour (1 - t) B + H is kept");
    export_json_set(b, c, "falloff", falloffs(b));
    export_json_set(b, c, "material", material(b));
    text(b, c, "tir", "refraction by Snell's law n1 sin th1 = n2 sin th2 with n1 the medium the ray is in and n2 "
                      "the one it enters (1 outside every solid; a stack of the solids entered); on total internal "
                      "reflection ((n1 cos th1)^2 < n1^2 - n2^2) the transmitted ray is the mirror ray M, still "
                      "weighted by t (spec/shading.md [SHADE-SNELL-2])");
    text(b, c, "miss", "a ray that hits nothing gives image.background");
    text(b, c, "image_rows", "pixel (i, j): column i from the left, row j from the top; row 0 is the top row");
    text(b, c, "pfm_rows", "a PFM file stores its rows bottom to top, as the PFM format defines: the first row in "
                           "the file is image row height - 1");
    text(b, c, "pixel", "the mean of the pixel's k x k camera samples (a box filter), k = image.samples");
    text(b, c, "pixel_samples", "camera sample (a, b) of pixel (i, j) is the image point (x, y) = (i + (a + 0.5) / k, "
                                "j + (b + 0.5) / k), for b = 0 .. k-1 (outer) and a = 0 .. k-1 (inner); its index "
                                "is b * k + a; camera.pixel_samples lists the offsets");
    text(b, c, "camera_ray", "for image point (x, y) of a width x height image: aspect = height / width; sx = 2 * x "
                             "/ width - 1; sy = 1 - 2 * y / height; perspective: half = tan(0.5 * fov * (pi / 180)), "
                             "d = forward + (right * (sx * half) + up * (sy * half * aspect)), direction = d / |d|, "
                             "origin = eye; orthographic: half = 0.5 * width, origin = eye + (right * (sx * half) + "
                             "up * (sy * half * aspect)), direction = forward; right, up, forward: camera.basis; "
                             "|v| = m * sqrt((x/m)^2 + (y/m)^2 + (z/m)^2) with m the largest |component|");
    export_json_set(b, c, "light_samples", light_samples(b));
    return c;
}

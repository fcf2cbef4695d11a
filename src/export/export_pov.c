/*
 * export_pov.c - see export_pov.h; the mapping and its reasons are in
 * spec/crosscheck.md ([XCHK-MAP-*]).
 *
 * Invariants: every point and direction goes through to_pov (z negated:
 * refray is right-handed, POV-Ray left-handed; the mirror maps refray's
 * right = forward x up onto POV-Ray's sky x direction, so the picture is
 * the same, not mirrored); every number is printed with 17 significant
 * digits, which POV-Ray's parser reads back as the same double; nothing is
 * written before pov_export_check has passed.
 *
 * POV-Ray 3.7 facts the mapping rests on (its source, backend/render/
 * trace.cpp, and renders made here):
 *   - a surface's ambient and diffuse terms are scaled by its opacity,
 *     1 - transmit for filter 0, and the transmitted ray by transmit: the
 *     seed's (1 - t) body and t * trace(refracted);
 *   - phong p, phong_size n adds p * light * (R_eye . L)^n when that
 *     cosine is > 0 and the light is in front (N.L > 0): Ks (V.R)^n, not
 *     scaled by the opacity; reflection { rgb K } adds K * trace(mirror);
 *   - a light fades by 2 / (1 + (d / fade_distance)^fade_power) when both
 *     are set, else not at all;
 *   - a camera ray is trace level 1 and a secondary ray of level L is
 *     traced only while L <= max_trace_level (else black): refray's depth.
 */
#include <math.h>
#include <stdarg.h>
#include <stdlib.h>
#include <string.h>
#include "export/export_pov.h"
#include "export/export_pov_far.h"
#include "io/atomic.h"
#include "render/lightsample.h"

/* ---- Notes ---- */

static void add_note(pov_notes *n, const char *fmt, ...)
#if defined(__GNUC__)
    __attribute__((format(printf, 2, 3)))
#endif
    ;

static void add_note(pov_notes *n, const char *fmt, ...)
{
    va_list ap;
    if (n->count < POV_NOTE_MAX) {
        va_start(ap, fmt);
        vsnprintf(n->text[n->count], POV_NOTE_LEN, fmt, ap);
        va_end(ap);
    }
    n->count++;
}

static void refuse(pov_notes *n, const char *fmt, ...)
#if defined(__GNUC__)
    __attribute__((format(printf, 2, 3)))
#endif
    ;

/* Keeps the first reason: the user fixes one thing at a time. */
static void refuse(pov_notes *n, const char *fmt, ...)
{
    va_list ap;
    if (n->refused)
        return;
    n->refused = 1;
    va_start(ap, fmt);
    vsnprintf(n->reason, POV_NOTE_LEN, fmt, ap);
    va_end(ap);
}

/* "file:line" of a span, for notes; "?" when it points nowhere. */
static void where(const scene_model *s, src_span sp, char *buf, size_t size)
{
    if (sp.file < 0 || sp.file >= s->sources.count) {
        snprintf(buf, size, "?");
        return;
    }
    const source_file *f = s->sources.files[sp.file];
    int line, col;
    source_line_col(f, sp.begin, &line, &col);
    snprintf(buf, size, "%.200s:%d", f->path, line);
}

/* "file:line" of primitive p, a mesh's where its statement is. */
static void prim_where(const scene_model *s, const scene_prim *p, char *buf, size_t size)
{
    where(s, p->mesh >= 0 ? s->meshes[p->mesh].where : p->where, buf, size);
}

/* ---- Falloff as POV-Ray fading ---- */

/* A light's falloff as colour * 2 / (1 + (d / distance)^power). */
typedef struct fade {
    double colour;     /* factor on E */
    double distance;   /* fade_distance; 0: no fading written */
    double power;      /* fade_power */
    int exact;
} fade;

/*
 * [XCHK-MAP-FADE-1] linear, d0 > 0: with D = d0 and p = 1,
 * 2/(1 + d/d0) * E/(2 d0) = E/(d + d0) exactly.  linear, d0 = 0: D small,
 * E/(d + D), off by D/(d + D) relative.  inverse_square, d0 = 0: p = 2,
 * 2/(1 + (d/D)^2) * E/(2 D^2) = E/(d^2 + D^2), off by about (D/d)^2.
 * inverse_square with d0 > 0 has no match: 1 + (d/D)^p has no term
 * linear in d, (d + d0)^2 = d^2 + 2 d d0 + d0^2 has.  Returns 0 then.
 */
static int light_fade(const scene_light *l, double radius, fade *f)
{
    f->colour = 1.0;
    f->distance = 0.0;
    f->power = 0.0;
    f->exact = 1;
    if (l->kind == LIGHT_DISTANT || l->falloff == FALLOFF_NONE)
        return 1;
    if (l->falloff == FALLOFF_LINEAR) {
        f->distance = l->d0 > 0 ? l->d0 : fmax(POV_LINEAR_FADE * radius, POV_LINEAR_FADE);
        f->power = 1.0;
        f->colour = 1.0 / (2.0 * f->distance);
        f->exact = l->d0 > 0;
        return 1;
    }
    if (l->d0 > 0)
        return 0;
    f->distance = fmax(POV_SQUARE_FADE * radius, POV_SQUARE_FADE);
    f->power = 2.0;
    f->colour = 1.0 / (2.0 * f->distance * f->distance);
    f->exact = 0;
    return 1;
}

/* ---- Checks ---- */

static const char *light_word(scene_light_kind k)
{
    return k == LIGHT_POINT ? "point_light" : k == LIGHT_DISTANT ? "distant_light" : "distributed_light";
}

static int is_pow2(int n)
{
    return n > 0 && (n & (n - 1)) == 0;
}

/* [XCHK-MAP-AREA-1] the sampling of a distributed light. */
static void check_sampling(const scene_light *l, const char *at, const pov_opts *o, pov_notes *n)
{
    light_grid g = light_grid_for(l->samples);
    if (!o->area_lights) {
        add_note(n, "distributed_light at %s: its %d point sources sit at the centres of their %dx%d cells; "
                 "refray jitters each within its cell (the two agree as samples grow, not sample for sample)",
                 at, l->samples, g.rows, g.cols);
        return;
    }
    add_note(n, "distributed_light at %s as a POV-Ray area_light: visibility is averaged apart from shading "
             "(exact where the light is wholly seen or wholly hidden, not in penumbrae)%s", at,
             l->kind == LIGHT_DISK ? "; `circular` maps the square to the disk radially, not by the concentric "
                                     "map, and not area-preserving" : "");
    if (l->kind == LIGHT_RECTANGLE && (!is_pow2(g.rows) || !is_pow2(g.cols)))
        add_note(n, "distributed_light at %s: a %dx%d grid is not a power of two per axis, so POV-Ray's "
                 "recursive visibility average weights its sources unevenly", at, g.rows, g.cols);
}

static void check_light(const scene_model *s, const scene_light *l, double radius, const pov_opts *o, pov_notes *n)
{
    char at[256];
    fade f;
    where(s, l->where, at, sizeof at);
    if (!light_fade(l, radius, &f)) {
        refuse(n, "%s at %s: inverse_square falloff with d0 %g > 0 has no POV-Ray equivalent (POV-Ray fades by "
               "2/(1 + (d/D)^p), which has no term linear in d as (d + d0)^2 has); use d0 0, or falloff "
               "linear or none", light_word(l->kind), at, l->d0);
        return;
    }
    if (!f.exact)
        add_note(n, "%s at %s: %s falloff with d0 0 written as fade_distance %.3g fade_power %g (light "
                 "E/(d%s + D%s), relative error about %s at distance d)", light_word(l->kind), at,
                 l->falloff == FALLOFF_LINEAR ? "linear" : "inverse_square", f.distance, f.power,
                 f.power == 2 ? "^2" : "", f.power == 2 ? "^2" : "", f.power == 2 ? "(D/d)^2" : "D/d");
    if (l->kind == LIGHT_RECTANGLE || l->kind == LIGHT_DISK)
        check_sampling(l, at, o, n);
}

/* An open cylinder or cone is a sheet, as in refray ([XCHK-MAP-QUADRIC-1]). */
static int is_solid(const scene_prim *p)
{
    return scene_prim_is_solid(p) || (p->kind == PRIM_MESH && p->u.mesh.closed);
}

static int is_smooth(const scene_trimesh *g)
{
    for (int i = 0; g->tri_normal && i < g->tri_count; i++)
        if (g->tri_normal[i][0] >= 0)
            return 1;
    return 0;
}

static int is_grey(rgb c)
{
    return c.x == c.y && c.y == c.z;
}

/* How the primitives use a material: as a solid, as a sheet. */
static void material_use(const scene_model *s, int m, int *solid, int *sheet)
{
    *solid = *sheet = 0;
    for (int i = 0; i < s->prim_count; i++) {
        if (s->prims[i].material != m)
            continue;
        if (is_solid(&s->prims[i]))
            *solid = 1;
        else
            *sheet = 1;
    }
}

/* [XCHK-MAP-TIR-1] On total internal reflection POV-Ray adds the mirror
 * ray once, unweighted (and skips the Ks mirror ray); refray adds it with
 * weight Ks + t.  They agree where Ks + t = 1. */
static int tir_differs(const scene_material *m)
{
    return fabs(m->ks.x + m->t - 1) > 1e-12 || fabs(m->ks.y + m->t - 1) > 1e-12 ||
           fabs(m->ks.z + m->t - 1) > 1e-12;
}

/* [XCHK-MAP-LEVEL-1] A transparent surface with the same ior on both sides
 * (a sheet, or a solid of ior 1) passes the ray straight on.  refray counts
 * that as a level of depth; POV-Ray does not when the two iors are equal
 * (it continues the ray), so by default each such surface gets its own ior
 * a few float steps above 1 (POV-Ray keeps iors in single precision). */
static int passes_straight(const scene_model *s, const scene_prim *p)
{
    const scene_material *m = &s->materials[p->material];
    return s->image.max_depth > 1 && m->t > 0 && (!is_solid(p) || m->ior == 1);
}

static void check_material(const scene_model *s, int index, const pov_opts *o, pov_notes *n)
{
    const scene_material *m = &s->materials[index];
    int solid, sheet, deep = s->image.max_depth > 1;
    char at[256], name[320];
    material_use(s, index, &solid, &sheet);
    if (!solid && !sheet)
        return;
    where(s, m->where, at, sizeof at);
    snprintf(name, sizeof name, "material %.40s (%.250s)", m->name ? m->name : "inline", at);
    if (!is_grey(m->ks) && s->light_count > 0)
        add_note(n, "%s: Ks [%g, %g, %g] is not grey and POV-Ray's phong is one number: the highlight uses "
                 "their mean %g (the mirror ray keeps the colour)", name, (double)m->ks.x, (double)m->ks.y,
                 (double)m->ks.z, (double)(m->ks.x + m->ks.y + m->ks.z) / 3);
    if (deep && solid && m->t > 0 && m->ior != 1 && tir_differs(m))
        add_note(n, "%s: on total internal reflection POV-Ray adds the mirror ray with weight 1, refray "
                 "with Ks + t (they agree only where Ks + t = 1)", name);
    if (deep && m->t > 0 && (sheet || m->ior == 1) && o->plain_sheets)
        add_note(n, "%s: POV-Ray passes a ray straight through a surface with the same ior on both sides "
                 "without counting a trace level, refray counts one (they differ only where max_depth cuts "
                 "such a path)", name);
    else if (deep && m->t > 0 && (sheet || m->ior == 1))
        add_note(n, "%s: its surfaces get iors 1 + j 2^-22 (j <= %d, one per surface) so that POV-Ray counts a "
                 "straight pass as a trace level as refray does; rays then bend by up to j 2.4e-7 tan(incidence)",
                 name, POV_NUDGE_CYCLE);
}

/* [XCHK-MAP-MESH-2] POV-Ray turns a mirror ray that a vertex normal sends
 * into the surface back out (reflecting it about the geometric normal);
 * refray traces the mirror ray as it is.  A ray refracted about a vertex
 * normal can head back into the mesh too: refray then goes by the face's
 * orientation, POV-Ray by its list of interiors. */
static void check_mesh_mirror(const scene_model *s, const scene_mesh *m, pov_notes *n)
{
    char at[256];
    const scene_material *mat = &s->materials[s->prims[m->prim].material];
    if (!is_smooth(&m->geom) || s->image.max_depth < 2 || (vec_max_component(mat->ks) <= 0 && !(mat->t > 0)))
        return;
    where(s, m->where, at, sizeof at);
    if (vec_max_component(mat->ks) > 0)
        add_note(n, "mesh at %s has vertex normals and Ks > 0: where a vertex normal sends the mirror ray into "
                 "the surface POV-Ray reflects it out again about the geometric normal, refray traces it as it is",
                 at);
    if (mat->t > 0)
        add_note(n, "mesh at %s has vertex normals and t > 0: where a ray refracted about a vertex normal heads "
                 "back into the surface, refray follows the face's orientation and POV-Ray its list of "
                 "interiors", at);
}

/* Whether some triangle's corners have different normals: a curved
 * surface, where Hanika's lifted point leaves the facet. */
static int is_curved(const scene_trimesh *g)
{
    for (int i = 0; g->tri_normal && i < g->tri_count; i++) {
        const int *c = g->tri_normal[i];
        if (c[0] >= 0 && (memcmp(&g->normals[c[0]], &g->normals[c[1]], sizeof(vec3)) != 0 ||
                          memcmp(&g->normals[c[0]], &g->normals[c[2]], sizeof(vec3)) != 0))
            return 1;
    }
    return 0;
}

/* [XCHK-MAP-MESH-3] refray starts the shadow rays of a smooth mesh at
 * Hanika's lifted point ([SHADE-TERMINATOR-1]); POV-Ray starts them on the
 * facet, which shadows itself near the terminator. */
static void check_mesh(const scene_model *s, const scene_mesh *m, const pov_opts *o, pov_notes *n)
{
    char at[256];
    check_mesh_mirror(s, m, n);
    if (o->facet_shadows || !s->features.shadows || !is_curved(&m->geom))
        return;
    where(s, m->where, at, sizeof at);
    add_note(n, "mesh at %s has vertex normals and the scene has shadows: refray starts a smooth triangle's shadow "
             "rays at the lifted point (no dark facets at the terminator), POV-Ray on the facet, which can shadow "
             "itself there", at);
}

/* [XCHK-MAP-SHADOW-2] POV-Ray does not count a shadow-ray crossing within
 * SHADOW_TOLERANCE (1e-3) of the shaded point or of the transparent
 * crossing before it.  Inside a transparent solid with edges, a point next
 * to an edge sends its shadow ray out through the adjacent face that
 * close; and a shadow ray that leaves a transparent solid where another
 * surface cuts or touches it passes that surface within 1e-3: refray
 * counts those crossings, POV-Ray does not. */
static void check_shadow_tolerance(const scene_model *s, pov_notes *n)
{
    if (s->light_count == 0)
        return;
    for (int i = 0; i < s->prim_count; i++) {
        const scene_prim *p = &s->prims[i];
        int mesh = p->kind == PRIM_MESH, other;
        char at[256], at_other[256];
        if (!(s->materials[p->material].t > 0))
            continue;
        prim_where(s, p, at, sizeof at);
        int edges = mesh || (scene_prim_is_solid(p) && p->kind != PRIM_SPHERE && p->kind != PRIM_TORUS);
        const char *kind = mesh ? "mesh" : scene_prim_name(p->kind);
        if (edges)
            add_note(n, "transparent %s at %s has edges: POV-Ray ignores a shadow-ray crossing within 1e-3 of the "
                     "shaded point (SHADOW_TOLERANCE), so inside it, next to an edge, the adjacent face does not "
                     "shadow in POV-Ray and lets t through in refray", kind, at);
        else if (scene_prim_is_solid(p) && (other = pov_far_near_solid(s, i, POV_SHADOW_TOLERANCE, 0)) >= 0) {
            const scene_prim *q = &s->prims[other];
            prim_where(s, q, at_other, sizeof at_other);
            add_note(n, "transparent %s at %s cuts or comes within 1e-3 of the surface at %s: POV-Ray ignores a "
                     "shadow-ray crossing within 1e-3 of the one before it (SHADOW_TOLERANCE), so a shadow ray "
                     "that leaves it next to that surface passes that surface in POV-Ray", kind, at, at_other);
        }
    }
}

/* [XCHK-MAP-CONTACT-1] A transparent surface touching an opaque one:
 * refray takes the contact as the limit of a gap between them
 * ([NUM-GLASS-3]), POV-Ray by its own tolerances (a shape drops a hit
 * nearer than 1e-6 along a ray, a shadow ray a crossing within 1e-3), so
 * the rays that reach the contact differ (tests/attack12 finding 7).
 * Conservative: any transparent primitive within 1e-3 of an opaque one,
 * by the sphere's own surface or by bounding boxes, lights or none. */
static void check_glass_contact(const scene_model *s, pov_notes *n)
{
    for (int i = 0; i < s->prim_count; i++) {
        const scene_prim *p = &s->prims[i];
        char at[256], at_other[256];
        int other;
        if (!(s->materials[p->material].t > 0) || (other = pov_far_near_solid(s, i, POV_SHADOW_TOLERANCE, 1)) < 0)
            continue;
        prim_where(s, p, at, sizeof at);
        prim_where(s, &s->prims[other], at_other, sizeof at_other);
        add_note(n, "transparent %s at %s touches or comes within 1e-3 of the opaque surface at %s: refray takes "
                 "the contact as the limit of a gap ([NUM-GLASS-3]), POV-Ray by its tolerances (hits within 1e-6 "
                 "along a ray, shadow crossings within 1e-3 dropped), so rays that reach the contact differ",
                 p->kind == PRIM_MESH ? "mesh" : scene_prim_name(p->kind), at, at_other);
    }
}

/* [XCHK-MAP-FAR-1] POV-Ray drops every hit beyond MAX_DISTANCE (1e7).  A
 * plane can be met that far by a camera ray (its horizon), and then so can
 * everything else by the rays that leave it; and a shadow ray toward a
 * distant light can meet a plane that far. */
static void check_far(const scene_model *s, pov_notes *n)
{
    pov_bounds b = pov_far_bounds(s);
    double spread = pov_far_spread(s, &b);
    for (int i = 0; i < s->prim_count; i++) {
        const scene_prim *w = &s->prims[i];
        char at[256], lat[256];
        if (w->kind != PRIM_PLANE)
            continue;
        where(s, w->where, at, sizeof at);
        double reach = pov_far_camera_reach(s, w);
        if (reach + spread > POV_MAX_DISTANCE)
            add_note(n, "plane at %s: camera rays meet it up to %.3g units away, and the rays that leave it reach "
                     "the rest of the scene within %.3g more: beyond 1e7 POV-Ray sees nothing (MAX_DISTANCE), "
                     "refray sees what is there", at, reach, spread);
        for (int j = 0; j < s->light_count; j++) {
            const scene_light *l = &s->lights[j];
            double shadow;
            if (l->kind != LIGHT_DISTANT || !((shadow = pov_far_shadow_reach(s, &b, l, w)) > POV_MAX_DISTANCE))
                continue;
            where(s, l->where, lat, sizeof lat);
            add_note(n, "distant_light at %s and plane at %s: a shadow ray can meet the plane %.3g units away; "
                     "beyond 1e7 POV-Ray finds no occluder (MAX_DISTANCE), refray finds the plane", lat, at,
                     shadow);
        }
    }
}

int pov_export_check(const scene_model *s, const pov_opts *o, pov_notes *notes)
{
    pov_bounds b = pov_far_bounds(s);
    memset(notes, 0, sizeof *notes);
    for (int i = 0; i < s->light_count; i++)
        check_light(s, &s->lights[i], b.radius, o, notes);
    for (int i = 0; i < s->material_count; i++)
        check_material(s, i, o, notes);
    for (int i = 0; i < s->mesh_count; i++)
        check_mesh(s, &s->meshes[i], o, notes);
    check_shadow_tolerance(s, notes);
    check_glass_contact(s, notes);
    check_far(s, notes);
    if (s->image.max_depth > POV_MAX_TRACE_LEVEL)
        add_note(notes, "max_depth %d is over POV-Ray's limit: max_trace_level %d (they differ only for paths "
                 "deeper than that)", s->image.max_depth, POV_MAX_TRACE_LEVEL);
    return !notes->refused;
}

/* ---- Writing ---- */

static vec3 to_pov(vec3 v)
{
    return vec_make(v.x, v.y, -v.z);
}

static void put_num(FILE *fp, double x)
{
    fprintf(fp, "%.17g", x == 0 ? 0.0 : x);
}

static void put_vec(FILE *fp, vec3 v)
{
    fputc('<', fp);
    put_num(fp, v.x);
    fputs(", ", fp);
    put_num(fp, v.y);
    fputs(", ", fp);
    put_num(fp, v.z);
    fputc('>', fp);
}

/* A comment line: control bytes (a newline in a path) would end it early. */
static void put_comment_text(FILE *fp, const char *text)
{
    for (const unsigned char *c = (const unsigned char *)text; *c; c++)
        fputc(*c < 0x20 || *c == 0x7f ? '?' : *c, fp);
}

static void write_header(FILE *fp, const scene_model *s, const pov_opts *o, const pov_notes *n)
{
    int w, h, k = pov_render_size(s, &w, &h);
    fputs("// POV-Ray 3.7 scene written by `refray export --to pov`", fp);
    if (o->source) {
        fputs(" from ", fp);
        put_comment_text(fp, o->source);
    }
    fprintf(fp, "\n// Render it linear, unfiltered, on one thread:\n"
                "//   povray +I<this file> +O<out>.png +W%d +H%d -A -D +WT1 +FN16 File_Gamma=1.0 "
                "Output_Alpha=off\n", w, h);
    if (k > 1)
        fprintf(fp, "// then average each %dx%d block of pixels: refray's %dx%d grid per pixel.\n", k, k, k, k);
    if (o->scale > 0 && o->scale != 1) {
        fputs("// then divide it by ", fp);
        put_num(fp, o->scale);
        fputs(": every light, the ambient light and the background are scaled by it.\n", fp);
    }
    fprintf(fp, "// pov-args: +W%d +H%d -A\n// pov-downsample: %d\n// pov-scale: ", w, h, k);
    put_num(fp, o->scale > 0 ? o->scale : 1);
    fputc('\n', fp);
    fprintf(fp, "// approximations: %d%s\n", n->count, n->count ? " (see spec/crosscheck.md)" : "");
    for (int i = 0; i < n->count && i < POV_NOTE_MAX; i++) {
        fputs("//   - ", fp);
        put_comment_text(fp, n->text[i]);
        fputc('\n', fp);
    }
    if (n->count > POV_NOTE_MAX)
        fprintf(fp, "//   - ... and %d more\n", n->count - POV_NOTE_MAX);
    fputs("#version 3.7;\n\n", fp);
}

/* [XCHK-MAP-GLOBAL-1] Linear working space, the ambient light, the depth,
 * and no adaptive cut-off of weak rays. */
static void write_globals(FILE *fp, const scene_model *s, double scale)
{
    int depth = s->image.max_depth < POV_MAX_TRACE_LEVEL ? s->image.max_depth : POV_MAX_TRACE_LEVEL;
    fputs("global_settings {\n  assumed_gamma 1.0\n  ambient_light rgb ", fp);
    put_vec(fp, vec_scale(s->ambient, scale));
    fprintf(fp, "\n  max_trace_level %d\n  adc_bailout 0\n}\n\nbackground { rgb ", depth);
    put_vec(fp, vec_scale(s->image.background, scale));
    fputs(" }\n\n", fp);
}

/* [XCHK-MAP-CAMERA-1] right and up carry the image's aspect; `angle` is
 * the horizontal field of view (POV-Ray sizes the direction from right);
 * an orthographic camera's right and up are the view's extent.  sky is
 * refray's up as written; look_at comes last, as it re-aims the others. */
static void write_camera(FILE *fp, const scene_model *s)
{
    const scene_camera *c = &s->camera;
    double aspect = (double)s->image.width / (double)s->image.height;
    int ortho = c->kind == CAMERA_ORTHOGRAPHIC;
    fprintf(fp, "camera {\n  %s\n  location ", ortho ? "orthographic" : "perspective");
    put_vec(fp, to_pov(c->eye));
    fputs("\n  right ", fp);
    put_vec(fp, vec_make(ortho ? c->width : aspect, 0, 0));
    fputs("\n  up ", fp);
    put_vec(fp, vec_make(0, ortho ? c->width / aspect : 1.0, 0));
    fputs("\n  sky ", fp);
    put_vec(fp, to_pov(c->up));
    if (!ortho) {
        fputs("\n  angle ", fp);
        put_num(fp, c->fov);
    }
    fputs("\n  look_at ", fp);
    put_vec(fp, to_pov(c->look_at));
    fputs("\n}\n\n", fp);
}

static void write_fade(FILE *fp, const fade *f)
{
    if (f->distance <= 0)
        return;
    fputs(" fade_distance ", fp);
    put_num(fp, f->distance);
    fputs(" fade_power ", fp);
    put_num(fp, f->power);
}

static void write_point_source(FILE *fp, vec3 pos, rgb power, const fade *f)
{
    fputs("light_source { ", fp);
    put_vec(fp, to_pov(pos));
    fputs(" color rgb ", fp);
    put_vec(fp, vec_scale(power, f->colour));
    write_fade(fp, f);
    fputs(" }\n", fp);
}

/* [XCHK-MAP-DISTANT-1] A parallel light: POV-Ray shades with the fixed
 * direction and tests shadows up to the plane through its location, which
 * is put beyond every point POV-Ray can shade by MAX_DISTANCE, so that its
 * shadow rays are cut by MAX_DISTANCE alone, like every other ray
 * (pov_far_distant_distance).  point_at is the scene's centre, so the
 * direction POV-Ray takes from the two is exact to rounding. */
static void write_distant(FILE *fp, const scene_model *s, const scene_light *l, double scale, const pov_bounds *b)
{
    int levels = s->image.max_depth < POV_MAX_TRACE_LEVEL ? s->image.max_depth : POV_MAX_TRACE_LEVEL;
    vec3 from = vec_sub(b->centre, vec_scale(l->direction, pov_far_distant_distance(s, b, levels)));
    fputs("light_source { ", fp);
    put_vec(fp, to_pov(from));
    fputs(" color rgb ", fp);
    put_vec(fp, vec_scale(l->power, scale));
    fputs(" parallel point_at ", fp);
    put_vec(fp, to_pov(b->centre));
    fputs(" }\n", fp);
}

/* [XCHK-MAP-AREA-1] Default: the light's samples as point sources of
 * E/samples at the centres of its cells, where refray puts them before
 * jitter (lightsample.h). */
static void write_distributed_points(FILE *fp, const scene_light *l, const fade *f)
{
    light_grid g = light_grid_for(l->samples);
    vec3 t1 = vec_splat(0), t2 = vec_splat(0);
    rgb power = vec_scale(l->power, 1.0 / l->samples);
    if (l->kind == LIGHT_DISK)
        light_frame(l->normal, &t1, &t2);
    for (int j = 0; j < l->samples; j++) {
        double a, b;
        light_cell_point(g, j, 0.5, 0.5, &a, &b);
        write_point_source(fp, light_point(l, t1, t2, a, b), power, f);
    }
}

static int ceil_log2(int n)
{
    int k = 0;
    while ((1 << k) < n)
        k++;
    return k;
}

/* With --area-lights: POV-Ray's grid runs from edge to edge of its axes,
 * so the axes are shrunk by (n - 1)/n to put the points at the cells'
 * centres; area_illumination shades each point (not only the centre);
 * adaptive as deep as the grid so every point's visibility is traced. */
static void write_area(FILE *fp, const scene_light *l, const fade *f)
{
    light_grid g = light_grid_for(l->samples);
    vec3 u = l->edge_u, v = l->edge_v, centre = l->position;
    if (l->kind == LIGHT_DISK) {
        light_frame(l->normal, &u, &v);
        u = vec_scale(u, 2 * l->radius);
        v = vec_scale(v, 2 * l->radius);
    } else {
        centre = vec_add(centre, vec_scale(vec_add(u, v), 0.5));
    }
    vec3 a1 = g.cols > 1 ? vec_scale(u, (g.cols - 1.0) / g.cols) : u;
    vec3 a2 = g.rows > 1 ? vec_scale(v, (g.rows - 1.0) / g.rows) : v;
    fputs("light_source { ", fp);
    put_vec(fp, to_pov(centre));
    fputs(" color rgb ", fp);
    put_vec(fp, vec_scale(l->power, f->colour));
    fputs("\n  area_light ", fp);
    put_vec(fp, to_pov(a1));
    fputs(", ", fp);
    put_vec(fp, to_pov(a2));
    fprintf(fp, ", %d, %d adaptive %d area_illumination on%s", g.cols, g.rows,
            ceil_log2(g.cols > g.rows ? g.cols : g.rows) + 1, l->kind == LIGHT_DISK ? " circular" : "");
    write_fade(fp, f);
    fputs(" }\n", fp);
}

static void write_lights(FILE *fp, const scene_model *s, const pov_opts *o, const pov_bounds *b)
{
    double scale = o->scale > 0 ? o->scale : 1.0;
    for (int i = 0; i < s->light_count; i++) {
        const scene_light *l = &s->lights[i];
        fade f;
        light_fade(l, b->radius, &f);
        f.colour *= scale;
        fprintf(fp, "// %s %d\n", light_word(l->kind), i + 1);
        if (l->kind == LIGHT_POINT)
            write_point_source(fp, l->position, l->power, &f);
        else if (l->kind == LIGHT_DISTANT)
            write_distant(fp, s, l, scale, b);
        else if (o->area_lights)
            write_area(fp, l, &f);
        else
            write_distributed_points(fp, l, &f);
    }
    fputs("\n", fp);
}

/* [XCHK-MAP-FINISH-1] pigment Kd with transmit t (opacity 1 - t scales
 * ambient and diffuse; t weights the transmitted ray and the shadows);
 * ambient 1 and diffuse 1 in place of POV-Ray's 0.1 and 0.6, so that the
 * terms are Kd Ia and Kd E cos; phong and reflection from Ks. */
static void write_texture(FILE *fp, int index, const scene_material *m)
{
    double phong = is_grey(m->ks) ? m->ks.x : (m->ks.x + m->ks.y + m->ks.z) / 3;
    fprintf(fp, "#declare RF_T%d = texture {  // %s\n  pigment { rgbt <", index, m->name ? m->name : "inline");
    put_num(fp, m->kd.x);
    fputs(", ", fp);
    put_num(fp, m->kd.y);
    fputs(", ", fp);
    put_num(fp, m->kd.z);
    fputs(", ", fp);
    put_num(fp, m->t);
    fputs("> }\n  finish { ambient 1 diffuse 1", fp);
    if (phong > 0) {
        fputs(" phong ", fp);
        put_num(fp, phong);
        fputs(" phong_size ", fp);
        put_num(fp, m->n);
        fputs(" reflection { rgb ", fp);
        put_vec(fp, m->ks);
        fputs(" }", fp);
    }
    fputs(" }\n}\n", fp);
}

/* [XCHK-MAP-SHADOW-1] Only solids get an ior: a sheet (plane, disk, lone
 * triangle) passes rays straight on, as POV-Ray does with ior 1 (a POV-Ray
 * plane is a half-space and would bend them).  A clear surface (t = 1)
 * lets all light through, which no_shadow says without tracing it. */
static void write_material_ref(FILE *fp, const scene_model *s, const pov_opts *o, const scene_prim *p, int *nudged)
{
    const scene_material *m = &s->materials[p->material];
    fprintf(fp, "  texture { RF_T%d }\n", p->material);
    if (is_solid(p) && m->t > 0 && m->ior != 1) {
        fputs("  interior { ior ", fp);
        put_num(fp, m->ior);
        fputs(" }\n", fp);
    } else if (passes_straight(s, p) && !o->plain_sheets) {
        fputs("  interior { ior ", fp);
        put_num(fp, 1.0 + (1 + (*nudged)++ % POV_NUDGE_CYCLE) * POV_NUDGE);
        fputs(" }  // not 1: see [XCHK-MAP-LEVEL-1]\n", fp);
    }
    if (m->t >= 1)
        fputs("  no_shadow\n", fp);
}

/* POV-Ray's matrix <a00, ..., a32> maps x' = a00 x + a10 y + a20 z + a30:
 * the transpose of refray's row-major linear part, then the translation.
 * In POV-Ray's frame the transform is F M F with F = diag(1, 1, -1). */
static void write_matrix(FILE *fp, const xform *x)
{
    static const double f[3] = {1, 1, -1};
    fputs("  matrix <", fp);
    for (int i = 0; i < 4; i++)
        for (int j = 0; j < 3; j++) {
            double a = i < 3 ? f[j] * x->m[j][i] * f[i] : f[j] * x->m[j][3];
            put_num(fp, a);
            if (i < 3 || j < 2)
                fputs(", ", fp);
        }
    fputs(">\n", fp);
}

/* [XCHK-MAP-QUADRIC-1] POV-Ray's torus lies about its y axis at the
 * origin: a matrix takes y to the axis (in POV-Ray's frame) and the origin
 * to the centre.  Any orthonormal frame with that image of y will do, the
 * torus being the same under every turn about its axis and every mirror
 * through it. */
static void write_torus_placement(FILE *fp, const scene_prim *p)
{
    vec3 a = vec_normalize(to_pov(p->u.torus.axis)), c = to_pov(p->u.torus.center);
    vec3 least = fabs(a.x) <= fabs(a.y) && fabs(a.x) <= fabs(a.z) ? vec_make(1, 0, 0)
                 : fabs(a.y) <= fabs(a.z)                          ? vec_make(0, 1, 0)
                                                                    : vec_make(0, 0, 1);
    vec3 u = vec_normalize(vec_cross(a, least)), w = vec_cross(u, a);
    const vec3 rows[4] = {u, a, w, c};
    fputs("  sturm\n  matrix <", fp);
    for (int i = 0; i < 4; i++) {
        put_num(fp, rows[i].x);
        fputs(", ", fp);
        put_num(fp, rows[i].y);
        fputs(", ", fp);
        put_num(fp, rows[i].z);
        fputs(i < 3 ? ", " : ">", fp);
    }
}

static void write_shape(FILE *fp, const scene_prim *p)
{
    switch (p->kind) {
    case PRIM_SPHERE:
        fputs("sphere {\n  ", fp);
        put_vec(fp, to_pov(p->u.sphere.center));
        fputs(", ", fp);
        put_num(fp, p->u.sphere.radius);
        break;
    case PRIM_PLANE:
        fputs("plane {\n  ", fp);
        put_vec(fp, to_pov(p->u.plane.normal));
        fputs(", ", fp);
        put_num(fp, vec_dot(p->u.plane.normal, p->u.plane.point));
        break;
    case PRIM_DISK:
        fputs("disc {\n  ", fp);
        put_vec(fp, to_pov(p->u.disk.center));
        fputs(", ", fp);
        put_vec(fp, to_pov(p->u.disk.normal));
        fputs(", ", fp);
        put_num(fp, p->u.disk.radius);
        break;
    case PRIM_BOX:
        /* z negated swaps which corner is low; POV-Ray takes either order. */
        fputs("box {\n  ", fp);
        put_vec(fp, to_pov(p->u.box.lo));
        fputs(", ", fp);
        put_vec(fp, to_pov(p->u.box.hi));
        break;
    case PRIM_CYLINDER:
        fputs("cylinder {\n  ", fp);
        put_vec(fp, to_pov(p->u.cylinder.from));
        fputs(", ", fp);
        put_vec(fp, to_pov(p->u.cylinder.to));
        fputs(", ", fp);
        put_num(fp, p->u.cylinder.radius);
        fputs(p->u.cylinder.open ? "\n  open" : "", fp);
        break;
    case PRIM_CONE:
        fputs("cone {\n  ", fp);
        put_vec(fp, to_pov(p->u.cone.from));
        fputs(", ", fp);
        put_num(fp, p->u.cone.radius[0]);
        fputs(", ", fp);
        put_vec(fp, to_pov(p->u.cone.to));
        fputs(", ", fp);
        put_num(fp, p->u.cone.radius[1]);
        fputs(p->u.cone.open ? "\n  open" : "", fp);
        break;
    case PRIM_TORUS:
        fputs("torus {\n  ", fp);
        put_num(fp, p->u.torus.major);
        fputs(", ", fp);
        put_num(fp, p->u.torus.minor);
        fputc('\n', fp);
        write_torus_placement(fp, p);
        break;
    case PRIM_MESH: /* written by write_mesh */
        break;
    case PRIM_TRIANGLE:
        fputs(p->u.triangle.n ? "smooth_triangle {\n  " : "triangle {\n  ", fp);
        for (int i = 0; i < 3; i++) {
            put_vec(fp, to_pov(p->u.triangle.p[i]));
            if (p->u.triangle.n) {
                fputs(", ", fp);
                put_vec(fp, to_pov(p->u.triangle.n[i]));
            }
            fputs(i < 2 ? ", " : "", fp);
        }
        break;
    }
    fputc('\n', fp);
}

static void write_prim(FILE *fp, const scene_model *s, const pov_opts *o, const scene_prim *p, int *nudged)
{
    write_shape(fp, p);
    write_material_ref(fp, s, o, p, nudged);
    if (p->frame)
        write_matrix(fp, &p->frame->to_world);
    fputs("}\n", fp);
}

static void put_list_item(FILE *fp, vec3 v)
{
    fputs(",\n    ", fp);
    put_vec(fp, to_pov(v));
}

/* normal_vectors: the mesh's normals, then one geometric normal for each
 * flat triangle of a smooth mesh (normal_indices, after the faces as
 * POV-Ray wants, says which each corner uses). */
static void write_mesh_normals(FILE *fp, const scene_trimesh *g)
{
    int flat = 0;
    for (int i = 0; i < g->tri_count; i++)
        flat += g->tri_normal[i][0] < 0;
    fprintf(fp, "  normal_vectors { %d", g->normal_count + flat);
    for (int i = 0; i < g->normal_count; i++)
        put_list_item(fp, g->normals[i]);
    for (int i = 0; i < g->tri_count; i++) {
        const int *c = g->tri[i];
        if (g->tri_normal[i][0] < 0)
            put_list_item(fp, vec_normalize(vec_cross(vec_sub(g->positions[c[1]], g->positions[c[0]]),
                                                      vec_sub(g->positions[c[2]], g->positions[c[0]]))));
    }
    fputs(" }\n", fp);
}

static void write_normal_indices(FILE *fp, const scene_trimesh *g)
{
    fprintf(fp, "  normal_indices { %d", g->tri_count);
    for (int i = 0, flat_index = g->normal_count; i < g->tri_count; i++) {
        int n[3] = {g->tri_normal[i][0], g->tri_normal[i][1], g->tri_normal[i][2]};
        if (n[0] < 0)
            n[0] = n[1] = n[2] = flat_index++;
        fprintf(fp, ",\n    <%d, %d, %d>", n[0], n[1], n[2]);
    }
    fputs(" }\n", fp);
}

/* [XCHK-MAP-MESH-1] A mesh as mesh2 with its shared vertices as refray
 * holds them (world space), its vertex normals if any triangle has them,
 * and, when it is closed, an inside_vector so that POV-Ray treats it as a
 * solid for refraction, as refray does (an open mesh is sheets in both). */
static void write_mesh(FILE *fp, const scene_model *s, const pov_opts *o, const scene_prim *p, int *nudged)
{
    const scene_trimesh *g = &p->u.mesh;
    fprintf(fp, "mesh2 {\n  vertex_vectors { %d", g->position_count);
    for (int i = 0; i < g->position_count; i++)
        put_list_item(fp, g->positions[i]);
    fputs(" }\n", fp);
    if (is_smooth(g))
        write_mesh_normals(fp, g);
    fprintf(fp, "  face_indices { %d", g->tri_count);
    for (int i = 0; i < g->tri_count; i++)
        fprintf(fp, ",\n    <%d, %d, %d>", g->tri[i][0], g->tri[i][1], g->tri[i][2]);
    fputs(" }\n", fp);
    if (is_smooth(g))
        write_normal_indices(fp, g);
    if (g->closed)
        fputs("  inside_vector <0, 0, 1>\n", fp);
    write_material_ref(fp, s, o, p, nudged);
    fputs("}\n", fp);
}

static void write_geometry(FILE *fp, const scene_model *s, const pov_opts *o)
{
    int nudged = 0;
    for (int i = 0; i < s->material_count; i++)
        write_texture(fp, i, &s->materials[i]);
    fputc('\n', fp);
    for (int i = 0; i < s->prim_count; i++) {
        const scene_prim *p = &s->prims[i];
        if (p->kind == PRIM_MESH)
            write_mesh(fp, s, o, p, &nudged);
        else
            write_prim(fp, s, o, p, &nudged);
    }
}

int pov_export_write(const scene_model *s, const pov_opts *o, FILE *fp, pov_notes *notes)
{
    pov_bounds b = pov_far_bounds(s);
    if (!pov_export_check(s, o, notes))
        return STATUS_DATA;
    write_header(fp, s, o, notes);
    write_globals(fp, s, o->scale > 0 ? o->scale : 1.0);
    write_camera(fp, s);
    write_lights(fp, s, o, &b);
    write_geometry(fp, s, o);
    return fflush(fp) != 0 || ferror(fp) ? STATUS_IO : 0;
}

/* ---- The file ---- */

typedef struct pov_job {
    const scene_model *s;
    const pov_opts *o;
    pov_notes *notes;
} pov_job;

static int fill_pov(FILE *fp, void *ctx)
{
    pov_job *job = ctx;
    return pov_export_write(job->s, job->o, fp, job->notes);
}

int pov_export_file(const scene_model *s, const pov_opts *o, const char *path, pov_notes *notes, char *err,
                    size_t errlen)
{
    pov_job job = {s, o, notes};
    char why[1024];
    if (err && errlen)
        err[0] = '\0';
    if (!pov_export_check(s, o, notes))
        return STATUS_DATA;
    int rc = file_write_atomic(path, fill_pov, &job, why, sizeof why);
    if (rc != STATUS_OK && rc != STATUS_DATA && err && errlen)
        snprintf(err, errlen, "%s", why);
    return rc;
}

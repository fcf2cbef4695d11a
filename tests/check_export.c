/*
 * check_export.c - the POV-Ray SDL writer (src/export/export_pov.c) and
 * `refray export` (src/cli/cli_export.c).
 *
 * Expected SDL text is derived by hand from the mapping in
 * spec/crosscheck.md: z negated (POV-Ray is left-handed), light colours
 * from E and the falloff, finish values from Kd, Ks, n, t.  Scene numbers
 * are chosen so that every expected value is a short exact decimal.
 * The command-line tests run $REFRAY_BIN (set by `make test`), else
 * build/refray.
 */
#include <dirent.h>
#include <fcntl.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/wait.h>
#include <unistd.h>
#include "io/scene_file.h"
#include "export/export_pov.h"
#include "export/export_pov_far.h"
#include "testlib.h"

static const char scene_a[] =
    "image  { width 64 height 48 max_depth 4 background [0.125, 0.25, 0.5] }\n"
    "camera { perspective eye [1, 2, 6] look_at [0, 0.5, 0] up [0, 1, 0] fov 50 }\n"
    "ambient { color 0.25 }\n"
    "point_light { position [3, 5, 4] power 2 falloff none }\n"
    "point_light { position [0, 4, 0] power 8 d0 2 falloff linear }\n"
    "distant_light { direction [0, -1, 0] power 0.5 }\n"
    "material paint { Kd [0.25, 0.5, 0.75] Ks 0.5 n 20 }\n"
    "material glass { Kd 0 Ks 0.25 n 100 t 0.75 ior 1.5 }\n"
    "material clear { Kd 0 t 1 }\n"
    "plane { point [0, 0, 0] normal [0, 1, 0] material paint }\n"
    "sphere { center [0, 1, -2] radius 1 material glass }\n"
    "disk { center [0, 2, 0] normal [0, 1, 0] radius 1 material glass }\n"
    "sphere { center [2, 1, 0] radius 0.5 material clear }\n"
    "box { from [-1, 0, -1] to [1, 1, 1] rotate [0, 90, 0] translate [3, 0, 4] material paint }\n";

static const char scene_ortho[] =
    "image  { width 64 height 48 samples 3 max_depth 1 }\n"
    "camera { orthographic eye [0, 0, 5] look_at [0, 0, 0] up [0, 1, 0] width 4 }\n"
    "point_light { position [0, 0, 5] power 1 falloff none }\n"
    "sphere { center [0, 0, 0] radius 1 }\n";

static const char scene_refused[] =
    "point_light { position [0, 3, 0] power 1 d0 1 falloff inverse_square }\n"
    "sphere { center [0, 0, 0] radius 1 }\n";

static const char scene_approx[] =
    "image { max_depth 1 }\n"
    "point_light { position [0, 3, 0] power 1 d0 0 falloff linear }\n"
    "material gold { Kd 0.25 Ks [0.25, 0.5, 0.75] n 10 }\n"
    "sphere { center [0, 0, 0] radius 1 material gold }\n";

static const char scene_rect[] =
    "image { max_depth 1 }\n"
    "distributed_light { rectangle [-1, 4, -1] [2, 0, 0] [0, 0, 2] power 4 samples 4 falloff none }\n"
    "sphere { center [0, 0, 0] radius 1 }\n";

/* Loads text (diagnostics, warnings included, thrown away). */
static scene_model *load(const char *text)
{
    int status;
    FILE *null = fopen("/dev/null", "w");
    scene_model *s = scene_file_load_text("t.scene", text, strlen(text), NULL, null, 1, &status);
    if (null)
        fclose(null);
    ck_assert_msg(s != NULL, "scene did not load (status %d)", status);
    return s;
}

/* The SDL of text, malloc'd; *rc the return of pov_export_write. */
static char *export_text(const char *text, const pov_opts *o, pov_notes *notes, int *rc)
{
    char *buf = NULL;
    size_t len = 0;
    scene_model *s = load(text);
    FILE *fp = open_memstream(&buf, &len);
    ck_assert_ptr_nonnull(fp);
    *rc = pov_export_write(s, o, fp, notes);
    fclose(fp);
    scene_free(s);
    return buf;
}

static char *export_default(const char *text, pov_notes *notes)
{
    pov_opts o = {0, "t.scene", 0, 0, 0};
    int rc;
    char *sdl = export_text(text, &o, notes, &rc);
    ck_assert_int_eq(rc, 0);
    return sdl;
}

#define ck_assert_has(sdl, want) \
    ck_assert_msg(strstr((sdl), (want)) != NULL, "SDL lacks \"%s\":\n%s", (want), (sdl))

static int count_of(const char *text, const char *needle)
{
    int n = 0;
    for (const char *p = strstr(text, needle); p; p = strstr(p + 1, needle))
        n++;
    return n;
}

/* [XCHK-MAP-CAMERA-1] z negated; right carries the aspect 64/48; angle is
 * the horizontal fov; sky is up as written. */
START_TEST(test_pov_export_write_camera)
{
    pov_notes n;
    char *sdl = export_default(scene_a, &n);
    ck_assert_has(sdl, "  perspective\n  location <1, 2, -6>\n");
    ck_assert_has(sdl, "  right <1.3333333333333333, 0, 0>\n  up <0, 1, 0>\n  sky <0, 1, 0>\n");
    ck_assert_has(sdl, "  angle 50\n  look_at <0, 0.5, 0>\n}");
    free(sdl);
}
END_TEST

/* Orthographic: right and up are the view's extent, 4 by 4 * 48/64 = 3;
 * no angle.  samples 3: POV-Ray renders 3 x 64 by 3 x 48 and the header
 * says to average 3 x 3 blocks. */
START_TEST(test_pov_export_write_orthographic)
{
    pov_notes n;
    char *sdl = export_default(scene_ortho, &n);
    ck_assert_has(sdl, "  orthographic\n  location <0, 0, -5>\n  right <4, 0, 0>\n  up <0, 3, 0>\n");
    ck_assert_msg(strstr(sdl, "angle") == NULL, "an orthographic camera got an angle:\n%s", sdl);
    ck_assert_has(sdl, "// pov-args: +W192 +H144 -A\n// pov-downsample: 3\n");
    free(sdl);
}
END_TEST

START_TEST(test_pov_render_size)
{
    scene_model *s = load(scene_ortho);
    int w, h;
    ck_assert_int_eq(pov_render_size(s, &w, &h), 3);
    ck_assert_int_eq(w, 192);
    ck_assert_int_eq(h, 144);
    scene_free(s);
}
END_TEST

/* [XCHK-MAP-GLOBAL-1] */
START_TEST(test_pov_export_write_globals)
{
    pov_notes n;
    char *sdl = export_default(scene_a, &n);
    ck_assert_has(sdl, "#version 3.7;");
    ck_assert_has(sdl, "  assumed_gamma 1.0\n  ambient_light rgb <0.25, 0.25, 0.25>\n");
    ck_assert_has(sdl, "  max_trace_level 4\n  adc_bailout 0\n");
    ck_assert_has(sdl, "background { rgb <0.125, 0.25, 0.5> }");
    free(sdl);
}
END_TEST

/* [XCHK-MAP-FADE-1] falloff none: colour E.  linear, E 8, d0 2: colour
 * E/(2 d0) = 2 with fade_distance 2, fade_power 1, since
 * 2 * 2/(1 + d/2) = 8/(d + 2).  Distant: a parallel light. */
START_TEST(test_pov_export_write_lights)
{
    pov_notes n;
    char *sdl = export_default(scene_a, &n);
    ck_assert_has(sdl, "light_source { <3, 5, -4> color rgb <2, 2, 2> }");
    ck_assert_has(sdl, "light_source { <0, 4, 0> color rgb <2, 2, 2> fade_distance 2 fade_power 1 }");
    ck_assert_has(sdl, " color rgb <0.5, 0.5, 0.5> parallel point_at <");
    ck_assert_int_eq(count_of(sdl, "light_source {"), 3);
    free(sdl);
}
END_TEST

/* [XCHK-MAP-DISTANT-1] A distant light travelling down (0, -1, 0) sits
 * above the scene's centre, which is its point_at, beyond every point
 * POV-Ray can shade by MAX_DISTANCE: (max_depth + 1) 1e7 = 5e7 plus the
 * spread of the scene (the eye's distance from the centre and the radius:
 * more than 1, far less than 100 in scene_a). */
START_TEST(test_pov_export_write_distant_direction)
{
    pov_notes n;
    char *sdl = export_default(scene_a, &n);
    const char *p = strstr(sdl, " parallel point_at <");
    ck_assert_ptr_nonnull(p);
    const char *start = p;
    while (start > sdl && strncmp(start, "light_source { <", 16) != 0)
        start--;
    double fx, fy, fz, tx, ty, tz;
    ck_assert_int_eq(sscanf(start, "light_source { <%lf, %lf, %lf>", &fx, &fy, &fz), 3);
    ck_assert_int_eq(sscanf(p, " parallel point_at <%lf, %lf, %lf>", &tx, &ty, &tz), 3);
    ck_assert_near(tx - fx, 0, 1e-9);
    ck_assert_near(tz - fz, 0, 1e-9);
    ck_assert_msg(fy - ty > 5e7 + 1 && fy - ty < 5e7 + 100, "the light is %.17g above its point_at", fy - ty);
    ck_assert(fabs(tx) < 10 && fabs(ty) < 10 && fabs(tz) < 10);
    free(sdl);
}
END_TEST

/* [XCHK-MAP-FINISH-1] pigment Kd with transmit t; ambient 1 and diffuse 1
 * replace POV-Ray's 0.1 and 0.6; phong Ks, phong_size n, reflection Ks. */
START_TEST(test_pov_export_write_finish)
{
    pov_notes n;
    char *sdl = export_default(scene_a, &n);
    ck_assert_has(sdl, "pigment { rgbt <0.25, 0.5, 0.75, 0> }\n  finish { ambient 1 diffuse 1 phong 0.5 "
                       "phong_size 20 reflection { rgb <0.5, 0.5, 0.5> } }");
    ck_assert_has(sdl, "pigment { rgbt <0, 0, 0, 0.75> }\n  finish { ambient 1 diffuse 1 phong 0.25 "
                       "phong_size 100 reflection { rgb <0.25, 0.25, 0.25> } }");
    ck_assert_has(sdl, "pigment { rgbt <0, 0, 0, 1> }\n  finish { ambient 1 diffuse 1 }");
    free(sdl);
}
END_TEST

/* [XCHK-MAP-SHADOW-1] The glass sphere is a solid and gets the ior; the
 * glass disk is a sheet and must not bend rays; the clear sphere casts no
 * shadow.  [XCHK-MAP-LEVEL-1] The disk and the clear sphere (ior 1) pass
 * rays straight on: by default the first gets ior 1 + 2^-22 =
 * 1.0000002384185791, the second 1 + 2 * 2^-22 = 1.0000004768371582. */
START_TEST(test_pov_export_write_interior)
{
    pov_notes n;
    char *sdl = export_default(scene_a, &n);
    ck_assert_has(sdl, "sphere {\n  <0, 1, 2>, 1\n  texture { RF_T1 }\n  interior { ior 1.5 }\n}");
    ck_assert_has(sdl, "disc {\n  <0, 2, 0>, <0, 1, 0>, 1\n  texture { RF_T1 }\n  interior { ior 1.0000002384185791 }");
    ck_assert_has(sdl, "sphere {\n  <2, 1, 0>, 0.5\n  texture { RF_T2 }\n  interior { ior 1.0000004768371582 }");
    ck_assert_int_eq(count_of(sdl, "interior"), 3);
    ck_assert_int_eq(count_of(sdl, "no_shadow"), 1);
    free(sdl);
}
END_TEST

/* plain_sheets: the disk and the clear sphere keep POV-Ray's ior 1. */
START_TEST(test_pov_export_write_plain_sheets)
{
    pov_opts o = {0, NULL, 0, 1, 0};
    pov_notes n;
    int rc;
    char *sdl = export_text(scene_a, &o, &n, &rc);
    ck_assert_int_eq(rc, 0);
    ck_assert_has(sdl, "disc {\n  <0, 2, 0>, <0, 1, 0>, 1\n  texture { RF_T1 }\n}");
    ck_assert_has(sdl, "sphere {\n  <2, 1, 0>, 0.5\n  texture { RF_T2 }\n  no_shadow\n}");
    ck_assert_int_eq(count_of(sdl, "interior"), 1);
    ck_assert_msg(strstr(n.text[0], "without counting a trace level") != NULL, "%s", n.text[0]);
    free(sdl);
}
END_TEST

/* scale 0.25: ambient, background and every light times 0.25, and the
 * header says so. */
START_TEST(test_pov_export_write_scale)
{
    pov_opts o = {0, NULL, 0.25, 0, 0};
    pov_notes n;
    int rc;
    char *sdl = export_text(scene_a, &o, &n, &rc);
    ck_assert_int_eq(rc, 0);
    ck_assert_has(sdl, "// pov-scale: 0.25\n");
    ck_assert_has(sdl, "ambient_light rgb <0.0625, 0.0625, 0.0625>");
    ck_assert_has(sdl, "background { rgb <0.03125, 0.0625, 0.125> }");
    ck_assert_has(sdl, "light_source { <3, 5, -4> color rgb <0.5, 0.5, 0.5> }");
    ck_assert_has(sdl, "color rgb <0.5, 0.5, 0.5> fade_distance 2 fade_power 1 }");
    ck_assert_has(sdl, " color rgb <0.125, 0.125, 0.125> parallel point_at <");
    free(sdl);
}
END_TEST

/* A box turned 90 degrees about y keeps its local corners (z negated) and
 * gets POV-Ray's matrix of F M F, F = diag(1, 1, -1).  By hand: refray's
 * turn takes x to -z and z to x, M = [[0,0,1],[0,1,0],[-1,0,0]]; F M F =
 * [[0,0,-1],[0,1,0],[1,0,0]]; POV-Ray lists it by columns (x' = a00 x +
 * a10 y + a20 z + a30): <0,0,1, 0,1,0, -1,0,0>, then F (3, 0, 4). */
START_TEST(test_pov_export_write_matrix)
{
    pov_notes n;
    char *sdl = export_default(scene_a, &n);
    ck_assert_has(sdl, "box {\n  <-1, 0, 1>, <1, 1, -1>\n  texture { RF_T0 }\n"
                       "  matrix <0, 0, 1, 0, 1, 0, -1, 0, 0, 3, 0, -4>\n}");
    ck_assert_has(sdl, "plane {\n  <0, 1, 0>, 0\n");
    free(sdl);
}
END_TEST

/* A triangle keeps its corners in order, z negated. */
START_TEST(test_pov_export_write_triangle)
{
    pov_notes n;
    char *sdl = export_default("triangle { vertices [0, 0, 1] [1, 0, 2] [0, 1, 3] }\n", &n);
    ck_assert_has(sdl, "triangle {\n  <0, 0, -1>, <1, 0, -2>, <0, 1, -3>\n  texture { RF_T0 }\n}");
    free(sdl);
}
END_TEST

/* [XCHK-MAP-MESH-1] A mesh is a mesh2 of its shared vertices (z negated),
 * its normals plus one face normal per flat triangle, faces and then, as
 * POV-Ray's grammar wants them, normal indices; an inside_vector only when
 * closed.  messy-vtvn.obj: 8 vertices, 6 normals, 12 triangles of which 6
 * are flat (its faces 1, 2 and 5 give no normals), so 12 normal vectors,
 * the first flat triangle's index 6 at all three corners. */
START_TEST(test_pov_export_write_mesh)
{
    pov_notes n;
    char *sdl = export_default("mesh { file \"tests/obj/messy-vtvn.obj\" }\n", &n);
    ck_assert_has(sdl, "mesh2 {\n  vertex_vectors { 8,\n    <-1, -1, 1>,");
    ck_assert_has(sdl, "normal_vectors { 12,");
    ck_assert_has(sdl, "normal_indices { 12,\n    <6, 6, 6>,");
    const char *faces = strstr(sdl, "face_indices { 12"), *normals = strstr(sdl, "normal_indices");
    const char *inside = strstr(sdl, "inside_vector");
    ck_assert(faces && normals && inside && faces < normals && normals < inside);
    free(sdl);
    sdl = export_default("mesh { file \"tests/obj/messy-open.obj\" }\n", &n);
    ck_assert_has(sdl, "face_indices { 10,");
    ck_assert_ptr_null(strstr(sdl, "inside_vector"));
    ck_assert_ptr_null(strstr(sdl, "normal_vectors"));
    free(sdl);
}
END_TEST

/* [XCHK-MAP-QUADRIC-1] POV-Ray's cylinder and cone take the end centres
 * and radii as refray's (z negated), `open` as it is.  Its torus lies
 * about y at the origin: a matrix takes y to the axis and the origin to
 * the centre.  By hand for axis +z: in POV-Ray's frame a = (0, 0, -1); the
 * axis with the least component is x, u = a x (1,0,0) = (0, -1, 0),
 * w = u x a = (1, 0, 0); rows u, a, w, then the centre (1, 2, -3). */
START_TEST(test_pov_export_write_quadrics)
{
    pov_notes n;
    char *sdl = export_default("cylinder { from [0, 0, 1] to [0, 2, 1] radius 0.5 }\n"
                               "cylinder { from [0, 0, 1] to [0, 2, 1] radius 0.5 open }\n"
                               "cone { from [0, 0, 0] to [0, 2, 0] radii 1 0 open }\n"
                               "torus { center [1, 2, 3] axis [0, 0, 1] major 2 minor 0.5 }\n", &n);
    ck_assert_has(sdl, "cylinder {\n  <0, 0, -1>, <0, 2, -1>, 0.5\n  texture { RF_T0 }\n}");
    ck_assert_has(sdl, "cylinder {\n  <0, 0, -1>, <0, 2, -1>, 0.5\n  open\n  texture { RF_T0 }\n}");
    ck_assert_has(sdl, "cone {\n  <0, 0, 0>, 1, <0, 2, 0>, 0\n  open\n  texture { RF_T0 }\n}");
    ck_assert_has(sdl, "torus {\n  2, 0.5\n  sturm\n  matrix <0, -1, 0, 0, 0, -1, 1, 0, 0, 1, 2, -3>\n"
                       "  texture { RF_T0 }\n}");
    free(sdl);
}
END_TEST

/* Four notes in scene_a: the glass disk (a transparent sheet) and the
 * clear sphere (ior 1) pass rays straight on, which POV-Ray does not count
 * as a trace level; and the glass sphere (centre 1 above the floor, radius
 * 1) touches the floor, for shadow rays ([XCHK-MAP-SHADOW-2]) and for
 * every ray ([XCHK-MAP-CONTACT-1]).  glass has Ks + t = 1: no
 * total-internal-reflection note.  The clear sphere (centre 1 above the
 * floor, radius 0.5) is 0.5 clear of it. */
START_TEST(test_pov_export_check_notes)
{
    scene_model *s = load(scene_a);
    pov_opts o = {0, NULL, 0, 0, 0};
    pov_notes n;
    ck_assert_int_eq(pov_export_check(s, &o, &n), 1);
    ck_assert_int_eq(n.refused, 0);
    ck_assert_int_eq(n.count, 4);
    ck_assert_msg(strstr(n.text[0], "material glass") && strstr(n.text[0], "trace level"), "%s", n.text[0]);
    ck_assert_msg(strstr(n.text[1], "material clear") && strstr(n.text[1], "trace level"), "%s", n.text[1]);
    ck_assert_msg(strstr(n.text[2], "transparent sphere at t.scene:11 cuts or comes within 1e-3 of the surface at "
                                    "t.scene:10"), "%s", n.text[2]);
    ck_assert_msg(strstr(n.text[3], "transparent sphere at t.scene:11 touches or comes within 1e-3 of the opaque "
                                    "surface at t.scene:10"), "%s", n.text[3]);
    scene_free(s);
}
END_TEST

/* The notes of the export of text (the scene must be exportable). */
static void notes_of(const char *text, pov_notes *n)
{
    scene_model *s = load(text);
    pov_opts o = {0, NULL, 0, 0, 0};
    ck_assert_int_eq(pov_export_check(s, &o, n), 1);
    scene_free(s);
}

/* How many of the notes contain a, and b when it is not NULL. */
static int notes_with(const pov_notes *n, const char *a, const char *b)
{
    int found = 0;
    for (int i = 0; i < n->count && i < POV_NOTE_MAX; i++)
        found += strstr(n->text[i], a) && (!b || strstr(n->text[i], b));
    return found;
}

/* [XCHK-MAP-MESH-2] A mesh with vertex normals (cube.obj has them) is
 * listed for Ks > 0 and for t > 0, each with its reason; without normals,
 * or at max_depth 1, or with neither, not. */
START_TEST(test_pov_export_check_smooth_mesh)
{
    pov_notes n;
    notes_of("image { max_depth 2 }\nmesh { file \"tests/obj/cube.obj\" material { t 0.5 ior 1.5 Ks 0.5 } }\n", &n);
    ck_assert_int_eq(notes_with(&n, "vertex normals and t > 0", "interiors"), 1);
    ck_assert_int_eq(notes_with(&n, "vertex normals and Ks > 0", NULL), 1);
    notes_of("image { max_depth 2 }\nmesh { file \"tests/obj/cube.obj\" material { t 0.5 ior 1.5 } }\n", &n);
    ck_assert_int_eq(notes_with(&n, "vertex normals", NULL), 1);
    notes_of("image { max_depth 1 }\nmesh { file \"tests/obj/cube.obj\" material { t 0.5 ior 1.5 } }\n", &n);
    ck_assert_int_eq(notes_with(&n, "vertex normals", NULL), 0);
    notes_of("image { max_depth 2 }\nmesh { file \"tests/obj/tetrahedron.obj\" material { t 0.5 ior 1.5 } }\n", &n);
    ck_assert_int_eq(notes_with(&n, "vertex normals", NULL), 0);
    notes_of("image { max_depth 2 }\nmesh { file \"tests/obj/cube.obj\" material { Kd 0.5 } }\n", &n);
    ck_assert_int_eq(n.count, 0);
}
END_TEST

/* [XCHK-MAP-MESH-3] A curved smooth mesh (the icosahedron with vertex
 * normals) in a scene with shadows is listed: refray lifts its shadow
 * rays, POV-Ray does not.  Not listed: with pov_opts.facet_shadows (the
 * comparison renders refray the seed's way), without a light, and for
 * cube.obj, whose corners of a face share the face's normal (flat). */
START_TEST(test_pov_export_check_terminator)
{
    static const char lit[] = "point_light { position [0, 5, 0] falloff none }\n"
                              "mesh { file \"tests/obj/icosahedron_smooth.obj\" material { Kd 0.5 } }\n";
    pov_notes n;
    notes_of(lit, &n);
    ck_assert_int_eq(notes_with(&n, "lifted point", "POV-Ray on the facet"), 1);
    scene_model *s = load(lit);
    pov_opts o = {0, NULL, 0, 0, 1};
    ck_assert_int_eq(pov_export_check(s, &o, &n), 1);
    ck_assert_int_eq(n.count, 0);
    scene_free(s);
    notes_of("mesh { file \"tests/obj/icosahedron_smooth.obj\" material { Kd 0.5 } }\n", &n);
    ck_assert_int_eq(n.count, 0);
    notes_of("point_light { position [0, 5, 0] falloff none }\n"
             "mesh { file \"tests/obj/cube.obj\" material { Kd 0.5 } }\n", &n);
    ck_assert_int_eq(n.count, 0);
}
END_TEST

/* [XCHK-MAP-SHADOW-2] A transparent box or mesh under a light is listed
 * (shadow rays inside it leave through an adjacent face within 1e-3 of the
 * point near its edges); a transparent sphere alone, an opaque box, or no
 * light, not.  A transparent sphere is listed when another surface cuts
 * it or comes within 1e-3 of it, and not when it keeps more than 1e-3
 * away or lies wholly inside without touching. */
START_TEST(test_pov_export_check_shadow_tolerance)
{
    static const char *const listed[] = {
        "point_light { position [0, 5, 0] }\nbox { from [0, 0, 0] to [1, 1, 1] material { t 0.5 ior 1.5 Ks 0.5 } }\n",
        "distant_light { direction [0, -1, 0] }\nmesh { file \"tests/obj/tetrahedron.obj\" material { t 0.5 "
        "ior 1.5 Ks 0.5 } }\n",
    };
    static const char *const near[] = {
        /* a plane 1 + 1e-3 from the centre of a unit sphere; a sphere 2 away */
        "point_light { position [0, 5, 0] falloff none }\nsphere { material { t 0.5 ior 1.5 Ks 0.5 } }\n"
        "plane { point [0, -1.001, 0] }\n",
        "point_light { position [0, 5, 0] falloff none }\nsphere { material { t 0.5 ior 1.5 Ks 0.5 } }\n"
        "sphere { center [2, 0, 0] }\n",
        /* a box whose nearest corner is 0.52 from the centre: it cuts the surface */
        "point_light { position [0, 5, 0] falloff none }\nsphere { material { t 0.5 ior 1.5 Ks 0.5 } }\n"
        "box { from [0.3, 0.3, 0.3] to [2, 2, 2] }\n",
    };
    static const char *const apart[] = {
        /* 1 + 2e-3 from the plane; a sphere 2.01 away; a ball well inside */
        "point_light { position [0, 5, 0] falloff none }\nsphere { material { t 0.5 ior 1.5 Ks 0.5 } }\n"
        "plane { point [0, -1.002, 0] }\n",
        "point_light { position [0, 5, 0] falloff none }\nsphere { material { t 0.5 ior 1.5 Ks 0.5 } }\n"
        "sphere { center [2.01, 0, 0] }\n",
        "point_light { position [0, 5, 0] falloff none }\nsphere { material { t 0.5 ior 1.5 Ks 0.5 } }\n"
        "sphere { radius 0.5 }\n",
    };
    static const char *const not_listed[] = {
        "point_light { position [0, 5, 0] }\nsphere { material { t 0.5 ior 1.5 Ks 0.5 } }\n",
        "point_light { position [0, 5, 0] }\nbox { from [0, 0, 0] to [1, 1, 1] material { Kd 0.5 } }\n",
        "box { from [0, 0, 0] to [1, 1, 1] material { t 0.5 ior 1.5 Ks 0.5 } }\n",
    };
    pov_notes n;
    for (int i = 0; i < 2; i++) {
        notes_of(listed[i], &n);
        ck_assert_int_eq(notes_with(&n, "SHADOW_TOLERANCE", "edges"), 1);
    }
    for (int i = 0; i < 3; i++) {
        notes_of(not_listed[i], &n);
        ck_assert_int_eq(notes_with(&n, "SHADOW_TOLERANCE", NULL), 0);
        notes_of(near[i], &n);
        ck_assert_msg(notes_with(&n, "transparent sphere", "cuts or comes within 1e-3") == 1, "scene %d: %d notes", i,
                      n.count);
        notes_of(apart[i], &n);
        ck_assert_int_eq(n.count, 0);
    }
}
END_TEST

/* [XCHK-MAP-CONTACT-1] Glass touching an opaque surface ([NUM-GLASS-3]),
 * or within 1e-3 of one, is listed with no light at all (tests/attack12
 * finding 7: a glass box standing on a floor under ambient light, which
 * POV-Ray renders 610 of 1728 pixels off, exported with "approximations:
 * 0"): the box on the floor, 1e-4 above it, a glass ball resting on an
 * opaque box, a glass disk 5e-4 above a floor, a glass plane tangent to an
 * opaque ball.  Not listed: the box 2e-3 above the floor, two glass boxes
 * touching with nothing opaque, an opaque box on the floor, a glass plane
 * parallel to an opaque one 1 apart. */
START_TEST(test_pov_export_check_glass_contact)
{
    static const char *const listed[] = {
        "plane { point [0, 0, 0] normal [0, 1, 0] }\n"
        "box { from [-1, 0, -1] to [1, 1, 1] material { Kd 0.1 Ks 0.2 t 0.8 ior 1.5 } }\n",
        "plane { point [0, 0, 0] normal [0, 1, 0] }\n"
        "box { from [-1, 1e-4, -1] to [1, 1, 1] material { Kd 0.1 Ks 0.2 t 0.8 ior 1.5 } }\n",
        "box { from [-1, 0, -1] to [1, 1, 1] }\n"
        "sphere { center [0, 2, 0] radius 1 material { Ks 0.2 t 0.8 ior 1.5 } }\n",
        "plane { point [0, 0, 0] normal [0, 1, 0] }\n"
        "disk { center [0, 5e-4, 0] normal [0, 1, 0] radius 1 material { t 0.5 } }\n",
        "sphere { }\nplane { point [0, -1, 0] normal [0, 1, 0] material { t 0.5 } }\n",
    };
    static const char *const not_listed[] = {
        "plane { point [0, 0, 0] normal [0, 1, 0] }\n"
        "box { from [-1, 2e-3, -1] to [1, 1, 1] material { Kd 0.1 Ks 0.2 t 0.8 ior 1.5 } }\n",
        "box { from [-1, 0, -1] to [1, 1, 1] material { Ks 0.2 t 0.8 ior 1.5 } }\n"
        "box { from [-1, 1, -1] to [1, 2, 1] material { Ks 0.2 t 0.8 ior 1.3 } }\n",
        "plane { point [0, 0, 0] normal [0, 1, 0] }\nbox { from [-1, 0, -1] to [1, 1, 1] }\n",
        "plane { point [0, 0, 0] normal [0, 1, 0] }\nplane { point [0, 1, 0] normal [0, -1, 0] material { t 0.5 } }\n",
    };
    pov_notes n;
    for (size_t i = 0; i < sizeof listed / sizeof listed[0]; i++) {
        notes_of(listed[i], &n);
        ck_assert_msg(notes_with(&n, "within 1e-3 of the opaque surface", "[NUM-GLASS-3]") == 1, "scene %d: %d notes",
                      (int)i, n.count);
    }
    notes_of(listed[0], &n);
    ck_assert_int_eq(n.count, 1);
    ck_assert_msg(strstr(n.text[0], "transparent box at t.scene:2 touches or comes within 1e-3 of the opaque surface "
                                    "at t.scene:1"), "%s", n.text[0]);
    for (size_t i = 0; i < sizeof not_listed / sizeof not_listed[0]; i++) {
        notes_of(not_listed[i], &n);
        ck_assert_msg(notes_with(&n, "opaque surface", NULL) == 0, "scene %d: %s", (int)i, n.text[0]);
    }
    char *sdl = export_default(listed[0], &n);
    ck_assert_has(sdl, "// approximations: 1 (see spec/crosscheck.md)");
    free(sdl);
}
END_TEST

/* [XCHK-MAP-FAR-1] A camera 2e5 above a floor, looking level, has pixels
 * whose rays meet the floor past 1e7 (a ray d below the horizon meets it
 * at 2e5 / sin d, and the row next to the horizon is about 0.0055 rad
 * below it with fov 45 over 64 pixels and 48 rows: 3.6e7): listed.  Looking
 * down at it from 2 units, or level from 2 units (the nearest rows meet it
 * at 2 / 0.0055 = 364), not. */
START_TEST(test_pov_export_check_far_plane)
{
    pov_notes n;
    notes_of("image { width 64 height 48 }\ncamera { eye [0, 2e5, 0] look_at [0, 2e5, -1] fov 45 }\n"
             "plane { }\n", &n);
    ck_assert_int_eq(notes_with(&n, "camera rays meet it", "MAX_DISTANCE"), 1);
    notes_of("image { width 64 height 48 }\ncamera { eye [0, 2, 0] look_at [0, 2, -1] fov 45 }\nplane { }\n", &n);
    ck_assert_int_eq(n.count, 0);
    notes_of("image { width 64 height 48 }\ncamera { eye [0, 2, 0] look_at [0, 0, 0] up [0, 0, -1] fov 45 }\n"
             "plane { }\n", &n);
    ck_assert_int_eq(n.count, 0);
}
END_TEST

/* [XCHK-MAP-FAR-1] A distant light straight down, a floor, and a wall
 * through the origin tilted 1e-9 rad off vertical: from the sphere (within
 * 2 of the origin) a shadow ray meets the wall up to (0 + R) / sin(1e-9)
 * away, R the scene's radius: listed.  An upright wall (its normal across
 * the light: never met) and the floor (met only by rays going down, which
 * no shadow ray toward this light does), not. */
START_TEST(test_pov_export_check_far_shadow)
{
    pov_notes n;
    notes_of("camera { eye [0, 2, 6] look_at [0, 0, 0] }\ndistant_light { direction [0, -1, 0] }\n"
             "sphere { center [1, 1, 0] }\nplane { point [0, -1, 0] }\n"
             "plane { normal [1, 1e-9, 0] }\n", &n);
    ck_assert_int_eq(notes_with(&n, "distant_light", "shadow ray can meet the plane"), 1);
    notes_of("camera { eye [0, 2, 6] look_at [0, 0, 0] }\ndistant_light { direction [0, -1, 0] }\n"
             "sphere { center [1, 1, 0] }\nplane { point [0, -1, 0] }\nplane { normal [1, 0, 0] }\n", &n);
    ck_assert_int_eq(n.count, 0);
}
END_TEST

/* [XCHK-MAP-FAR-1] [XCHK-MAP-DISTANT-1] A mesh is bounded by its
 * positions: cube.obj ([-1, 1]^3) moved 100 along x, the eye at (0, 0, 5)
 * and no other primitive or positional light.  The extent is (0, -1, -1)
 * to (101, 1, 5): centre (50.5, 0, 2), radius half its diagonal,
 * sqrt(101^2 + 2^2 + 6^2) / 2 = sqrt(10241) / 2.  (Left out, the mesh
 * would leave the eye alone: radius 1.)  A transparent sphere whose
 * surface that cube cuts (the cube from x = 0.5) is listed as near it. */
START_TEST(test_pov_export_far_bounds_mesh)
{
    scene_model *s = load("camera { eye [0, 0, 5] look_at [0, 0, 0] }\n"
                          "mesh { file \"tests/obj/cube.obj\" translate [100, 0, 0] }\n");
    pov_bounds b = pov_far_bounds(s);
    ck_assert_double_eq_tol(b.centre.x, 50.5, 1e-12);
    ck_assert_double_eq_tol(b.centre.y, 0, 1e-12);
    ck_assert_double_eq_tol(b.centre.z, 2, 1e-12);
    ck_assert_double_eq_tol(b.radius, 0.5 * sqrt(10241.0), 1e-12);
    scene_free(s);
    pov_notes n;
    notes_of("point_light { position [0, 5, 0] falloff none }\nsphere { material { t 0.5 ior 1.5 Ks 0.5 } }\n"
             "mesh { file \"tests/obj/cube.obj\" translate [1.5, 0, 0] }\n", &n);
    ck_assert_int_eq(notes_with(&n, "transparent sphere", "cuts or comes within 1e-3"), 1);
    ck_assert_int_eq(notes_with(&n, "transparent sphere", "within 1e-3 of the opaque surface"), 1);
    notes_of("point_light { position [0, 5, 0] falloff none }\nsphere { material { t 0.5 ior 1.5 Ks 0.5 } }\n"
             "mesh { file \"tests/obj/cube.obj\" translate [3, 0, 0] }\n", &n);
    ck_assert_int_eq(n.count, 0);
}
END_TEST

/* linear with d0 0 is approximated (fade_distance stands in for d0), a
 * non-grey Ks gives phong its mean (0.25 + 0.5 + 0.75)/3 = 0.5 and keeps
 * the colour for the mirror ray; both listed, in the header too. */
START_TEST(test_pov_export_write_approximations)
{
    pov_notes n;
    char *sdl = export_default(scene_approx, &n);
    ck_assert_int_eq(n.count, 2);
    ck_assert_msg(strstr(n.text[0], "linear falloff with d0 0") && strstr(n.text[0], "fade_distance"), "%s",
                  n.text[0]);
    ck_assert_msg(strstr(n.text[1], "not grey") && strstr(n.text[1], "mean 0.5"), "%s", n.text[1]);
    ck_assert_has(sdl, "// approximations: 2");
    ck_assert_has(sdl, "phong 0.5 phong_size 10 reflection { rgb <0.25, 0.5, 0.75> }");
    ck_assert_has(sdl, "fade_power 1 }");
    free(sdl);
}
END_TEST

/* inverse_square with d0 > 0 cannot be matched: refused with the reason,
 * and nothing written. */
START_TEST(test_pov_export_write_refused)
{
    pov_opts o = {0, NULL, 0, 0, 0};
    pov_notes n;
    int rc;
    char *sdl = export_text(scene_refused, &o, &n, &rc);
    ck_assert_int_eq(rc, STATUS_DATA);
    ck_assert_int_eq(n.refused, 1);
    ck_assert_msg(strstr(n.reason, "point_light at t.scene:1") && strstr(n.reason, "inverse_square") &&
                      strstr(n.reason, "d0 1"), "%s", n.reason);
    ck_assert_str_eq(sdl, "");
    free(sdl);
}
END_TEST

/* [XCHK-MAP-AREA-1] 4 samples: a 2 x 2 grid; the cell centres of the
 * rectangle from (-1, 4, -1) with edges (2,0,0), (0,0,2) are x, z in
 * {-0.5, 0.5}; each source has 4/4 = 1. */
START_TEST(test_pov_export_write_distributed_points)
{
    pov_notes n;
    char *sdl = export_default(scene_rect, &n);
    ck_assert_int_eq(count_of(sdl, "light_source {"), 4);
    ck_assert_has(sdl, "light_source { <-0.5, 4, 0.5> color rgb <1, 1, 1> }");
    ck_assert_has(sdl, "light_source { <0.5, 4, 0.5> color rgb <1, 1, 1> }");
    ck_assert_has(sdl, "light_source { <-0.5, 4, -0.5> color rgb <1, 1, 1> }");
    ck_assert_has(sdl, "light_source { <0.5, 4, -0.5> color rgb <1, 1, 1> }");
    ck_assert_int_eq(n.count, 1);
    free(sdl);
}
END_TEST

/* --area-lights: centre (0, 4, 0); POV-Ray's grid includes its ends, so
 * the axes shrink by (n-1)/n = 1/2 to (1,0,0) and (0,0,2)/2, z negated. */
START_TEST(test_pov_export_write_area_light)
{
    pov_opts o = {1, NULL, 0, 0, 0};
    pov_notes n;
    int rc;
    char *sdl = export_text(scene_rect, &o, &n, &rc);
    ck_assert_int_eq(rc, 0);
    ck_assert_has(sdl, "light_source { <0, 4, 0> color rgb <4, 4, 4>\n  area_light <1, 0, 0>, <0, 0, -1>, 2, 2 "
                       "adaptive 2 area_illumination on }");
    ck_assert_msg(strstr(n.text[0], "area_light") && strstr(n.text[0], "penumbrae"), "%s", n.text[0]);
    free(sdl);
}
END_TEST

/* ---- The file: atomic, or nothing ---- */

static char *read_file(const char *path)
{
    FILE *f = fopen(path, "rb");
    if (!f)
        return NULL;
    char *buf = malloc(1 << 20);
    size_t n = fread(buf, 1, (1 << 20) - 1, f);
    buf[n] = '\0';
    fclose(f);
    return buf;
}

static int dir_entries(const char *dir)
{
    DIR *d = opendir(dir);
    int n = 0;
    struct dirent *e;
    ck_assert_ptr_nonnull(d);
    while ((e = readdir(d)) != NULL)
        n += strcmp(e->d_name, ".") != 0 && strcmp(e->d_name, "..") != 0;
    closedir(d);
    return n;
}

static void remove_dir(const char *dir)
{
    DIR *d = opendir(dir);
    struct dirent *e;
    char path[512];
    while (d && (e = readdir(d)) != NULL) {
        if (strcmp(e->d_name, ".") == 0 || strcmp(e->d_name, "..") == 0)
            continue;
        snprintf(path, sizeof path, "%s/%s", dir, e->d_name);
        unlink(path);
    }
    if (d)
        closedir(d);
    rmdir(dir);
}

/* The file holds what the stream gets, replaces an older file whole, and
 * no temporary file is left beside it. */
START_TEST(test_pov_export_file_atomic)
{
    char dir[] = "/tmp/refray-export-XXXXXX", path[256], err[256];
    ck_assert_ptr_nonnull(mkdtemp(dir));
    snprintf(path, sizeof path, "%s/out.pov", dir);
    FILE *old = fopen(path, "w");
    fputs("old contents\n", old);
    fclose(old);
    scene_model *s = load(scene_a);
    pov_opts o = {0, "t.scene", 0, 0, 0};
    pov_notes n;
    ck_assert_int_eq(pov_export_file(s, &o, path, &n, err, sizeof err), 0);
    scene_free(s);
    pov_notes n2;
    char *want = export_default(scene_a, &n2), *got = read_file(path);
    ck_assert_ptr_nonnull(got);
    ck_assert_str_eq(got, want);
    ck_assert_int_eq(dir_entries(dir), 1);
    free(want);
    free(got);
    remove_dir(dir);
}
END_TEST

/* A refused scene and an unwritable place create nothing. */
START_TEST(test_pov_export_file_failures)
{
    char dir[] = "/tmp/refray-export-XXXXXX", path[256], err[256];
    ck_assert_ptr_nonnull(mkdtemp(dir));
    pov_opts o = {0, NULL, 0, 0, 0};
    pov_notes n;
    scene_model *bad = load(scene_refused), *good = load(scene_a);
    snprintf(path, sizeof path, "%s/refused.pov", dir);
    ck_assert_int_eq(pov_export_file(bad, &o, path, &n, err, sizeof err), STATUS_DATA);
    ck_assert_int_eq(access(path, F_OK), -1);
    snprintf(path, sizeof path, "%s/missing/out.pov", dir);
    ck_assert_int_eq(pov_export_file(good, &o, path, &n, err, sizeof err), STATUS_IO);
    ck_assert_msg(strstr(err, "cannot write") && strstr(err, "missing/out.pov"), "%s", err);
    ck_assert_int_eq(dir_entries(dir), 0);
    scene_free(bad);
    scene_free(good);
    remove_dir(dir);
}
END_TEST

/* ---- `refray export` ---- */

typedef struct run_result {
    int code;
    char out[4096];   /* the start of stdout */
    char err[4096];   /* the start of stderr */
} run_result;

static void read_all(int fd, char *buf, size_t size)
{
    size_t used = 0;
    ssize_t got;
    char sink[4096];
    while (used + 1 < size && (got = read(fd, buf + used, size - 1 - used)) > 0)
        used += (size_t)got;
    buf[used] = '\0';
    while (read(fd, sink, sizeof sink) > 0)
        ;
}

/* Runs refray with argv (NULL-terminated, argv[0] ignored).  stderr goes
 * to a file so that a full stdout pipe cannot block the child. */
static void run_refray(const char *const argv[], run_result *r)
{
    const char *bin = getenv("REFRAY_BIN");
    if (!bin || !*bin)
        bin = "build/refray";
    ck_assert_msg(access(bin, X_OK) == 0, "no refray binary at %s (set REFRAY_BIN)", bin);
    FILE *errf = tmpfile();
    int fds[2];
    ck_assert_ptr_nonnull(errf);
    ck_assert_int_eq(pipe(fds), 0);
    pid_t pid = fork();
    ck_assert_int_ge(pid, 0);
    if (pid == 0) {
        dup2(fds[1], 1);
        dup2(fileno(errf), 2);
        close(fds[0]);
        close(fds[1]);
        execv(bin, (char *const *)argv);
        _exit(127);
    }
    close(fds[1]);
    read_all(fds[0], r->out, sizeof r->out);
    close(fds[0]);
    int status;
    ck_assert_int_eq(waitpid(pid, &status, 0), pid);
    r->code = WIFEXITED(status) ? WEXITSTATUS(status) : -1;
    rewind(errf);
    read_all(fileno(errf), r->err, sizeof r->err);
    fclose(errf);
}

static void write_text(const char *path, const char *text)
{
    FILE *f = fopen(path, "w");
    ck_assert_ptr_nonnull(f);
    fputs(text, f);
    fclose(f);
}

/* Without -o the SDL goes to stdout and the notes to stderr. */
START_TEST(test_cli_export_stdout)
{
    char dir[] = "/tmp/refray-export-XXXXXX", scene[256];
    ck_assert_ptr_nonnull(mkdtemp(dir));
    snprintf(scene, sizeof scene, "%s/a.scene", dir);
    write_text(scene, scene_approx);
    const char *argv[] = {"refray", "export", scene, "--to", "pov", NULL};
    run_result r;
    run_refray(argv, &r);
    ck_assert_int_eq(r.code, 0);
    ck_assert_msg(strncmp(r.out, "// POV-Ray 3.7 scene written by `refray export --to pov`", 55) == 0, "%s",
                  r.out);
    ck_assert_msg(strncmp(r.err, "refray: approximation: point_light at ", 38) == 0, "%s", r.err);
    ck_assert_int_eq(count_of(r.err, "refray: approximation: "), 2);
    remove_dir(dir);
}
END_TEST

/* [JSON-OUT-1] -o - is standard output too, for both targets, as for
 * render and as the help says (tests/attack12 finding 8: a file named
 * "-" in the working directory, nothing on stdout). */
START_TEST(test_cli_export_dash_is_stdout)
{
    char dir[] = "/tmp/refray-export-XXXXXX", scene[256];
    ck_assert_ptr_nonnull(mkdtemp(dir));
    snprintf(scene, sizeof scene, "%s/a.scene", dir);
    write_text(scene, scene_ortho);
    for (int json = 0; json < 1 + scene_json_available(); json++) {
        const char *argv[] = {"refray", "export", scene, "--to", json ? "json" : "pov", "-o", "-", NULL};
        run_result r;
        run_refray(argv, &r);
        int stray = access("-", F_OK) == 0;
        unlink("-");
        ck_assert_msg(r.code == 0, "exit %d: %s", r.code, r.err);
        ck_assert_msg(!stray, "--to %s -o - wrote a file named '-'", argv[4]);
        const char *head = json ? "{" : "// POV-Ray 3.7 scene written by `refray export --to pov`";
        ck_assert_msg(strncmp(r.out, head, strlen(head)) == 0, "stdout: '%.80s'", r.out);
    }
    remove_dir(dir);
}
END_TEST

/* -o writes the file and nothing to stdout; a refused scene exits 65
 * with the reason and writes nothing; a wrong target is a usage error. */
START_TEST(test_cli_export_file_and_refusal)
{
    char dir[] = "/tmp/refray-export-XXXXXX", scene[256], bad[256], out[256], out2[256];
    ck_assert_ptr_nonnull(mkdtemp(dir));
    snprintf(scene, sizeof scene, "%s/a.scene", dir);
    snprintf(bad, sizeof bad, "%s/bad.scene", dir);
    snprintf(out, sizeof out, "%s/a.pov", dir);
    snprintf(out2, sizeof out2, "%s/bad.pov", dir);
    write_text(scene, scene_ortho);
    write_text(bad, scene_refused);
    run_result r;
    const char *argv1[] = {"refray", "export", scene, "--to", "pov", "-o", out, NULL};
    run_refray(argv1, &r);
    ck_assert_int_eq(r.code, 0);
    ck_assert_str_eq(r.out, "");
    char *sdl = read_file(out);
    ck_assert_ptr_nonnull(sdl);
    ck_assert_has(sdl, "  orthographic\n");
    free(sdl);
    const char *argv2[] = {"refray", "export", bad, "--to", "pov", "-o", out2, NULL};
    run_refray(argv2, &r);
    ck_assert_int_eq(r.code, 65);
    ck_assert_msg(strstr(r.err, "refray: error: cannot export '") && strstr(r.err, "inverse_square"), "%s",
                  r.err);
    ck_assert_int_eq(access(out2, F_OK), -1);
    const char *argv3[] = {"refray", "export", scene, "--to", "mitsuba", NULL};
    run_refray(argv3, &r);
    ck_assert_int_eq(r.code, 64);
    ck_assert_msg(strstr(r.err, "unknown target 'mitsuba'") != NULL, "%s", r.err);
    remove_dir(dir);
}
END_TEST

Suite *suite_export(void)
{
    Suite *s = suite_create("export");
    TCase *sdl = tcase_create("sdl");
    tcase_add_test(sdl, test_pov_export_write_camera);
    tcase_add_test(sdl, test_pov_export_write_orthographic);
    tcase_add_test(sdl, test_pov_render_size);
    tcase_add_test(sdl, test_pov_export_write_globals);
    tcase_add_test(sdl, test_pov_export_write_lights);
    tcase_add_test(sdl, test_pov_export_write_distant_direction);
    tcase_add_test(sdl, test_pov_export_write_finish);
    tcase_add_test(sdl, test_pov_export_write_interior);
    tcase_add_test(sdl, test_pov_export_write_plain_sheets);
    tcase_add_test(sdl, test_pov_export_write_scale);
    tcase_add_test(sdl, test_pov_export_write_matrix);
    tcase_add_test(sdl, test_pov_export_write_triangle);
    tcase_add_test(sdl, test_pov_export_write_mesh);
    tcase_add_test(sdl, test_pov_export_write_quadrics);
    tcase_add_test(sdl, test_pov_export_check_notes);
    tcase_add_test(sdl, test_pov_export_check_smooth_mesh);
    tcase_add_test(sdl, test_pov_export_check_terminator);
    tcase_add_test(sdl, test_pov_export_check_shadow_tolerance);
    tcase_add_test(sdl, test_pov_export_check_glass_contact);
    tcase_add_test(sdl, test_pov_export_check_far_plane);
    tcase_add_test(sdl, test_pov_export_check_far_shadow);
    tcase_add_test(sdl, test_pov_export_far_bounds_mesh);
    tcase_add_test(sdl, test_pov_export_write_approximations);
    tcase_add_test(sdl, test_pov_export_write_refused);
    tcase_add_test(sdl, test_pov_export_write_distributed_points);
    tcase_add_test(sdl, test_pov_export_write_area_light);
    suite_add_tcase(s, sdl);
    TCase *file = tcase_create("file");
    tcase_add_test(file, test_pov_export_file_atomic);
    tcase_add_test(file, test_pov_export_file_failures);
    tcase_add_test(file, test_cli_export_stdout);
    tcase_add_test(file, test_cli_export_dash_is_stdout);
    tcase_add_test(file, test_cli_export_file_and_refusal);
    suite_add_tcase(s, file);
    return s;
}

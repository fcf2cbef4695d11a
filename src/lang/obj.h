/*
 * obj.h - reads the part of Wavefront OBJ that a `mesh` statement needs:
 * vertex positions, vertex normals and polygonal faces, the faces cut into
 * triangles.
 *
 * Accepted statements (anything else: see obj_parse):
 *   v x y z [w]        a position; w (and the r g b colours some writers
 *                      append) are checked to be numbers and dropped
 *   vn x y z           a normal, kept as read (not normalised)
 *   f c1 c2 c3 ...     a polygon of n >= 3 corners, each `i`, `i/t`,
 *                      `i//n` or `i/t/n`; indices are 1-based, or negative
 *                      for "counted back from the last one defined so far"
 *                      (-1 is the latest)
 *   vt o g s usemtl mtllib   silently ignored (texture coordinates are
 *                      still counted, so `t` indices are range-checked)
 * Lexical rules: `#` starts a comment running to the end of its physical
 * line; lines end in LF, CRLF or a lone CR; a backslash that is the last
 * non-blank byte of a line joins the next line to it (the pair acts as a
 * blank, so it may separate tokens but never splits one); blanks are
 * spaces, tabs, VT and FF; a UTF-8 byte-order mark at the start is skipped.
 *
 * Triangulation: a polygon c0 c1 ... c(n-1) becomes the fan
 * (c0, ck, ck+1) for k = 1 .. n-2, which keeps the polygon's winding.  The
 * fan covers the polygon exactly only when the polygon is convex (and
 * planar); a concave polygon's fan overlaps itself or spills outside it.
 * OBJ writers triangulate or emit convex faces in practice.
 */
#ifndef REFRAY_OBJ_H
#define REFRAY_OBJ_H

#include "base/diag.h"
#include "base/source.h"
#include "base/vec.h"

typedef struct obj_triangle {
    int v[3];          /* 0-based indices into positions */
    int vn[3];         /* 0-based indices into normals, or -1 when the face gave none */
    src_span where;    /* the `f` statement it came from, keyword to last corner */
} obj_triangle;

typedef struct obj_mesh {
    vec3 *positions;
    int position_count;
    vec3 *normals;               /* as read; not normalised */
    int normal_count;
    obj_triangle *triangles;
    int triangle_count;
    int position_cap, normal_cap, triangle_cap; /* entries allocated */
    mem mem;                     /* the source set's: where the arrays live */
} obj_mesh;

/* Parses sources->files[file] as OBJ.  Every problem goes to d with the
 * span of the offending token: errors for bad input, one warning per kind of
 * unknown statement ("unknown OBJ statement 'xyz' ignored").  Returns 1 when
 * the mesh is usable (this call reported no error; warnings allowed); 0
 * otherwise, -1 when memory ran out ("out of memory reading OBJ file"
 * reported), and *out is then empty (all NULL / 0, nothing to free).  The
 * arrays come from the allocator of sources.
 * max_triangles: a mesh with more triangles is refused with an error at the
 * face that crosses the limit, and no memory is ever reserved for more than
 * that many triangles.  A mesh with no faces is an error.  Degenerate
 * triangles are not detected here.  Parsing stops early once
 * diag_too_many(d) holds.  strtod reads the numbers: the C locale's '.'
 * decimal point is assumed (the library never calls setlocale). */
int obj_parse(const source_set *sources, int file, diag *d, long max_triangles, obj_mesh *out);

/* Frees what obj_parse allocated and empties *mesh; safe on an empty mesh. */
void obj_free(obj_mesh *mesh);

#endif

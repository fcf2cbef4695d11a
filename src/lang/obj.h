/*
 * obj.h - reads the part of Wavefront OBJ that a `mesh` statement needs:
 * vertex positions, vertex normals and polygonal faces, the faces cut into
 * triangles (into a polymesh, shared with the PLY reader).
 *
 * Accepted statements (anything else: see obj_parse):
 *   v x y z [w]        a position; w (and the r g b colours some writers
 *                      append) are checked to be numbers and dropped; at
 *                      most 7 numbers
 *   vn x y z           a normal, kept as read (not normalised); a zero one
 *                      is an error at the vn statement
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
 * Triangulation: a polygon is cut by ear clipping on its plane, keeping
 * its winding (polygon.h); faces with no area give no triangle and are
 * counted, as are non-planar ones (polymesh.h), for the caller to report.
 */
#ifndef REFRAY_OBJ_H
#define REFRAY_OBJ_H

#include "base/diag.h"
#include "base/source.h"
#include "lang/polymesh.h"

/* Parses sources->files[file] as OBJ into *out.  Every problem goes to d
 * with the span of the offending token: errors for bad input, one warning
 * per kind of unknown statement ("unknown OBJ statement 'xyz' ignored").
 * Returns 1 when the mesh is usable (this call reported no error; warnings
 * allowed); 0 otherwise, -1 when memory ran out ("out of memory reading OBJ
 * file" reported), and *out is then empty (polymesh_free done).  The
 * arrays come from the allocator of sources.
 * max_triangles: a mesh with more triangles is refused with an error at the
 * face that crosses the limit, and no memory is ever reserved for more than
 * that many triangles.  A mesh with no faces is an error.  Triangles whose
 * corners are on one line are not detected here (the caller drops them
 * after its transforms).  Parsing stops early once diag_too_many(d) holds.
 * strtod reads the numbers: the C locale's '.' decimal point, which each
 * load of the library sets for its thread ([EMBED-LOCALE-1]).  The text is read from memory only:
 * sources->files[file]->text and len. */
int obj_parse(const source_set *sources, int file, diag *d, long max_triangles, polymesh *out);

#endif

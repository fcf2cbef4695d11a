/*
 * ply.h - reads the Stanford PLY polygon format for the `mesh` statement:
 * vertex positions, optional vertex normals and polygon faces, cut into
 * triangles into a polymesh (shared with the OBJ reader).
 *
 * Accepted (spec/language.md, section 8):
 *   ply
 *   format ascii 1.0 | binary_little_endian 1.0 | binary_big_endian 1.0
 *   comment ... | obj_info ...           (any number, anywhere in the header)
 *   element NAME COUNT                   (any number of elements)
 *   property TYPE NAME                   (scalars)
 *   property list COUNT_TYPE TYPE NAME   (lists)
 *   end_header
 * TYPE is char uchar short ushort int uint float double or int8 uint8
 * int16 uint16 int32 uint32 float32 float64.  The element `vertex` must
 * have properties x, y, z and may have nx, ny, nz (all three); the element
 * `face` must have a list vertex_indices (or vertex_index) of integer type.
 * The elements may come in any order (faces before vertices too).  Every
 * other element and property is read past and ignored.  ASCII data are
 * whitespace-separated numbers; binary data are packed, with the header's
 * byte order.  A face of fewer than 3 corners has no area and is counted
 * as such; polygons are cut as OBJ ones are (polygon.h).
 *
 * Errors: a header mistake points at its token (file:line:col); a mistake
 * in ASCII data at the offending number, naming the element, its number
 * and the property; in binary data at the header line that declared the
 * element, with the byte offset in the message.
 */
#ifndef REFRAY_PLY_H
#define REFRAY_PLY_H

#include "base/diag.h"
#include "base/source.h"
#include "lang/polymesh.h"

/* Whether text starts like a PLY file ("ply" and a line end). */
int ply_is_ply(const char *text, size_t len);

/* Parses sources->files[file] (text and len, in memory; NUL bytes allowed
 * in binary data) as PLY into *out.  Returns 1 when the mesh is usable (no
 * error reported by this call); 0 otherwise, with *out empty.  As obj_parse:
 * max_triangles is enforced before memory is reserved, a mesh with no faces
 * is an error, parsing stops once diag_too_many(d) holds. */
int ply_parse(const source_set *sources, int file, diag *d, long max_triangles, polymesh *out);

#endif

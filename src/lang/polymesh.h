/*
 * polymesh.h - a mesh as a file gives it: positions, normals and faces cut
 * into triangles.  The OBJ reader (obj.h) and the PLY reader (ply.h) both
 * fill one; the scene's `mesh` statement (src/scene/lower_mesh.c) turns it
 * into the compact world-space store the tracer reads.
 *
 * Faces go through polymesh_add_face, the one place where polygons are cut
 * (polygon.h) and where what the readers share is counted: faces with no
 * area (dropped), non-planar faces, faces that had to be fanned.  The
 * readers report their own syntax errors; those counts are reported once
 * per mesh by the caller.
 */
#ifndef REFRAY_POLYMESH_H
#define REFRAY_POLYMESH_H

#include <stddef.h>
#include "base/diag.h"
#include "base/mem.h"
#include "base/vec.h"
#include "lang/polygon.h"

/* A count of faces with something to say, and where the first one is. */
typedef struct polymesh_tally {
    int count;
    size_t first_at;
} polymesh_tally;

/* The triangles are parallel arrays, so that the scene can take over the
 * corner and normal arrays as they are (src/scene/lower_mesh.c). */
typedef struct polymesh {
    vec3 *positions;
    int position_count;
    vec3 *normals;               /* as read; not normalised */
    int normal_count;
    int (*tri)[3];               /* corners: 0-based indices into positions */
    int (*tri_normal)[3];        /* 0-based indices into normals, -1 where the face
                                    gave none; NULL until some face gives normals */
    size_t *tri_at;              /* byte offset of each triangle's face, for messages */
    int triangle_count;
    int face_count;              /* faces given (of any size) */
    polymesh_tally no_area;      /* faces with no area: no triangle made */
    polymesh_tally nonplanar;    /* polygons not on one plane (cut all the same) */
    polymesh_tally fanned;       /* not simple, or over the ear-clipping budget */
    /* entries allocated (every array comes from mem) */
    int position_cap, normal_cap, tri_cap, tri_normal_cap, tri_at_cap;
    /* builder state */
    long max_triangles;          /* refuse a face that would pass this */
    vec3 *corners;               /* one polygon's positions, then its */
    int (*cuts)[3];              /* triangles as corner numbers: one block */
    int cut_cap;
    polygon_work work;
    mem mem;
} polymesh;

/* An empty mesh that accepts up to max_triangles triangles (clamped to
 * [0, INT_MAX]), allocating from m (NULL: the C library). */
void polymesh_init(polymesh *m, long max_triangles, const mem *mm);

/* Returns array (of *cap elements of size bytes, from m) grown to hold at
 * least `need` elements (at least 1), its capacity doubling from 16 and
 * capped at limit; NULL when need exceeds limit, the byte count would
 * overflow, or memory runs out (array and *cap untouched then).  The
 * readers' arrays grow through it. */
void *polymesh_grow(const mem *m, void *array, int *cap, long need, size_t size, long limit);

/* Frees everything and leaves an empty mesh; safe to call twice. */
void polymesh_free(polymesh *m);

/* The end of a reader's parse into m (obj.h, ply.h): "mesh has no faces"
 * at *no_faces_at when no face was read and no error reported since
 * errors_before (NULL: the reader has reported why already).  Returns 1
 * when no error was reported and the reader was not stopped; else frees m
 * and returns -1 after running out of memory, 0 otherwise. */
int polymesh_finish(polymesh *m, diag *d, int errors_before, const src_span *no_faces_at, int stopped,
                    int out_of_memory);

/* What polymesh_add_* return besides 1 (done). */
enum {
    POLYMESH_NO_MEMORY = 0,
    POLYMESH_TOO_MANY = -1      /* past INT_MAX items or max_triangles */
};

int polymesh_add_position(polymesh *m, vec3 p);
int polymesh_add_normal(polymesh *m, vec3 n);

/*
 * Adds the face of n corners: v[i] are position indices (already checked
 * to be in range), vn[i] normal indices or NULL for none.  Cuts it into
 * triangles (polygon.h) and counts it in the tallies (fewer than 3 corners:
 * no area, no triangle); `at` is the
 * face's byte offset in its file.  Returns 1, or POLYMESH_TOO_MANY when the
 * mesh would pass max_triangles (checked before any room is made), or
 * POLYMESH_NO_MEMORY.  Nothing is added on failure.
 */
int polymesh_add_face(polymesh *m, const int *v, const int *vn, int n, size_t at);

#endif

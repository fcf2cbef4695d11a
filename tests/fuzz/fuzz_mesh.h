/*
 * fuzz_mesh.h - what the OBJ and PLY harnesses share: the input becomes the
 * file "fuzz.mesh" of a source set, is read by one of the readers, every
 * diagnostic is printed (the caret printer is part of what hostile input
 * reaches), and a mesh that was accepted goes on to what the scene does
 * with one: its topology (mesh_topo.c) over its triangles as read.
 *
 * A reader must accept or refuse, never both (a refused mesh is empty), and
 * what it accepts indexes only what it read.  Limits are low so that a huge
 * legal input costs milliseconds (the fuzzer looks for crashes, leaks and
 * undefined behaviour; a slow input would only hide them).
 */
#ifndef REFRAY_FUZZ_MESH_H
#define REFRAY_FUZZ_MESH_H

#include <stddef.h>
#include <stdint.h>
#include <stdio.h>
#include <string.h>
#include "base/diag.h"
#include "lang/polymesh.h"
#include "scene/mesh_topo.h"

typedef int (*fuzz_reader)(const source_set *sources, int file, diag *d, long max_triangles, polymesh *out);

static inline void fuzz_check(const polymesh *m)
{
    for (int t = 0; t < m->triangle_count; t++)
        for (int k = 0; k < 3; k++) {
            if (m->tri[t][k] < 0 || m->tri[t][k] >= m->position_count)
                __builtin_trap();
            if (m->tri_normal && (m->tri_normal[t][k] < -1 || m->tri_normal[t][k] >= m->normal_count))
                __builtin_trap();
        }
}

static inline int fuzz_mesh(const uint8_t *data, size_t size, fuzz_reader read)
{
    source_set set;
    diag d;
    polymesh m;
    source_set_init(&set, NULL);
    int file = source_set_add(&set, "fuzz.mesh", (const char *)data, size, src_span_none());
    if (file < 0) {
        source_set_free(&set);
        return 0;
    }
    /* Messages counted, not delivered. */
    diag_init(&d, &set, NULL, NULL);
    d.max_errors = 8;
    int ok = read(&set, file, &d, 2000, &m);
    if (ok != (d.errors == 0) || (!ok && (m.tri || m.positions || m.triangle_count)))
        __builtin_trap();
    fuzz_check(&m);
    if (ok) {
        scene_trimesh g;
        mesh_topo topo;
        memset(&g, 0, sizeof g);
        g.positions = m.positions;
        g.position_count = m.position_count;
        g.tri = m.tri;
        g.tri_count = m.triangle_count;
        unsigned char open[2000];
        if (mesh_topo_analyse(&g, NULL, &topo, open) && topo.closed != (topo.open_edges == 0 && topo.crowded_edges == 0))
            __builtin_trap();
    }
    polymesh_free(&m);
    source_set_free(&set);
    return 0;
}

#endif

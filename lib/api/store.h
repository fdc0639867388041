/*
 * store.h - the one way lib/api reaches the simplex store behind a cvm_mesh:
 * counts, views of points, weights, cells, neighbours, segments and
 * attributes, iteration over the domain's cells, and the store operations
 * the public calls need (create, clear, locate, insert, weights, check).
 * The 2D store (cvm__tri2 of lib/delaunay) sits behind it in store2.c; the 3D
 * handle's tetrahedra (m->m3, lib/api/mesh3_internal.h: flat arrays written
 * by lib/delaunay3 and lib/tetgen) join by dimension: the accessors of the
 * first section branch on cvm__store_dim(m). The ghost, adjacency and face
 * accessors and the operations are 2D only so far.
 *
 * Vocabulary, the same in every dimension: a *vertex* has cvm__store_dim(m)
 * coordinates (and one weight when weights are set); a *cell* is a simplex
 * of dim + 1 vertices held in a *slot* (slots 0..cvm__store_nslots(m)-1,
 * some dead, ghost or outside the domain); *face* j of a cell is the one
 * opposite its vertex j; a cell is *in the domain* when it is live, not a
 * ghost, and not carved away (exterior, holes). The domain cells in slot
 * order are the output order (output_internal.h).
 *
 * Engines of one dimension take that dimension's store: cvm__store_tri2()
 * hands the 2D engines (lib/refine, lib/dual, lib/boundary, the CDT) their
 * triangulation, and is where a 3D call would take its own instead.
 * No file of lib/api but this header and store2.c names the store's fields
 * or the kernel's cvm__tri2_* functions (.ci/check_layers.sh checks it).
 */
#ifndef CVM_API_STORE_H
#define CVM_API_STORE_H

#include "api_internal.h"
#include "api/mesh3_internal.h"

/* ---- counts and views (valid until the next call that changes m) ---- */

/* Dimension of the store: 2 (triangles of m->tri) or 3 (the tetrahedra of a
 * 3D handle, m->m3: dense, every slot a cell of the domain, no ghosts). */
static inline int cvm__store_dim(const cvm_mesh *m)
{
    return m->m3 ? 3 : 2;
}
/* Vertices per cell (dim + 1); also faces per cell. */
static inline int cvm__store_cell_size(const cvm_mesh *m)
{
    return cvm__store_dim(m) + 1;
}
/* Vertices: the input less duplicates, then Steiner points. */
static inline size_t cvm__store_nv(const cvm_mesh *m)
{
    if (m->m3)
        return m->m3->have ? m->m3->nv : 0;
    return m->tri.nv;
}
/* Cell slots (live or not). */
static inline size_t cvm__store_nslots(const cvm_mesh *m)
{
    if (m->m3)
        return m->m3->have ? m->m3->ntet : 0;
    return m->tri.nt;
}
/* Coordinates of every vertex, dim per vertex. */
static inline const double *cvm__store_points(const cvm_mesh *m)
{
    return m->m3 ? m->m3->xyz : m->tri.xy;
}
/* Coordinates of vertex v. */
static inline const double *cvm__store_point(const cvm_mesh *m, size_t v)
{
    return m->m3 ? m->m3->xyz + 3 * v : m->tri.xy + 2 * v;
}
/* Weight of every vertex, or NULL when no weights are set. */
static inline const double *cvm__store_weights(const cvm_mesh *m)
{
    return m->m3 ? m->m3->w : m->tri.w;
}
/* Vertices of the cell in slot t (counter-clockwise in 2D, positively
 * oriented in 3D). */
static inline const int32_t *cvm__store_cell(const cvm_mesh *m, size_t t)
{
    return m->m3 ? m->m3->tet + 4 * t : m->tri.tv + 3 * t;
}
/* 1 when slot t holds a cell of the domain (0 for t < 0). */
static inline int cvm__store_in_domain(const cvm_mesh *m, int32_t t)
{
    if (m->m3)
        return t >= 0 && (size_t)t < cvm__store_nslots(m);
    return t >= 0 && cvm__tri2_in_domain(&m->tri, t);
}
/* 1 when slot t holds a ghost cell (beyond the convex hull). */
static inline int cvm__store_is_ghost(const cvm_mesh *m, int32_t t)
{
    return cvm__tri2_is_ghost(&m->tri, t);
}
/* The slot across face j of cell t (a domain cell, an outside or a ghost
 * one), or -1 when there is none. */
static inline int32_t cvm__store_across(const cvm_mesh *m, size_t t, int j)
{
    int32_t a = m->tri.tn[3 * t + (size_t)j];
    return a < 0 ? -1 : a / 3;
}
/* The input segment (2D; facet in 3D) face j of cell t lies on, or -1. */
static inline int32_t cvm__store_face_segment(const cvm_mesh *m, size_t t, int j)
{
    return cvm__tri2_edge_seg(&m->tri, (int32_t)t, j);
}
/* Regional attribute per slot (writable through a non-const m), or NULL
 * without regions. */
static inline double *cvm__store_cell_attributes(const cvm_mesh *m)
{
    return m->m3 ? m->m3->tattr : m->tri.ta;
}
/* The first domain cell after slot t (t = -1: the first), or -1 after the last:
 * for (t = cvm__store_next_cell(m, -1); t >= 0; t = cvm__store_next_cell(m, t)). */
static inline int32_t cvm__store_next_cell(const cvm_mesh *m, int32_t t)
{
    if (m->m3)
        return (size_t)(t + 1) < cvm__store_nslots(m) ? t + 1 : -1;
    for (t++; (size_t)t < m->tri.nt; t++)
        if (cvm__tri2_in_domain(&m->tri, t))
            return t;
    return -1;
}

/* ---- the store of the 2D engines ---- */

/* The triangulation the 2D engines work on; the only way an API file hands
 * the store to lib/delaunay, lib/refine, lib/dual, lib/boundary or lib/sizing. */
static inline cvm__tri2 *cvm__store_tri2(cvm_mesh *m)
{
    return &m->tri;
}
static inline const cvm__tri2 *cvm__store_tri2_const(const cvm_mesh *m)
{
    return &m->tri;
}

/* ---- operations (store2.c) ---- */

/* An empty store for the new handle m (allocates nothing). */
void cvm__store_init(cvm_mesh *m);
/* Free the store's memory. */
void cvm__store_destroy(cvm_mesh *m);
/* Empty the store, keeping its memory for the next triangulation. */
void cvm__store_clear(cvm_mesh *m);
/* Renumber the input segment of every constrained face: seg k (0 <= k < n) becomes map[k]
 * (a triangulation built from pieces of the input segments names them as the input does). */
void cvm__store_remap_segments(cvm_mesh *m, const int32_t *map, size_t n);
/* Exchange the store's triangulation with *T (same dimension and context). */
void cvm__store_exchange_tri2(cvm_mesh *m, cvm__tri2 *T);
/* Replace the store's triangulation by *T, built through another context of
 * the same allocator (it now uses m's), and free the old one; *T is left
 * empty. */
void cvm__store_adopt_tri2(cvm_mesh *m, cvm__tri2 *T);

/* The domain cell holding point p, or -1 outside the triangulation. */
int32_t cvm__store_locate(cvm_mesh *m, const double *p);

/* Append vertex p (not yet inserted) as *v_out. CVM_OK, CVM_E_NOMEM or
 * CVM_E_TOO_LARGE (no message). */
cvm_status cvm__store_add_vertex(cvm_mesh *m, const double *p, int32_t *v_out);
/* Remove the last vertex appended and not inserted. */
void cvm__store_drop_last_vertex(cvm_mesh *m);
/* Insert appended vertex v into the domain (starting the walk at the last
 * cell touched); *inserted = 0 when v falls outside the domain, on a
 * vertex, or closer than min_dist to one (v is then not in any cell).
 * CVM_OK, CVM_E_NOMEM, or another error of the kernel (no message). */
cvm_status cvm__store_insert_vertex(cvm_mesh *m, int32_t v, double min_dist, int *inserted);

/* Replace the weights by w (nv values, copied; NULL removes them) and flip
 * to the regular triangulation. On error the old weights and cells stay.
 * CVM_OK, CVM_E_NOMEM or a kernel error (no message). */
cvm_status cvm__store_set_weights(cvm_mesh *m, const double *w);
/* Vertices whose weight keeps them out of the regular triangulation; mark
 * (nv bytes) receives 1 for each. */
size_t cvm__store_count_vanished(cvm_mesh *m, uint8_t *mark);
/* Give value to the regional attribute of domain cell t and of every cell
 * reached from it without crossing a constrained face. CVM_OK or CVM_E_NOMEM. */
cvm_status cvm__store_flood_attribute(cvm_mesh *m, int32_t t, double value);
/* The kernel's own checks of the store (orientation, adjacency, the
 * constrained Delaunay/regular property) and of the input segment chains;
 * set the message. */
cvm_status cvm__store_check(cvm_mesh *m);

#endif

/*
 * output.c - counts, copies and views of a mesh's output and input arrays.
 *
 * These functions take a const handle: they neither change the last error
 * nor its message (the status says what failed). Output order:
 * triangles in slot order of the kernel, edges and segments sorted by
 * (lower, higher) vertex id (output_internal.h). A NULL dst is accepted only
 * with dst_len 0 (then any non-empty copy reports CVM_E_BUFFER_TOO_SMALL).
 */
#include <string.h>

#include "output_internal.h"
#include "api/mesh3.h"
#include "store.h"

/* The allocator of a const handle: allocation does not change the handle. */
static cvm__ctx *alloc_ctx(const cvm_mesh *m)
{
    return (cvm__ctx *)&m->ctx;
}

static size_t n_vertices(const cvm_mesh *m)
{
    return m->triangulated ? cvm__store_nv(m) : 0;
}

cvm_status cvm_mesh_count(size_t *out, const cvm_mesh *m, cvm_entity kind)
{
    if (out && m && m->m3)
        return cvm__mesh3_count(out, m, kind);
    size_t ne = 0, ns = 0;
    if (!out || !m)
        return CVM_E_NULL_ARG;
    *out = 0;
    switch (kind) {
    case CVM_ENT_VERTEX: *out = n_vertices(m); return CVM_OK;
    case CVM_ENT_TRIANGLE: *out = cvm__mesh_n_triangles(m); return CVM_OK;
    case CVM_ENT_EDGE:
    case CVM_ENT_SEGMENT:
        if (m->triangulated)
            cvm__domain_edge_counts(cvm__store_tri2_const(m), &ne, &ns);
        *out = kind == CVM_ENT_EDGE ? ne : ns;
        return CVM_OK;
    case CVM_ENT_INPUT_POINT: *out = m->in.np; return CVM_OK;
    case CVM_ENT_INPUT_SEGMENT: *out = m->in.nseg; return CVM_OK;
    case CVM_ENT_HOLE: *out = m->in.nholes; return CVM_OK;
    case CVM_ENT_REGION: *out = m->in.nregions; return CVM_OK;
    case CVM_ENT_DUPLICATE: *out = m->triangulated ? m->n_dup : 0; return CVM_OK;
    case CVM_ENT_REFINE_UNMET: *out = m->n_refine_unmet; return CVM_OK;
    default: return CVM_E_ARGUMENT;
    }
}

cvm_status cvm_mesh_copy_points(double *dst, size_t dst_len, const cvm_mesh *m)
{
    if (m && m->m3)
        return CVM_E_UNSUPPORTED; /* a 2D call on a 3D mesh */
    size_t nv;
    cvm_status s;
    if (!m)
        return CVM_E_NULL_ARG;
    nv = n_vertices(m);
    if ((s = cvm__room(dst, dst_len, 2 * nv)))
        return s;
    if (nv)
        memcpy(dst, cvm__store_points(m), 2 * nv * sizeof *dst);
    return CVM_OK;
}

static cvm_status copy_triangles(cvm_index *dst, size_t dst_len, const cvm_mesh *m)
{
    int32_t t;
    size_t k = 0;
    cvm_status s = cvm__room(dst, dst_len, 3 * cvm__mesh_n_triangles(m));
    if (s || !m->triangulated)
        return s;
    for (t = cvm__store_next_cell(m, -1); t >= 0; t = cvm__store_next_cell(m, t)) {
        memcpy(dst + 3 * k, cvm__store_cell(m, (size_t)t), 3 * sizeof *dst);
        k++;
    }
    return CVM_OK;
}

static cvm_status copy_edges(cvm_index *dst, size_t dst_len, const cvm_mesh *m, int segments)
{
    size_t ne = 0, ns = 0;
    cvm__edges e;
    cvm_status s;
    if (m->triangulated)
        cvm__domain_edge_counts(cvm__store_tri2_const(m), &ne, &ns);
    if ((s = cvm__room(dst, dst_len, 2 * (segments ? ns : ne))) || !m->triangulated)
        return s;
    if (cvm__domain_edges(alloc_ctx(m), cvm__store_tri2_const(m), segments, &e))
        return CVM_E_NOMEM;
    if (e.n)
        memcpy(dst, e.ev, 2 * e.n * sizeof *dst);
    cvm__edges_free(alloc_ctx(m), &e);
    return CVM_OK;
}

cvm_status cvm_mesh_copy_cells(cvm_index *dst, size_t dst_len, const cvm_mesh *m, cvm_entity kind)
{
    if (m && m->m3)
        return cvm__mesh3_copy_cells(dst, dst_len, m, kind);
    if (!m)
        return CVM_E_NULL_ARG;
    switch (kind) {
    case CVM_ENT_TRIANGLE: return copy_triangles(dst, dst_len, m);
    case CVM_ENT_EDGE: return copy_edges(dst, dst_len, m, 0);
    case CVM_ENT_SEGMENT: return copy_edges(dst, dst_len, m, 1);
    default: return CVM_E_ARGUMENT;
    }
}

cvm_status cvm_mesh_copy_neighbors(cvm_index *dst, size_t dst_len, const cvm_mesh *m)
{
    if (m && m->m3)
        return CVM_E_UNSUPPORTED; /* a 2D call on a 3D mesh */
    int32_t *map;
    size_t t, k = 0;
    int j;
    cvm_status s;
    if (!m)
        return CVM_E_NULL_ARG;
    if ((s = cvm__room(dst, dst_len, 3 * cvm__mesh_n_triangles(m))) || !m->triangulated)
        return s;
    if (cvm__domain_map(alloc_ctx(m), cvm__store_tri2_const(m), &map))
        return CVM_E_NOMEM;
    for (t = 0; t < cvm__store_nslots(m); t++) {
        if (map[t] < 0)
            continue;
        for (j = 0; j < 3; j++) {
            int32_t a = cvm__store_across(m, t, j);
            dst[3 * k + (size_t)j] = a < 0 ? -1 : map[a];
        }
        k++;
    }
    cvm__free(alloc_ctx(m), map);
    return CVM_OK;
}

static cvm_status segment_markers(int32_t *dst, size_t dst_len, const cvm_mesh *m)
{
    size_t ne = 0, ns = 0, k;
    cvm__edges e;
    cvm_status s;
    if (m->triangulated)
        cvm__domain_edge_counts(cvm__store_tri2_const(m), &ne, &ns);
    if ((s = cvm__room(dst, dst_len, ns)) || !m->triangulated)
        return s;
    if (cvm__domain_edges(alloc_ctx(m), cvm__store_tri2_const(m), 1, &e))
        return CVM_E_NOMEM;
    for (k = 0; k < e.n; k++)
        dst[k] = cvm__segment_marker(m, e.seg[k]);
    cvm__edges_free(alloc_ctx(m), &e);
    return CVM_OK;
}

cvm_status cvm_mesh_copy_markers(int32_t *dst, size_t dst_len, const cvm_mesh *m, cvm_entity kind)
{
    if (m && m->m3)
        return CVM_E_UNSUPPORTED; /* a 2D call on a 3D mesh */
    size_t nv;
    cvm_status s;
    if (!m)
        return CVM_E_NULL_ARG;
    if (kind == CVM_ENT_SEGMENT)
        return segment_markers(dst, dst_len, m);
    if (kind != CVM_ENT_VERTEX)
        return CVM_E_ARGUMENT;
    nv = n_vertices(m);
    if ((s = cvm__room(dst, dst_len, nv)))
        return s;
    if (nv && m->vmark)
        memcpy(dst, m->vmark, nv * sizeof *dst);
    else if (nv)
        memset(dst, 0, nv * sizeof *dst);
    return CVM_OK;
}

cvm_status cvm_mesh_copy_triangle_attributes(double *dst, size_t dst_len, const cvm_mesh *m)
{
    if (m && m->m3)
        return CVM_E_UNSUPPORTED; /* a 2D call on a 3D mesh */
    const double *ta;
    size_t k = 0;
    int32_t t;
    cvm_status s;
    if (!m)
        return CVM_E_NULL_ARG;
    if ((s = cvm__room(dst, dst_len, cvm__mesh_n_triangles(m))) || !m->triangulated)
        return s;
    ta = cvm__store_cell_attributes(m);
    for (t = cvm__store_next_cell(m, -1); t >= 0; t = cvm__store_next_cell(m, t))
        dst[k++] = ta ? ta[t] : 0.0;
    return CVM_OK;
}

cvm_status cvm_mesh_copy_point_attributes(double *dst, size_t dst_len, size_t *nattr_out,
                                          const cvm_mesh *m)
{
    if (m && m->m3)
        return CVM_E_UNSUPPORTED; /* a 2D call on a 3D mesh */
    size_t nv, na;
    cvm_status s;
    if (!m || !nattr_out)
        return CVM_E_NULL_ARG;
    nv = n_vertices(m);
    na = m->vattr ? m->in.nattr : 0;
    *nattr_out = na;
    if ((s = cvm__room(dst, dst_len, nv * na)))
        return s;
    if (nv && na)
        memcpy(dst, m->vattr, nv * na * sizeof *dst);
    return CVM_OK;
}

cvm_status cvm_mesh_copy_input_map(cvm_index *dst, size_t dst_len, const cvm_mesh *m)
{
    if (m && m->m3)
        return CVM_E_UNSUPPORTED; /* a 2D call on a 3D mesh */
    cvm_status s;
    if (!m)
        return CVM_E_NULL_ARG;
    if (!m->triangulated)
        return CVM_E_STATE;
    if ((s = cvm__room(dst, dst_len, m->in.np)))
        return s;
    if (m->in.np)
        memcpy(dst, m->input_map, m->in.np * sizeof *dst);
    return CVM_OK;
}

cvm_status cvm_mesh_view_points(const double **ptr_out, size_t *count_out, const cvm_mesh *m)
{
    if (m && m->m3)
        return CVM_E_UNSUPPORTED; /* a 2D call on a 3D mesh */
    if (!ptr_out || !count_out || !m)
        return CVM_E_NULL_ARG;
    *count_out = n_vertices(m);
    *ptr_out = *count_out ? cvm__store_points(m) : NULL;
    return CVM_OK;
}

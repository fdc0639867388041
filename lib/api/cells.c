/* cells.c - cells of several types (offsets + type codes + vertex ids), their neighbours and
 * attributes, for any cell kind of the mesh: the triangles or tetrahedra, or the quad-dominant
 * cells of cvm_mesh_quadmesh(). */
#include <stdlib.h>
#include <string.h>

#include "api_internal.h"
#include "api/mesh3.h"

/* Check dst against need entries (the rule of output.c). */
static cvm_status room(const void *dst, size_t dst_len, size_t need)
{
    if (!dst && dst_len)
        return CVM_E_NULL_ARG;
    return dst_len < need ? CVM_E_BUFFER_TOO_SMALL : CVM_OK;
}

cvm_status cvm_mesh_count_cells_mixed(size_t *ncells_out, size_t *nconn_out, const cvm_mesh *m,
                                      cvm_entity kind)
{
    size_t nt = 0;
    cvm_status s;
    if (!ncells_out || !nconn_out || !m)
        return CVM_E_NULL_ARG;
    *ncells_out = *nconn_out = 0;
    if (kind != CVM_ENT_CELL)
        return CVM_E_ARGUMENT;
    if (m->quad) {
        *ncells_out = m->quad->ncell;
        *nconn_out = m->quad->nconn;
        return CVM_OK;
    }
    if ((s = cvm_mesh_count(&nt, m, m->m3 ? CVM_ENT_CELL : CVM_ENT_TRIANGLE)))
        return s;
    if (nt > (size_t)INT32_MAX / (m->m3 ? 4 : 3)) /* offsets are cvm_index */
        return CVM_E_TOO_LARGE;
    *ncells_out = nt;
    *nconn_out = (m->m3 ? 4 : 3) * nt;
    return CVM_OK;
}

cvm_status cvm_mesh_copy_cells_mixed(cvm_index *offsets, size_t offsets_len, int32_t *types,
                                     size_t types_len, cvm_index *conn, size_t conn_len,
                                     const cvm_mesh *m, cvm_entity kind)
{
    size_t nc, nconn, c;
    cvm_status s;
    if (!m)
        return CVM_E_NULL_ARG;
    if ((s = cvm_mesh_count_cells_mixed(&nc, &nconn, m, kind)))
        return s;
    /* every array is checked before any is written */
    if ((s = room(offsets, offsets_len, nc + 1)) || (s = room(types, types_len, nc)) ||
        (s = room(conn, conn_len, nconn)))
        return s;
    if (m->quad) {
        memcpy(offsets, m->quad->off, (nc + 1) * sizeof *offsets);
        memcpy(types, m->quad->types, nc * sizeof *types);
        memcpy(conn, m->quad->conn, nconn * sizeof *conn);
        return CVM_OK;
    }
    if ((s = cvm_mesh_copy_cells(conn, conn_len, m, m->m3 ? CVM_ENT_TETRAHEDRON : CVM_ENT_TRIANGLE)))
        return s;
    for (c = 0; c <= nc; c++)
        offsets[c] = (cvm_index)((m->m3 ? 4 : 3) * c);
    for (c = 0; c < nc; c++)
        types[c] = m->m3 ? CVM_CELL_TETRAHEDRON : CVM_CELL_TRIANGLE;
    return CVM_OK;
}

typedef struct face_key {
    uint64_t key; /* the face's two vertex ids, lower first */
    size_t at;    /* its slot in the offsets layout */
} face_key;

static int cmp_face(const void *a, const void *b)
{
    const face_key *x = (const face_key *)a, *y = (const face_key *)b;
    if (x->key != y->key)
        return x->key < y->key ? -1 : 1;
    return x->at < y->at ? -1 : x->at > y->at;
}

/* Neighbours of the quad-dominant cells: face k of cell c joins its vertices k and k+1; two
 * faces with the same vertices are neighbours (a conforming mesh has no third). */
static cvm_status quad_neighbors(cvm_index *dst, size_t dst_len, const cvm_mesh *m)
{
    const cvm__quad_cells *q = m->quad;
    cvm__ctx *ctx = (cvm__ctx *)&m->ctx; /* allocation does not change the handle */
    face_key *f;
    size_t c, k;
    cvm_status s;
    if ((s = room(dst, dst_len, q->nconn)))
        return s;
    f = cvm__malloc(ctx, (q->nconn + 1) * sizeof *f);
    if (!f)
        return CVM_E_NOMEM;
    for (c = 0; c < q->ncell; c++) {
        int32_t a = q->off[c], n = q->off[c + 1] - a, j;
        for (j = 0; j < n; j++) {
            uint32_t u = (uint32_t)q->conn[a + j], v = (uint32_t)q->conn[a + (j + 1) % n];
            f[a + j].key = u < v ? (uint64_t)u << 32 | v : (uint64_t)v << 32 | u;
            f[a + j].at = (size_t)(a + j);
        }
    }
    qsort(f, q->nconn, sizeof *f, cmp_face);
    for (k = 0; k < q->nconn; k++)
        dst[k] = -1;
    for (k = 0; k + 1 < q->nconn; k++)
        if (f[k].key == f[k + 1].key) {
            size_t a = f[k].at, b = f[k + 1].at, ca = 0, cb = 0, lo, hi;
            for (lo = 0, hi = q->ncell; lo < hi;) { /* the cell holding slot a */
                size_t mid = (lo + hi) / 2;
                if ((size_t)q->off[mid + 1] <= a) lo = mid + 1; else hi = mid;
            }
            ca = lo;
            for (lo = 0, hi = q->ncell; lo < hi;) {
                size_t mid = (lo + hi) / 2;
                if ((size_t)q->off[mid + 1] <= b) lo = mid + 1; else hi = mid;
            }
            cb = lo;
            dst[a] = (cvm_index)cb;
            dst[b] = (cvm_index)ca;
            k++;
        }
    cvm__free(ctx, f);
    return CVM_OK;
}

/* The regional attribute of each quad-dominant cell: its first triangle's. */
static cvm_status quad_attributes(double *dst, size_t dst_len, const cvm_mesh *m)
{
    const cvm__quad_cells *q = m->quad;
    cvm__ctx *ctx = (cvm__ctx *)&m->ctx; /* allocation does not change the handle */
    size_t nt = 0, c;
    double *ta;
    cvm_status s;
    if ((s = room(dst, dst_len, q->ncell)) || (s = cvm_mesh_count(&nt, m, CVM_ENT_TRIANGLE)))
        return s;
    ta = cvm__malloc(ctx, (nt + 1) * sizeof *ta);
    if (!ta)
        return CVM_E_NOMEM;
    if ((s = cvm_mesh_copy_triangle_attributes(ta, nt, m)) == CVM_OK)
        for (c = 0; c < q->ncell; c++)
            dst[c] = ta[q->first[c]];
    cvm__free(ctx, ta);
    return s;
}

cvm_status cvm_mesh_copy_cell_neighbors(cvm_index *dst, size_t dst_len, const cvm_mesh *m,
                                        cvm_entity kind)
{
    if (m && m->m3)
        return CVM_E_UNSUPPORTED; /* a 2D call on a 3D mesh */
    if (!m)
        return CVM_E_NULL_ARG;
    if (kind == CVM_ENT_TETRAHEDRON)
        return CVM_E_UNSUPPORTED;
    if (kind != CVM_ENT_TRIANGLE && kind != CVM_ENT_CELL)
        return CVM_E_ARGUMENT;
    if (kind == CVM_ENT_CELL && m->quad)
        return quad_neighbors(dst, dst_len, m);
    /* cells are the triangles, in that order, face k opposite vertex k: the same array */
    return cvm_mesh_copy_neighbors(dst, dst_len, m);
}

cvm_status cvm_mesh_copy_cell_attributes(double *dst, size_t dst_len, const cvm_mesh *m,
                                         cvm_entity kind)
{
    if (m && m->m3)
        return CVM_E_UNSUPPORTED; /* a 2D call on a 3D mesh */
    if (!m)
        return CVM_E_NULL_ARG;
    if (kind != CVM_ENT_TRIANGLE && kind != CVM_ENT_CELL)
        return CVM_E_ARGUMENT;
    if (kind == CVM_ENT_CELL && m->quad)
        return quad_attributes(dst, dst_len, m);
    return cvm_mesh_copy_triangle_attributes(dst, dst_len, m);
}

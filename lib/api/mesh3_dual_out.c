/*
 * mesh3_dual_out.c - the power dual of a 3D handle given back: power
 * vertices, cell volumes, dual face areas and dual edge lengths, and the
 * bounded cells written as VTK polyhedra (lib/io/write_dual3.c).
 */
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "api/mesh3_dual.h"
#include "api/output_internal.h"
#include "api/store.h"
#include "geom/measure3.h"
#include "io/io_internal.h"

/* The const readers allocate through a copy of the handle's context, so that
 * an error leaves the handle's message alone. */
static cvm_status build(cvm__ctx *tmp, const cvm_mesh *m, cvm__dual3 *d)
{
    *tmp = m->ctx;
    if (!m->m3->have)
        return CVM_E_STATE;
    return cvm__dual3_build(tmp, m->m3, d);
}

cvm_status cvm__mesh3_copy_dual_vertices(double *dst, size_t dst_len, const cvm_mesh *m)
{
    const double *w = cvm__store_weights(m);
    size_t n = cvm__store_nslots(m), t;
    cvm_status s;
    if ((s = cvm__room(dst, dst_len, 3 * n)))
        return s;
    for (t = 0; t < n; t++) {
        const int32_t *v = cvm__store_cell(m, t);
        double w4[4];
        int i;
        for (i = 0; i < 4; i++)
            w4[i] = w ? w[v[i]] : 0;
        (void)cvm__tet_power_centre(cvm__store_point(m, (size_t)v[0]),
                                    cvm__store_point(m, (size_t)v[1]),
                                    cvm__store_point(m, (size_t)v[2]),
                                    cvm__store_point(m, (size_t)v[3]), w4, dst + 3 * t);
    }
    return CVM_OK;
}

cvm_status cvm_mesh_count_dual3(size_t *edges_out, size_t *faces_out, const cvm_mesh *m)
{
    cvm__ctx tmp;
    cvm__dual3 d;
    size_t i, ne = 0, nf = 0;
    cvm_status s;
    if (!edges_out || !faces_out || !m)
        return CVM_E_NULL_ARG;
    if (!m->m3)
        return CVM_E_UNSUPPORTED;
    if ((s = build(&tmp, m, &d)))
        return s;
    for (i = 0; i < d.nedge; i++)
        ne += d.edge_in[i];
    for (i = 0; i < 4 * d.ntet; i++)
        nf += d.nbr[i] >= 0 && (int32_t)i < d.nbr[i];
    cvm__dual3_free(&tmp, &d);
    *edges_out = ne;
    *faces_out = nf;
    return CVM_OK;
}

cvm_status cvm_mesh_copy_dual3_volumes(double *dst, size_t dst_len, const cvm_mesh *m)
{
    cvm__ctx tmp;
    cvm__dual3 d;
    cvm_status s;
    if (!m)
        return CVM_E_NULL_ARG;
    if (!m->m3)
        return CVM_E_UNSUPPORTED;
    if (!m->m3->have)
        return CVM_E_STATE;
    if ((s = cvm__room(dst, dst_len, m->m3->nv)))
        return s;
    if ((s = build(&tmp, m, &d)))
        return s;
    if (d.nv)
        memcpy(dst, d.volume, d.nv * sizeof *dst);
    cvm__dual3_free(&tmp, &d);
    return CVM_OK;
}

cvm_status cvm_mesh_copy_dual3_face_areas(cvm_index *edges, size_t edges_len, double *areas,
                                          size_t areas_len, const cvm_mesh *m)
{
    cvm__ctx tmp;
    cvm__dual3 d;
    size_t i, k = 0, ne = 0;
    cvm_status s;
    if (!m)
        return CVM_E_NULL_ARG;
    if (!m->m3)
        return CVM_E_UNSUPPORTED;
    if ((s = build(&tmp, m, &d)))
        return s;
    for (i = 0; i < d.nedge; i++)
        ne += d.edge_in[i];
    if (!(s = cvm__room(edges, edges_len, 2 * ne)) && !(s = cvm__room(areas, areas_len, ne)))
        for (i = 0; i < d.nedge; i++)
            if (d.edge_in[i]) {
                edges[2 * k] = d.edge[2 * i];
                edges[2 * k + 1] = d.edge[2 * i + 1];
                areas[k++] = d.edge_area[i];
            }
    cvm__dual3_free(&tmp, &d);
    return s;
}

/* The interior faces (corners outward from the lower tetrahedron) and their
 * dual edge lengths, into face / len when not NULL; the count. */
static size_t interior_faces(const cvm__mesh3 *g, const cvm__dual3 *d, int32_t *face, double *len)
{
    size_t i, k = 0;
    for (i = 0; i < 4 * d->ntet; i++) {
        int32_t s = d->nbr[i];
        if (s < 0 || (int32_t)i > s)
            continue;
        if (face)
            cvm__mesh3_face_corners(g->tet + 4 * (i / 4), (int)(i % 4), face + 3 * k);
        if (len)
            len[k] = d->dvert[i / 4] == d->dvert[s / 4]
                         ? 0.0
                         : sqrt(cvm__dist2_3(d->pv + 3 * (i / 4), d->pv + 3 * (s / 4)));
        k++;
    }
    return k;
}

cvm_status cvm_mesh_copy_dual3_edge_lengths(cvm_index *faces, size_t faces_len, double *lengths,
                                            size_t lengths_len, const cvm_mesh *m)
{
    cvm__ctx tmp;
    cvm__dual3 d;
    size_t nf;
    cvm_status s;
    if (!m)
        return CVM_E_NULL_ARG;
    if (!m->m3)
        return CVM_E_UNSUPPORTED;
    if ((s = build(&tmp, m, &d)))
        return s;
    nf = interior_faces(m->m3, &d, NULL, NULL);
    if (!(s = cvm__room(faces, faces_len, 3 * nf)) && !(s = cvm__room(lengths, lengths_len, nf)))
        interior_faces(m->m3, &d, faces, lengths);
    cvm__dual3_free(&tmp, &d);
    return s;
}

/* Growable arrays of the polyhedron layout. */
typedef struct dual3_grow {
    void *p;
    size_t n, cap, size;
} dual3_grow;

static int grow_room(cvm__ctx *ctx, dual3_grow *g, size_t extra)
{
    if (g->n + extra > g->cap) {
        size_t cap = g->cap ? 2 * g->cap : 1024;
        void *np;
        while (cap < g->n + extra)
            cap *= 2;
        if (!(np = cvm__realloc(ctx, g->p, cap * g->size)))
            return -1;
        g->p = np;
        g->cap = cap;
    }
    return 0;
}

static int cmp_i32(const void *a, const void *b)
{
    int32_t x = *(const int32_t *)a, y = *(const int32_t *)b;
    return (x > y) - (x < y);
}

/* The face stream and distinct corners of interior vertex v's cell appended;
 * -1 when out of memory. */
static int add_cell(cvm__ctx *ctx, const cvm__mesh3 *g, cvm__dual3 *d, size_t v, dual3_grow *faces,
                    dual3_grow *conn)
{
    int32_t k;
    size_t head = faces->n, c0 = conn->n, i, j;
    int64_t nf = 0;
    if (grow_room(ctx, faces, 1))
        return -1;
    ((int64_t *)faces->p)[faces->n++] = 0; /* the face count, set below */
    for (k = d->vedge_off[v]; k < d->vedge_off[v + 1]; k++) {
        int32_t e = d->vedge[k];
        long n = cvm__dual3_face(ctx, d, g->tet, (size_t)e), q;
        int forward = d->edge[2 * e] == (int32_t)v; /* outward is along the other end */
        if (n < 0)
            return -1;
        if (n < 3)
            continue;
        if (grow_room(ctx, faces, (size_t)n + 1) || grow_room(ctx, conn, (size_t)n))
            return -1;
        ((int64_t *)faces->p)[faces->n++] = n;
        for (q = 0; q < n; q++) {
            int32_t id = d->ring[forward ? q : n - 1 - q];
            ((int64_t *)faces->p)[faces->n++] = id;
            ((int32_t *)conn->p)[conn->n++] = id;
        }
        nf++;
    }
    ((int64_t *)faces->p)[head] = nf;
    qsort((int32_t *)conn->p + c0, conn->n - c0, sizeof(int32_t), cmp_i32);
    for (i = c0, j = c0; i < conn->n; i++)
        if (j == c0 || ((int32_t *)conn->p)[j - 1] != ((int32_t *)conn->p)[i])
            ((int32_t *)conn->p)[j++] = ((int32_t *)conn->p)[i];
    conn->n = j;
    return 0;
}

cvm_status cvm__mesh3_write_dual_to_set(cvm_mesh *m, const char *path, cvm__write_set *ws)
{
    const cvm__mesh3 *g = m->m3;
    cvm__ctx *ctx = &m->ctx;
    cvm__dual3 d;
    cvm__dual3_out o;
    dual3_grow faces = {NULL, 0, 0, sizeof(int64_t)}, conn = {NULL, 0, 0, sizeof(int32_t)};
    int64_t *conn_off = NULL, *face_off = NULL;
    int32_t *vertex = NULL, *edge = NULL, *face = NULL;
    double *volume = NULL, *weight = NULL, *pts = NULL, *area = NULL, *flen = NULL;
    size_t v, i, nc = 0, ne = 0, nf;
    cvm_status s = CVM_OK;
    if (!path)
        return cvm__error(ctx, CVM_E_NULL_ARG, CVM_ENT_NONE, -1, "path is NULL");
    if (!g->have)
        return cvm__error(ctx, CVM_E_STATE, CVM_ENT_NONE, -1,
                          "nothing to write: call cvm_mesh_triangulate() first");
    if (cvm__format_of(path) != CVM__FMT_VTU)
        return cvm__error(ctx, CVM_E_UNSUPPORTED, CVM_ENT_NONE, -1,
                          "cannot write the dual to %s: only .vtu is supported", path);
    if ((s = cvm__dual3_build(ctx, g, &d)))
        return s;
    conn_off = cvm__malloc(ctx, (d.nv + 1) * sizeof *conn_off);
    face_off = cvm__malloc(ctx, (d.nv + 1) * sizeof *face_off);
    vertex = cvm__malloc(ctx, (d.nv + 1) * sizeof *vertex);
    volume = cvm__malloc(ctx, (d.nv + 1) * sizeof *volume);
    weight = cvm__malloc(ctx, (d.nv + 1) * sizeof *weight);
    pts = cvm__malloc(ctx, (3 * d.ndv + 1) * sizeof *pts);
    edge = cvm__malloc(ctx, (2 * d.nedge + 1) * sizeof *edge);
    area = cvm__malloc(ctx, (d.nedge + 1) * sizeof *area);
    nf = interior_faces(g, &d, NULL, NULL);
    face = cvm__malloc(ctx, (3 * nf + 1) * sizeof *face);
    flen = cvm__malloc(ctx, (nf + 1) * sizeof *flen);
    if (!conn_off || !face_off || !vertex || !volume || !weight || !pts || !edge || !area ||
        !face || !flen) {
        s = cvm__nomem(ctx);
        goto done;
    }
    conn_off[0] = face_off[0] = 0;
    for (v = 0; v < d.nv; v++) {
        if (d.vbnd[v])
            continue; /* unbounded (or clipped by the boundary): not written */
        if (add_cell(ctx, g, &d, v, &faces, &conn)) {
            s = cvm__nomem(ctx);
            goto done;
        }
        vertex[nc] = (int32_t)v;
        volume[nc] = d.volume[v];
        weight[nc] = g->w ? g->w[v] : 0;
        conn_off[nc + 1] = (int64_t)conn.n;
        face_off[nc + 1] = (int64_t)faces.n;
        nc++;
    }
    for (i = 0; i < d.ndv; i++)
        memcpy(pts + 3 * i, d.pv + 3 * d.dv_tet[i], 3 * sizeof *pts);
    for (i = 0; i < d.nedge; i++)
        if (d.edge_in[i]) {
            edge[2 * ne] = d.edge[2 * i];
            edge[2 * ne + 1] = d.edge[2 * i + 1];
            area[ne++] = d.edge_area[i];
        }
    interior_faces(g, &d, face, flen);
    memset(&o, 0, sizeof o);
    o.pts = pts;
    o.pt_tet = d.dv_tet;
    o.npts = d.ndv;
    o.ncell = nc;
    o.conn = conn.p ? conn.p : vertex;
    o.conn_off = conn_off;
    o.faces = faces.p ? faces.p : conn_off;
    o.face_off = face_off;
    o.vertex = vertex;
    o.volume = volume;
    o.weight = weight;
    o.edge = edge;
    o.edge_area = area;
    o.nedge = ne;
    o.face = face;
    o.face_len = flen;
    o.nface = nf;
    s = cvm__write_dual3_file_to_set(ws, path, &o);
done:
    cvm__free(ctx, faces.p);
    cvm__free(ctx, conn.p);
    cvm__free(ctx, conn_off);
    cvm__free(ctx, face_off);
    cvm__free(ctx, vertex);
    cvm__free(ctx, volume);
    cvm__free(ctx, weight);
    cvm__free(ctx, pts);
    cvm__free(ctx, edge);
    cvm__free(ctx, area);
    cvm__free(ctx, face);
    cvm__free(ctx, flen);
    cvm__dual3_free(ctx, &d);
    return s;
}

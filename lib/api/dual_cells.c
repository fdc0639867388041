/*
 * dual_cells.c - the power (Voronoi) cell polygon of every vertex, restricted
 * to the domain, as CSR arrays and as a .vtu file of polygons.
 *
 * Each cell is gathered by walking the fan of domain triangles around its
 * vertex counter-clockwise through the adjacency (tn): in triangle t with
 * the vertex at position i, the next triangle counter-clockwise lies across
 * edge (i+1)%3 and the previous one across edge (i+2)%3. A fan that meets the
 * domain boundary is opened there and closed by the vertex and the
 * power-bisector feet of its two boundary edges. Corners are constructions
 * (plain doubles).
 */
#include <limits.h>
#include <string.h>

#include "output_internal.h"
#include "dual/dual_internal.h"
#include "api/mesh3.h"

static double vweight(const cvm__tri2 *T, int32_t v)
{
    return T->w ? T->w[v] : 0.0;
}

/* Domain triangles incident to each vertex, CSR: first (nv+1), list. */
typedef struct incidence {
    int32_t *first, *list;
    uint8_t *seen; /* per slot: visited by the current walk */
} incidence;

static void inc_free(cvm__ctx *ctx, incidence *in)
{
    cvm__free(ctx, in->first);
    cvm__free(ctx, in->list);
    cvm__free(ctx, in->seen);
}

static cvm_status inc_build(cvm__ctx *ctx, const cvm__tri2 *T, incidence *in)
{
    size_t t, v;
    int j;
    memset(in, 0, sizeof *in);
    in->first = cvm__calloc(ctx, T->nv + 2, sizeof *in->first);
    in->list = cvm__malloc(ctx, (3 * T->nt + 1) * sizeof *in->list);
    in->seen = cvm__calloc(ctx, T->nt + 1, 1);
    if (!in->first || !in->list || !in->seen) {
        inc_free(ctx, in);
        return CVM_E_NOMEM;
    }
    for (t = 0; t < T->nt; t++)
        if (cvm__tri2_in_domain(T, (int32_t)t))
            for (j = 0; j < 3; j++)
                in->first[T->tv[3 * t + (size_t)j] + 2]++;
    for (v = 0; v < T->nv; v++)
        in->first[v + 2] += in->first[v + 1];
    for (t = 0; t < T->nt; t++)
        if (cvm__tri2_in_domain(T, (int32_t)t))
            for (j = 0; j < 3; j++)
                in->list[in->first[T->tv[3 * t + (size_t)j] + 1]++] = (int32_t)t;
    return CVM_OK;
}

/* Domain triangle across edge j of t, or -1. */
static int32_t across(const cvm__tri2 *T, int32_t t, int j)
{
    int32_t a = T->tn[3 * (size_t)t + (size_t)j], u = a < 0 ? -1 : a / 3;
    return u >= 0 && cvm__tri2_in_domain(T, u) ? u : -1;
}

static void put(double *xy, size_t *k, const double *p)
{
    if (xy) {
        xy[2 * *k] = p[0];
        xy[2 * *k + 1] = p[1];
    }
    (*k)++;
}

/* Corners of vertex v's cell appended at xy[2*k..] (xy NULL: count only). */
static void cell(const cvm__tri2 *T, incidence *in, int32_t v, double *xy, size_t *k)
{
    int32_t i, f;
    const double *pv = T->xy + 2 * (size_t)v;
    for (i = in->first[v]; i < in->first[v + 1]; i++)
        in->seen[in->list[i]] = 0;
    /* fans that meet the boundary first, in slot order of their first triangle */
    for (f = 0; f < 2; f++) {
        for (i = in->first[v]; i < in->first[v + 1]; i++) {
            int32_t t = in->list[i], u;
            double P[2];
            int p = cvm__tri2_corner(T, t, v);
            if (in->seen[t] || (f == 0 && across(T, t, (p + 2) % 3) >= 0))
                continue;
            if (f == 0) { /* open fan starting at boundary edge (v, tv[p+1]) */
                int32_t a = T->tv[3 * (size_t)t + (size_t)(p + 1) % 3];
                put(xy, k, pv);
                cvm__power_foot2d(pv, T->xy + 2 * (size_t)a, vweight(T, v), vweight(T, a), P);
                put(xy, k, P);
            }
            for (u = t; u >= 0 && !in->seen[u]; u = across(T, u, (cvm__tri2_corner(T, u, v) + 1) % 3)) {
                const int32_t *tv = T->tv + 3 * (size_t)u;
                in->seen[u] = 1;
                if (xy)
                    cvm__power_vertex2d(T->xy + 2 * (size_t)tv[0], T->xy + 2 * (size_t)tv[1],
                                        T->xy + 2 * (size_t)tv[2], vweight(T, tv[0]),
                                        vweight(T, tv[1]), vweight(T, tv[2]), P);
                put(xy, k, P);
                t = u;
            }
            if (f == 0) { /* close at boundary edge (tv[p+2], v) of the last triangle */
                int32_t b = T->tv[3 * (size_t)t + (size_t)(cvm__tri2_corner(T, t, v) + 2) % 3];
                cvm__power_foot2d(pv, T->xy + 2 * (size_t)b, vweight(T, v), vweight(T, b), P);
                put(xy, k, P);
            }
        }
    }
}

cvm_status cvm__dual_cells(cvm__ctx *ctx, const cvm__tri2 *T, int32_t *off, double *xy)
{
    incidence in;
    size_t v, k = 0;
    if (inc_build(ctx, T, &in))
        return CVM_E_NOMEM;
    for (v = 0; v < T->nv; v++) {
        off[v] = (int32_t)k;
        cell(T, &in, (int32_t)v, xy, &k);
        if (k > (size_t)INT32_MAX) {
            inc_free(ctx, &in);
            return CVM_E_TOO_LARGE;
        }
    }
    off[T->nv] = (int32_t)k;
    inc_free(ctx, &in);
    return CVM_OK;
}

/* Fresh offsets of m's cells (nv + 1 entries). */
static cvm_status offsets(cvm__ctx *ctx, const cvm_mesh *m, int32_t **out)
{
    int32_t *off = cvm__malloc(ctx, (m->tri.nv + 1) * sizeof *off);
    cvm_status s;
    *out = NULL;
    if (!off)
        return CVM_E_NOMEM;
    if ((s = cvm__dual_cells(ctx, &m->tri, off, NULL))) {
        cvm__free(ctx, off);
        return s;
    }
    *out = off;
    return CVM_OK;
}

cvm_status cvm_mesh_copy_dual_cell_offsets(cvm_index *dst, size_t dst_len, const cvm_mesh *m)
{
    if (m && m->m3)
        return CVM_E_UNSUPPORTED; /* a 2D call on a 3D mesh */
    cvm__ctx *ctx;
    int32_t *off;
    size_t nv;
    cvm_status s;
    if (!m)
        return CVM_E_NULL_ARG;
    nv = m->triangulated ? m->tri.nv : 0;
    if ((s = cvm__room(dst, dst_len, nv + 1)))
        return s;
    if (!nv) {
        dst[0] = 0;
        return CVM_OK;
    }
    ctx = (cvm__ctx *)&m->ctx; /* allocation does not change the handle */
    if ((s = offsets(ctx, m, &off)))
        return s;
    memcpy(dst, off, (nv + 1) * sizeof *dst);
    cvm__free(ctx, off);
    return CVM_OK;
}

cvm_status cvm_mesh_copy_dual_cells(double *dst, size_t dst_len, const cvm_mesh *m)
{
    if (m && m->m3)
        return CVM_E_UNSUPPORTED; /* a 2D call on a 3D mesh */
    cvm__ctx *ctx;
    int32_t *off;
    cvm_status s;
    if (!m)
        return CVM_E_NULL_ARG;
    if (!m->triangulated || !m->tri.nv)
        return cvm__room(dst, dst_len, 0);
    ctx = (cvm__ctx *)&m->ctx;
    if ((s = offsets(ctx, m, &off)))
        return s;
    if ((s = cvm__room(dst, dst_len, 2 * (size_t)off[m->tri.nv])) == CVM_OK)
        s = cvm__dual_cells(ctx, &m->tri, off, dst);
    cvm__free(ctx, off);
    return s;
}

/* The non-empty cells of m as a cvm__dual_out (arrays freed by dual_out_free). */
static cvm_status dual_out_build(cvm_mesh *m, cvm__dual_out *d)
{
    const cvm__tri2 *T = &m->tri;
    int32_t *off = NULL, *coff, *vid;
    double *xy, *area, *w;
    size_t v, n = 0;
    cvm_status s;
    memset(d, 0, sizeof *d);
    if ((s = offsets(&m->ctx, m, &off)))
        return s;
    xy = cvm__malloc(&m->ctx, (2 * (size_t)off[T->nv] + 1) * sizeof *xy);
    coff = cvm__malloc(&m->ctx, (T->nv + 1) * sizeof *coff);
    vid = cvm__malloc(&m->ctx, (T->nv + 1) * sizeof *vid);
    area = cvm__malloc(&m->ctx, (T->nv + 1) * sizeof *area);
    w = cvm__malloc(&m->ctx, (T->nv + 1) * sizeof *w);
    d->xy = xy;
    d->off = coff;
    d->vertex = vid;
    d->area = area;
    d->weight = w;
    if (!xy || !coff || !vid || !area || !w) {
        cvm__free(&m->ctx, off);
        return CVM_E_NOMEM;
    }
    if ((s = cvm__dual_cells(&m->ctx, T, off, xy)) ||
        (s = cvm_mesh_copy_dual_areas(area, T->nv, m))) {
        cvm__free(&m->ctx, off);
        return s;
    }
    coff[0] = 0;
    for (v = 0; v < T->nv; v++) {
        if (off[v + 1] == off[v])
            continue; /* no domain triangle: no cell */
        vid[n] = (int32_t)v;
        area[n] = area[v];
        w[n] = vweight(T, (int32_t)v);
        coff[++n] = off[v + 1];
    }
    d->ncell = n;
    d->ncorner = (size_t)off[T->nv];
    cvm__free(&m->ctx, off);
    return CVM_OK;
}

static void dual_out_free(cvm_mesh *m, cvm__dual_out *d)
{
    cvm__free(&m->ctx, (void *)d->xy);
    cvm__free(&m->ctx, (void *)d->off);
    cvm__free(&m->ctx, (void *)d->vertex);
    cvm__free(&m->ctx, (void *)d->area);
    cvm__free(&m->ctx, (void *)d->weight);
    memset(d, 0, sizeof *d);
}

/* The checks and cells of cvm_mesh_write_dual(), the file into ws. */
static cvm_status write_dual_to_set(cvm_mesh *m, const char *path, cvm__write_set *ws)
{
    cvm__dual_out d;
    cvm_status s;
    if (!path)
        return cvm__error(&m->ctx, CVM_E_NULL_ARG, CVM_ENT_NONE, -1, "path is NULL");
    if (!m->triangulated)
        return cvm__error(&m->ctx, CVM_E_STATE, CVM_ENT_NONE, -1,
                          "nothing to write: call cvm_mesh_triangulate() first");
    if (cvm__format_of(path) != CVM__FMT_VTU)
        return cvm__error(&m->ctx, CVM_E_UNSUPPORTED, CVM_ENT_NONE, -1,
                          "cannot write the dual to %s: only .vtu is supported", path);
    s = dual_out_build(m, &d);
    if (s == CVM_E_NOMEM)
        s = cvm__nomem(&m->ctx);
    else if (s == CVM_E_TOO_LARGE)
        s = cvm__error(&m->ctx, s, CVM_ENT_NONE, -1, "the dual has more than INT32_MAX corners");
    if (!s)
        s = cvm__write_dual_file_to_set(ws, path, &d);
    dual_out_free(m, &d);
    return s;
}

cvm_status cvm_mesh_write_dual(cvm_mesh *m, const char *path)
{
    if (m && m->m3) {
        CVM__BEGIN(m);
        return cvm__mesh3_unsupported(m, "cvm_mesh_write_dual");
    }
    return cvm__mesh_write_now(m, path, write_dual_to_set);
}

cvm_status cvm_mesh_stage_write_dual(cvm_mesh *m, const char *path)
{
    if (m && m->m3) {
        CVM__BEGIN(m);
        return cvm__mesh3_unsupported(m, "cvm_mesh_stage_write_dual");
    }
    if (!m)
        return CVM_E_NULL_ARG;
    CVM__BEGIN(m);
    return cvm__mesh_stage_settle(m, write_dual_to_set(m, path, &m->staged));
}

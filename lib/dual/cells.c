/*
 * dual_cells.c - the power (Voronoi) cell polygon of every vertex, restricted
 * to the domain, as CSR arrays.
 *
 * Each cell is gathered by walking the fan of domain triangles around its
 * vertex counter-clockwise through the adjacency (tn): in triangle t with
 * the vertex at position i, the next triangle counter-clockwise lies across
 * edge (i+1)%3 and the previous one across edge (i+2)%3. A fan that meets the
 * domain boundary is opened there and closed by the vertex and the
 * power-bisector feet of its two boundary edges. Corners are constructions
 * (plain doubles). The same walk gives the cells of the finite-volume dual as
 * ids of shared points, with its face table (cvm__dual_fv_build).
 */
#include <limits.h>
#include <math.h>
#include <string.h>

#include "dual_internal.h"

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

/* Where a walk puts the corners: coordinates (xy) or point ids of the
 * finite-volume dual (ids, through the maps of cvm__dual_fv_build); either may
 * be NULL (count only). */
typedef struct sink {
    double *xy;
    int32_t *ids;
    const int32_t *tri_pt;  /* slot -> point id of its power vertex */
    const int32_t *foot_pt; /* 3 per slot: edge j -> point id of its foot, or -1 */
    const int32_t *vert_pt; /* vertex -> point id of the vertex, or -1 */
    size_t k;
} sink;

static void put(sink *o, const double *p, int32_t id)
{
    if (o->xy) {
        o->xy[2 * o->k] = p[0];
        o->xy[2 * o->k + 1] = p[1];
    }
    if (o->ids)
        o->ids[o->k] = id;
    o->k++;
}

/* The foot of boundary edge j of slot t (tv[j+1] -> tv[j+2], the triangle's
 * own counter-clockwise order, so both cells of the edge get the same
 * double). */
static void put_foot(const cvm__tri2 *T, int32_t t, int j, sink *o)
{
    const int32_t *tv = T->tv + 3 * (size_t)t;
    int32_t a = tv[(j + 1) % 3], b = tv[(j + 2) % 3];
    double P[2] = {0, 0};
    if (o->xy)
        cvm__power_foot2d(T->xy + 2 * (size_t)a, T->xy + 2 * (size_t)b, cvm__dual_weight(T, a),
                          cvm__dual_weight(T, b), P);
    put(o, P, o->ids ? o->foot_pt[3 * (size_t)t + (size_t)j] : -1);
}

/* Corners of vertex v's cell appended to o. */
static void cell(const cvm__tri2 *T, incidence *in, int32_t v, sink *o)
{
    int32_t i, f;
    const double *pv = T->xy + 2 * (size_t)v;
    for (i = in->first[v]; i < in->first[v + 1]; i++)
        in->seen[in->list[i]] = 0;
    /* fans that meet the boundary first, in slot order of their first triangle */
    for (f = 0; f < 2; f++) {
        for (i = in->first[v]; i < in->first[v + 1]; i++) {
            int32_t t = in->list[i], u;
            double P[2] = {0, 0};
            int p = cvm__tri2_corner(T, t, v);
            if (in->seen[t] || (f == 0 && across(T, t, (p + 2) % 3) >= 0))
                continue;
            if (f == 0) { /* open fan starting at boundary edge (v, tv[p+1]) */
                put(o, pv, o->ids ? o->vert_pt[v] : -1);
                put_foot(T, t, (p + 2) % 3, o);
            }
            for (u = t; u >= 0 && !in->seen[u]; u = across(T, u, (cvm__tri2_corner(T, u, v) + 1) % 3)) {
                const int32_t *tv = T->tv + 3 * (size_t)u;
                in->seen[u] = 1;
                if (o->xy)
                    cvm__power_vertex2d(T->xy + 2 * (size_t)tv[0], T->xy + 2 * (size_t)tv[1],
                                        T->xy + 2 * (size_t)tv[2], cvm__dual_weight(T, tv[0]),
                                        cvm__dual_weight(T, tv[1]), cvm__dual_weight(T, tv[2]), P);
                put(o, P, o->ids ? o->tri_pt[u] : -1);
                t = u;
            }
            if (f == 0) /* close at boundary edge (tv[p+2], v) of the last triangle */
                put_foot(T, t, (cvm__tri2_corner(T, t, v) + 1) % 3, o);
        }
    }
}

/* Offsets (nv + 1) and the corners of every cell into o. */
static cvm_status walk(cvm__ctx *ctx, const cvm__tri2 *T, int32_t *off, sink *o)
{
    incidence in;
    size_t v;
    if (inc_build(ctx, T, &in))
        return CVM_E_NOMEM;
    for (v = 0; v < T->nv; v++) {
        off[v] = (int32_t)o->k;
        cell(T, &in, (int32_t)v, o);
        if (o->k > (size_t)INT32_MAX) {
            inc_free(ctx, &in);
            return CVM_E_TOO_LARGE;
        }
    }
    off[T->nv] = (int32_t)o->k;
    inc_free(ctx, &in);
    return CVM_OK;
}

cvm_status cvm__dual_cells(cvm__ctx *ctx, const cvm__tri2 *T, int32_t *off, double *xy)
{
    sink o;
    memset(&o, 0, sizeof o);
    o.xy = xy;
    return walk(ctx, T, off, &o);
}

void cvm__dual_fv_free(cvm__ctx *ctx, cvm__dual_fv *fv)
{
    cvm__free(ctx, fv->pt);
    cvm__free(ctx, fv->off);
    cvm__free(ctx, fv->corner);
    cvm__free(ctx, fv->face);
    cvm__free(ctx, fv->flen);
    memset(fv, 0, sizeof *fv);
}

/* Scratch of cvm__dual_fv_build: the domain edges, each edge's two sides
 * (slot and edge index; side 0 holds the edge as lo -> hi), the maps of the
 * corner ids. */
typedef struct fv_work {
    cvm__edges e;
    int32_t *side;     /* 2 per edge: slot * 3 + j, or -1 */
    int32_t *bidx;     /* per edge: rank among the boundary edges, or -1 */
    int32_t *tri_pt, *foot_pt, *vert_pt;
    size_t *first;     /* nv + 1: edges by lower vertex */
} fv_work;

static void work_free(cvm__ctx *ctx, fv_work *w)
{
    cvm__edges_free(ctx, &w->e);
    cvm__free(ctx, w->side);
    cvm__free(ctx, w->bidx);
    cvm__free(ctx, w->tri_pt);
    cvm__free(ctx, w->foot_pt);
    cvm__free(ctx, w->vert_pt);
    cvm__free(ctx, w->first);
}

/* The edge (a, b) of e, from first[]; e holds every domain edge. */
static size_t edge_of(const fv_work *w, int32_t a, int32_t b)
{
    int32_t lo = a < b ? a : b, hi = a < b ? b : a;
    size_t k = w->first[lo];
    while (k + 1 < w->first[lo + 1] && w->e.ev[2 * k + 1] != hi)
        k++;
    return k;
}

/* Sides, ranks and point ids; the points into fv->pt. */
static cvm_status work_build(cvm__ctx *ctx, const cvm__tri2 *T, fv_work *w, cvm__dual_fv *fv)
{
    size_t k, t, v, ne;
    int32_t n = 0;
    int j;
    if (cvm__domain_edges(ctx, T, 0, &w->e))
        return CVM_E_NOMEM;
    ne = w->e.n;
    w->side = cvm__malloc(ctx, (2 * ne + 1) * sizeof *w->side);
    w->bidx = cvm__malloc(ctx, (ne + 1) * sizeof *w->bidx);
    w->tri_pt = cvm__malloc(ctx, (T->nt + 1) * sizeof *w->tri_pt);
    w->foot_pt = cvm__malloc(ctx, (3 * T->nt + 1) * sizeof *w->foot_pt);
    w->vert_pt = cvm__malloc(ctx, (T->nv + 1) * sizeof *w->vert_pt);
    w->first = cvm__calloc(ctx, T->nv + 2, sizeof *w->first);
    if (!w->side || !w->bidx || !w->tri_pt || !w->foot_pt || !w->vert_pt || !w->first)
        return CVM_E_NOMEM;
    for (k = 0; k < ne; k++)
        w->first[(size_t)w->e.ev[2 * k] + 1]++;
    for (v = 0; v < T->nv; v++)
        w->first[v + 1] += w->first[v];
    for (t = 0; t < T->nt; t++)
        w->tri_pt[t] = cvm__tri2_in_domain(T, (int32_t)t) ? n++ : -1;
    fv->ntri = (size_t)n;
    for (k = 0; k < 2 * ne; k++)
        w->side[k] = -1;
    for (t = 0; t < 3 * T->nt; t++)
        w->foot_pt[t] = -1;
    for (v = 0; v < T->nv; v++)
        w->vert_pt[v] = -1;
    for (t = 0; t < T->nt; t++) {
        const int32_t *tv = T->tv + 3 * t;
        if (w->tri_pt[t] < 0)
            continue;
        for (j = 0; j < 3; j++) {
            int32_t a = tv[(j + 1) % 3], b = tv[(j + 2) % 3];
            w->side[2 * edge_of(w, a, b) + (a < b ? 0 : 1)] = (int32_t)(3 * t) + j;
        }
    }
    for (k = 0, n = 0; k < ne; k++) {
        w->bidx[k] = w->e.bnd[k] ? n++ : -1;
        if (w->e.bnd[k]) {
            int32_t h = w->side[2 * k] >= 0 ? w->side[2 * k] : w->side[2 * k + 1];
            w->foot_pt[h] = (int32_t)fv->ntri + w->bidx[k];
            w->vert_pt[w->e.ev[2 * k]] = w->vert_pt[w->e.ev[2 * k + 1]] = 0;
        }
    }
    fv->nbedge = (size_t)n;
    for (v = 0, n = 0; v < T->nv; v++)
        if (w->vert_pt[v] == 0)
            w->vert_pt[v] = (int32_t)(fv->ntri + fv->nbedge) + n++;
    fv->nbvert = (size_t)n;
    fv->npt = fv->ntri + fv->nbedge + fv->nbvert;
    if (fv->npt > (size_t)INT32_MAX)
        return CVM_E_TOO_LARGE;
    fv->pt = cvm__malloc(ctx, (2 * fv->npt + 1) * sizeof *fv->pt);
    if (!fv->pt)
        return CVM_E_NOMEM;
    for (t = 0; t < T->nt; t++)
        if (w->tri_pt[t] >= 0)
            cvm__dual_tri_vertex(T, (int32_t)t, fv->pt + 2 * (size_t)w->tri_pt[t]);
    for (t = 0; t < 3 * T->nt; t++)
        if (w->foot_pt[t] >= 0) {
            const int32_t *tv = T->tv + 3 * (t / 3);
            int32_t a = tv[(t + 1) % 3], b = tv[(t + 2) % 3];
            cvm__power_foot2d(T->xy + 2 * (size_t)a, T->xy + 2 * (size_t)b, cvm__dual_weight(T, a),
                              cvm__dual_weight(T, b), fv->pt + 2 * (size_t)w->foot_pt[t]);
        }
    for (v = 0; v < T->nv; v++)
        if (w->vert_pt[v] >= 0)
            memcpy(fv->pt + 2 * (size_t)w->vert_pt[v], T->xy + 2 * v, 2 * sizeof *fv->pt);
    return CVM_OK;
}

static double dist(const double *pt, int32_t p, int32_t q)
{
    return hypot(pt[2 * (size_t)p] - pt[2 * (size_t)q], pt[2 * (size_t)p + 1] - pt[2 * (size_t)q + 1]);
}

static void put_face(cvm__dual_fv *fv, const cvm__tri2 *T, size_t f, const int32_t *ids)
{
    const double *a = T->xy + 2 * (size_t)ids[2], *b = T->xy + 2 * (size_t)ids[3];
    memcpy(fv->face + 6 * f, ids, 6 * sizeof *ids);
    fv->flen[2 * f] = hypot(a[0] - b[0], a[1] - b[1]);
    fv->flen[2 * f + 1] = dist(fv->pt, ids[4], ids[5]);
}

/* The face table of fv from the sides of w. */
static void faces(const cvm__tri2 *T, const fv_work *w, cvm__dual_fv *fv)
{
    size_t k, ne = w->e.n;
    for (k = 0; k < ne; k++) {
        int32_t lo = w->e.ev[2 * k], hi = w->e.ev[2 * k + 1], l = w->side[2 * k], r = w->side[2 * k + 1];
        int32_t f[6];
        f[0] = f[2] = lo;
        f[1] = f[3] = hi;
        if (!w->e.bnd[k]) { /* from the right triangle's power vertex to the left one's */
            f[4] = w->tri_pt[r / 3];
            f[5] = w->tri_pt[l / 3];
        } else if (l >= 0) {
            f[4] = w->foot_pt[l];
            f[5] = w->tri_pt[l / 3];
        } else {
            f[4] = w->tri_pt[r / 3];
            f[5] = w->foot_pt[r];
        }
        put_face(fv, T, k, f);
        if (w->e.bnd[k]) { /* (s, h): counter-clockwise around the domain */
            int32_t s = l >= 0 ? lo : hi, h = l >= 0 ? hi : lo, foot = w->foot_pt[l >= 0 ? l : r];
            size_t g = ne + 2 * (size_t)w->bidx[k];
            int32_t fs[6], fh[6];
            fs[0] = fs[2] = s;
            fs[1] = -1;
            fs[3] = h;
            fs[4] = w->vert_pt[s];
            fs[5] = foot;
            fh[0] = fh[2] = h;
            fh[1] = -1;
            fh[3] = s;
            fh[4] = foot;
            fh[5] = w->vert_pt[h];
            put_face(fv, T, g, fs);
            put_face(fv, T, g + 1, fh);
        }
    }
}

cvm_status cvm__dual_fv_build(cvm__ctx *ctx, const cvm__tri2 *T, cvm__dual_fv *fv)
{
    fv_work w;
    sink o;
    cvm_status s;
    memset(&w, 0, sizeof w);
    memset(fv, 0, sizeof *fv);
    memset(&o, 0, sizeof o);
    if ((s = work_build(ctx, T, &w, fv)))
        goto fail;
    fv->off = cvm__malloc(ctx, (T->nv + 1) * sizeof *fv->off);
    fv->nface = w.e.n + 2 * fv->nbedge;
    fv->face = cvm__malloc(ctx, (6 * fv->nface + 1) * sizeof *fv->face);
    fv->flen = cvm__malloc(ctx, (2 * fv->nface + 1) * sizeof *fv->flen);
    if (!fv->off || !fv->face || !fv->flen) {
        s = CVM_E_NOMEM;
        goto fail;
    }
    if ((s = walk(ctx, T, fv->off, &o))) /* count the corners */
        goto fail;
    fv->corner = cvm__malloc(ctx, (o.k + 1) * sizeof *fv->corner);
    if (!fv->corner) {
        s = CVM_E_NOMEM;
        goto fail;
    }
    o.k = 0;
    o.ids = fv->corner;
    o.tri_pt = w.tri_pt;
    o.foot_pt = w.foot_pt;
    o.vert_pt = w.vert_pt;
    if ((s = walk(ctx, T, fv->off, &o)))
        goto fail;
    faces(T, &w, fv);
    work_free(ctx, &w);
    return CVM_OK;
fail:
    work_free(ctx, &w);
    cvm__dual_fv_free(ctx, fv);
    return s;
}

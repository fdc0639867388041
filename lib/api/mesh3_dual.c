/*
 * mesh3_dual.c - the power dual of a tetrahedralisation: power vertices
 * (merged where the exact power test ties), edges and their rings of
 * tetrahedra, dual face areas and the co-volume of each interior vertex.
 */
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "api/mesh3_dual.h"
#include "geom/geom_internal.h"
#include "geom/measure3.h"

typedef struct dual3_edge_key {
    int32_t a, b, t;
} dual3_edge_key;

static int cmp_edge_key(const void *x, const void *y)
{
    const dual3_edge_key *p = (const dual3_edge_key *)x, *q = (const dual3_edge_key *)y;
    if (p->a != q->a)
        return (p->a > q->a) - (p->a < q->a);
    if (p->b != q->b)
        return (p->b > q->b) - (p->b < q->b);
    return (p->t > q->t) - (p->t < q->t);
}

void cvm__dual3_free(cvm__ctx *ctx, cvm__dual3 *d)
{
    cvm__free(ctx, d->pv);
    cvm__free(ctx, d->dvert);
    cvm__free(ctx, d->dv_tet);
    cvm__free(ctx, d->nbr);
    cvm__free(ctx, d->vbnd);
    cvm__free(ctx, d->edge);
    cvm__free(ctx, d->edge_tet);
    cvm__free(ctx, d->edge_area);
    cvm__free(ctx, d->edge_in);
    cvm__free(ctx, d->vedge_off);
    cvm__free(ctx, d->vedge);
    cvm__free(ctx, d->volume);
    cvm__free(ctx, d->ring);
    memset(d, 0, sizeof *d);
}

static int32_t uf_find(int32_t *p, int32_t x)
{
    while (p[x] != x) {
        p[x] = p[p[x]];
        x = p[x];
    }
    return x;
}

/* Dual vertices: union of the tetrahedra across faces where the far corner
 * ties exactly with the circumsphere (orthosphere) of the near tetrahedron. */
static cvm_status merge_ties(cvm__ctx *ctx, const cvm__mesh3 *g, cvm__dual3 *d)
{
    int32_t *p = cvm__malloc(ctx, (d->ntet ? d->ntet : 1) * sizeof *p);
    const double *X = g->xyz;
    size_t t, i;
    if (!p)
        return cvm__nomem(ctx);
    for (t = 0; t < d->ntet; t++)
        p[t] = (int32_t)t;
    for (i = 0; i < 4 * d->ntet; i++) {
        const int32_t *a = g->tet + 4 * (i / 4);
        int32_t s = d->nbr[i], e, ra, rb;
        double r;
        if (s < 0 || (int32_t)i > s)
            continue;
        e = g->tet[4 * (s / 4) + s % 4];
        r = g->w ? cvm__power3d(X + 3 * a[0], X + 3 * a[1], X + 3 * a[2], X + 3 * a[3], X + 3 * e,
                                g->w[a[0]], g->w[a[1]], g->w[a[2]], g->w[a[3]], g->w[e])
                 : cvm__insphere(X + 3 * a[0], X + 3 * a[1], X + 3 * a[2], X + 3 * a[3], X + 3 * e);
        if (r != 0.0)
            continue;
        ra = uf_find(p, (int32_t)(i / 4));
        rb = uf_find(p, s / 4);
        if (ra != rb) /* the smaller tetrahedron id is the root */
            p[ra > rb ? ra : rb] = ra > rb ? rb : ra;
    }
    d->ndv = 0;
    for (t = 0; t < d->ntet; t++) {
        int32_t r = uf_find(p, (int32_t)t);
        d->dvert[t] = r == (int32_t)t ? (int32_t)d->ndv++ : d->dvert[r];
    }
    cvm__free(ctx, p);
    d->dv_tet = cvm__malloc(ctx, (d->ndv ? d->ndv : 1) * sizeof *d->dv_tet);
    if (!d->dv_tet)
        return cvm__nomem(ctx);
    for (t = d->ntet; t-- > 0;)
        d->dv_tet[d->dvert[t]] = (int32_t)t;
    return CVM_OK;
}

/* The unique edges, a tetrahedron of each, and the edges at each vertex. */
static cvm_status build_edges(cvm__ctx *ctx, const cvm__mesh3 *g, cvm__dual3 *d)
{
    static const int pair[6][2] = {{0, 1}, {0, 2}, {0, 3}, {1, 2}, {1, 3}, {2, 3}};
    size_t n = 6 * d->ntet, i, k = 0;
    dual3_edge_key *keys = cvm__malloc(ctx, (n ? n : 1) * sizeof *keys);
    if (!keys)
        return cvm__nomem(ctx);
    for (i = 0; i < n; i++) {
        const int32_t *t = g->tet + 4 * (i / 6);
        int32_t a = t[pair[i % 6][0]], b = t[pair[i % 6][1]];
        keys[i].a = a < b ? a : b;
        keys[i].b = a < b ? b : a;
        keys[i].t = (int32_t)(i / 6);
    }
    qsort(keys, n, sizeof *keys, cmp_edge_key);
    for (i = 0; i < n; i++)
        if (i == 0 || keys[i].a != keys[i - 1].a || keys[i].b != keys[i - 1].b)
            keys[k++] = keys[i];
    if (k > (size_t)INT32_MAX / 2) {
        cvm__free(ctx, keys);
        return cvm__error(ctx, CVM_E_TOO_LARGE, CVM_ENT_NONE, -1, "the mesh has too many edges");
    }
    d->nedge = k;
    d->edge = cvm__malloc(ctx, (2 * k + 1) * sizeof *d->edge);
    d->edge_tet = cvm__malloc(ctx, (k + 1) * sizeof *d->edge_tet);
    d->edge_area = cvm__calloc(ctx, k + 1, sizeof *d->edge_area);
    d->edge_in = cvm__calloc(ctx, k + 1, 1);
    d->vedge_off = cvm__calloc(ctx, d->nv + 1, sizeof *d->vedge_off);
    d->vedge = cvm__malloc(ctx, (2 * k + 1) * sizeof *d->vedge);
    if (!d->edge || !d->edge_tet || !d->edge_area || !d->edge_in || !d->vedge_off || !d->vedge) {
        cvm__free(ctx, keys);
        return cvm__nomem(ctx);
    }
    for (i = 0; i < k; i++) {
        d->edge[2 * i] = keys[i].a;
        d->edge[2 * i + 1] = keys[i].b;
        d->edge_tet[i] = keys[i].t;
        d->vedge_off[keys[i].a + 1]++;
        d->vedge_off[keys[i].b + 1]++;
    }
    cvm__free(ctx, keys);
    for (i = 0; i < d->nv; i++)
        d->vedge_off[i + 1] += d->vedge_off[i];
    {
        int32_t *fill = cvm__malloc(ctx, (d->nv ? d->nv : 1) * sizeof *fill);
        if (!fill)
            return cvm__nomem(ctx);
        memcpy(fill, d->vedge_off, d->nv * sizeof *fill);
        for (i = 0; i < k; i++) { /* increasing edge ids per vertex */
            d->vedge[fill[d->edge[2 * i]]++] = (int32_t)i;
            d->vedge[fill[d->edge[2 * i + 1]]++] = (int32_t)i;
        }
        cvm__free(ctx, fill);
    }
    return CVM_OK;
}

long cvm__dual3_ring(cvm__ctx *ctx, cvm__dual3 *d, const int32_t *tet, size_t e)
{
    int32_t a = d->edge[2 * e], b = d->edge[2 * e + 1], t0 = d->edge_tet[e], t = t0;
    size_t n = 0;
    for (;;) {
        const int32_t *v = tet + 4 * t;
        int pos[4], ia = -1, ib = -1, k, r = 2, inv = 0, i, j;
        int32_t s;
        for (k = 0; k < 4; k++) {
            if (v[k] == a)
                ia = k;
            else if (v[k] == b)
                ib = k;
            else
                pos[r++] = k;
        }
        if (ia < 0 || ib < 0)
            return 0; /* not reached on a valid mesh */
        pos[0] = ia;
        pos[1] = ib;
        for (i = 0; i < 4; i++)
            for (j = i + 1; j < 4; j++)
                inv += pos[i] > pos[j];
        /* (a, b, x, y) an even permutation of a positive tetrahedron: turning
         * positively about b - a goes from y's side to x's, out through the
         * face opposite y */
        if (n == d->ring_cap) {
            size_t cap = d->ring_cap ? 2 * d->ring_cap : 32;
            int32_t *nr = cvm__realloc(ctx, d->ring, cap * sizeof *nr);
            if (!nr) {
                cvm__nomem(ctx);
                return -1;
            }
            d->ring = nr;
            d->ring_cap = cap;
        }
        d->ring[n++] = t;
        s = d->nbr[4 * t + (inv % 2 == 0 ? pos[3] : pos[2])];
        if (s < 0)
            return 0;
        t = s / 4;
        if (t == t0)
            return (long)n;
        if (n > d->ntet)
            return 0;
    }
}

long cvm__dual3_face(cvm__ctx *ctx, cvm__dual3 *d, const int32_t *tet, size_t e)
{
    long n = cvm__dual3_ring(ctx, d, tet, e), i, k = 0;
    if (n <= 0)
        return n;
    for (i = 0; i < n; i++) {
        int32_t v = d->dvert[d->ring[i]];
        if (k == 0 || d->ring[k - 1] != v)
            d->ring[k++] = v;
    }
    while (k > 1 && d->ring[k - 1] == d->ring[0])
        k--;
    return k;
}

/* Signed area of the dual face of interior edge e (ring in d->ring, n tets):
 * the vector area of the polygon of power vertices dotted with the unit edge. */
static double face_area(const cvm__dual3 *d, const double *X, size_t e, long n)
{
    const double *pa = X + 3 * d->edge[2 * e], *pb = X + 3 * d->edge[2 * e + 1];
    double o[3], u[3], s[3] = {0, 0, 0}, len;
    long i;
    int k;
    for (k = 0; k < 3; k++) {
        o[k] = 0.5 * (pa[k] + pb[k]);
        u[k] = pb[k] - pa[k];
    }
    for (i = 0; i < n; i++) {
        const double *p = d->pv + 3 * d->ring[i], *q = d->pv + 3 * d->ring[(i + 1) % n];
        double x[3], y[3];
        for (k = 0; k < 3; k++) {
            x[k] = p[k] - o[k];
            y[k] = q[k] - o[k];
        }
        s[0] += x[1] * y[2] - x[2] * y[1];
        s[1] += x[2] * y[0] - x[0] * y[2];
        s[2] += x[0] * y[1] - x[1] * y[0];
    }
    len = sqrt(u[0] * u[0] + u[1] * u[1] + u[2] * u[2]);
    return len > 0 ? 0.5 * (s[0] * u[0] + s[1] * u[1] + s[2] * u[2]) / len : 0;
}

cvm_status cvm__dual3_build(cvm__ctx *ctx, const cvm__mesh3 *g, cvm__dual3 *d)
{
    const double *X = g->xyz;
    size_t t, i, e;
    cvm_status s;
    memset(d, 0, sizeof *d);
    d->nv = g->nv;
    d->ntet = g->ntet;
    d->pv = cvm__malloc(ctx, (3 * d->ntet + 1) * sizeof *d->pv);
    d->dvert = cvm__malloc(ctx, (d->ntet + 1) * sizeof *d->dvert);
    d->vbnd = cvm__malloc(ctx, d->nv + 1);
    d->volume = cvm__malloc(ctx, (d->nv + 1) * sizeof *d->volume);
    if (!d->pv || !d->dvert || !d->vbnd || !d->volume) {
        s = cvm__nomem(ctx);
        goto fail;
    }
    if ((s = cvm__mesh3_adjacency(ctx, g->tet, d->ntet, &d->nbr)))
        goto fail;
    memset(d->vbnd, 1, d->nv + 1);
    for (t = 0; t < d->ntet; t++) {
        const int32_t *v = g->tet + 4 * t;
        double w4[4];
        for (i = 0; i < 4; i++) {
            w4[i] = g->w ? g->w[v[i]] : 0;
            d->vbnd[v[i]] = 0;
        }
        if (cvm__tet_power_centre(X + 3 * v[0], X + 3 * v[1], X + 3 * v[2], X + 3 * v[3], w4,
                                  d->pv + 3 * t))
            d->pv[3 * t] = d->pv[3 * t + 1] = d->pv[3 * t + 2] = NAN;
    }
    for (i = 0; i < 4 * d->ntet; i++)
        if (d->nbr[i] < 0) {
            int32_t f[3];
            cvm__mesh3_face_corners(g->tet + 4 * (i / 4), (int)(i % 4), f);
            d->vbnd[f[0]] = d->vbnd[f[1]] = d->vbnd[f[2]] = 1;
        }
    if ((s = merge_ties(ctx, g, d)) || (s = build_edges(ctx, g, d)))
        goto fail;
    for (e = 0; e < d->nedge; e++) {
        long n = cvm__dual3_ring(ctx, d, g->tet, e);
        if (n < 0) {
            s = CVM_E_NOMEM;
            goto fail;
        }
        d->edge_in[e] = n > 0;
        d->edge_area[e] = n > 0 ? face_area(d, X, e, n) : 0;
    }
    for (i = 0; i < d->nv; i++) {
        int32_t k;
        double vol = 0;
        if (d->vbnd[i]) {
            d->volume[i] = -1;
            continue;
        }
        for (k = d->vedge_off[i]; k < d->vedge_off[i + 1]; k++) {
            int32_t ed = d->vedge[k], u = d->edge[2 * ed] == (int32_t)i ? d->edge[2 * ed + 1]
                                                                        : d->edge[2 * ed];
            double l2 = cvm__dist2_3(X + 3 * i, X + 3 * u);
            double h = (l2 + (g->w ? g->w[i] - g->w[u] : 0)) / (2 * sqrt(l2));
            vol += d->edge_area[ed] * h / 3;
        }
        d->volume[i] = vol;
    }
    return CVM_OK;
fail:
    cvm__dual3_free(ctx, d);
    return s;
}

/*
 * d3_slide.c - boundary vertices of the 3D power-dual optimiser that slide on
 * the surface as it was (params.slide 2): a vertex of the boundary (faces
 * without a neighbour; no internal facet at it) that is not inside an
 * axis-aligned plane and whose boundary faces all turn less than
 * D3S_SMOOTH_DEG from their mean normal moves in that normal's tangent plane,
 * and each trial point is then put on the nearest point of its ring: its
 * boundary faces as they were when the run began. Every ring is a piece of
 * the input surface, so a vertex never leaves it, and never crosses a feature
 * (a sharper bend, an edge between facets, a corner), where vertices stay.
 * The exact checks of every move (orientation of the star, regularity) are
 * unchanged; only the set of trial points differs.
 */
#include <math.h>
#include <string.h>

#include "dual3/d3_internal.h"
#include "geom/measure.h"

#define D3S_SMOOTH_DEG 25.0

static void d3s_sub(const double *a, const double *b, double *o)
{
    o[0] = a[0] - b[0], o[1] = a[1] - b[1], o[2] = a[2] - b[2];
}

static double d3s_dot(const double *a, const double *b)
{
    return a[0] * b[0] + a[1] * b[1] + a[2] * b[2];
}

static void d3s_cross(const double *a, const double *b, double *o)
{
    o[0] = a[1] * b[2] - a[2] * b[1];
    o[1] = a[2] * b[0] - a[0] * b[2];
    o[2] = a[0] * b[1] - a[1] * b[0];
}

/* The point of triangle abc nearest to p (Ericson, Real-Time Collision
 * Detection, 5.1.5: Voronoi regions of the corners and edges). */
static void d3s_closest(const double *p, const double *a, const double *b, const double *c,
                        double *o)
{
    double ab[3], ac[3], ap[3], bp[3], cp[3], d1, d2, d3, d4, d5, d6, va, vb, vc, v, w, den;
    int k;
    d3s_sub(b, a, ab), d3s_sub(c, a, ac), d3s_sub(p, a, ap);
    d1 = d3s_dot(ab, ap), d2 = d3s_dot(ac, ap);
    if (d1 <= 0 && d2 <= 0) {
        memcpy(o, a, 3 * sizeof *o);
        return;
    }
    d3s_sub(p, b, bp);
    d3 = d3s_dot(ab, bp), d4 = d3s_dot(ac, bp);
    if (d3 >= 0 && d4 <= d3) {
        memcpy(o, b, 3 * sizeof *o);
        return;
    }
    vc = d1 * d4 - d3 * d2;
    if (vc <= 0 && d1 >= 0 && d3 <= 0) {
        v = d1 / (d1 - d3);
        for (k = 0; k < 3; k++)
            o[k] = a[k] + v * ab[k];
        return;
    }
    d3s_sub(p, c, cp);
    d5 = d3s_dot(ab, cp), d6 = d3s_dot(ac, cp);
    if (d6 >= 0 && d5 <= d6) {
        memcpy(o, c, 3 * sizeof *o);
        return;
    }
    vb = d5 * d2 - d1 * d6;
    if (vb <= 0 && d2 >= 0 && d6 <= 0) {
        w = d2 / (d2 - d6);
        for (k = 0; k < 3; k++)
            o[k] = a[k] + w * ac[k];
        return;
    }
    va = d3 * d6 - d5 * d4;
    if (va <= 0 && (d4 - d3) >= 0 && (d5 - d6) >= 0) {
        w = (d4 - d3) / ((d4 - d3) + (d5 - d6));
        for (k = 0; k < 3; k++)
            o[k] = b[k] + w * (c[k] - b[k]);
        return;
    }
    den = 1.0 / (va + vb + vc);
    v = vb * den, w = vc * den;
    for (k = 0; k < 3; k++)
        o[k] = a[k] + ab[k] * v + ac[k] * w;
}

void cvm__d3_slide_project(const cvm__d3_work *K, int32_t v, double *x)
{
    double best[3], q[3], dbest = HUGE_VAL, d[3];
    int32_t i;
    for (i = K->rstart[v]; i < K->rstart[v + 1]; i++) {
        const double *f = K->rxyz + 9 * (size_t)K->rface[i];
        double dd;
        d3s_closest(x, f, f + 3, f + 6, q);
        d3s_sub(x, q, d);
        dd = d3s_dot(d, d);
        if (dd < dbest)
            dbest = dd, memcpy(best, q, sizeof best);
    }
    if (dbest < HUGE_VAL)
        memcpy(x, best, sizeof best);
}

void cvm__d3_slide_free(cvm__ctx *ctx, cvm__d3_work *K)
{
    cvm__free(ctx, K->curved);
    cvm__free(ctx, K->tan);
    cvm__free(ctx, K->rstart);
    cvm__free(ctx, K->rface);
    cvm__free(ctx, K->rxyz);
    K->curved = NULL, K->tan = K->rxyz = NULL, K->rstart = K->rface = NULL;
}

cvm_status cvm__d3_slide_init(cvm__ctx *ctx, cvm__d3_work *K, const cvm__d3_mesh *M)
{
    size_t nv = M->nv, t, nf = 0, i;
    uint8_t *inner;
    double cmin = cos(D3S_SMOOTH_DEG * (CVM__PI / 180));
    int f;
    for (t = 0; t < 4 * M->ntet; t++)
        nf += M->nbr[t] < 0;
    K->curved = cvm__calloc(ctx, nv + 1, 1);
    K->tan = cvm__calloc(ctx, 6 * nv + 1, sizeof *K->tan);
    K->rstart = cvm__calloc(ctx, nv + 2, sizeof *K->rstart);
    K->rface = cvm__malloc(ctx, (3 * nf + 1) * sizeof *K->rface);
    K->rxyz = cvm__malloc(ctx, (9 * nf + 1) * sizeof *K->rxyz);
    inner = cvm__calloc(ctx, nv + 1, 1);
    if (!K->curved || !K->tan || !K->rstart || !K->rface || !K->rxyz || !inner) {
        cvm__free(ctx, inner);
        cvm__d3_slide_free(ctx, K);
        return cvm__nomem(ctx);
    }
    /* the ring of each vertex: its boundary faces as they are now (CSR), and the
       vertices on an internal facet, which stay */
    nf = 0;
    for (t = 0; t < M->ntet; t++)
        for (f = 0; f < 4; f++) {
            int a, j = 0;
            int32_t c[3];
            if (!M->cface[4 * t + (size_t)f])
                continue;
            for (a = 0; a < 4; a++)
                if (a != f)
                    c[j++] = M->tet[4 * t + (size_t)a];
            if (M->nbr[4 * t + (size_t)f] >= 0) {
                inner[c[0]] = inner[c[1]] = inner[c[2]] = 1;
                continue;
            }
            for (a = 0; a < 3; a++) {
                memcpy(K->rxyz + 9 * nf + 3 * (size_t)a, M->xyz + 3 * (size_t)c[a], 3 * sizeof(double));
                K->rstart[c[a] + 1]++;
            }
            nf++;
        }
    for (i = 0; i < nv; i++)
        K->rstart[i + 1] += K->rstart[i];
    {
        /* fill: rface[rstart[v] ..] (a second pass over the same faces, in order) */
        int32_t *fill = (int32_t *)K->tan; /* scratch: nv counters, zeroed below */
        size_t k = 0;
        memset(fill, 0, nv * sizeof *fill);
        for (t = 0; t < M->ntet; t++)
            for (f = 0; f < 4; f++) {
                int a;
                if (!M->cface[4 * t + (size_t)f] || M->nbr[4 * t + (size_t)f] >= 0)
                    continue;
                for (a = 0; a < 4; a++)
                    if (a != f) {
                        int32_t q = M->tet[4 * t + (size_t)a];
                        K->rface[K->rstart[q] + fill[q]++] = (int32_t)k;
                    }
                k++;
            }
        memset(K->tan, 0, 6 * nv * sizeof *K->tan);
    }
    for (i = 0; i < nv; i++) {
        double n[3] = {0, 0, 0}, len, e[3], *t1 = K->tan + 6 * i, *t2 = t1 + 3;
        int32_t j;
        int ok = K->fixpos[i] && !K->slide[i] && !inner[i] && K->rstart[i + 1] > K->rstart[i];
        for (j = K->rstart[i]; ok && j < K->rstart[i + 1]; j++) {
            const double *p = K->rxyz + 9 * (size_t)K->rface[j];
            double u[3], w[3], fn[3];
            d3s_sub(p + 3, p, u), d3s_sub(p + 6, p, w), d3s_cross(u, w, fn);
            n[0] += fn[0], n[1] += fn[1], n[2] += fn[2];
        }
        len = sqrt(d3s_dot(n, n));
        ok = ok && len > 0;
        for (j = K->rstart[i]; ok && j < K->rstart[i + 1]; j++) {
            const double *p = K->rxyz + 9 * (size_t)K->rface[j];
            double u[3], w[3], fn[3], fl;
            d3s_sub(p + 3, p, u), d3s_sub(p + 6, p, w), d3s_cross(u, w, fn);
            fl = sqrt(d3s_dot(fn, fn));
            ok = fl > 0 && d3s_dot(fn, n) >= cmin * fl * len;
        }
        if (!ok)
            continue;
        n[0] /= len, n[1] /= len, n[2] /= len;
        /* a tangent basis: the axis least aligned with n, made orthogonal */
        e[0] = e[1] = e[2] = 0;
        e[fabs(n[0]) <= fabs(n[1]) && fabs(n[0]) <= fabs(n[2]) ? 0 : fabs(n[1]) <= fabs(n[2]) ? 1 : 2] = 1;
        d3s_cross(n, e, t1);
        len = sqrt(d3s_dot(t1, t1));
        t1[0] /= len, t1[1] /= len, t1[2] /= len;
        d3s_cross(n, t1, t2);
        K->curved[i] = 1;
    }
    cvm__free(ctx, inner);
    return CVM_OK;
}

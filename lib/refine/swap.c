/* swap.c - post-processing by edge flips: swapping towards the ideal vertex degree, and restoring the (constrained) Delaunay property. */
#include <math.h>
#include <string.h>

#include "refine_internal.h"
#include "delaunay/tri2_store.h"
#include "geom/geom_internal.h"
#include "geom/measure.h"

/* Sweeps of degree swapping at most (each flip lowers an integer energy, so
 * the passes end anyway; the cap bounds the time). */
#define SW_MAX_SWEEPS 8

/* Edge j of t is flippable: both sides real domain triangles, not a segment,
 * and the quadrilateral strictly convex (exact orient2d). */
static int sw_flippable(const cvm__tri2 *T, int32_t t, int j)
{
    int32_t h = T->tn[3 * (size_t)t + j], u = h / 3;
    const int32_t *tv = T->tv + 3 * (size_t)t;
    const double *pa, *pb, *pc, *pd;
    if (cvm__tri2_edge_seg(T, t, j) >= 0 || !cvm__tri2_in_domain(T, t) ||
        !cvm__tri2_in_domain(T, u))
        return 0;
    pa = cvm__tri2_pt(T, tv[j]);
    pb = cvm__tri2_pt(T, tv[(j + 1) % 3]);
    pc = cvm__tri2_pt(T, tv[(j + 2) % 3]);
    pd = cvm__tri2_pt(T, T->tv[h]);
    return cvm__orient2d_inline(pa, pb, pd) > 0 && cvm__orient2d_inline(pa, pd, pc) > 0;
}

/* Flip edge j of t: t = (a, b, c) with edge b-c shared with u = (d, c, b)
 * becomes t = (a, b, d) and u = (d, c, a). Slots, te and vtri follow. */
static void sw_flip(cvm__tri2 *T, int32_t t, int j)
{
    int32_t h = T->tn[3 * (size_t)t + j], u = h / 3;
    int k = h % 3, j1 = (j + 1) % 3, j2 = (j + 2) % 3, k1 = (k + 1) % 3, k2 = (k + 2) % 3;
    int32_t *tv = T->tv + 3 * (size_t)t, *uv = T->tv + 3 * (size_t)u;
    int32_t a = tv[j], b = tv[j1], c = tv[j2], d = uv[k]; /* t = (a, b, c), u = (d, c, b) */
    int32_t n_ca = T->tn[3 * (size_t)t + j1], n_bd = T->tn[3 * (size_t)u + k1];
    int32_t e_ca = T->te ? T->te[3 * (size_t)t + j1] : -1;
    int32_t e_bd = T->te ? T->te[3 * (size_t)u + k1] : -1;
    tv[j2] = d;   /* t = (a, b, d) */
    uv[k2] = a;   /* u = (d, c, a) */
    /* t edge j (b-d) takes u's old edge k1 (b-d); u edge k (c-a) takes t's old edge j1 */
    T->tn[3 * (size_t)t + j] = n_bd;
    T->tn[n_bd] = 3 * t + j;
    T->tn[3 * (size_t)u + k] = n_ca;
    T->tn[n_ca] = 3 * u + k;
    cvm__tri2_link(T, t, j1, u, k1); /* the new edge a-d */
    if (T->te) {
        T->te[3 * (size_t)t + j] = e_bd;
        T->te[3 * (size_t)u + k] = e_ca;
        T->te[3 * (size_t)t + j1] = -1;
        T->te[3 * (size_t)u + k1] = -1;
    }
    if (T->vtri[b] == u)
        T->vtri[b] = t;
    if (T->vtri[c] == t)
        T->vtri[c] = u;
}

/* Degree of every vertex (edges in the domain) and its ideal degree: 6 inside,
 * round(angle / 60 degrees) + 1 on the domain boundary (angle: the sum of the
 * domain angles at the vertex), at least 2. */
static cvm_status sw_degrees(const cvm__tri2 *T, cvm__ctx *ctx, int32_t **deg_out,
                             int32_t **ideal_out)
{
    int32_t *deg = cvm__malloc(ctx, (T->nv + 1) * sizeof *deg);
    int32_t *ideal = cvm__malloc(ctx, (T->nv + 1) * sizeof *ideal);
    double *ang = cvm__malloc(ctx, (T->nv + 1) * sizeof *ang);
    uint8_t *bnd = cvm__malloc(ctx, T->nv + 1);
    size_t t, v;
    if (!deg || !ideal || !ang || !bnd) {
        cvm__free(ctx, deg);
        cvm__free(ctx, ideal);
        cvm__free(ctx, ang);
        cvm__free(ctx, bnd);
        return cvm__nomem(ctx);
    }
    memset(deg, 0, T->nv * sizeof *deg);
    memset(ang, 0, T->nv * sizeof *ang);
    memset(bnd, 0, T->nv);
    for (t = 0; t < T->nt; t++) {
        const int32_t *tv = T->tv + 3 * t;
        int j;
        if (!cvm__tri2_in_domain(T, (int32_t)t))
            continue;
        for (j = 0; j < 3; j++) {
            int32_t u = T->tn[3 * t + (size_t)j] / 3;
            int32_t a = tv[(j + 1) % 3], b = tv[(j + 2) % 3];
            if (!cvm__tri2_in_domain(T, u)) {
                bnd[a] = bnd[b] = 1;
                deg[a]++;
                deg[b]++;
            } else if ((size_t)u > t) {
                deg[a]++;
                deg[b]++;
            }
        }
    }
    /* the domain angle at each boundary vertex */
    for (t = 0; t < T->nt; t++) {
        const int32_t *tv = T->tv + 3 * t;
        int j;
        if (!cvm__tri2_in_domain(T, (int32_t)t) || !(bnd[tv[0]] | bnd[tv[1]] | bnd[tv[2]]))
            continue;
        for (j = 0; j < 3; j++) {
            const double *o = cvm__tri2_pt(T, tv[j]), *p = cvm__tri2_pt(T, tv[(j + 1) % 3]);
            const double *q = cvm__tri2_pt(T, tv[(j + 2) % 3]);
            if (bnd[tv[j]])
                ang[tv[j]] += cvm__corner_angle(o, p, q);
        }
    }
    for (v = 0; v < T->nv; v++) {
        if (bnd[v]) {
            int32_t id = (int32_t)floor(ang[v] / (CVM__PI / 3) + 0.5) + 1;
            ideal[v] = id < 2 ? 2 : id;
        } else {
            ideal[v] = 6;
        }
    }
    cvm__free(ctx, ang);
    cvm__free(ctx, bnd);
    *deg_out = deg;
    *ideal_out = ideal;
    return CVM_OK;
}

/* After a flip in the sweep at triangle t_now: every triangle with an edge
 * whose decision may have changed (those around the four vertices of the
 * flip, and their neighbours, since an edge is looked at from its lower
 * triangle) is marked for the next sweep, and for this one when it comes
 * later in it. */
static void sw_mark_around(const cvm__tri2 *T, int32_t v, size_t t_now, uint8_t *cur, uint8_t *next)
{
    int32_t t0 = T->vtri[v], t = t0;
    size_t n = 0;
    int k;
    if (t0 < 0)
        return;
    do {
        const int32_t *tv = T->tv + 3 * (size_t)t;
        int i = tv[0] == v ? 0 : tv[1] == v ? 1 : 2;
        for (k = 0; k < 4; k++) {
            int32_t w = k < 3 ? T->tn[3 * (size_t)t + (size_t)k] / 3 : t;
            next[w] = 1;
            if ((size_t)w > t_now)
                cur[w] = 1;
        }
        t = T->tn[3 * (size_t)t + (size_t)(i + 1) % 3] / 3;
    } while (t != t0 && ++n <= T->nt);
}

/* Triangle (p, q, r) (counter-clockwise) with vertices a, b, c would be too
 * big for the refiner's bounds: circumradius above the mean size at its
 * vertices, or area above max_area (the test of Delaunay refinement). */
static int sw_too_big(const cvm__refiner *R, int32_t t, int32_t a, int32_t b, int32_t c)
{
    const double *p = cvm__tri2_pt(R->T, a), *q = cvm__tri2_pt(R->T, b), *r = cvm__tri2_pt(R->T, c);
    double l0 = (q[0] - r[0]) * (q[0] - r[0]) + (q[1] - r[1]) * (q[1] - r[1]);
    double l1 = (p[0] - r[0]) * (p[0] - r[0]) + (p[1] - r[1]) * (p[1] - r[1]);
    double l2 = (p[0] - q[0]) * (p[0] - q[0]) + (p[1] - q[1]) * (p[1] - q[1]);
    double cross = (q[0] - p[0]) * (r[1] - p[1]) - (q[1] - p[1]) * (r[0] - p[0]);
    double ls = (R->vls[a] + R->vls[b] + R->vls[c]) / 3;
    double ma = cvm__rf_max_area(R, t); /* the flip stays in t's region */
    if (ma > 0 && cross / 2 > ma)
        return 1;
    return isfinite(ls) && l0 * l1 * l2 > 4 * cross * cross * ls * ls * R->size2;
}

cvm_status cvm__rf_swap_degree(const cvm__refiner *R, size_t *flips_out)
{
    cvm__tri2 *T = R->T;
    const double sin2_min = R->sin2_min;
    int32_t *deg = NULL, *ideal = NULL;
    uint8_t *cur, *next;
    size_t t, flips = 0;
    int sweep, any = 1;
    cvm_status s;
    if (flips_out)
        *flips_out = 0;
    if ((s = sw_degrees(T, T->ctx, &deg, &ideal)))
        return s;
    /* Sweeps after the first visit only the triangles marked by the flips of
     * the sweep before (sw_mark_around): the others would decide as before,
     * so the result is that of full sweeps. */
    cur = cvm__malloc(T->ctx, T->nt + 1);
    next = cvm__malloc(T->ctx, T->nt + 1);
    if (!cur || !next) {
        cvm__free(T->ctx, cur);
        cvm__free(T->ctx, next);
        cvm__free(T->ctx, deg);
        cvm__free(T->ctx, ideal);
        return cvm__nomem(T->ctx);
    }
    memset(cur, 1, T->nt);
    for (sweep = 0; sweep < SW_MAX_SWEEPS && any; sweep++) {
        any = 0;
        memset(next, 0, T->nt);
        for (t = 0; t < T->nt; t++) {
            int j;
            if (!cur[t] || !cvm__tri2_in_domain(T, (int32_t)t))
                continue;
            for (j = 0; j < 3; j++) {
                int32_t h = T->tn[3 * t + (size_t)j], u = h / 3;
                const int32_t *tv = T->tv + 3 * t;
                int32_t a = tv[j], b = tv[(j + 1) % 3], c = tv[(j + 2) % 3], d = T->tv[h];
                int32_t gain;
                if ((size_t)u < t || d == CVM__GHOST)
                    continue;
                /* energy change of the flip: 2 ((ea + ed) - (eb + ec)) + 4 with e = deg - ideal */
                gain = (deg[b] - ideal[b]) + (deg[c] - ideal[c]) - (deg[a] - ideal[a]) -
                       (deg[d] - ideal[d]);
                if (gain < 3 || !sw_flippable(T, (int32_t)t, j))
                    continue;
                if (cvm__min_sin2_ccw(cvm__tri2_pt(T, a), cvm__tri2_pt(T, b), cvm__tri2_pt(T, d)) <
                        sin2_min ||
                    cvm__min_sin2_ccw(cvm__tri2_pt(T, d), cvm__tri2_pt(T, c), cvm__tri2_pt(T, a)) <
                        sin2_min ||
                    sw_too_big(R, (int32_t)t, a, b, d) || sw_too_big(R, (int32_t)t, d, c, a))
                    continue;
                sw_flip(T, (int32_t)t, j);
                deg[a]++;
                deg[d]++;
                deg[b]--;
                deg[c]--;
                flips++;
                any = 1;
                sw_mark_around(T, a, t, cur, next);
                sw_mark_around(T, b, t, cur, next);
                sw_mark_around(T, c, t, cur, next);
                sw_mark_around(T, d, t, cur, next);
            }
        }
        {
            uint8_t *sw = cur;
            cur = next;
            next = sw;
        }
    }
    cvm__free(T->ctx, cur);
    cvm__free(T->ctx, next);
    cvm__free(T->ctx, deg);
    cvm__free(T->ctx, ideal);
    if (flips_out)
        *flips_out = flips;
    return CVM_OK;
}

/* Edge j of t is not locally Delaunay (exact in-circle) and may be flipped. */
static int sw_illegal(const cvm__tri2 *T, int32_t t, int j)
{
    int32_t h = T->tn[3 * (size_t)t + j];
    const int32_t *tv = T->tv + 3 * (size_t)t;
    int32_t d = T->tv[h];
    if (d == CVM__GHOST || cvm__tri2_edge_seg(T, t, j) >= 0 ||
        cvm__incircle_inline(cvm__tri2_pt(T, tv[0]), cvm__tri2_pt(T, tv[1]),
                             cvm__tri2_pt(T, tv[2]), cvm__tri2_pt(T, d)) <= 0)
        return 0;
    return sw_flippable(T, t, j);
}

/* Allocation-free fallback: sweeps in triangle order until no edge flips. */
static size_t sw_restore_sweeps(cvm__tri2 *T)
{
    size_t t, flips = 0;
    int any = 1;
    while (any) {
        any = 0;
        for (t = 0; t < T->nt; t++) {
            int j;
            if (!cvm__tri2_in_domain(T, (int32_t)t))
                continue;
            for (j = 0; j < 3; j++)
                if (sw_illegal(T, (int32_t)t, j)) {
                    sw_flip(T, (int32_t)t, j);
                    flips++;
                    any = 1;
                }
        }
    }
    return flips;
}

cvm_status cvm__rf_restore_delaunay(cvm__tri2 *T, size_t *flips_out)
{
    int32_t *st = NULL;
    size_t n = 0, cap = 0, t, flips = 0;
    if (flips_out)
        *flips_out = 0;
    for (t = 0; t < T->nt; t++) {
        int j;
        if (!cvm__tri2_in_domain(T, (int32_t)t))
            continue;
        for (j = 0; j < 3; j++) {
            if ((size_t)(T->tn[3 * t + (size_t)j] / 3) < t || !sw_illegal(T, (int32_t)t, j))
                continue;
            if (n >= cap && cvm__grow(T->ctx, (void **)&st, &cap, n + 1, sizeof *st))
                goto fallback;
            st[n++] = (int32_t)(3 * t + (size_t)j);
        }
    }
    /* Lawson's flips from a stack of half-edges; a stale entry is simply re-tested. */
    while (n > 0) {
        int32_t h = st[--n], tt = h / 3, u;
        int j = h % 3, k;
        if (!sw_illegal(T, tt, j))
            continue;
        if (n + 4 > cap && cvm__grow(T->ctx, (void **)&st, &cap, n + 4, sizeof *st))
            goto fallback;
        u = T->tn[h] / 3;
        sw_flip(T, tt, j);
        flips++;
        /* the four edges of the quadrilateral: t edges j, j+2 and u edges k, k+2 */
        for (k = 0; k < 3; k++) {
            if (k != (j + 1) % 3)
                st[n++] = 3 * tt + k;
        }
        {
            int32_t hu = T->tn[3 * tt + (j + 1) % 3];
            int ku = hu % 3;
            for (k = 0; k < 3; k++)
                if (k != ku)
                    st[n++] = 3 * u + k;
        }
    }
    cvm__free(T->ctx, st);
    if (flips_out)
        *flips_out = flips;
    return CVM_OK;
fallback:
    /* out of memory for the stack: finish without allocating (the error stays recorded) */
    cvm__free(T->ctx, st);
    flips += sw_restore_sweeps(T);
    if (flips_out)
        *flips_out = flips;
    return cvm__nomem(T->ctx);
}

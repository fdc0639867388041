/* split_segment.c - splitting subsegments: the encroached-segment queue, concentric shells near small angles, and marching with the sizing. */
#include <math.h>

#include "refine_internal.h"
#include "geom/geom_internal.h"

static const double *ss_pt(const cvm__refiner *R, int32_t v)
{
    return R->T->xy + 2 * (size_t)v;
}

cvm_status cvm__rf_segq_push(cvm__refiner *R, int32_t a, int32_t b, int32_t seg)
{
    size_t need = 3 * (R->segq_n + 1);
    if (need > R->cap_segq &&
        cvm__grow(R->ctx, (void **)&R->segq, &R->cap_segq, need, sizeof *R->segq))
        return cvm__nomem(R->ctx);
    R->segq[3 * R->segq_n] = a;
    R->segq[3 * R->segq_n + 1] = b;
    R->segq[3 * R->segq_n + 2] = seg;
    R->segq_n++;
    return CVM_OK;
}

cvm_status cvm__rf_split_queued(cvm__refiner *R)
{
    cvm_status s;
    while (R->segq_head < R->segq_n) {
        const int32_t *e = R->segq + 3 * R->segq_head;
        int32_t a = e[0], b = e[1], seg = e[2];
        int done;
        R->segq_head++;
        if ((s = cvm__rf_split_segment(R, a, b, seg, &done)))
            return s;
        if (R->segq_head == R->segq_n)
            R->segq_head = R->segq_n = 0;
    }
    R->segq_head = R->segq_n = 0;
    return CVM_OK;
}

/* The constrained edge a-b as a half-edge of a domain triangle, or 0. */
static int ss_domain_side(cvm__refiner *R, int32_t a, int32_t b, int32_t *t, int *j)
{
    const cvm__tri2 *T = R->T;
    if (cvm__rf_find_edge(R, a, b, t, j) && cvm__tri2_in_domain(T, *t))
        return 1;
    if (cvm__rf_find_edge(R, b, a, t, j) && cvm__tri2_in_domain(T, *t))
        return 1;
    return 0;
}

/* 1 when, in domain triangle t, the edge at vertex v other than edge j is
 * constrained: another segment meets this one at v inside t (Triangle's
 * "acute" endpoint test). */
static int ss_acute_at(const cvm__tri2 *T, int32_t t, int j, int32_t v)
{
    const int32_t *tv = T->tv + 3 * (size_t)t;
    int iv = tv[0] == v ? 0 : tv[1] == v ? 1 : 2, k;
    for (k = 0; k < 3; k++)
        if (k != j && k != iv)
            return T->te[3 * (size_t)t + (size_t)k] >= 0;
    return 0;
}

/* Fraction along a->b at which to split. Near an endpoint where another
 * segment meets (only one such endpoint), split at a power-of-two distance
 * from it, so that splits around a small input angle fall on concentric
 * circular shells and the refinement terminates (Ruppert; Shewchuk 2000;
 * Triangle's splitencsegs). Otherwise the midpoint. */
static double ss_fraction(cvm__refiner *R, int32_t a, int32_t b, int32_t t, int j)
{
    const cvm__tri2 *T = R->T;
    int acute_a = ss_acute_at(T, t, j, a), acute_b = ss_acute_at(T, t, j, b);
    int32_t u = T->tn[3 * (size_t)t + (size_t)j] / 3;
    int k = T->tn[3 * (size_t)t + (size_t)j] % 3;
    const double *pa = ss_pt(R, a), *pb = ss_pt(R, b);
    double len, pw = 1.0, f;
    if (cvm__tri2_in_domain(T, u)) {
        acute_a |= ss_acute_at(T, u, k, a);
        acute_b |= ss_acute_at(T, u, k, b);
    }
    if (!acute_a && !acute_b)
        return 0.5;
    len = hypot(pb[0] - pa[0], pb[1] - pa[1]);
    while (len > 3.0 * pw)
        pw *= 2.0;
    while (len < 1.5 * pw)
        pw *= 0.5;
    f = pw / len;
    return acute_b ? 1.0 - f : f;
}

/* Insert the vertex at pa + f (pb - pa) on constrained edge j of domain
 * triangle t (segment seg; pa, pb its ends in either order, copied by the
 * caller). *v_out: the new vertex, or -1 when no usable point exists (it
 * rounds onto an end). */
static cvm_status ss_insert_on(cvm__refiner *R, int32_t t, int j, int32_t seg, const double *pa,
                               const double *pb, double f, int32_t *v_out)
{
    cvm__tri2 *T = R->T;
    int32_t a = T->tv[3 * (size_t)t + (size_t)(j + 1) % 3], b = T->tv[3 * (size_t)t + (size_t)(j + 2) % 3];
    double x[2];
    int32_t v;
    cvm_status s;
    *v_out = -1;
    x[0] = pa[0] + f * (pb[0] - pa[0]);
    x[1] = pa[1] + f * (pb[1] - pa[1]);
    /* On a hull segment the rounded point may fall a few ulps inside or outside
     * the line: the hull then stops being exactly convex, which the kernel
     * allows because hull edges of a domain are constrained (no cavity grows
     * into a ghost across them). */
    (void)a;
    (void)b;
    if ((x[0] == pa[0] && x[1] == pa[1]) || (x[0] == pb[0] && x[1] == pb[1]))
        return CVM_OK;
    if ((s = cvm__rf_may_insert(R)))
        return s;
    if ((s = cvm__tri2_add_vertex(T, x, &v)))
        return s == CVM_E_NOMEM ? cvm__nomem(R->ctx)
                                : cvm__error(R->ctx, s, CVM_ENT_NONE, -1, "too many vertices");
    if ((s = cvm__tri2_split_edge(T, v, t, j))) {
        T->nv--;
        return s == CVM_E_NOMEM ? cvm__nomem(R->ctx) : s;
    }
    *v_out = v;
    return cvm__rf_new_vertex(R, v, seg);
}

cvm_status cvm__rf_split_segment(cvm__refiner *R, int32_t a, int32_t b, int32_t seg, int *done_out)
{
    cvm__tri2 *T = R->T;
    int32_t t, v;
    int j;
    double f, pa[2], pb[2];
    cvm_status s;
    *done_out = 0;
    if (!ss_domain_side(R, a, b, &t, &j) || T->te[3 * (size_t)t + (size_t)j] < 0)
        return CVM_OK; /* already split, or not a subsegment */
    seg = T->te[3 * (size_t)t + (size_t)j];
    /* work in the orientation of the half-edge so the split point does not
     * depend on how the pair was queued */
    a = T->tv[3 * (size_t)t + (size_t)(j + 1) % 3];
    b = T->tv[3 * (size_t)t + (size_t)(j + 2) % 3];
    pa[0] = ss_pt(R, a)[0];
    pa[1] = ss_pt(R, a)[1];
    pb[0] = ss_pt(R, b)[0];
    pb[1] = ss_pt(R, b)[1];
    f = ss_fraction(R, a, b, t, j);
    if ((s = ss_insert_on(R, t, j, seg, pa, pb, f, &v)) || v < 0)
        return s;
    *done_out = 1;
    if ((s = cvm__rf_queue_encroached_star(R, v)))
        return s;
    return R->queue_star(R, v);
}

/* ---- marching ---- */

/* Size at the point a + (d/len)(b - a). */
static cvm_status ss_size_along(cvm__refiner *R, const double *pa, double dx, double dy,
                                double frac, double *h)
{
    return cvm__sizing_at(R->p->sizing, pa[0] + dx * frac, pa[1] + dy * frac, h, R->ctx);
}

/* Tabulate I(s) = integral from 0 to s of du / h(u) along a-b (midpoint rule,
 * steps of h/8) into pairs (s, I) of *tab; *n_out pairs. */
static cvm_status ss_integrate(cvm__refiner *R, const double *pa, double dx, double dy, double len,
                               double **tab, size_t *cap, size_t *n_out)
{
    double sofar = 0, total = 0;
    size_t n = 0;
    cvm_status s;
    while (sofar < len && total <= 1e7) {
        double h, ds;
        if ((s = ss_size_along(R, pa, dx, dy, sofar / len, &h)))
            return s;
        ds = h / 8 < len - sofar ? h / 8 : len - sofar;
        if ((s = ss_size_along(R, pa, dx, dy, (sofar + ds / 2) / len, &h)))
            return s;
        total += ds / h;
        sofar += ds;
        if (cvm__grow(R->ctx, (void **)tab, cap, 2 * n + 2, sizeof **tab))
            return cvm__nomem(R->ctx);
        (*tab)[2 * n] = sofar;
        (*tab)[2 * n + 1] = total;
        n++;
    }
    *n_out = n;
    return CVM_OK;
}

/* March subsegment a-b: n = round(I(len)) pieces, vertex k where I reaches
 * k I(len) / n, so the pieces follow the sizing with no 2:1 jumps. */
static cvm_status ss_march_one(cvm__refiner *R, int32_t a, int32_t b, double **tab, size_t *cap)
{
    double pa[2], pb[2], dx, dy, len, total; /* copies: inserting may move T->xy */
    size_t ns = 0, i = 0;
    long n, k;
    int32_t prev = a;
    cvm_status s;
    pa[0] = ss_pt(R, a)[0];
    pa[1] = ss_pt(R, a)[1];
    pb[0] = ss_pt(R, b)[0];
    pb[1] = ss_pt(R, b)[1];
    dx = pb[0] - pa[0];
    dy = pb[1] - pa[1];
    len = hypot(dx, dy);
    if ((s = ss_integrate(R, pa, dx, dy, len, tab, cap, &ns)) || ns == 0)
        return s;
    total = (*tab)[2 * ns - 1];
    n = (long)floor(total + 0.5);
    if (n < 2 || total > 1e7)
        return CVM_OK;
    for (k = 1; k < n; k++) {
        double target = total * (double)k / (double)n, s0, i0, f;
        int32_t t, v;
        int j;
        while (i + 1 < ns && (*tab)[2 * i + 1] < target)
            i++;
        s0 = i ? (*tab)[2 * i - 2] : 0.0;
        i0 = i ? (*tab)[2 * i - 1] : 0.0;
        f = (*tab)[2 * i + 1] > i0 ? (target - i0) / ((*tab)[2 * i + 1] - i0) : 0.0;
        f = (s0 + f * ((*tab)[2 * i] - s0)) / len;
        if (!ss_domain_side(R, prev, b, &t, &j) || R->T->te[3 * (size_t)t + (size_t)j] < 0)
            return CVM_OK;
        if ((s = ss_insert_on(R, t, j, R->T->te[3 * (size_t)t + (size_t)j], pa, pb, f, &v)))
            return s;
        if (v >= 0)
            prev = v;
    }
    return CVM_OK;
}

cvm_status cvm__rf_march_segments(cvm__refiner *R)
{
    const cvm__tri2 *T = R->T;
    int32_t *list = NULL;
    double *tab = NULL;
    size_t n = 0, cap = 0, cap_tab = 0, t, i;
    cvm_status s = CVM_OK;
    int j;
    /* collect first: marching changes the triangles */
    for (t = 0; t < T->nt && !s; t++) {
        if (!cvm__tri2_in_domain(T, (int32_t)t))
            continue;
        for (j = 0; j < 3; j++) {
            size_t h = 3 * t + (size_t)j;
            int32_t a = T->tv[3 * t + (size_t)(j + 1) % 3], b = T->tv[3 * t + (size_t)(j + 2) % 3];
            if (T->te[h] < 0 || (cvm__tri2_in_domain(T, T->tn[h] / 3) && a > b))
                continue;
            if (cvm__grow(R->ctx, (void **)&list, &cap, n + 2, sizeof *list)) {
                s = cvm__nomem(R->ctx);
                break;
            }
            list[n++] = a;
            list[n++] = b;
        }
    }
    for (i = 0; i + 1 < n && !s; i += 2)
        s = ss_march_one(R, list[i], list[i + 1], &tab, &cap_tab);
    cvm__free(R->ctx, list);
    cvm__free(R->ctx, tab);
    return s;
}

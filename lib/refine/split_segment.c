/* split_segment.c - splitting subsegments: the encroached-segment queue, concentric shells near small angles, and marching with the sizing. */
#include <math.h>
#include <string.h>

#include "refine_internal.h"
#include "geom/geom_internal.h"
#include "delaunay/tri2_store.h"

static const double *ss_pt(const cvm__refiner *R, int32_t v)
{
    return R->T->xy + 2 * (size_t)v;
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
    if (cvm__tri2_find_edge(R->T, a, b, t, j) && cvm__tri2_in_domain(T, *t))
        return 1;
    if (cvm__tri2_find_edge(R->T, b, a, t, j) && cvm__tri2_in_domain(T, *t))
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
    cvm__ins res;
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
    if ((s = cvm__tri2_split_edge(T, v, t, j, &res)) == CVM_OK && res != CVM__INS_DONE) {
        /* the rounded point cannot split this (tiny) subsegment: like a point
           that rounds onto an end, the split is refused and the triangles it
           was for are reported, not an error */
        T->nv--;
        return CVM_OK;
    }
    if (s) {
        if (T->vtri[v] < 0) {
            T->nv--; /* not inserted: nothing changed */
            return s == CVM_E_NOMEM ? cvm__nomem(R->ctx) : s;
        }
        /* inserted, only the Delaunay flips around it ran out of memory: the
           triangulation is valid and holds v, so v must be recorded */
        (void)cvm__rf_new_vertex(R, v, seg);
        return s == CVM_E_NOMEM ? cvm__nomem(R->ctx) : s;
    }
    *v_out = v;
    return cvm__rf_new_vertex(R, v, seg);
}

int cvm__rf_on_chain(const double *a, const double *b, const double *c)
{
    double dx = b[0] - a[0], dy = b[1] - a[1], len = sqrt(dx * dx + dy * dy);
    double mag = fmax(fmax(fabs(a[0]), fabs(a[1])), fmax(fabs(b[0]), fabs(b[1])));
    double along = ((c[0] - a[0]) * dx + (c[1] - a[1]) * dy) / len;
    return len > 0 && along > 0 && along < len &&
           fabs(cvm__orient2d(a, b, c)) <= 0x1p-40 * (mag + len) * len;
}

/* Constrain edge j of t for segment seg unless another segment holds it: an
 * edge stores one segment, and the chain check does not consult labels. */
static void ss_constrain(cvm__tri2 *T, int32_t t, int j, int32_t seg)
{
    size_t h = 3 * (size_t)t + (size_t)j;
    if (T->te[h] >= 0)
        return;
    T->te[h] = seg;
    T->te[T->tn[h]] = seg;
}

cvm_status cvm__rf_route_through(cvm__refiner *R, int32_t t, int j, int32_t seg, int requeue,
                                 int *done_out)
{
    cvm__tri2 *T = R->T;
    int side;
    *done_out = 0;
    for (side = 0; side < 2; side++) {
        int32_t h = side ? T->tn[3 * (size_t)t + (size_t)j] : (int32_t)(3 * (size_t)t + (size_t)j);
        int32_t tt = h / 3, hu = T->tn[h], u = hu / 3, c, d, a, b, ea = -1, eb = -1, verts[4];
        int jj = h % 3;
        const int32_t *tv = T->tv + 3 * (size_t)tt;
        cvm_status s;
        if (!cvm__tri2_in_domain(T, tt) || !cvm__tri2_in_domain(T, u))
            continue;
        c = tv[jj];
        a = tv[(jj + 1) % 3];
        b = tv[(jj + 2) % 3];
        d = T->tv[3 * (size_t)u + (size_t)(hu % 3)];
        if (seg < (int32_t)R->nseg) {
            ea = R->seg_ends[2 * (size_t)seg];
            eb = R->seg_ends[2 * (size_t)seg + 1];
        }
        if (!cvm__rf_on_chain(ss_pt(R, a), ss_pt(R, b), ss_pt(R, c)) ||
            (ea >= 0 && eb >= 0 && !cvm__rf_on_chain(ss_pt(R, ea), ss_pt(R, eb), ss_pt(R, c))) ||
            cvm__orient2d(ss_pt(R, c), ss_pt(R, a), ss_pt(R, d)) <= 0 ||
            cvm__orient2d(ss_pt(R, d), ss_pt(R, b), ss_pt(R, c)) <= 0)
            continue;
        /* both new triangles lie on d's side of the chain a-c-b */
        T->tf[tt] = T->tf[u];
        if (T->ta)
            T->ta[tt] = T->ta[u];
        T->te[h] = T->te[hu] = -1;
        cvm__tri2_flip(T, tt, jj);
        /* now tt = (c, a, d) and u = (d, b, c): their edges c-a and b-c */
        ss_constrain(T, tt, 2, seg);
        ss_constrain(T, u, 0, seg);
        if (R->vseg[c] == -1)
            R->vseg[c] = -2;
        verts[0] = a;
        verts[1] = b;
        verts[2] = c;
        verts[3] = d;
        if ((s = cvm__tri2_legalize_stars(T, verts, 4)))
            return s == CVM_E_NOMEM ? cvm__nomem(R->ctx) : s;
        *done_out = 1;
        for (side = 0; side < 4 * requeue; side++)
            if ((s = cvm__rf_queue_encroached_star(R, verts[side])) ||
                (s = R->queue_star(R, verts[side])))
                return s;
        return CVM_OK;
    }
    return CVM_OK;
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
    if ((s = ss_insert_on(R, t, j, seg, pa, pb, f, &v)))
        return s;
    if (v < 0)
        return cvm__rf_route_through(R, t, j, seg, 1, done_out);
    *done_out = 1;
    if ((s = cvm__rf_queue_encroached_star(R, v)))
        return s;
    return R->queue_star(R, v);
}

/* ---- marching ---- */

/* A subsegment a-b being marched: a's coordinates, b - a, its length, and the
 * limits la, lb on the pieces at a and b set by the pieces of the neighbouring
 * subsegments there (HUGE_VAL: none), graded at rate g. */
typedef struct ss_line {
    double pa[2], dx, dy, len, la, lb, g;
} ss_line;

static void ss_line_init(ss_line *L, const cvm__refiner *R, int32_t a, int32_t b, double la,
                         double lb)
{
    const double *p = ss_pt(R, a), *q = ss_pt(R, b);
    L->pa[0] = p[0];
    L->pa[1] = p[1];
    L->dx = q[0] - p[0];
    L->dy = q[1] - p[1];
    L->len = hypot(L->dx, L->dy);
    L->la = la;
    L->lb = lb;
    L->g = R->p->march_grade;
}

/* The size at distance d from a along the line: the sizing, capped by
 * la + g d and lb + g (len - d) when grading (so pieces grow geometrically
 * away from a short neighbour instead of jumping). */
static cvm_status ss_size_along(cvm__refiner *R, const ss_line *L, double d, double *h)
{
    double f = d / L->len;
    cvm_status s = cvm__sizing_at(R->p->sizing, L->pa[0] + L->dx * f, L->pa[1] + L->dy * f, h, R->ctx);
    if (!s && L->g > 0) {
        double ha = L->la + L->g * d, hb = L->lb + L->g * (L->len - d);
        *h = ha < *h ? ha : *h;
        *h = hb < *h ? hb : *h;
    }
    return s;
}

/* The most pieces a march may plan: 1e7, and no more than the Steiner points
 * left (CVM_OPT_MAX_STEINER), since a longer march would stop half-way while
 * its table (eight entries per piece) had already grown without bound. */
static double ss_piece_limit(const cvm__refiner *R)
{
    double left;
    if (!R->p->max_steiner)
        return 1e7;
    left = R->steiner < R->p->max_steiner ? (double)(R->p->max_steiner - R->steiner) + 1.0 : 1.0;
    return left < 1e7 ? left : 1e7;
}

/* Tabulate I(s) = integral from 0 to s of du / h(u) along the line (midpoint
 * rule, steps of h/8) into pairs (s, I) of *tab; *n_out pairs. Stops once I
 * passes ss_piece_limit(). */
static cvm_status ss_integrate(cvm__refiner *R, const ss_line *L, double **tab, size_t *cap,
                               size_t *n_out)
{
    double sofar = 0, total = 0, limit = ss_piece_limit(R);
    size_t n = 0;
    cvm_status s;
    while (sofar < L->len && total <= limit) {
        double h, ds;
        if ((s = ss_size_along(R, L, sofar, &h)))
            return s;
        ds = h / 8 < L->len - sofar ? h / 8 : L->len - sofar;
        if ((s = ss_size_along(R, L, sofar + ds / 2, &h)))
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

/* Distance along the line at which the tabulated integral (ns pairs) reaches
 * target; *i: the table position to search from (targets ascend). */
static double ss_reach(const double *tab, size_t ns, double target, size_t *i)
{
    double s0, i0, f;
    while (*i + 1 < ns && tab[2 * *i + 1] < target)
        (*i)++;
    s0 = *i ? tab[2 * *i - 2] : 0.0;
    i0 = *i ? tab[2 * *i - 1] : 0.0;
    f = tab[2 * *i + 1] > i0 ? (target - i0) / (tab[2 * *i + 1] - i0) : 0.0;
    return s0 + f * (tab[2 * *i] - s0);
}

/* Plan the march of the line: n = round(I(len)) pieces (*n_out; < 2: the
 * subsegment stays whole), vertex k where I reaches k I(len) / n, so the pieces
 * follow the (graded) sizing with no 2:1 jumps. *first, *last: the lengths
 * of the pieces at a and at b. The table stays in *tab (*ns pairs). */
static cvm_status ss_plan(cvm__refiner *R, const ss_line *L, double **tab, size_t *cap, size_t *ns,
                          long *n_out, double *first, double *last)
{
    double total;
    size_t i = 0;
    cvm_status s;
    *n_out = 1;
    *first = *last = L->len;
    if ((s = ss_integrate(R, L, tab, cap, ns)) || *ns == 0)
        return s;
    total = (*tab)[2 * *ns - 1];
    if (total > ss_piece_limit(R) || (long)floor(total + 0.5) < 2)
        return CVM_OK;
    *n_out = (long)floor(total + 0.5);
    *first = ss_reach(*tab, *ns, total / (double)*n_out, &i);
    *last = L->len - ss_reach(*tab, *ns, total * (double)(*n_out - 1) / (double)*n_out, &i);
    return CVM_OK;
}

/* March subsegment a-b as planned with the limits la, lb. */
static cvm_status ss_march_one(cvm__refiner *R, int32_t a, int32_t b, double la, double lb,
                               double **tab, size_t *cap)
{
    ss_line L; /* a copy: inserting may move T->xy */
    double pb[2], first, last;
    size_t ns = 0, i = 0;
    long n, k;
    int32_t prev = a;
    cvm_status s;
    ss_line_init(&L, R, a, b, la, lb);
    pb[0] = ss_pt(R, b)[0];
    pb[1] = ss_pt(R, b)[1];
    if ((s = ss_plan(R, &L, tab, cap, &ns, &n, &first, &last)) || n < 2)
        return s;
    for (k = 1; k < n; k++) {
        double f = ss_reach(*tab, ns, (*tab)[2 * ns - 1] * (double)k / (double)n, &i) / L.len;
        int32_t t, v;
        int j;
        if (!ss_domain_side(R, prev, b, &t, &j) || R->T->te[3 * (size_t)t + (size_t)j] < 0)
            return CVM_OK;
        if ((s = ss_insert_on(R, t, j, R->T->te[3 * (size_t)t + (size_t)j], L.pa, pb, f, &v)))
            return s;
        if (v >= 0)
            prev = v;
    }
    return CVM_OK;
}

/* The subsegments to march and their grading state. */
typedef struct ss_subs {
    int32_t *ab;    /* 2 per subsegment: its ends */
    double *lim;    /* 2 per subsegment: the limits at its ends (HUGE_VAL: none) */
    double *piece;  /* 2 per subsegment: its planned pieces at its ends */
    size_t n;
    size_t *first;  /* per vertex + 1: start of its incidences in inc */
    int32_t *inc;   /* 2 per subsegment: 2 i + e for end e of subsegment i */
    int32_t *queue; /* FIFO of subsegments to plan again */
    unsigned char *queued;
} ss_subs;

static void ss_subs_free(cvm__ctx *ctx, ss_subs *S)
{
    cvm__free(ctx, S->ab);
    cvm__free(ctx, S->lim);
    cvm__free(ctx, S->piece);
    cvm__free(ctx, S->first);
    cvm__free(ctx, S->inc);
    cvm__free(ctx, S->queue);
    cvm__free(ctx, S->queued);
}

/* The limit at end e of subsegment i: the shortest planned piece of the other
 * subsegments at that vertex. */
static double ss_limit(const ss_subs *S, size_t i, int e)
{
    int32_t v = S->ab[2 * i + (size_t)e];
    double l = HUGE_VAL;
    size_t k;
    for (k = S->first[v]; k < S->first[v + 1]; k++) {
        size_t o = (size_t)S->inc[k];
        if (o / 2 != i && S->piece[o] < l)
            l = S->piece[o];
    }
    return l;
}

/* Planning runs before any insertion and, with a costly sizing and many
 * segments, for long: it checks the time limit and the progress callback as
 * insertions do. A stop leaves the mesh as it was (valid). */
static cvm_status ss_tick(cvm__refiner *R, double frac)
{
    cvm_status s = cvm__tick(R->ctx, 1, CVM_STAGE_REFINE, frac);
    if (s)
        return cvm__error(R->ctx, s, CVM_ENT_NONE, -1,
                          "refinement %s while planning the segment splits, after %lu Steiner "
                          "points; the mesh is valid but some triangles may not meet the bounds",
                          s == CVM_INCOMPLETE_CANCELLED ? "was cancelled" : "reached the time limit",
                          (unsigned long)R->steiner);
    return CVM_OK;
}

/* Grade the plans across subsegment ends: every subsegment's limits are the
 * shortest pieces of its neighbours at its ends (l(e) in h_b = min(h, l(e) +
 * g d(x, e))); a subsegment is planned again (FIFO, in collection order, so
 * the result is deterministic) when a neighbouring end piece changes, until
 * nothing changes or after 50 plans per subsegment. */
static cvm_status ss_grade(cvm__refiner *R, ss_subs *S, double **tab, size_t *cap)
{
    const cvm__tri2 *T = R->T;
    size_t i, k, nv = T->nv, head = 0, count, budget;
    cvm_status s;
    int e;
    S->lim = cvm__malloc(R->ctx, (2 * S->n + 1) * sizeof *S->lim);
    S->piece = cvm__malloc(R->ctx, (2 * S->n + 1) * sizeof *S->piece);
    S->first = cvm__malloc(R->ctx, (nv + 2) * sizeof *S->first);
    S->inc = cvm__malloc(R->ctx, (2 * S->n + 1) * sizeof *S->inc);
    S->queue = cvm__malloc(R->ctx, (S->n + 1) * sizeof *S->queue);
    S->queued = cvm__malloc(R->ctx, S->n + 1);
    if (!S->lim || !S->piece || !S->first || !S->inc || !S->queue || !S->queued)
        return cvm__nomem(R->ctx);
    for (k = 0; k < nv + 2; k++)
        S->first[k] = 0;
    for (k = 0; k < 2 * S->n; k++)
        S->first[S->ab[k] + 2]++;
    for (k = 2; k < nv + 2; k++)
        S->first[k] += S->first[k - 1];
    for (k = 0; k < 2 * S->n; k++)
        S->inc[S->first[S->ab[k] + 1]++] = (int32_t)k;
    /* first plans: ungraded */
    for (i = 0; i < S->n; i++) {
        ss_line L;
        size_t ns;
        long n;
        S->lim[2 * i] = S->lim[2 * i + 1] = HUGE_VAL;
        ss_line_init(&L, R, S->ab[2 * i], S->ab[2 * i + 1], HUGE_VAL, HUGE_VAL);
        if ((s = ss_plan(R, &L, tab, cap, &ns, &n, &S->piece[2 * i], &S->piece[2 * i + 1])) ||
            (s = ss_tick(R, 0.0)))
            return s;
        S->queue[i] = (int32_t)i;
        S->queued[i] = 1;
    }
    count = S->n;
    budget = 50 * S->n;
    while (count > 0 && budget-- > 0) {
        ss_line L;
        size_t ns;
        long n;
        double p[2];
        i = (size_t)S->queue[head];
        head = head + 1 == S->n ? 0 : head + 1;
        count--;
        S->queued[i] = 0;
        S->lim[2 * i] = ss_limit(S, i, 0);
        S->lim[2 * i + 1] = ss_limit(S, i, 1);
        ss_line_init(&L, R, S->ab[2 * i], S->ab[2 * i + 1], S->lim[2 * i], S->lim[2 * i + 1]);
        if ((s = ss_plan(R, &L, tab, cap, &ns, &n, &p[0], &p[1])) || (s = ss_tick(R, 0.0)))
            return s;
        for (e = 0; e < 2; e++) {
            int32_t v = S->ab[2 * i + (size_t)e];
            if (fabs(p[e] - S->piece[2 * i + (size_t)e]) <= 1e-9 * p[e])
                continue;
            S->piece[2 * i + (size_t)e] = p[e];
            for (k = S->first[v]; k < S->first[v + 1]; k++) {
                size_t o = (size_t)S->inc[k] / 2;
                if (o == i || S->queued[o])
                    continue;
                S->queue[(head + count) % S->n] = (int32_t)o;
                S->queued[o] = 1;
                count++;
            }
        }
    }
    return CVM_OK;
}

cvm_status cvm__rf_march_segments(cvm__refiner *R)
{
    const cvm__tri2 *T = R->T;
    ss_subs S;
    double *tab = NULL;
    size_t cap = 0, cap_tab = 0, t, i;
    cvm_status s = CVM_OK;
    int j;
    memset(&S, 0, sizeof S);
    /* collect first: marching changes the triangles */
    for (t = 0; t < T->nt && !s; t++) {
        if (!cvm__tri2_in_domain(T, (int32_t)t))
            continue;
        for (j = 0; j < 3; j++) {
            size_t h = 3 * t + (size_t)j;
            int32_t a = T->tv[3 * t + (size_t)(j + 1) % 3], b = T->tv[3 * t + (size_t)(j + 2) % 3];
            if (T->te[h] < 0 || (cvm__tri2_in_domain(T, T->tn[h] / 3) && a > b))
                continue;
            if (cvm__grow(R->ctx, (void **)&S.ab, &cap, 2 * S.n + 2, sizeof *S.ab)) {
                s = cvm__nomem(R->ctx);
                break;
            }
            S.ab[2 * S.n] = a;
            S.ab[2 * S.n + 1] = b;
            S.n++;
        }
    }
    if (!s && S.n && R->p->march_grade > 0)
        s = ss_grade(R, &S, &tab, &cap_tab);
    for (i = 0; i < S.n && !s; i++)
        s = ss_march_one(R, S.ab[2 * i], S.ab[2 * i + 1], S.lim ? S.lim[2 * i] : HUGE_VAL,
                         S.lim ? S.lim[2 * i + 1] : HUGE_VAL, &tab, &cap_tab);
    ss_subs_free(R->ctx, &S);
    cvm__free(R->ctx, tab);
    return s;
}

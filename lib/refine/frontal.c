/* frontal.c - frontal-Delaunay refinement after Rebay (1993): triangles grow layer by layer from the boundary and from accepted triangles, each new point placed on the bisector of a front edge so that it forms a triangle of the local size. */
/*
 * Each triangle's measure (fr_measure) is kept in a per-slot record for the
 * length of the pass (struct cvm__fr_rec): a triangle is looked at on push,
 * on pop and by each neighbour testing the front, but its vertices never move
 * while the pass runs. The output is bit-identical to measuring every time.
 */
#include <math.h>

#include "refine_internal.h"
#include "geom/geom_internal.h"
#include "geom/measure.h"

/* Accepted (Rebay's "small enough"): circumradius at most sqrt(this) times
 * the local size (CVM__FRONTAL_ACCEPT2, refine_internal.h). */
#define FR_ACCEPT2 CVM__FRONTAL_ACCEPT2

/* Edge j of a triangle joins its vertices fr_next[j] and fr_prev[j]. */
static const int fr_next[3] = {1, 2, 0}, fr_prev[3] = {2, 0, 1};

static const double *fr_pt(const cvm__refiner *R, int32_t v)
{
    return R->T->xy + 2 * (size_t)v;
}

/* Local size at vertex v: the sizing, capped by the edge of the equilateral
 * triangle of area max_area; +infinity when neither bounds the size. */
static double fr_size(const cvm__refiner *R, int32_t v)
{
    double h = R->vls[v];
    if (R->p->max_area > 0) {
        double ha = sqrt(4.0 * R->p->max_area / 1.7320508075688772);
        if (!(h <= ha))
            h = ha;
    }
    return h;
}

/* Squared circumradius of domain triangle t over its squared mean local size
 * (*ratio; 0 when there is no size) and sin^2 of its smallest angle (*sin2;
 * 0 when it is too thin for floating point). */
static void fr_measure(const cvm__refiner *R, int32_t t, double *ratio, double *sin2)
{
    const int32_t *tv = R->T->tv + 3 * (size_t)t;
    const double *p0 = fr_pt(R, tv[0]), *p1 = fr_pt(R, tv[1]), *p2 = fr_pt(R, tv[2]);
    double l0, l1, l2, cross, ls;
    l0 = cvm__dist2(p1, p2);
    l1 = cvm__dist2(p2, p0);
    l2 = cvm__dist2(p0, p1);
    cross = cvm__cross2(p0, p1, p2);
    ls = (fr_size(R, tv[0]) + fr_size(R, tv[1]) + fr_size(R, tv[2])) / 3;
    if (!(cross > 0)) {
        *sin2 = 0;
        *ratio = isfinite(ls) ? HUGE_VAL : 0;
        return;
    }
    *sin2 = cvm__min_sin2_sides(l0, l1, l2, cross);
    *ratio = isfinite(ls) ? l0 * l1 * l2 / (4 * cross * cross * ls * ls) : 0;
}

/* The quality record of a triangle slot: what fr_quality last measured there.
 * fr_measure depends only on the slot's three vertices in their order (their
 * coordinates and sizes never change during the pass, R->p->max_area and
 * R->sin2_min are fixed), so a record holds while the slot keeps those
 * vertices, however often the Delaunay kernel rewrote it in between. */
struct cvm__fr_rec {
    double ratio; /* fr_measure's *ratio */
    int32_t v[3]; /* the slot's vertices when written; -1: none */
    int32_t acc;  /* accepted: small enough and well shaped */
};

/* Records for every slot below T->nt (new ones empty). CVM_OK or CVM_E_NOMEM. */
static cvm_status fr_rec_reserve(cvm__refiner *R)
{
    size_t k = R->cap_fr_rec;
    if (R->T->nt <= k)
        return CVM_OK;
    if (cvm__grow(R->ctx, (void **)&R->fr_rec, &R->cap_fr_rec, R->T->nt, sizeof *R->fr_rec))
        return cvm__nomem(R->ctx);
    for (; k < R->cap_fr_rec; k++)
        R->fr_rec[k].v[0] = R->fr_rec[k].v[1] = R->fr_rec[k].v[2] = -1;
    return CVM_OK;
}

/* fr_quality when t's record is not valid: measure t, record it if it has a
 * slot in the records (slots created since the last fr_rec_reserve have none). */
static int fr_quality_measure(const cvm__refiner *R, int32_t t, double *ratio)
{
    const int32_t *tv = R->T->tv + 3 * (size_t)t;
    struct cvm__fr_rec *r = (size_t)t < R->cap_fr_rec ? R->fr_rec + t : NULL;
    double sin2;
    int acc;
    fr_measure(R, t, ratio, &sin2);
    acc = *ratio <= FR_ACCEPT2 && sin2 >= R->sin2_min;
    if (r) {
        r->ratio = *ratio;
        r->v[0] = tv[0];
        r->v[1] = tv[1];
        r->v[2] = tv[2];
        r->acc = acc;
    }
    return acc;
}

/* Quality of domain triangle t: returns 1 when it is accepted (small enough
 * and well shaped), and its ratio of fr_measure into *ratio; read from t's
 * record when valid, else measured (and recorded). Kept small so that it
 * inlines: most calls find a valid record. */
static inline int fr_quality(const cvm__refiner *R, int32_t t, double *ratio)
{
    if ((size_t)t < R->cap_fr_rec) {
        const struct cvm__fr_rec *r = R->fr_rec + t;
        if (cvm__tri2_slot_holds(R->T, t, r->v)) {
            *ratio = r->ratio;
            return r->acc;
        }
    }
    return fr_quality_measure(R, t, ratio);
}

/* Domain triangle t is accepted: small enough and well shaped. */
static int fr_accepted(const cvm__refiner *R, int32_t t)
{
    double ratio;
    return fr_quality(R, t, &ratio);
}

/* How far the length of edge j of the triangle with vertices tv is from the
 * local size: max(len/h, h/len)^2, which grows with |log(len / h)|; +infinity
 * when that cannot be told (no size, zero length). */
static double fr_edge_dev(const cvm__refiner *R, const int32_t *tv, int j)
{
    int32_t ia = tv[fr_next[j]], ib = tv[fr_prev[j]];
    const double *a = fr_pt(R, ia), *b = fr_pt(R, ib);
    double len2, h;
    len2 = (b[0] - a[0]) * (b[0] - a[0]) + (b[1] - a[1]) * (b[1] - a[1]);
    h = (fr_size(R, ia) + fr_size(R, ib)) / 2;
    h *= h;
    return len2 >= h ? len2 / h : len2 > 0 ? h / len2 : HUGE_VAL;
}

/* The front edge of a triangle t that is too big (squared ratio > FR_ACCEPT2):
 * of the edges j with acc[j] set (on a segment, or shared with an accepted
 * triangle), the one whose length is nearest the local size, then the lowest
 * index; -1 when there is none. */
static int fr_front_edge(const cvm__refiner *R, int32_t t, const int *acc)
{
    const int32_t *tv = R->T->tv + 3 * (size_t)t;
    double best = HUGE_VAL;
    int j, jf = -1;
    for (j = 0; j < 3; j++) {
        double dev;
        if (!acc[j])
            continue;
        dev = fr_edge_dev(R, tv, j);
        if (dev < best) {
            best = dev;
            jf = j;
        }
    }
    return jf;
}

/* Edge j of domain triangle t is a segment or is shared with an accepted triangle. */
static int fr_edge_on_front(const cvm__refiner *R, int32_t t, int j)
{
    const cvm__tri2 *T = R->T;
    int32_t u = T->tn[3 * (size_t)t + (size_t)j] / 3;
    return T->te[3 * (size_t)t + (size_t)j] >= 0 || (cvm__tri2_in_domain(T, u) && fr_accepted(R, u));
}

/* 1 when domain triangle t is active: too big, and on the front, i.e. with an
 * edge on a segment or shared with an accepted triangle. Triangles small
 * enough but badly shaped are neither active nor part of the front: the
 * clean-up pass splits them by circumcentres, which never crowd points as a
 * frontal point could. The small-input-angle exemption is tested when t is
 * popped. *jf: the front edge (fr_front_edge); *key: its queue position
 * (largest circumradius over size first). Without any size bound nothing is
 * active. */
static int fr_active(cvm__refiner *R, int32_t t, int *jf, double *key)
{
    double ratio;
    int acc[3], j;
    fr_quality(R, t, &ratio);
    if (ratio <= FR_ACCEPT2)
        return 0;
    for (j = 0; j < 3; j++)
        acc[j] = fr_edge_on_front(R, t, j);
    *jf = fr_front_edge(R, t, acc);
    *key = -ratio;
    return *jf >= 0;
}

/* Queue domain triangle t if it is active. */
static cvm_status fr_queue_triangle(cvm__refiner *R, int32_t t)
{
    double key;
    int jf;
    if (cvm__tri2_in_domain(R->T, t) && fr_active(R, t, &jf, &key) &&
        cvm__bq_push(&R->q, R->T, t, 0, key))
        return cvm__nomem(R->ctx);
    return CVM_OK;
}

/* Star triangles measured at once by fr_queue_star (larger stars: one by one). */
#define FR_STAR_MAX 32

/* After vertex v was inserted: queue the active triangles of its star, and,
 * behind each accepted one, the neighbour that now lies on the front. Each
 * star triangle is measured once; its neighbours in the star are looked up. */
static cvm_status fr_queue_star(cvm__refiner *R, int32_t v)
{
    const cvm__tri2 *T = R->T;
    size_t n = cvm__rf_star(R, v), k;
    double ratio[FR_STAR_MAX];
    int acc[FR_STAR_MAX];
    cvm_status s;
    if (n == 0)
        return cvm__nomem(R->ctx);
    if ((s = fr_rec_reserve(R)))
        return s;
    if (n > FR_STAR_MAX) {
        for (k = 0; k < n; k++) {
            int32_t t = R->star[k];
            const int32_t *tv = T->tv + 3 * (size_t)t;
            int i = tv[0] == v ? 0 : tv[1] == v ? 1 : 2;
            if (!cvm__tri2_in_domain(T, t))
                continue;
            s = fr_accepted(R, t) ? fr_queue_triangle(R, T->tn[3 * (size_t)t + (size_t)i] / 3)
                                  : fr_queue_triangle(R, t);
            if (s)
                return s;
        }
        return CVM_OK;
    }
    for (k = 0; k < n; k++) {
        int32_t t = R->star[k];
        if (cvm__tri2_in_domain(T, t)) {
            /* new triangles (they hold v): no record to look up */
            acc[k] = fr_quality_measure(R, t, &ratio[k]);
        } else {
            ratio[k] = 0;
            acc[k] = -1;
        }
    }
    for (k = 0; k < n; k++) {
        int32_t t = R->star[k];
        const int32_t *tv = T->tv + 3 * (size_t)t;
        int i = tv[0] == v ? 0 : tv[1] == v ? 1 : 2, i1 = fr_next[i], i2 = fr_prev[i];
        if (acc[k] < 0)
            continue;
        if (acc[k]) {
            if ((s = fr_queue_triangle(R, T->tn[3 * (size_t)t + (size_t)i] / 3)))
                return s;
            continue;
        }
        if (ratio[k] <= FR_ACCEPT2)
            continue; /* small enough, badly shaped: for the clean-up pass */
        /* Active when fr_front_edge would find a front edge, i.e. when some
         * edge on the front has a finite fr_edge_dev. The star turns through
         * edge i1 to the next triangle, i2 to the previous; edge i, whose
         * test looks beyond the star, is tried last. */
        if (((T->te[3 * (size_t)t + (size_t)i1] >= 0 || acc[k + 1 < n ? k + 1 : 0] == 1) &&
             fr_edge_dev(R, tv, i1) < HUGE_VAL) ||
            ((T->te[3 * (size_t)t + (size_t)i2] >= 0 || acc[k > 0 ? k - 1 : n - 1] == 1) &&
             fr_edge_dev(R, tv, i2) < HUGE_VAL) ||
            (fr_edge_on_front(R, t, i) && fr_edge_dev(R, tv, i) < HUGE_VAL)) {
            if (cvm__bq_push(&R->q, R->T, t, 0, -ratio[k]))
                return cvm__nomem(R->ctx);
        }
    }
    return CVM_OK;
}

/* Rebay's point for active triangle t with front edge jf: on the bisector of
 * the edge (half length p), on the side of t, at the distance
 * d = rho + sqrt(rho^2 - p^2) that makes the new triangle on the edge have
 * circumradius rho = min(max(rho_M, p), (p^2 + q^2) / (2 q)), with rho_M the
 * circumradius of the equilateral triangle of the size at the edge and q the
 * distance from the edge midpoint to the circumcentre c of t (the cap keeps
 * the point at or before c when q >= p). When q < p the formula can pass c;
 * d is then capped at q + R/2 (R: t's circumradius), so the point stays in
 * t's circumcircle, at least R/2 from its boundary. Either way no vertex
 * visible from t lies closer than min(R/2, rho_M) to the point (up to the
 * 1e-9 jitter below), a fixed fraction of the local size since t is too big
 * (R > 0.707 x its size): the frontal pass cannot crowd points. (On the shared geometries the cap never acts.)
 * Returns 0 (no point) when c is not beyond the edge: t's angle opposite the
 * front edge is not acute, and the clean-up pass handles t. */
static int fr_point(const cvm__refiner *R, int32_t t, int jf, double *x)
{
    const int32_t *tv = R->T->tv + 3 * (size_t)t;
    int32_t ia = tv[(jf + 1) % 3], ib = tv[(jf + 2) % 3];
    const double *a = fr_pt(R, ia), *b = fr_pt(R, ib);
    double c[2], m[2], nx, ny, len, p, q, rho, d, h;
    cvm__circumcenter2d(fr_pt(R, tv[0]), fr_pt(R, tv[1]), fr_pt(R, tv[2]), c);
    m[0] = (a[0] + b[0]) / 2;
    m[1] = (a[1] + b[1]) / 2;
    len = hypot(b[0] - a[0], b[1] - a[1]);
    if (!(len > 0) || !isfinite(c[0]) || !isfinite(c[1])) {
        return 0;
    }
    /* unit normal of a->b towards the apex (t is counter-clockwise) */
    nx = -(b[1] - a[1]) / len;
    ny = (b[0] - a[0]) / len;
    p = len / 2;
    q = (c[0] - m[0]) * nx + (c[1] - m[1]) * ny;
    h = (fr_size(R, ia) + fr_size(R, ib)) / 2;
    rho = h / 1.7320508075688772;
    if (!(rho >= p))
        rho = p;
    if (q > 0 && rho > (p * p + q * q) / (2 * q))
        rho = (p * p + q * q) / (2 * q);
    d = rho + sqrt(rho * rho > p * p ? rho * rho - p * p : 0);
    if (d > q + 0.5 * sqrt(p * p + q * q))
        d = q + 0.5 * sqrt(p * p + q * q);
    d *= cvm__rf_lattice_jitter(R->T->nv);
    x[0] = m[0] + d * nx;
    x[1] = m[1] + d * ny;
    return q > 0;
}

/* 1 when x is reached from triangle t by a visibility walk (exact orient2d)
 * that crosses no constrained edge and never leaves the domain: the point lies
 * on t's side of every segment, so inserting it splits no segment. */
static int fr_reachable(const cvm__refiner *R, int32_t t, const double *x)
{
    const cvm__tri2 *T = R->T;
    int32_t prev = -1;
    size_t steps = 0;
    for (;;) {
        const int32_t *tv = T->tv + 3 * (size_t)t;
        int k, moved = 0;
        if (++steps > T->nt + 3)
            return 0;
        for (k = 0; k < 3 && !moved; k++) {
            int j = (int)((k + steps) % 3);
            int32_t nb = T->tn[3 * (size_t)t + (size_t)j] / 3;
            if (nb == prev || cvm__orient2d(fr_pt(R, tv[(j + 1) % 3]), fr_pt(R, tv[(j + 2) % 3]), x) >= 0)
                continue;
            if (T->te[3 * (size_t)t + (size_t)j] >= 0 || !cvm__tri2_in_domain(T, nb))
                return 0;
            prev = t;
            t = nb;
            moved = 1;
        }
        if (!moved)
            return 1;
    }
}

static cvm_status fr_queue_all(cvm__refiner *R)
{
    size_t t;
    cvm_status s;
    cvm__bq_clear(&R->q);
    for (t = 0; t < R->T->nt; t++)
        if ((s = fr_queue_triangle(R, (int32_t)t)))
            return s;
    return CVM_OK;
}

static cvm_status fr_run(cvm__refiner *R)
{
    cvm__bad_entry e;
    cvm_status s;
    if ((s = fr_rec_reserve(R)) || (s = fr_queue_all(R)))
        return s;
    while (cvm__bq_pop(&R->q, &e)) {
        double key, x[2];
        int32_t v;
        int jf, r;
        if (!cvm__bq_valid(R->T, &e) || !fr_active(R, e.t, &jf, &key) ||
            cvm__rf_classify(R, e.t, &key) == 3)
            continue;
        if (!fr_point(R, e.t, jf, x))
            continue;
        /* a point beyond a segment is left to the clean-up pass: splitting the
         * segment where the walk meets it would not remove t */
        if (!isfinite(x[0]) || !isfinite(x[1]) || !fr_reachable(R, e.t, x))
            continue;
        r = cvm__rf_try_interior_point(R, e.t, x, &v, &s);
        if (s)
            return s;
        if (r == CVM__RF_DONE)
            s = fr_queue_star(R, v);
        if (!s)
            s = cvm__rf_split_queued(R);
        if (s)
            return s;
    }
    return CVM_OK;
}

cvm_status cvm__rf_frontal(cvm__refiner *R)
{
    cvm_status s;
    R->queue_star = fr_queue_star;
    s = fr_run(R);
    R->queue_star = cvm__rf_queue_star;
    cvm__free(R->ctx, R->fr_rec);
    R->fr_rec = NULL;
    R->cap_fr_rec = 0;
    return s;
}

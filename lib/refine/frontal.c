/* frontal.c - frontal-Delaunay refinement (Engwirda 2014): off-centres on the Voronoi edge of the shortest edge, grown from the boundary. */
#include <math.h>

#include "refine_internal.h"
#include "geom/geom_internal.h"

/* Too big: mean edge length above this times the mean size at the vertices. */
#define FR_SIZE_BAD 1.5
/* A bad triangle enters the queue only when its shortest edge is already
 * shorter than this times the size at that edge: the front. */
#define FR_ADMIT 1.5
/* The shape-optimal off-centre makes the apex angle the requested minimum
 * angle (|e| / (2 tan(alpha_min / 2)) from the edge), so the front may grow
 * by up to 1/(2 sin(alpha_min / 2)) per layer; below this angle it is not used. */
#define FR_SHAPE_MIN_DEG 1.0
/* Bisection tolerance of the size-optimal off-centre, relative to the edge. */
#define FR_BISECT_TOL 1e-4

static const double *fr_pt(const cvm__refiner *R, int32_t v)
{
    return R->T->xy + 2 * (size_t)v;
}

/* 1 when t is bad under the frontal rules and on the front; *key (shape,
 * worst first) and *jmin (its shortest edge) are set. */
static int fr_classify(cvm__refiner *R, int32_t t, double *key, int *jmin)
{
    const int32_t *tv = R->T->tv + 3 * (size_t)t;
    const double *p[3];
    double l[3], cross, sin2, ls, lse, mean;
    int k, bad, dr;
    for (k = 0; k < 3; k++)
        p[k] = fr_pt(R, tv[k]);
    for (k = 0; k < 3; k++) {
        const double *a = p[(k + 1) % 3], *b = p[(k + 2) % 3];
        l[k] = (a[0] - b[0]) * (a[0] - b[0]) + (a[1] - b[1]) * (a[1] - b[1]);
    }
    *jmin = l[0] <= l[1] && l[0] <= l[2] ? 0 : l[1] <= l[2] ? 1 : 2;
    cross = (p[1][0] - p[0][0]) * (p[2][1] - p[0][1]) - (p[1][1] - p[0][1]) * (p[2][0] - p[0][0]);
    dr = cvm__rf_classify(R, t, &sin2);
    if (dr == 3)
        return 0; /* subtended by a small input angle */
    sin2 = cross > 0 ? l[*jmin] * cross * cross / (l[0] * l[1] * l[2]) : 0.0;
    ls = (R->vls[tv[0]] + R->vls[tv[1]] + R->vls[tv[2]]) / 3;
    mean = (sqrt(l[0]) + sqrt(l[1]) + sqrt(l[2])) / 3;
    bad = dr != 0 || sin2 < R->sin2_min || (isfinite(ls) && mean > FR_SIZE_BAD * ls);
    if (!bad)
        return 0;
    lse = (R->vls[tv[(*jmin + 1) % 3]] + R->vls[tv[(*jmin + 2) % 3]]) / 2;
    if (isfinite(lse) && !(sqrt(l[*jmin]) < FR_ADMIT * lse))
        return 0;
    *key = sin2;
    return 1;
}

/* Queue domain triangle t if the front has reached it and it is bad. */
static cvm_status fr_queue_triangle(cvm__refiner *R, int32_t t)
{
    double key;
    int jmin;
    if (cvm__tri2_in_domain(R->T, t) && fr_classify(R, t, &key, &jmin) &&
        cvm__bq_push(&R->q, R->T, t, 0, key))
        return cvm__nomem(R->ctx);
    return CVM_OK;
}

static cvm_status fr_queue_star(cvm__refiner *R, int32_t v)
{
    size_t n = cvm__rf_star(R, v), k;
    cvm_status s;
    if (n == 0)
        return cvm__nomem(R->ctx);
    for (k = 0; k < n; k++)
        if ((s = fr_queue_triangle(R, R->star[k])))
            return s;
    return CVM_OK;
}

/* Distance along the bisector, from the midpoint m towards the circumcentre
 * (unit direction u, at distance dc), where the new edges reach the local
 * size: bisection to FR_BISECT_TOL x |e|. Returns dc when the size there is
 * still larger than the edges (or no sizing), and via *d. */
static cvm_status fr_size_optimal(cvm__refiner *R, const double *m, const double *u, double dc,
                                  double le, double *d)
{
    double lo = 0, hi = dc, h;
    cvm_status s;
    *d = dc;
    if (cvm__sizing_is_empty(R->p->sizing))
        return CVM_OK;
    if ((s = cvm__sizing_at(R->p->sizing, m[0] + dc * u[0], m[1] + dc * u[1], &h, R->ctx)))
        return s;
    if (sqrt(le * le / 4 + dc * dc) <= h)
        return CVM_OK;
    if ((s = cvm__sizing_at(R->p->sizing, m[0], m[1], &h, R->ctx)))
        return s;
    if (le / 2 >= h)
        return CVM_OK; /* the edge itself is already too long: no size-optimal point */
    while (hi - lo > FR_BISECT_TOL * le) {
        double mid = (lo + hi) / 2;
        if ((s = cvm__sizing_at(R->p->sizing, m[0] + mid * u[0], m[1] + mid * u[1], &h, R->ctx)))
            return s;
        if (sqrt(le * le / 4 + mid * mid) < h)
            lo = mid;
        else
            hi = mid;
    }
    *d = (lo + hi) / 2;
    return CVM_OK;
}

/* The Steiner point for t: on the Voronoi edge of its shortest edge jmin, the
 * one nearest that edge among the circumcentre, the shape-optimal and the
 * size-optimal off-centres. */
static cvm_status fr_point(cvm__refiner *R, int32_t t, int jmin, double *x)
{
    const int32_t *tv = R->T->tv + 3 * (size_t)t;
    const double *p = fr_pt(R, tv[(jmin + 1) % 3]), *q = fr_pt(R, tv[(jmin + 2) % 3]);
    double c[2], m[2], u[2], dc, le, d, ds;
    cvm_status s;
    cvm__circumcenter2d(fr_pt(R, tv[0]), fr_pt(R, tv[1]), fr_pt(R, tv[2]), c);
    m[0] = (p[0] + q[0]) / 2;
    m[1] = (p[1] + q[1]) / 2;
    u[0] = c[0] - m[0];
    u[1] = c[1] - m[1];
    dc = hypot(u[0], u[1]);
    le = hypot(q[0] - p[0], q[1] - p[1]);
    if (!(dc > 0) || !isfinite(dc)) {
        x[0] = c[0];
        x[1] = c[1];
        return CVM_OK;
    }
    u[0] /= dc;
    u[1] /= dc;
    d = dc;
    if (R->p->min_angle_deg >= FR_SHAPE_MIN_DEG) {
        ds = le / (2 * tan(R->p->min_angle_deg * 3.14159265358979323846 / 360.0));
        if (ds < d)
            d = ds;
    }
    if ((s = fr_size_optimal(R, m, u, dc, le, &ds)))
        return s;
    if (ds < d)
        d = ds;
    x[0] = m[0] + d * u[0];
    x[1] = m[1] + d * u[1];
    return CVM_OK;
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

cvm_status cvm__rf_frontal(cvm__refiner *R)
{
    cvm__bad_entry e;
    cvm_status s;
    R->queue_star = fr_queue_star;
    if ((s = fr_queue_all(R)))
        return s;
    while (cvm__bq_pop(&R->q, &e)) {
        double key, x[2];
        int32_t v;
        int jmin, r;
        if (!cvm__bq_valid(R->T, &e) || !fr_classify(R, e.t, &key, &jmin))
            continue;
        if ((s = fr_point(R, e.t, jmin, x)))
            return s;
        r = cvm__rf_insert_free(R, e.t, x, &v, &s);
        if (s)
            return s;
        if (r == CVM__RF_DONE)
            s = fr_queue_star(R, v);
        else if (r == CVM__RF_SPLIT && cvm__bq_valid(R->T, &e))
            s = cvm__bq_push(&R->q, R->T, e.t, e.cls, e.key) ? cvm__nomem(R->ctx) : CVM_OK;
        if (!s)
            s = cvm__rf_split_queued(R);
        if (s)
            return s;
    }
    R->queue_star = cvm__rf_queue_star;
    return CVM_OK;
}

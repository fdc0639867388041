/* delaunay_refine.c - Delaunay refinement (Ruppert 1995, Shewchuk 1997): circumcentres or off-centres of bad triangles, size problems first. */
#include <math.h>

#include "refine_internal.h"
#include "geom/geom_internal.h"
#include "geom/measure.h"

/* Size test of Delaunay refinement: a triangle is too big when its
 * circumradius exceeds the mean size at its three vertices times this. */
#define DR_SIZE_FACTOR 1.0
/* Miller-Pav-Walkington exemption (as Triangle): the two ends of the shortest
 * edge are this close to equidistant from the apex of a small input angle. */
#define DR_SHELL_TOL 0.001
/* How far along a re-discretised chain the join with another segment is
 * sought (dr_chain_join): the shells around a small angle halve their
 * radius each step, so 64 edges cover any range of doubles. */
#define DR_JOIN_STEPS 64
/* Input angles below this are "small" (cos 60 degrees = 0.5). */
#define DR_SMALL_ANGLE_COS 0.5
/* Ungor's off-centre (2004), as Triangle places it: on the bisector of the
 * shortest edge e, DR_OFFCENTRE x cot(theta/2) x |e| from its midpoint (0.5
 * would make the new triangle on e have exactly the bound theta at its apex;
 * 0.475 leaves it a degree or two above), used when nearer to e's ends than
 * the circumcentre (only for triangles below about theta/2). */
#define DR_OFFCENTRE 0.475

static const double *dr_pt(const cvm__refiner *R, int32_t v)
{
    return R->T->xy + 2 * (size_t)v;
}

/* Segment ids containing vertex u: its own segment for a vertex split onto
 * one, else the segments of the constrained edges at u (at most max). */
static size_t dr_segs_at(cvm__refiner *R, int32_t u, int32_t *out, size_t max)
{
    const cvm__tri2 *T = R->T;
    int32_t t0 = T->vtri[u], t = t0;
    size_t n = 0, steps = 0, k;
    if (R->vseg[u] >= 0) {
        out[0] = R->vseg[u];
        return 1;
    }
    if (t0 < 0)
        return 0;
    do {
        const int32_t *tv = T->tv + 3 * (size_t)t;
        int i = tv[0] == u ? 0 : tv[1] == u ? 1 : 2;
        int32_t seg = T->te[3 * (size_t)t + (size_t)(i + 2) % 3];
        if (seg >= 0 && n < max) {
            for (k = 0; k < n && out[k] != seg; k++)
                ;
            if (k == n)
                out[n++] = seg;
        }
        t = T->tn[3 * (size_t)t + (size_t)(i + 1) % 3] / 3;
    } while (t != t0 && ++steps <= T->nt);
    return n;
}

/* Where input segments s1 and s2 cross inside both (not at an end, decided
 * by exact orient2d): 1 and the point in *x. Crossing segments always meet at
 * a vertex of the mesh there (cvm_mesh_triangulate splits them with the same
 * cvm__segment_intersection2d), which is a join like a shared end. */
static int dr_crossing(const cvm__refiner *R, int32_t s1, int32_t s2, double *x)
{
    const double *p = dr_pt(R, R->seg_ends[2 * (size_t)s1]), *p2 = dr_pt(R, R->seg_ends[2 * (size_t)s1 + 1]);
    const double *q = dr_pt(R, R->seg_ends[2 * (size_t)s2]), *q2 = dr_pt(R, R->seg_ends[2 * (size_t)s2 + 1]);
    double a = cvm__orient2d(p, p2, q), b = cvm__orient2d(p, p2, q2);
    double c = cvm__orient2d(q, q2, p), d = cvm__orient2d(q, q2, p2);
    if (!((a > 0 && b < 0) || (a < 0 && b > 0)) || !((c > 0 && d < 0) || (c < 0 && d > 0)))
        return 0;
    cvm__segment_intersection2d(p, p2, q, q2, x);
    return 1;
}

/* An end of segment e1 lying in the interior of segment e2, exactly or within
 * the chain tolerance (cvm__rf_on_chain), or the other way round (a T-junction:
 * cvm_mesh_triangulate() makes it a vertex of the other's chain, or the
 * refiner routes the chain through it, so the two meet there as at a shared
 * end); else -1. */
static int32_t dr_end_on(const cvm__refiner *R, const int32_t *e1, const int32_t *e2)
{
    int k, side;
    for (side = 0; side < 2; side++) {
        const int32_t *e = side ? e2 : e1, *f = side ? e1 : e2;
        const double *p = dr_pt(R, f[0]), *q = dr_pt(R, f[1]);
        for (k = 0; k < 2; k++) {
            const double *x = dr_pt(R, e[k]);
            int i = p[0] != q[0] ? 0 : 1;
            if ((cvm__orient2d(p, q, x) == 0 && x[i] != p[i] && x[i] != q[i] &&
                 (x[i] > p[i]) != (x[i] > q[i])) ||
                cvm__rf_on_chain(p, q, x))
                return e[k];
        }
    }
    return -1;
}

/* The neighbour of x other than prev joined to it by a constrained edge of
 * segment seg (else -1); with mark >= 0, instead 1 when x has a constrained
 * edge of segment mark (else -1). */
static int32_t dr_chain_step(const cvm__refiner *R, int32_t x, int32_t prev, int32_t seg,
                             int32_t mark)
{
    const cvm__tri2 *T = R->T;
    int32_t t0 = T->vtri[x], t = t0;
    size_t steps = 0;
    if (t0 < 0)
        return -1;
    do {
        const int32_t *tv = T->tv + 3 * (size_t)t;
        int i = tv[0] == x ? 0 : tv[1] == x ? 1 : 2;
        int32_t e = T->te[3 * (size_t)t + (size_t)(i + 2) % 3], y = tv[(i + 1) % 3];
        if (mark >= 0 && e == mark)
            return 1;
        if (mark < 0 && e == seg && y >= 0 && y != prev)
            return y;
        t = T->tn[3 * (size_t)t + (size_t)(i + 1) % 3] / 3;
    } while (t != t0 && ++steps <= T->nt);
    return -1;
}

/* Where the chain of segment sa through u meets segment sb: the nearest vertex
 * along it (at most DR_JOIN_STEPS edges either way from u) with a constrained
 * edge of sb; -1 if none. For a chain re-discretised with
 * CVM_OPT_KEEP_SEGMENT_VERTICES = 0, whose input ends are gone, so that no
 * shared end or crossing can be computed from them. */
static int32_t dr_chain_join(const cvm__refiner *R, int32_t u, int32_t sa, int32_t sb)
{
    int32_t first = -1;
    int dir, k;
    for (dir = 0; dir < 2; dir++) {
        int32_t prev = u, x = dr_chain_step(R, u, first, sa, -1);
        if (dir == 0)
            first = x;
        for (k = 0; k < DR_JOIN_STEPS && x >= 0; k++) {
            int32_t next;
            if (dr_chain_step(R, x, -1, -1, sb) == 1)
                return x;
            next = dr_chain_step(R, x, prev, sa, -1);
            prev = x;
            x = next;
        }
    }
    return -1;
}

/* A skinny triangle whose shortest edge u-w joins two different segments that
 * meet at a small angle (at a shared end, an end on the other, or where they
 * cross), with u and w on the same concentric shell around the join, is not
 * split: splitting it
 * cannot help (Miller, Pav, Walkington 2003; Triangle's testtriangle, where a
 * crossing vertex also ends the pieces of both segments). */
static int dr_exempt(cvm__refiner *R, int32_t u, int32_t w)
{
    int32_t su[8], sw[8];
    size_t nu, nw, a, b;
    if (R->vseg[u] == -1 || R->vseg[w] == -1)
        return 0;
    nu = dr_segs_at(R, u, su, 8);
    nw = dr_segs_at(R, w, sw, 8);
    for (a = 0; a < nu; a++)
        for (b = 0; b < nw; b++)
            if (su[a] == sw[b])
                return 0;
    for (a = 0; a < nu; a++)
        for (b = 0; b < nw; b++) {
            const int32_t *e1 = R->seg_ends + 2 * (size_t)su[a], *e2 = R->seg_ends + 2 * (size_t)sw[b];
            int32_t J = (e1[0] >= 0 && (e1[0] == e2[0] || e1[0] == e2[1])) ? e1[0]
                      : (e1[1] >= 0 && (e1[1] == e2[0] || e1[1] == e2[1])) ? e1[1] : -1;
            const double *pj, *pu, *pw;
            double ux, uy, wx, wy, d1, d2, xc[2];
            if (J < 0 && e1[0] >= 0 && e1[1] >= 0 && e2[0] >= 0 && e2[1] >= 0)
                J = dr_end_on(R, e1, e2);
            if (J < 0 && (e1[0] < 0 || e1[1] < 0 || e2[0] < 0 || e2[1] < 0)) {
                /* a re-discretised chain: the input segment is gone, so the
                 * join with another input segment is found along the chains
                 * (a hull segment's meeting with a chain is no input angle) */
                if ((size_t)su[a] >= R->p->nseg || (size_t)sw[b] >= R->p->nseg)
                    continue;
                J = dr_chain_join(R, u, su[a], sw[b]);
                if (J < 0)
                    J = dr_chain_join(R, w, sw[b], su[a]);
                if (J < 0)
                    continue;
            }
            if (J >= 0)
                pj = dr_pt(R, J);
            else if (dr_crossing(R, su[a], sw[b], xc))
                pj = xc;
            else
                continue;
            pu = dr_pt(R, u);
            pw = dr_pt(R, w);
            ux = pu[0] - pj[0];
            uy = pu[1] - pj[1];
            wx = pw[0] - pj[0];
            wy = pw[1] - pj[1];
            d1 = ux * ux + uy * uy;
            d2 = wx * wx + wy * wy;
            if (d1 < (1 + DR_SHELL_TOL) * d2 && d1 > (1 - DR_SHELL_TOL) * d2 &&
                ux * wx + uy * wy > DR_SMALL_ANGLE_COS * sqrt(d1 * d2))
                return 1;
        }
    return 0;
}

/* cvm__rf_classify, also giving the squared shortest edge in *lmin_out. */
static int dr_classify(cvm__refiner *R, int32_t t, double *key_out, double *lmin_out)
{
    const int32_t *tv = R->T->tv + 3 * (size_t)t;
    const double *p0 = dr_pt(R, tv[0]), *p1 = dr_pt(R, tv[1]), *p2 = dr_pt(R, tv[2]);
    double l[3], cross, lmin, r2, ls, sin2;
    int jmin = 0, k;
    l[0] = cvm__dist2(p1, p2);
    l[1] = cvm__dist2(p2, p0);
    l[2] = cvm__dist2(p0, p1);
    cross = cvm__cross2(p0, p1, p2);
    for (k = 1; k < 3; k++)
        if (l[k] < l[jmin])
            jmin = k;
    lmin = l[jmin];
    *lmin_out = lmin;
    if (!(cross > 0)) {
        /* too thin for floating point: the worst shape there is */
        *key_out = 0;
        return dr_exempt(R, tv[(jmin + 1) % 3], tv[(jmin + 2) % 3]) ? 3 : 2;
    }
    r2 = cvm__circumradius2_sides(l[0], l[1], l[2], cross);
    ls = (R->vls[tv[0]] + R->vls[tv[1]] + R->vls[tv[2]]) / 3 * DR_SIZE_FACTOR;
    {
        double ratio = isfinite(ls) ? r2 / (ls * ls * R->size2) : 0;
        double ma = cvm__rf_max_area(R, t);
        if (ma > 0 && cross / 2 / ma > ratio)
            ratio = cross / 2 / ma;
        if (ratio > 1) {
            *key_out = -ratio;
            return 1;
        }
    }
    sin2 = cvm__min_sin2_sides(l[0], l[1], l[2], cross);
    *key_out = sin2;
    if (sin2 >= R->sin2_min)
        return 0;
    return dr_exempt(R, tv[(jmin + 1) % 3], tv[(jmin + 2) % 3]) ? 3 : 2;
}

int cvm__rf_classify(cvm__refiner *R, int32_t t, double *key_out)
{
    double lmin;
    return dr_classify(R, t, key_out, &lmin);
}

/* Queue domain triangle t if it is too large (class 0, largest ratio first)
 * or badly shaped (class 1, shortest shortest edge first).
 *
 * Why shortest edge first and not worst angle first: with the worst first,
 * circumcentres at 34 degrees cascade into ever smaller clusters on the
 * cylinder and the NACA 0012 (at h = 0.2 and with no size at all). Fixing
 * the finest triangles first lets the coarser ones around them be split once,
 * by a point that already fits the finer neighbourhood. With this order and
 * off-centres refinement terminates at 34 and 34.5 degrees on the example
 * domains (Triangle keys its queue by the shortest edge too). */
static cvm_status dr_queue_triangle(cvm__refiner *R, int32_t t)
{
    double key, lmin;
    int c;
    if (!cvm__tri2_in_domain(R->T, t))
        return CVM_OK;
    c = dr_classify(R, t, &key, &lmin);
    if ((c == 1 || c == 2) && cvm__bq_push(&R->q, R->T, t, c == 1 ? 0 : 1, c == 1 ? key : lmin))
        return cvm__nomem(R->ctx);
    return CVM_OK;
}

#if defined(__GNUC__) || defined(__clang__)
#  define dr_prefetch(p) __builtin_prefetch(p)
#else
#  define dr_prefetch(p) ((void)(p))
#endif

cvm_status cvm__rf_queue_star(cvm__refiner *R, int32_t v)
{
    size_t n = cvm__rf_star(R, v), k;
    cvm_status s;
    if (n == 0)
        return cvm__nomem(R->ctx);
    /* the sizes at the star's vertices are cold (the cavity search read only
     * coordinates): fetch them together rather than one miss per test */
    for (k = 0; k < n; k++) {
        const int32_t *tv = R->T->tv + 3 * (size_t)R->star[k];
        dr_prefetch(R->vls + (tv[1] >= 0 ? tv[1] : 0));
        dr_prefetch(R->vls + (tv[2] >= 0 ? tv[2] : 0));
    }
    for (k = 0; k < n; k++)
        if ((s = dr_queue_triangle(R, R->star[k])))
            return s;
    return CVM_OK;
}

/* Visibility walk from t towards x that stops at constrained edges. Returns
 * the triangle whose closed interior holds x with *seg_t = -1, or the
 * constrained edge (*seg_t, *seg_j) in the way (also when x lies on it);
 * -1 when x coincides with a vertex or the walk fails. */
static int32_t dr_walk(cvm__refiner *R, int32_t t, const double *x, int32_t *seg_t, int *seg_j)
{
    const cvm__tri2 *T = R->T;
    int32_t prev = -1;
    size_t steps = 0;
    *seg_t = -1;
    for (;;) {
        const int32_t *tv = T->tv + 3 * (size_t)t;
        double o[3];
        int k, moved = 0, zeros = 0, zj = 0;
        if (++steps > T->nt + 3)
            return -1;
        for (k = 0; k < 3; k++) {
            int j = (int)((k + steps) % 3);
            int32_t nb = T->tn[3 * (size_t)t + (size_t)j] / 3;
            o[j] = cvm__orient2d(dr_pt(R, tv[(j + 1) % 3]), dr_pt(R, tv[(j + 2) % 3]), x);
            if (o[j] >= 0 || nb == prev)
                continue;
            if (T->te[3 * (size_t)t + (size_t)j] >= 0) {
                *seg_t = t;
                *seg_j = j;
                return t;
            }
            if (!cvm__tri2_in_domain(T, nb))
                return -1;
            prev = t;
            t = nb;
            moved = 1;
            break;
        }
        if (moved)
            continue;
        for (k = 0; k < 3; k++) {
            if (!(o[k] > 0) && !(o[k] < 0)) {
                zeros++;
                zj = k;
            }
            if (o[k] < 0)
                return -1; /* only beyond the edge we came through: not convex here */
        }
        if (zeros >= 2)
            return -1;
        if (zeros == 1 && T->te[3 * (size_t)t + (size_t)zj] >= 0) {
            *seg_t = t;
            *seg_j = zj;
        }
        return t;
    }
}

/* Split the subsegments in R->enc (x encroached them); *split_any set when one was split. */
static cvm_status dr_split_encroached(cvm__refiner *R, int *split_any)
{
    size_t i, n = R->nenc, before = R->steiner;
    cvm_status s;
    for (i = 0; i < n; i++)
        if ((s = cvm__rf_segq_push(R, R->enc[3 * i], R->enc[3 * i + 1], R->enc[3 * i + 2])))
            return s;
    s = cvm__rf_split_queued(R);
    *split_any = R->steiner > before;
    return s;
}

int cvm__rf_try_interior_point(cvm__refiner *R, int32_t t, const double *x, int32_t *v_out,
                               cvm_status *s_out)
{
    cvm__tri2 *T = R->T;
    int32_t tc, st, v, other;
    int sj, split = 0;
    cvm__ins res;
    cvm_status s;
    *v_out = -1;
    *s_out = CVM_OK;
    if (!isfinite(x[0]) || !isfinite(x[1]))
        return CVM__RF_REJECT;
    tc = dr_walk(R, t, x, &st, &sj);
    if (tc < 0)
        return CVM__RF_REJECT;
    if (st >= 0) {
        const int32_t *tv = T->tv + 3 * (size_t)st;
        size_t before = R->steiner;
        if ((s = cvm__rf_segq_push(R, tv[(sj + 1) % 3], tv[(sj + 2) % 3],
                                   T->te[3 * (size_t)st + (size_t)sj])) ||
            (s = cvm__rf_split_queued(R))) {
            *s_out = s;
            return CVM__RF_SPLIT;
        }
        return R->steiner > before ? CVM__RF_SPLIT : CVM__RF_REJECT;
    }
    if ((s = cvm__rf_may_insert(R)) || (s = cvm__tri2_add_vertex(T, x, &v))) {
        *s_out = s == CVM_E_NOMEM ? cvm__nomem(R->ctx) : s;
        return CVM__RF_REJECT;
    }
    if ((s = cvm__rf_cavity_encroached(R, v, tc))) {
        T->nv--;
        *s_out = s;
        return CVM__RF_REJECT;
    }
    if (R->nenc) {
        T->nv--;
        *s_out = dr_split_encroached(R, &split);
        return split ? CVM__RF_SPLIT : CVM__RF_REJECT;
    }
    if (!T->w && st < 0) {
        /* x lies in tc off every constrained edge (dr_walk), so the cavity just
         * searched is the one insertion would search again */
        s = cvm__tri2_insert_in_cavity(T, v, R->cav, R->ncav);
        res = CVM__INS_DONE;
    } else {
        s = cvm__tri2_insert_vertex(T, v, tc, CVM__INSF_DOMAIN_ONLY, 0.0, &res, &other);
    }
    if (s || res != CVM__INS_DONE) {
        T->nv--;
        *s_out = s == CVM_E_NOMEM ? cvm__nomem(R->ctx) : s;
        return CVM__RF_REJECT;
    }
    *v_out = v;
    *s_out = cvm__rf_new_vertex(R, v, -1);
    return CVM__RF_DONE;
}

/* Distance factor of the off-centre (times |e|, from e's midpoint) for the
 * requested angle; 0 when there is no angle bound. */
static double dr_offcentre_factor(const cvm__refiner *R)
{
    double c = sqrt(1 - R->sin2_min); /* cos theta */
    if (!(R->sin2_min > 0))
        return 0;
    return DR_OFFCENTRE * sqrt((1 + c) / (1 - c)); /* cot(theta / 2) */
}

/* The Steiner point of bad triangle tv: its circumcentre, or the off-centre
 * on its shortest edge's bisector (factor koff) when that is nearer to the
 * edge's ends. */
static void dr_steiner_point(const cvm__refiner *R, const int32_t *tv, double koff, double *c)
{
    const double *p[3];
    const double *a, *b;
    double l[3], dx, dy, ox, oy;
    int j = 0, i;
    for (i = 0; i < 3; i++)
        p[i] = dr_pt(R, tv[i]);
    cvm__circumcenter2d(p[0], p[1], p[2], c);
    if (!(koff > 0))
        return;
    for (i = 0; i < 3; i++) {
        const double *u = p[(i + 1) % 3], *w = p[(i + 2) % 3];
        l[i] = (u[0] - w[0]) * (u[0] - w[0]) + (u[1] - w[1]) * (u[1] - w[1]);
        if (l[i] < l[j])
            j = i;
    }
    /* a, b, p[j] counter-clockwise: the apex side of a->b is its left */
    a = p[(j + 1) % 3];
    b = p[(j + 2) % 3];
    dx = b[0] - a[0];
    dy = b[1] - a[1];
    ox = 0.5 * dx - koff * dy;
    oy = 0.5 * dy + koff * dx;
    if (ox * ox + oy * oy < (c[0] - a[0]) * (c[0] - a[0]) + (c[1] - a[1]) * (c[1] - a[1])) {
        c[0] = a[0] + ox;
        c[1] = a[1] + oy;
    }
}

/* Queue every bad triangle of the domain with the current rules. */
static cvm_status dr_queue_all(cvm__refiner *R)
{
    size_t t;
    cvm_status s;
    cvm__bq_clear(&R->q);
    for (t = 0; t < R->T->nt; t++)
        if ((s = dr_queue_triangle(R, (int32_t)t)))
            return s;
    return CVM_OK;
}

cvm_status cvm__rf_delaunay(cvm__refiner *R)
{
    cvm__bad_entry e;
    cvm_status s;
    const double koff = dr_offcentre_factor(R);
    R->queue_star = cvm__rf_queue_star;
    if ((s = dr_queue_all(R)) || (s = cvm__rf_split_queued(R)))
        return s;
    while (cvm__bq_pop_valid(&R->q, R->T, R->vls, &e)) {
        const int32_t *tv;
        double key, c[2];
        int32_t v;
        int cls, r;
        cls = cvm__rf_classify(R, e.t, &key);
        if (cls != 1 && cls != 2)
            continue;
        tv = R->T->tv + 3 * (size_t)e.t;
        dr_steiner_point(R, tv, koff, c);
        r = cvm__rf_try_interior_point(R, e.t, c, &v, &s);
        if (s)
            return s;
        if (r == CVM__RF_DONE)
            s = cvm__rf_queue_star(R, v);
        else if (r == CVM__RF_SPLIT && cvm__bq_valid(R->T, &e))
            s = cvm__bq_push(&R->q, R->T, e.t, e.cls, e.key) ? cvm__nomem(R->ctx) : CVM_OK;
        if (!s)
            s = cvm__rf_split_queued(R);
        if (s)
            return s;
    }
    return CVM_OK;
}

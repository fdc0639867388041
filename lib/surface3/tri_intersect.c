/*
 * tri_intersect.c - exact intersection tests between closed triangles in 3D,
 * built on orient3d and on orient2d of the coordinate projections.
 *
 * Two triangles that share no corner must be disjoint. When they are not
 * coplanar, their intersection is a segment of the line where their planes
 * meet, whose endpoints lie on edges, so they meet exactly when an edge of one
 * meets the other; when coplanar the same holds in the plane. Triangles that
 * share a corner v meet beyond it exactly when their sectors at v overlap: a
 * far edge of one meets the other, or a side through v of one lies in the
 * other's plane inside its angle. Triangles that share an edge overlap only
 * when coplanar and folded onto the same side of it.
 */
#include "geom/geom_internal.h"
#include "surface3_internal.h"

static int sgn(double x)
{
    return (x > 0) - (x < 0);
}

static int o3(const double *a, const double *b, const double *c, const double *d)
{
    return sgn(cvm__orient3d(a, b, c, d));
}

/* orient2d of a, b, c projected along axis (dropping that coordinate). */
static int o2(const double *a, const double *b, const double *c, int axis)
{
    int u = axis == 0 ? 1 : 0, v = axis == 2 ? 1 : 2;
    double pa[2], pb[2], pc[2];
    pa[0] = a[u], pa[1] = a[v];
    pb[0] = b[u], pb[1] = b[v];
    pc[0] = c[u], pc[1] = c[v];
    return sgn(cvm__orient2d(pa, pb, pc));
}

/* An axis along which abc projects to a proper triangle, or -1 (collinear). */
static int proj_axis(const double *a, const double *b, const double *c)
{
    int k;
    for (k = 2; k >= 0; k--)
        if (o2(a, b, c, k) != 0)
            return k;
    return -1;
}

int cvm__collinear3(const double *a, const double *b, const double *c)
{
    return proj_axis(a, b, c) < 0;
}

/* p on the closed segment ab, all three collinear in the projection. */
static int on_segment(const double *p, const double *a, const double *b)
{
    int k;
    for (k = 0; k < 3; k++) {
        double lo = a[k] < b[k] ? a[k] : b[k], hi = a[k] < b[k] ? b[k] : a[k];
        if (p[k] < lo || p[k] > hi)
            return 0;
    }
    return 1;
}

/* Closed segments pq and rs, coplanar, meet (in projection axis). Collinear
 * points in a faithful projection are collinear in 3D, so the box test of
 * on_segment is exact. */
static int seg_seg_2d(const double *p, const double *q, const double *r, const double *s, int axis)
{
    int d1 = o2(p, q, r, axis), d2 = o2(p, q, s, axis);
    int d3 = o2(r, s, p, axis), d4 = o2(r, s, q, axis);
    if (d1 * d2 < 0 && d3 * d4 < 0)
        return 1;
    return (d1 == 0 && on_segment(r, p, q)) || (d2 == 0 && on_segment(s, p, q)) ||
           (d3 == 0 && on_segment(p, r, s)) || (d4 == 0 && on_segment(q, r, s));
}

static int point_in_tri_2d(const double *p, const double *a, const double *b, const double *c, int axis)
{
    int o = o2(a, b, c, axis);
    return o2(a, b, p, axis) * o >= 0 && o2(b, c, p, axis) * o >= 0 && o2(c, a, p, axis) * o >= 0;
}

/* Closed segment pq meets closed triangle abc (non-degenerate). */
static int seg_tri(const double *p, const double *q, const double *a, const double *b, const double *c)
{
    int sp = o3(a, b, c, p), sq = o3(a, b, c, q), s1, s2, s3;
    if (sp * sq > 0)
        return 0;
    if (sp == 0 && sq == 0) {
        int axis = proj_axis(a, b, c);
        return point_in_tri_2d(p, a, b, c, axis) || point_in_tri_2d(q, a, b, c, axis) ||
               seg_seg_2d(p, q, a, b, axis) || seg_seg_2d(p, q, b, c, axis) ||
               seg_seg_2d(p, q, c, a, axis);
    }
    /* the line pq crosses the plane within [p, q]: does it pass through abc? */
    s1 = o3(p, q, a, b);
    s2 = o3(p, q, b, c);
    s3 = o3(p, q, c, a);
    return (s1 >= 0 && s2 >= 0 && s3 >= 0) || (s1 <= 0 && s2 <= 0 && s3 <= 0);
}

/* x, coplanar with v, c, d, lies in the closed angle of the triangle vcd at v. */
static int in_sector(const double *v, const double *c, const double *d, const double *x)
{
    int axis = proj_axis(v, c, d);
    int o = o2(v, c, d, axis);
    return o2(v, c, x, axis) * o >= 0 && o2(v, x, d, axis) * o >= 0;
}

static int disjoint_general(const double *t[3], const double *u[3])
{
    int i, s0 = o3(t[0], t[1], t[2], u[0]), s1 = o3(t[0], t[1], t[2], u[1]),
           s2 = o3(t[0], t[1], t[2], u[2]);
    if ((s0 > 0 && s1 > 0 && s2 > 0) || (s0 < 0 && s1 < 0 && s2 < 0))
        return 1;
    for (i = 0; i < 3; i++)
        if (seg_tri(t[i], t[(i + 1) % 3], u[0], u[1], u[2]) || seg_tri(u[i], u[(i + 1) % 3], t[0], t[1], t[2]))
            return 0;
    return 1;
}

int cvm__tri_tri_improper(const double *a, const double *b, const double *c, const double *d,
                          const double *e, const double *f, const int32_t *iabc, const int32_t *idef)
{
    const double *t[3], *u[3];
    int i, j, shared = 0, ti = -1, uj = -1, ti2 = -1, uj2 = -1;
    t[0] = a, t[1] = b, t[2] = c;
    u[0] = d, u[1] = e, u[2] = f;
    for (i = 0; i < 3; i++)
        for (j = 0; j < 3; j++)
            if (iabc[i] == idef[j]) {
                if (shared == 0)
                    ti = i, uj = j;
                else
                    ti2 = i, uj2 = j;
                shared++;
            }
    if (shared == 0)
        return !disjoint_general(t, u);
    if (shared >= 3)
        return 1;
    if (shared == 2) {
        /* shared edge: improper only when coplanar and folded onto one side */
        const double *p = t[ti], *q = t[ti2], *x = t[3 - ti - ti2], *y = u[3 - uj - uj2];
        int axis;
        if (o3(p, q, x, y) != 0)
            return 0;
        axis = proj_axis(p, q, x);
        return o2(p, q, x, axis) * o2(p, q, y, axis) > 0;
    }
    {
        /* one shared corner v: t = v, t1, t2 and u = v, u1, u2 */
        const double *v = t[ti], *t1 = t[(ti + 1) % 3], *t2 = t[(ti + 2) % 3];
        const double *u1 = u[(uj + 1) % 3], *u2 = u[(uj + 2) % 3];
        if (seg_tri(t1, t2, u[0], u[1], u[2]) || seg_tri(u1, u2, t[0], t[1], t[2]))
            return 1;
        if ((o3(v, u1, u2, t1) == 0 && in_sector(v, u1, u2, t1)) ||
            (o3(v, u1, u2, t2) == 0 && in_sector(v, u1, u2, t2)) ||
            (o3(v, t1, t2, u1) == 0 && in_sector(v, t1, t2, u1)) ||
            (o3(v, t1, t2, u2) == 0 && in_sector(v, t1, t2, u2)))
            return 1;
        return 0;
    }
}

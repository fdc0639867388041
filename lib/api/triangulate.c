/* triangulate.c - cvm_mesh_triangulate (Delaunay / constrained Delaunay of the input), point insertion and checking. */
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "api_internal.h"
#include "geom/geom_internal.h"

/* Marker and attributes of Steiner vertices from..nv-1 created on segment k. */
static void steiner_data(cvm_mesh *m, size_t from, int32_t k)
{
    size_t v;
    for (v = from; v < m->tri.nv; v++)
        cvm__segment_vertex_data(m, v, k);
}

static size_t count_domain(const cvm__tri2 *T)
{
    size_t t, n = 0;
    for (t = 0; t < T->nt; t++)
        n += cvm__tri2_in_domain(T, (int32_t)t);
    return n;
}

/* Number naming input point i in messages (the file's, or i; i may be out of range). */
static long long point_num(const cvm_mesh *m, int32_t i)
{
    return i < 0 ? (long long)i : cvm__src_num(&m->in.src_point, (size_t)i);
}

static cvm_status check_segments(cvm_mesh *m)
{
    size_t k;
    for (k = 0; k < m->in.nseg; k++) {
        int32_t a = m->in.seg[2 * k], b = m->in.seg[2 * k + 1];
        char where[CVM__WHERE_LEN];
        if (a < 0 || b < 0 || (size_t)a >= m->in.np || (size_t)b >= m->in.np)
            return cvm__error(&m->ctx, CVM_E_INPUT_INDEX, CVM_ENT_INPUT_SEGMENT, (int64_t)k,
                              "%ssegment %lld (points %lld-%lld) names a point that does not exist "
                              "(there are %lu points)",
                              cvm__src_where(where, sizeof where, &m->in.src_segment, k),
                              cvm__src_num(&m->in.src_segment, k), point_num(m, a), point_num(m, b),
                              (unsigned long)m->in.np);
    }
    return CVM_OK;
}

static cvm_status recover_segments(cvm_mesh *m)
{
    cvm__tri2 *T = &m->tri;
    size_t k;
    int split = cvm__opt(m, CVM_OPT_SPLIT_INTERSECTIONS) != 0;
    cvm_status s;
    for (k = 0; k < m->in.nseg; k++) {
        int32_t ia = m->in.seg[2 * k], ib = m->in.seg[2 * k + 1];
        int32_t a = m->input_map[ia], b = m->input_map[ib], other = -1;
        size_t nv0 = T->nv;
        char where[CVM__WHERE_LEN], also[CVM__WHERE_LEN];
        const cvm__item_src *src = &m->in.src_segment;
        if (a == b)
            return cvm__error(&m->ctx, CVM_E_INPUT_DEGENERATE, CVM_ENT_INPUT_SEGMENT, (int64_t)k,
                              "%ssegment %lld (points %lld-%lld) has zero length%s",
                              cvm__src_where(where, sizeof where, src, k), cvm__src_num(src, k),
                              point_num(m, ia), point_num(m, ib),
                              ia == ib ? "" : ": its endpoints are at the same position");
        s = cvm__tri2_insert_segment(T, a, b, (int32_t)k, split, &other);
        if (s == CVM_E_INPUT_INTERSECTING) {
            const int32_t *o = m->in.seg + 2 * (size_t)other;
            return cvm__error(&m->ctx, s, CVM_ENT_INPUT_SEGMENT, (int64_t)k,
                              "%ssegment %lld (points %lld-%lld) crosses segment %lld%s (points "
                              "%lld-%lld) in its interior",
                              cvm__src_where(where, sizeof where, src, k), cvm__src_num(src, k),
                              point_num(m, ia), point_num(m, ib), cvm__src_num(src, (size_t)other),
                              cvm__src_also(also, sizeof also, src, (size_t)other, src),
                              point_num(m, o[0]), point_num(m, o[1]));
        }
        if (s == CVM_E_NOMEM)
            return cvm__nomem(&m->ctx);
        if (s)
            return s;
        if (T->nv > nv0) {
            if (cvm__grow_vertex_data(m))
                return cvm__nomem(&m->ctx);
            steiner_data(m, nv0, (int32_t)k);
        }
        s = cvm__tick(&m->ctx, 1, CVM_STAGE_RECOVER_SEGMENTS, (double)k / (double)m->in.nseg);
        if (s)
            return cvm__error(&m->ctx, s, CVM_ENT_NONE, -1, "%s during segment recovery; the mesh is empty",
                              s == CVM_INCOMPLETE_CANCELLED ? "cancelled" : "time limit reached");
    }
    return CVM_OK;
}

/* Locate a seed point: the domain triangle containing it, or -1 outside. */
int32_t cvm__mesh_seed_triangle(cvm_mesh *m, const double *p)
{
    int32_t t;
    int j;
    cvm__loc loc = cvm__tri2_locate(&m->tri, p, -1, &t, &j);
    if (loc == CVM__LOC_OUTSIDE || t < 0)
        return -1;
    return t;
}

/* A stop (time limit or cancellation) while carving: the caller drops the mesh. */
static cvm_status carve_stopped(cvm_mesh *m, cvm_status s, const char *what, size_t k, size_t n)
{
    return cvm__error(&m->ctx, s, CVM_ENT_NONE, -1,
                      "%s while carving (%s %lu of %lu); the mesh is empty",
                      s == CVM_INCOMPLETE_CANCELLED ? "cancelled" : "time limit reached", what,
                      (unsigned long)k + 1, (unsigned long)n);
}

/* Holes are carved one after another, as if each flooded the whole
 * triangulation afresh, but a triangle is visited by one hole at most (see
 * cvm__tri2_flood_out_more) and the domain is counted down rather than
 * recounted, so the work is linear in the triangles plus the walks that
 * locate the hole points (each starts where the previous one ended). */
static cvm_status carve_holes(cvm_mesh *m, size_t ndomain)
{
    cvm__tri2 *T = &m->tri;
    size_t k, visited = 0, removed = 0;
    cvm_status s = CVM_OK;
    for (k = 0; k < m->in.nholes && !s; k++) {
        const double *h = m->in.holes + 2 * k;
        int32_t t = cvm__mesh_seed_triangle(m, h);
        char where[CVM__WHERE_LEN];
        if (t < 0) {
            s = cvm__error(&m->ctx, CVM_E_INPUT_OUTSIDE, CVM_ENT_HOLE, (int64_t)k,
                           "%shole %lld at (%.17g, %.17g) lies outside the convex hull of the points",
                           cvm__src_where(where, sizeof where, &m->in.src_hole, k),
                           cvm__src_num(&m->in.src_hole, k), h[0], h[1]);
            break;
        }
        if (cvm__tri2_flood_out_more(T, t, &visited, &removed)) {
            s = cvm__nomem(&m->ctx);
            break;
        }
        ndomain -= removed;
        /* the flood stops only at segments: when it reached every triangle left,
           no closed loop of segments separates the hole from the rest (the hole
           lies in the outer region itself, or its own loop is open) */
        if (ndomain == 0) {
            s = cvm__error(&m->ctx, CVM_E_INPUT_NOT_CLOSED, CVM_ENT_HOLE, (int64_t)k,
                           "%shole %lld at (%.17g, %.17g) removed every remaining triangle: no "
                           "closed loop of segments separates it from the rest of the domain",
                           cvm__src_where(where, sizeof where, &m->in.src_hole, k),
                           cvm__src_num(&m->in.src_hole, k), h[0], h[1]);
            break;
        }
        if ((s = cvm__tick(&m->ctx, 1 + (int64_t)visited, CVM_STAGE_CARVE,
                           (double)k / (double)m->in.nholes)))
            s = carve_stopped(m, s, "hole", k, m->in.nholes);
    }
    cvm__tri2_clear_mark2(T);
    return s;
}

cvm_status cvm__mesh_carve(cvm_mesh *m)
{
    cvm__tri2 *T = &m->tri;
    size_t k, ndomain;
    int keep = cvm__opt(m, CVM_OPT_KEEP_CONVEX_HULL) != 0 || m->in.nseg == 0;
    cvm_status s = cvm__tri2_flood_out(T, NULL, 0, !keep);
    if (s)
        return cvm__nomem(&m->ctx);
    ndomain = count_domain(T);
    if (ndomain == 0)
        return cvm__error(&m->ctx, CVM_E_INPUT_NOT_CLOSED, CVM_ENT_NONE, -1,
                          "removing the exterior removed every triangle: the segments do not "
                          "enclose a region (open boundary)");
    if ((s = cvm__tick(&m->ctx, 1 + (int64_t)T->nt, CVM_STAGE_CARVE, 0.0)))
        return carve_stopped(m, s, "exterior", 0, 1);
    if (m->in.nholes && (s = carve_holes(m, ndomain)))
        return s;
    for (k = 0; k < m->in.nregions; k++) {
        const double *r = m->in.regions + 4 * k;
        int32_t t = cvm__mesh_seed_triangle(m, r);
        char where[CVM__WHERE_LEN];
        if (t < 0 || !cvm__tri2_in_domain(T, t))
            return cvm__error(&m->ctx, CVM_E_INPUT_OUTSIDE, CVM_ENT_REGION, (int64_t)k,
                              "%sregion %lld at (%.17g, %.17g) lies outside the domain",
                              cvm__src_where(where, sizeof where, &m->in.src_region, k),
                              cvm__src_num(&m->in.src_region, k), r[0], r[1]);
        if ((s = cvm__tri2_flood_attribute(T, t, r[2])))
            return cvm__nomem(&m->ctx);
        if ((s = cvm__tick(&m->ctx, 1, CVM_STAGE_CARVE, (double)k / (double)m->in.nregions)))
            return carve_stopped(m, s, "region", k, m->in.nregions);
    }
    return CVM_OK;
}

/* Vertices on constrained edges with marker 0 take the segment's marker. */
static void boundary_vertex_markers(cvm_mesh *m)
{
    const cvm__tri2 *T = &m->tri;
    size_t t;
    int j;
    if (!T->te)
        return;
    for (t = 0; t < T->nt; t++) {
        if (!cvm__tri2_in_domain(T, (int32_t)t))
            continue;
        for (j = 0; j < 3; j++) {
            int32_t seg = T->te[3 * t + j];
            int k;
            if (seg < 0)
                continue;
            for (k = 1; k <= 2; k++) {
                int32_t v = T->tv[3 * t + (j + k) % 3];
                if (m->vmark[v] == 0)
                    m->vmark[v] = cvm__segment_marker(m, seg);
            }
        }
    }
}

/* The exact predicates work on double expansions, whose error-free
 * transformations fail when a product underflows: with every coordinate
 * rescaled (by a power of two) near the largest one, a nonzero coordinate more
 * than 2^180 times smaller than the largest could make a product of four of
 * them underflow. Such input is refused rather than decided inexactly. */
static cvm_status check_dynamic_range(cvm_mesh *m)
{
    const double *xy = m->in.xy;
    size_t i, n = 2 * m->in.np;
    double big = 0, lim;
    for (i = 0; i < n; i++)
        big = fabs(xy[i]) > big ? fabs(xy[i]) : big;
    lim = ldexp(big, -180);
    for (i = 0; i < n; i++) {
        double a = fabs(xy[i]);
        char where[CVM__WHERE_LEN];
        if (a != 0 && a < lim)
            return cvm__error(&m->ctx, CVM_E_INPUT_DEGENERATE, CVM_ENT_INPUT_POINT, (int64_t)(i / 2),
                              "%spoint %lld has %c = %.17g, more than 2^180 times smaller than the "
                              "largest coordinate %.17g: exact predicates cannot span that range; "
                              "round it to 0 or translate the input",
                              cvm__src_where(where, sizeof where, &m->in.src_point, i / 2),
                              point_num(m, (int32_t)(i / 2)), i % 2 ? 'y' : 'x', xy[i], big);
    }
    return CVM_OK;
}

static cvm_status check_segment_chains(cvm_mesh *m);

static cvm_status triangulate(cvm_mesh *m)
{
    cvm__tri2 *T = &m->tri;
    size_t i, n = m->in.np, na = m->in.nattr;
    int32_t *dup_of = NULL;
    cvm_status s;

    if ((s = check_segments(m)) || (s = check_dynamic_range(m)))
        return s;
    if ((s = cvm__tri2_reserve_vertices(T, n)))
        return s == CVM_E_NOMEM ? cvm__nomem(&m->ctx) : cvm__error(&m->ctx, s, CVM_ENT_NONE, -1, "too many points");
    for (i = 0; i < n; i++) {
        int32_t id;
        if ((s = cvm__tri2_add_vertex(T, m->in.xy + 2 * i, &id)))
            return cvm__nomem(&m->ctx);
    }
    dup_of = cvm__malloc(&m->ctx, n * sizeof *dup_of);
    m->input_map = cvm__malloc(&m->ctx, n * sizeof *m->input_map);
    if (!dup_of || !m->input_map) {
        cvm__free(&m->ctx, dup_of);
        return cvm__nomem(&m->ctx);
    }
    s = cvm__tri2_build(T, (uint64_t)cvm__opt(m, CVM_OPT_SEED), dup_of);
    if (s) {
        cvm__free(&m->ctx, dup_of);
        return s;
    }
    m->n_dup = 0;
    for (i = 0; i < n; i++) {
        if (dup_of[i] < 0)
            continue;
        if (cvm__opt(m, CVM_OPT_REJECT_DUPLICATES) != 0) {
            const cvm__item_src *src = &m->in.src_point;
            char where[CVM__WHERE_LEN], also[CVM__WHERE_LEN];
            s = cvm__error(&m->ctx, CVM_E_INPUT_DUPLICATE, CVM_ENT_INPUT_POINT, (int64_t)i,
                           "%spoint %lld at (%.17g, %.17g) duplicates point %lld%s",
                           cvm__src_where(where, sizeof where, src, i), point_num(m, (int32_t)i),
                           m->in.xy[2 * i], m->in.xy[2 * i + 1], point_num(m, dup_of[i]),
                           cvm__src_also(also, sizeof also, src, (size_t)dup_of[i], src));
            cvm__free(&m->ctx, dup_of);
            return s;
        }
        m->n_dup++;
    }
    cvm__tri2_compact(T, dup_of, m->input_map);
    cvm__free(&m->ctx, dup_of);
    if (cvm__grow_vertex_data(m))
        return cvm__nomem(&m->ctx);
    /* first occurrences win: write them last */
    for (i = n; i-- > 0;) {
        int32_t v = m->input_map[i];
        size_t k;
        m->vmark[v] = m->in.pmark ? m->in.pmark[i] : 0;
        for (k = 0; k < na; k++)
            m->vattr[(size_t)v * na + k] = m->in.pattr[i * na + k];
    }
    if (m->in.nseg) {
        if ((s = recover_segments(m)))
            return s;
    }
    if (m->in.nseg || m->in.nholes || m->in.nregions) {
        if ((s = cvm__mesh_carve(m)))
            return s;
    }
    boundary_vertex_markers(m);
    /* post-condition, linear in the mesh: never report success on a mesh
     * that cvm_mesh_check() rejects for a missing segment */
    return check_segment_chains(m);
}

cvm_status cvm_mesh_triangulate(cvm_mesh *m)
{
    cvm_status s;
    if (!m)
        return CVM_E_NULL_ARG;
    CVM__BEGIN(m);
    cvm__mesh_drop_output(m);
    if (m->in.np == 0)
        return cvm__error(&m->ctx, CVM_E_INPUT_EMPTY, CVM_ENT_INPUT_POINT, -1, "no input points");
    cvm__run_begin(&m->ctx, cvm__opt(m, CVM_OPT_TIME_LIMIT_S));
    s = triangulate(m);
    if (s) {
        cvm__mesh_drop_output(m);
        return s;
    }
    m->triangulated = 1;
    m->nv_triangulated = m->tri.nv;
    return CVM_OK;
}

cvm_status cvm_mesh_insert_points(cvm_index *ids_out, cvm_mesh *m, const double *xy, size_t count,
                                  double min_dist)
{
    cvm__tri2 *T;
    size_t i;
    cvm_status s = CVM_OK;
    if (!m)
        return CVM_E_NULL_ARG;
    CVM__BEGIN(m);
    cvm__mesh_forget_layers(m);
    T = &m->tri;
    if (!xy && count > 0)
        return cvm__error(&m->ctx, CVM_E_NULL_ARG, CVM_ENT_NONE, -1, "xy is NULL");
    if (!m->triangulated)
        return cvm__error(&m->ctx, CVM_E_STATE, CVM_ENT_NONE, -1,
                          "no triangulation: call cvm_mesh_triangulate() first");
    if (!isfinite(min_dist))
        return cvm__error(&m->ctx, CVM_E_INPUT_NONFINITE, CVM_ENT_NONE, -1, "min_dist is not finite");
    if (min_dist < 0)
        return cvm__error(&m->ctx, CVM_E_ARGUMENT, CVM_ENT_NONE, -1, "min_dist %.17g is negative",
                          min_dist);
    for (i = 0; i < 2 * count; i++)
        if (!isfinite(xy[i]))
            return cvm__error(&m->ctx, CVM_E_INPUT_NONFINITE, CVM_ENT_INPUT_POINT, (int64_t)(i / 2),
                              "point %lu has a non-finite %c", (unsigned long)(i / 2),
                              i % 2 ? 'y' : 'x');
    if (ids_out)
        for (i = 0; i < count; i++)
            ids_out[i] = CVM_REJECTED;
    cvm__run_begin(&m->ctx, cvm__opt(m, CVM_OPT_TIME_LIMIT_S));
    for (i = 0; i < count; i++) {
        int32_t v, other;
        cvm__ins res;
        if ((s = cvm__tri2_add_vertex(T, xy + 2 * i, &v)))
            return s == CVM_E_NOMEM ? cvm__nomem(&m->ctx)
                                    : cvm__error(&m->ctx, s, CVM_ENT_INPUT_POINT, (int64_t)i, "too many vertices");
        if (cvm__grow_vertex_data(m)) {
            T->nv--;
            return cvm__nomem(&m->ctx);
        }
        s = cvm__tri2_insert_vertex(T, v, T->last, CVM__INSF_DOMAIN_ONLY, min_dist, &res, &other);
        if (s) {
            T->nv--;
            return s == CVM_E_NOMEM ? cvm__nomem(&m->ctx)
                                    : cvm__error(&m->ctx, s, CVM_ENT_INPUT_POINT, (int64_t)i,
                                                 "inserting point %lu failed", (unsigned long)i);
        }
        if (res != CVM__INS_DONE) {
            T->nv--;
            continue;
        }
        m->vmark[v] = 0;
        if (m->in.nattr)
            memset(m->vattr + (size_t)v * m->in.nattr, 0, m->in.nattr * sizeof(double));
        if (ids_out)
            ids_out[i] = v;
        s = cvm__tick(&m->ctx, 1, CVM_STAGE_INSERT, (double)i / (double)count);
        if (s)
            return cvm__error(&m->ctx, s, CVM_ENT_INPUT_POINT, (int64_t)i,
                              "%s after point %lu; points after it were not inserted",
                              s == CVM_INCOMPLETE_CANCELLED ? "cancelled" : "time limit reached",
                              (unsigned long)i);
    }
    return CVM_OK;
}

/* Whether x may be an inner vertex of the chain of segment a-b: within
 * CVM__CHAIN_SLACK x (M + L) of the segment, M the largest absolute
 * coordinate of a and b, L the length (the rule stated at cvm_mesh_check()).
 * A crossing point is rounded at the scale of M, not of L: segments of length
 * 0.01 near 1e6 put it 1e-8 of L off. Labels are not consulted: an edge
 * stores one segment index, so a piece two segments share, exactly or within
 * rounding, carries only one of them. This is a check of the output, with a
 * stated tolerance; no meshing decision depends on it. */
#define CVM__CHAIN_SLACK 0x1p-40
static int on_chain(const cvm__tri2 *T, int32_t x, int32_t a, int32_t b)
{
    const double *pa = T->xy + 2 * (size_t)a, *pb = T->xy + 2 * (size_t)b, *px = T->xy + 2 * (size_t)x;
    double dx = pb[0] - pa[0], dy = pb[1] - pa[1], len = sqrt(dx * dx + dy * dy);
    double mag = fmax(fmax(fabs(pa[0]), fabs(pa[1])), fmax(fabs(pb[0]), fabs(pb[1])));
    double tol = CVM__CHAIN_SLACK * (mag + len), along;
    if (x == b)
        return 1;
    if (!(len > 0))
        return 0;
    along = ((px[0] - pa[0]) * dx + (px[1] - pa[1]) * dy) / len;
    if (!(along >= -tol && along <= len + tol))
        return 0;
    /* distance x length in plain floating point: its rounding error, about
     * 2^-51 L |x - a|, is far below the tolerance 2^-40 (M + L) L */
    return fabs(dx * (px[1] - pa[1]) - dy * (px[0] - pa[0])) <= tol * len;
}

/* Every input segment must be joined end to end by constrained edges through
 * vertices that on_chain() accepts. A breadth-first search per segment visits
 * each vertex at most once (seen[] holds the last segment that queued it), so
 * the check costs the stars of the chain vertices: linear in the mesh unless
 * many segments overlap. cvm_mesh_triangulate() runs it as its post-condition. */
static cvm_status check_segment_chains(cvm_mesh *m)
{
    cvm__tri2 *T = &m->tri;
    size_t k;
    int32_t *seen;
    cvm_status s = CVM_OK;
    if (!m->in.nseg)
        return CVM_OK;
    seen = cvm__malloc(&m->ctx, (T->nv ? T->nv : 1) * sizeof *seen);
    if (!seen)
        return cvm__nomem(&m->ctx);
    for (k = 0; k < T->nv; k++)
        seen[k] = -1;
    for (k = 0; k < m->in.nseg && !s; k++) {
        int32_t a = m->input_map[m->in.seg[2 * k]], b = m->input_map[m->in.seg[2 * k + 1]];
        size_t n = 0, head = 0;
        int found = a == b;
        if (a < 0 || b < 0)
            continue; /* an end removed by CVM_OPT_KEEP_SEGMENT_VERTICES = 0: the chain was
                         re-discretised, its pieces are checked as constrained edges */
        if (cvm__grow(T->ctx, (void **)&T->stack, &T->cap_stack, 1, sizeof(int32_t))) {
            s = cvm__nomem(&m->ctx);
            break;
        }
        T->stack[n++] = a;
        seen[a] = (int32_t)k;
        while (head < n && !found && !s) {
            int32_t cur = T->stack[head++], t0 = T->vtri[cur], t = t0;
            if (t0 < 0)
                continue;
            do {
                const int32_t *v = T->tv + 3 * (size_t)t;
                int i = v[0] == cur ? 0 : v[1] == cur ? 1 : 2;
                int32_t x = v[(i + 1) % 3], seg = cvm__tri2_edge_seg(T, t, (i + 2) % 3);
                t = T->tn[3 * (size_t)t + (i + 1) % 3] / 3;
                if (x < 0 || seg < 0 || seen[x] == (int32_t)k || !on_chain(T, x, a, b))
                    continue;
                if (x == b)
                    found = 1;
                if (n + 1 > T->cap_stack &&
                    cvm__grow(T->ctx, (void **)&T->stack, &T->cap_stack, n + 1, sizeof(int32_t))) {
                    s = cvm__nomem(&m->ctx);
                    break;
                }
                seen[x] = (int32_t)k;
                T->stack[n++] = x;
            } while (t != t0);
        }
        if (!found && !s)
            s = cvm__error(&m->ctx, CVM_E_INTERNAL, CVM_ENT_INPUT_SEGMENT, (int64_t)k,
                              "check failed: input segment %lu (points %ld-%ld) is not joined end "
                              "to end by constrained edges",
                              (unsigned long)k, (long)m->in.seg[2 * k], (long)m->in.seg[2 * k + 1]);
    }
    cvm__free(&m->ctx, seen);
    return s;
}

cvm_status cvm_mesh_check(cvm_mesh *m)
{
    const cvm__tri2 *T;
    size_t t;
    int j;
    cvm_status s;
    if (!m)
        return CVM_E_NULL_ARG;
    CVM__BEGIN(m);
    if (!m->triangulated)
        return cvm__error(&m->ctx, CVM_E_STATE, CVM_ENT_NONE, -1, "nothing triangulated");
    if ((s = cvm__tri2_check(&m->tri)) || (s = check_segment_chains(m)))
        return s;
    T = &m->tri;
    /* the domain is bounded by constrained edges or by the convex hull */
    for (t = 0; t < T->nt; t++) {
        if (!cvm__tri2_in_domain(T, (int32_t)t))
            continue;
        for (j = 0; j < 3; j++) {
            int32_t u = T->tn[3 * t + j] / 3;
            if (cvm__tri2_in_domain(T, u) || cvm__tri2_edge_seg(T, (int32_t)t, j) >= 0)
                continue;
            if (cvm__tri2_is_ghost(T, u) && (m->in.nseg == 0 || cvm__opt(m, CVM_OPT_KEEP_CONVEX_HULL) != 0))
                continue;
            return cvm__error(&m->ctx, CVM_E_INTERNAL, CVM_ENT_TRIANGLE, (int64_t)t,
                              "check failed: triangle slot %lu borders the outside across an "
                              "unconstrained edge",
                              (unsigned long)t);
        }
    }
    return CVM_OK;
}

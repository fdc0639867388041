/* pslg_build.c - a planar straight-line graph to its constrained triangulation: points, segments, carving, markers. */
#include <math.h>
#include <string.h>

#include "delaunay_internal.h"

static cvm_status fault_at(cvm__cdt_fault *f, cvm_status s, cvm__cdt_fault_kind kind, size_t item,
                           size_t other)
{
    f->kind = kind;
    f->item = item;
    f->other = other;
    return s;
}

int32_t cvm__cdt_segment_marker(const int32_t *smark, size_t nseg, int32_t seg)
{
    if (seg < 0 || (size_t)seg >= nseg)
        return 0;
    return smark ? smark[seg] : 1;
}

void cvm__cdt_segment_point(const cvm__cdt_input *in, const double *p, int32_t seg, int32_t *mark,
                            double *attr)
{
    size_t na = in->nattr, i;
    const int32_t *s;
    const double *pa, *pb;
    double len2, t;
    *mark = cvm__cdt_segment_marker(in->smark, in->nseg, seg);
    if (seg < 0 || (size_t)seg >= in->nseg)
        return; /* a convex-hull segment: marker 0, attributes as they are */
    s = in->seg + 2 * (size_t)seg;
    pa = in->xy + 2 * (size_t)s[0];
    pb = in->xy + 2 * (size_t)s[1];
    len2 = (pb[0] - pa[0]) * (pb[0] - pa[0]) + (pb[1] - pa[1]) * (pb[1] - pa[1]);
    t = len2 > 0 ? ((p[0] - pa[0]) * (pb[0] - pa[0]) + (p[1] - pa[1]) * (pb[1] - pa[1])) / len2 : 0;
    t = t < 0 ? 0 : t > 1 ? 1 : t;
    for (i = 0; i < na; i++)
        attr[i] = (1 - t) * in->pattr[(size_t)s[0] * na + i] + t * in->pattr[(size_t)s[1] * na + i];
}

/* Grow out's per-vertex arrays to T's vertex count (new entries uninitialised). */
static cvm_status grow_vertex_data(const cvm__tri2 *T, size_t na, cvm__cdt_out *out)
{
    size_t nv = T->nv;
    if (nv > out->cap_vmark &&
        cvm__grow(T->ctx, (void **)&out->vmark, &out->cap_vmark, nv, sizeof(int32_t)))
        return CVM_E_NOMEM;
    if (na && nv * na > out->cap_vattr &&
        cvm__grow(T->ctx, (void **)&out->vattr, &out->cap_vattr, nv * na, sizeof(double)))
        return CVM_E_NOMEM;
    return CVM_OK;
}

/* The exact predicates work on double expansions, whose error-free
 * transformations fail when a product underflows: with every coordinate
 * rescaled (by a power of two) near the largest one, a nonzero coordinate more
 * than 2^180 times smaller than the largest could make a product of four of
 * them underflow. Such input is refused rather than decided inexactly. */
static cvm_status check_dynamic_range(const cvm__cdt_input *in, cvm__cdt_fault *f)
{
    const double *xy = in->xy;
    size_t i, n = 2 * in->np;
    double big = 0, lim;
    for (i = 0; i < n; i++)
        big = fabs(xy[i]) > big ? fabs(xy[i]) : big;
    lim = ldexp(big, -180);
    for (i = 0; i < n; i++) {
        double a = fabs(xy[i]);
        if (a != 0 && a < lim) {
            f->axis = (int)(i % 2);
            f->big = big;
            return fault_at(f, CVM_E_INPUT_DEGENERATE, CVM__CDT_FAULT_RANGE, i / 2, 0);
        }
    }
    return CVM_OK;
}

/* The points as vertices: the Delaunay triangulation of the distinct ones,
 * input_map, markers and attributes (first occurrences win). */
static cvm_status add_points(cvm__tri2 *T, const cvm__cdt_input *in, cvm__cdt_out *out,
                             cvm__cdt_fault *f)
{
    size_t i, n = in->np, na = in->nattr;
    int32_t *dup_of;
    cvm_status s;
    if ((s = cvm__tri2_reserve_vertices(T, n)))
        return s == CVM_E_NOMEM ? cvm__nomem(T->ctx) : cvm__error(T->ctx, s, CVM_ENT_NONE, -1, "too many points");
    for (i = 0; i < n; i++) {
        int32_t id;
        if (cvm__tri2_add_vertex(T, in->xy + 2 * i, &id))
            return cvm__nomem(T->ctx);
    }
    cvm__free(T->ctx, out->input_map);
    dup_of = cvm__malloc(T->ctx, n * sizeof *dup_of);
    out->input_map = cvm__malloc(T->ctx, n * sizeof *out->input_map);
    if (!dup_of || !out->input_map) {
        cvm__free(T->ctx, dup_of);
        return cvm__nomem(T->ctx);
    }
    if ((s = cvm__tri2_build(T, in->seed, dup_of))) {
        cvm__free(T->ctx, dup_of);
        return s;
    }
    out->n_dup = 0;
    for (i = 0; i < n; i++) {
        if (dup_of[i] < 0)
            continue;
        if (in->reject_duplicates) {
            s = fault_at(f, CVM_E_INPUT_DUPLICATE, CVM__CDT_FAULT_DUPLICATE, i, (size_t)dup_of[i]);
            cvm__free(T->ctx, dup_of);
            return s;
        }
        out->n_dup++;
    }
    cvm__tri2_compact(T, dup_of, out->input_map);
    cvm__free(T->ctx, dup_of);
    if (grow_vertex_data(T, na, out))
        return cvm__nomem(T->ctx);
    /* first occurrences win: write them last */
    for (i = n; i-- > 0;) {
        int32_t v = out->input_map[i];
        size_t k;
        out->vmark[v] = in->pmark ? in->pmark[i] : 0;
        for (k = 0; k < na; k++)
            out->vattr[(size_t)v * na + k] = in->pattr[i * na + k];
    }
    return CVM_OK;
}

static cvm_status recover_segments(cvm__tri2 *T, const cvm__cdt_input *in, cvm__cdt_out *out,
                                   cvm__cdt_fault *f)
{
    size_t k, na = in->nattr;
    cvm_status s;
    for (k = 0; k < in->nseg; k++) {
        int32_t ia = in->seg[2 * k], ib = in->seg[2 * k + 1];
        int32_t a = out->input_map[ia], b = out->input_map[ib], other = -1;
        size_t nv0 = T->nv, v;
        if (a == b)
            return fault_at(f, CVM_E_INPUT_DEGENERATE, CVM__CDT_FAULT_ZERO_LENGTH, k, 0);
        s = cvm__tri2_insert_segment(T, a, b, (int32_t)k, in->split, &other);
        if (s == CVM_E_INPUT_INTERSECTING)
            return fault_at(f, s, CVM__CDT_FAULT_CROSSING, k, (size_t)other);
        if (s == CVM_E_NOMEM)
            return cvm__nomem(T->ctx);
        if (s)
            return s;
        if (T->nv > nv0) { /* crossings split: the new vertices lie on segment k */
            if (grow_vertex_data(T, na, out))
                return cvm__nomem(T->ctx);
            for (v = nv0; v < T->nv; v++)
                cvm__cdt_segment_point(in, T->xy + 2 * v, (int32_t)k, out->vmark + v,
                                       na ? out->vattr + v * na : NULL);
        }
        s = cvm__tick(T->ctx, 1, CVM_STAGE_RECOVER_SEGMENTS, (double)k / (double)in->nseg);
        if (s)
            return cvm__error(T->ctx, s, CVM_ENT_NONE, -1, "%s during segment recovery; the mesh is empty",
                              s == CVM_INCOMPLETE_CANCELLED ? "cancelled" : "time limit reached");
    }
    return CVM_OK;
}

static size_t count_domain(const cvm__tri2 *T)
{
    size_t t, n = 0;
    for (t = 0; t < T->nt; t++)
        n += cvm__tri2_in_domain(T, (int32_t)t);
    return n;
}

/* The domain triangle holding p (a hole or region seed), or -1 outside the hull. */
static int32_t seed_triangle(cvm__tri2 *T, const double *p)
{
    int32_t t;
    int j;
    cvm__loc loc = cvm__tri2_locate(T, p, -1, &t, &j);
    if (loc == CVM__LOC_OUTSIDE || t < 0)
        return -1;
    return t;
}

/* A stop (time limit or cancellation) while carving: the caller drops the mesh. */
static cvm_status carve_stopped(cvm__ctx *ctx, cvm_status s, const char *what, size_t k, size_t n)
{
    return cvm__error(ctx, s, CVM_ENT_NONE, -1, "%s while carving (%s %lu of %lu); the mesh is empty",
                      s == CVM_INCOMPLETE_CANCELLED ? "cancelled" : "time limit reached", what,
                      (unsigned long)k + 1, (unsigned long)n);
}

/* Holes are carved one after another, as if each flooded the whole
 * triangulation afresh, but a triangle is visited by one hole at most (see
 * cvm__tri2_flood_out_more) and the domain is counted down rather than
 * recounted, so the work is linear in the triangles plus the walks that
 * locate the hole points (each starts where the previous one ended). */
static cvm_status carve_holes(cvm__tri2 *T, const cvm__cdt_input *in, size_t ndomain,
                              cvm__cdt_fault *f)
{
    size_t k, visited = 0, removed = 0;
    cvm_status s = CVM_OK;
    for (k = 0; k < in->nholes && !s; k++) {
        int32_t t = seed_triangle(T, in->holes + 2 * k);
        if (t < 0) {
            s = fault_at(f, CVM_E_INPUT_OUTSIDE, CVM__CDT_FAULT_HOLE_OUTSIDE, k, 0);
            break;
        }
        if (cvm__tri2_flood_out_more(T, t, &visited, &removed)) {
            s = cvm__nomem(T->ctx);
            break;
        }
        ndomain -= removed;
        /* the flood stops only at segments: when it reached every triangle left,
           no closed loop of segments separates the hole from the rest (the hole
           lies in the outer region itself, or its own loop is open) */
        if (ndomain == 0) {
            s = fault_at(f, CVM_E_INPUT_NOT_CLOSED, CVM__CDT_FAULT_HOLE_ALL, k, 0);
            break;
        }
        if ((s = cvm__tick(T->ctx, 1 + (int64_t)visited, CVM_STAGE_CARVE, (double)k / (double)in->nholes)))
            s = carve_stopped(T->ctx, s, "hole", k, in->nholes);
    }
    cvm__tri2_clear_mark2(T);
    return s;
}

cvm_status cvm__cdt_carve(cvm__tri2 *T, const cvm__cdt_input *in, cvm__cdt_fault *f)
{
    size_t k, ndomain;
    int keep = in->keep_hull || in->nseg == 0;
    cvm_status s = cvm__tri2_flood_out(T, NULL, 0, !keep);
    f->kind = CVM__CDT_FAULT_NONE;
    if (s)
        return cvm__nomem(T->ctx);
    ndomain = count_domain(T);
    if (ndomain == 0)
        return cvm__error(T->ctx, CVM_E_INPUT_NOT_CLOSED, CVM_ENT_NONE, -1,
                          "removing the exterior removed every triangle: the segments do not "
                          "enclose a region (open boundary)");
    if ((s = cvm__tick(T->ctx, 1 + (int64_t)T->nt, CVM_STAGE_CARVE, 0.0)))
        return carve_stopped(T->ctx, s, "exterior", 0, 1);
    if (in->nholes && (s = carve_holes(T, in, ndomain, f)))
        return s;
    for (k = 0; k < in->nregions; k++) {
        const double *r = in->regions + 4 * k;
        int32_t t = seed_triangle(T, r);
        if (t < 0 || !cvm__tri2_in_domain(T, t))
            return fault_at(f, CVM_E_INPUT_OUTSIDE, CVM__CDT_FAULT_REGION_OUTSIDE, k, 0);
        if ((s = cvm__tri2_flood_attribute(T, t, r[2])))
            return cvm__nomem(T->ctx);
        if ((s = cvm__tick(T->ctx, 1, CVM_STAGE_CARVE, (double)k / (double)in->nregions)))
            return carve_stopped(T->ctx, s, "region", k, in->nregions);
    }
    return CVM_OK;
}

/* Vertices on constrained edges with marker 0 take the segment's marker. */
static void boundary_vertex_markers(const cvm__tri2 *T, const cvm__cdt_input *in, int32_t *vmark)
{
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
                if (vmark[v] == 0)
                    vmark[v] = cvm__cdt_segment_marker(in->smark, in->nseg, seg);
            }
        }
    }
}

cvm_status cvm__cdt_build(cvm__tri2 *T, const cvm__cdt_input *in, cvm__cdt_out *out,
                          cvm__cdt_fault *fault)
{
    cvm_status s;
    fault->kind = CVM__CDT_FAULT_NONE;
    if ((s = check_dynamic_range(in, fault)) || (s = add_points(T, in, out, fault)))
        return s;
    if (in->nseg && (s = recover_segments(T, in, out, fault)))
        return s;
    if ((in->nseg || in->nholes || in->nregions) && (s = cvm__cdt_carve(T, in, fault)))
        return s;
    boundary_vertex_markers(T, in, out->vmark);
    /* post-condition, linear in the mesh: never report success on a mesh
     * that cvm_mesh_check() rejects for a missing segment */
    return cvm__cdt_check_chains(T, in->seg, in->nseg, out->input_map);
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

/* A breadth-first search per segment visits each vertex at most once (seen[]
 * holds the last segment that queued it), so the check costs the stars of
 * the chain vertices: linear in the mesh unless many segments overlap. */
cvm_status cvm__cdt_check_chains(cvm__tri2 *T, const int32_t *seg, size_t nseg,
                                 const int32_t *input_map)
{
    size_t k;
    int32_t *seen;
    cvm_status s = CVM_OK;
    if (!nseg)
        return CVM_OK;
    seen = cvm__malloc(T->ctx, (T->nv ? T->nv : 1) * sizeof *seen);
    if (!seen)
        return cvm__nomem(T->ctx);
    for (k = 0; k < T->nv; k++)
        seen[k] = -1;
    for (k = 0; k < nseg && !s; k++) {
        int32_t a = input_map[seg[2 * k]], b = input_map[seg[2 * k + 1]];
        size_t n = 0, head = 0;
        int found = a == b;
        if (a < 0 || b < 0)
            continue; /* an end removed by CVM_OPT_KEEP_SEGMENT_VERTICES = 0: the chain was
                         re-discretised, its pieces are checked as constrained edges */
        if (cvm__grow(T->ctx, (void **)&T->stack, &T->cap_stack, 1, sizeof(int32_t))) {
            s = cvm__nomem(T->ctx);
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
                int32_t x = v[(i + 1) % 3], sg = cvm__tri2_edge_seg(T, t, (i + 2) % 3);
                t = T->tn[3 * (size_t)t + (i + 1) % 3] / 3;
                if (x < 0 || sg < 0 || seen[x] == (int32_t)k || !on_chain(T, x, a, b))
                    continue;
                if (x == b)
                    found = 1;
                if (n + 1 > T->cap_stack &&
                    cvm__grow(T->ctx, (void **)&T->stack, &T->cap_stack, n + 1, sizeof(int32_t))) {
                    s = cvm__nomem(T->ctx);
                    break;
                }
                seen[x] = (int32_t)k;
                T->stack[n++] = x;
            } while (t != t0);
        }
        if (!found && !s)
            s = cvm__error(T->ctx, CVM_E_INTERNAL, CVM_ENT_INPUT_SEGMENT, (int64_t)k,
                           "check failed: input segment %lu (points %ld-%ld) is not joined end "
                           "to end by constrained edges",
                           (unsigned long)k, (long)seg[2 * k], (long)seg[2 * k + 1]);
    }
    cvm__free(T->ctx, seen);
    return s;
}

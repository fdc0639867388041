/*
 * recombine.c - pairs the triangles of a triangulation into metric-quality
 * quads by maximum-weight matching on the dual graph (recombine.h).
 */
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "geom/measure.h"
#include "quad/recombine.h"
#include "quad/matching.h"
#include "geom/geom_internal.h"


/* One candidate pair: triangles t1 < t2 sharing the edge a-b; t1 = (a, b, c)
 * and t2 = (b, a, d) counter-clockwise, so the quad is (a, d, b, c). */
typedef struct pair {
    cvm_index t1, t2, a, b, c, d;
    cvm_index s1, s2; /* the shared side in t1 (a to b) and in t2 (b to a) */
    double q;
} pair;

typedef struct work {
    cvm__ctx *ctx;
    const cvm__recombine_in *in;
    uint64_t *key;   /* 3 ntri side keys: lo << 32 | hi */
    cvm_index *ord;  /* sides sorted by key, ties by side number */
    cvm_index *tmp;
    pair *pairs;
    size_t npair;
    cvm_index *ends;
    int64_t *w;
    cvm_index *mate; /* per triangle: the pair matched, or -1 */
    cvm_index *eid;  /* per side: its edge number */
    size_t nedge;
} work;

static void sort_sides(cvm_index *a, cvm_index *tmp, size_t n, const uint64_t *key)
{
    size_t h = n / 2, i, j, k;
    if (n < 2)
        return;
    sort_sides(a, tmp, h, key);
    sort_sides(a + h, tmp, n - h, key);
    for (i = 0, j = h, k = 0; k < n; k++)
        tmp[k] = (j >= n || (i < h && (key[a[i]] < key[a[j]] ||
                                       (key[a[i]] == key[a[j]] && a[i] < a[j]))))
                     ? a[i++]
                     : a[j++];
    memcpy(a, tmp, n * sizeof *a);
}

static cvm_status check_metric(cvm__ctx *ctx, const double g[3], const char *what, double x,
                               double y, int64_t index)
{
    if (!isfinite(g[0]) || !isfinite(g[1]) || !isfinite(g[2]) || !(g[0] > 0) || !(g[2] > 0) ||
        !(g[0] * g[2] - g[1] * g[1] > 0))
        return cvm__error(ctx, CVM_E_ARGUMENT, CVM_ENT_VERTEX, index,
                          "recombine: the metric (%g, %g, %g) %s (%g, %g) is not finite and "
                          "positive definite", g[0], g[1], g[2], what, x, y);
    return CVM_OK;
}

static cvm_status check_input(cvm__ctx *ctx, const cvm__recombine_in *in)
{
    size_t i, t;
    if (!in->xy && in->npts > 0)
        return cvm__error(ctx, CVM_E_NULL_ARG, CVM_ENT_NONE, -1, "recombine: xy is NULL");
    if (!in->tri && in->ntri > 0)
        return cvm__error(ctx, CVM_E_NULL_ARG, CVM_ENT_NONE, -1, "recombine: tri is NULL");
    if (in->npts > (size_t)INT32_MAX / 2 || in->ntri > (size_t)INT32_MAX / 4)
        return cvm__error(ctx, CVM_E_TOO_LARGE, CVM_ENT_NONE, -1,
                          "recombine: %zu points or %zu triangles are too many", in->npts,
                          in->ntri);
    if (!(in->min_quality >= 0 && in->min_quality <= 1))
        return cvm__error(ctx, CVM_E_ARGUMENT, CVM_ENT_NONE, -1,
                          "recombine: min_quality %g is outside [0, 1]", in->min_quality);
    if (in->method != CVM__RECOMBINE_BLOSSOM && in->method != CVM__RECOMBINE_GREEDY)
        return cvm__error(ctx, CVM_E_ARGUMENT, CVM_ENT_NONE, -1, "recombine: unknown method %d",
                          (int)in->method);
    for (i = 0; i < in->npts; i++) {
        if (!isfinite(in->xy[2 * i]) || !isfinite(in->xy[2 * i + 1]))
            return cvm__error(ctx, CVM_E_INPUT_NONFINITE, CVM_ENT_VERTEX, (int64_t)i,
                              "recombine: point %zu has a non-finite coordinate", i);
        if (in->g) {
            cvm_status st = check_metric(ctx, in->g + 3 * i, "at point", in->xy[2 * i],
                                         in->xy[2 * i + 1], (int64_t)i);
            if (st)
                return st;
        }
    }
    for (t = 0; t < in->ntri; t++) {
        const cvm_index *v = in->tri + 3 * t;
        int j;
        for (j = 0; j < 3; j++)
            if (v[j] < 0 || (size_t)v[j] >= in->npts)
                return cvm__error(ctx, CVM_E_INPUT_INDEX, CVM_ENT_TRIANGLE, (int64_t)t,
                                  "recombine: triangle %zu names point %ld outside [0, %zu)", t,
                                  (long)v[j], in->npts);
        if (!(cvm__orient2d(in->xy + 2 * v[0], in->xy + 2 * v[1], in->xy + 2 * v[2]) > 0))
            return cvm__error(ctx, CVM_E_INPUT_DEGENERATE, CVM_ENT_TRIANGLE, (int64_t)t,
                              "recombine: triangle %zu (points %ld, %ld, %ld) is not strictly "
                              "counter-clockwise", t, (long)v[0], (long)v[1], (long)v[2]);
    }
    return CVM_OK;
}

/* The metric of the cell p[0..n-1] (input points): the callback at the
 * centroid, the mean of the corner tensors, or the identity. */
static cvm_status cell_metric(work *W, const cvm_index *p, int n, double g[3])
{
    const cvm__recombine_in *in = W->in;
    double f = 1.0 / n;
    int k;
    if (in->g) {
        g[0] = g[1] = g[2] = 0;
        for (k = 0; k < n; k++) {
            g[0] += f * in->g[3 * p[k]];
            g[1] += f * in->g[3 * p[k] + 1];
            g[2] += f * in->g[3 * p[k] + 2];
        }
        return CVM_OK;
    }
    if (in->metric) {
        double x = 0, y = 0;
        for (k = 0; k < n; k++) {
            x += f * in->xy[2 * p[k]];
            y += f * in->xy[2 * p[k] + 1];
        }
        if (in->metric(x, y, g, in->metric_user))
            return cvm__error(W->ctx, CVM_E_ARGUMENT, CVM_ENT_NONE, -1,
                              "recombine: the metric callback rejected the point (%g, %g)", x, y);
        return check_metric(W->ctx, g, "at the quad centroid", x, y, -1);
    }
    g[0] = g[2] = 1;
    g[1] = 0;
    return CVM_OK;
}

/* Quality of the strictly convex quad p[0..3] (counter-clockwise) under g. */
static double quad_quality(const double *xy, const cvm_index p[4], const double g[3])
{
    double worst = 0;
    int k;
    for (k = 0; k < 4; k++) {
        const double *o = xy + 2 * p[k], *a = xy + 2 * p[(k + 3) % 4], *b = xy + 2 * p[(k + 1) % 4];
        double dev = fabs(cvm__metric_angle_deg(g, o, a, b) - 90);
        if (dev > worst)
            worst = dev;
    }
    return 1 - worst / 90;
}

/* Sort the sides, pair interior unconstrained edges, keep the good pairs. */
static cvm_status find_pairs(work *W)
{
    const cvm__recombine_in *in = W->in;
    size_t ns = 3 * in->ntri, i, j, k;
    for (i = 0; i < ns; i++) {
        cvm_index a = in->tri[i], b = in->tri[i - i % 3 + (i % 3 + 1) % 3];
        cvm_index lo = a < b ? a : b, hi = a < b ? b : a;
        W->key[i] = (uint64_t)lo << 32 | (uint64_t)hi;
        W->ord[i] = (cvm_index)i;
    }
    sort_sides(W->ord, W->tmp, ns, W->key);
    for (i = 0; i < ns; i = j) {
        size_t s1 = (size_t)W->ord[i], s2;
        cvm_index p[4];
        pair pr;
        double g[3];
        cvm_status st;
        for (j = i + 1; j < ns && W->key[W->ord[j]] == W->key[s1]; j++)
            ;
        for (k = i; k < j; k++)
            W->eid[W->ord[k]] = (cvm_index)W->nedge;
        W->nedge++;
        if (j - i == 1)
            continue; /* boundary */
        s2 = (size_t)W->ord[i + 1];
        if (j - i > 2 || in->tri[s1] == in->tri[s2])
            return cvm__error(W->ctx, CVM_E_INPUT_DEGENERATE, CVM_ENT_TRIANGLE,
                              (int64_t)(s1 / 3),
                              "recombine: triangles %zu and %zu share edge %ld-%ld %s", s1 / 3,
                              s2 / 3, (long)in->tri[s1], (long)in->tri[s2 - s2 % 3 + (s2 % 3 + 1) % 3],
                              j - i > 2 ? "with a third triangle" : "in the same direction");
        if (in->side_fixed && (in->side_fixed[s1] || in->side_fixed[s2]))
            continue;
        pr.t1 = (cvm_index)(s1 / 3);
        pr.t2 = (cvm_index)(s2 / 3);
        pr.s1 = (cvm_index)s1;
        pr.s2 = (cvm_index)s2;
        pr.a = in->tri[s1];
        pr.b = in->tri[s1 - s1 % 3 + (s1 % 3 + 1) % 3];
        pr.c = in->tri[s1 - s1 % 3 + (s1 % 3 + 2) % 3];
        pr.d = in->tri[s2 - s2 % 3 + (s2 % 3 + 2) % 3];
        p[0] = pr.a;
        p[1] = pr.d;
        p[2] = pr.b;
        p[3] = pr.c;
        if (!(cvm__orient2d(in->xy + 2 * pr.c, in->xy + 2 * pr.a, in->xy + 2 * pr.d) > 0) ||
            !(cvm__orient2d(in->xy + 2 * pr.d, in->xy + 2 * pr.b, in->xy + 2 * pr.c) > 0))
            continue; /* not strictly convex: q = 0 */
        st = cell_metric(W, p, 4, g);
        if (st)
            return st;
        pr.q = quad_quality(in->xy, p, g);
        if (pr.q < in->min_quality || !(pr.q > 0))
            continue;
        W->pairs[W->npair++] = pr;
    }
    return CVM_OK;
}

static cvm_status match(work *W)
{
    const cvm__recombine_in *in = W->in;
    size_t k;
    cvm_index *mate_e = W->tmp; /* reused: per triangle, the pair matched */
    cvm_status st;
    for (k = 0; k < W->npair; k++) {
        W->ends[2 * k] = W->pairs[k].t1;
        W->ends[2 * k + 1] = W->pairs[k].t2;
        W->w[k] = cvm__match_scale(W->pairs[k].q);
    }
    if (in->method == CVM__RECOMBINE_GREEDY)
        st = cvm__matching_greedy(mate_e, W->ctx, in->ntri, W->npair, W->ends, W->w);
    else
        st = cvm__matching_solve(mate_e, NULL, W->ctx, in->ntri, W->npair, W->ends, W->w,
                                 in->perfect ? CVM__MATCH_MAX_CARDINALITY : CVM__MATCH_MAX_WEIGHT);
    W->mate = mate_e;
    return st;
}

static cvm_index next_side(cvm_index s)
{
    return s - s % 3 + (s % 3 + 1) % 3;
}

/* Split each cell of out (sides cside: 4 per cell, the side of each cell
 * edge) into quads through its centroid and edge midpoints. */
static cvm_status split_all(work *W, cvm__recombine_out *out, const cvm_index *cside)
{
    const cvm__recombine_in *in = W->in;
    cvm__recombine_out r;
    size_t np = in->npts, nc = out->ncell, nsub = 4 * out->nquad + 3 * out->ntri, c, i, sc = 0;
    cvm_index *mid = W->tmp, nmid = 0; /* per edge: its midpoint; the mates are done with */
    memset(&r, 0, sizeof r);
    r.nquad = out->nquad;
    r.ntri = out->ntri;
    r.ncell = nsub;
    /* at most: the points, the centroids, one midpoint per cell edge */
    r.xy = cvm__malloc(W->ctx, (2 * (np + nc + 4 * nc) + 1) * sizeof *r.xy);
    r.offsets = cvm__malloc(W->ctx, (nsub + 1) * sizeof *r.offsets);
    r.types = cvm__malloc(W->ctx, (nsub + 1) * sizeof *r.types);
    r.conn = cvm__malloc(W->ctx, (4 * nsub + 1) * sizeof *r.conn);
    r.source = cvm__malloc(W->ctx, (2 * nsub + 1) * sizeof *r.source);
    r.quality = cvm__malloc(W->ctx, (nsub + 1) * sizeof *r.quality);
    if (!r.xy || !r.offsets || !r.types || !r.conn || !r.source || !r.quality) {
        cvm__recombine_out_free(W->ctx, &r);
        return CVM_E_NOMEM;
    }
    memcpy(r.xy, in->xy, 2 * np * sizeof *r.xy);
    for (i = 0; i < W->nedge; i++)
        mid[i] = -1;
    /* midpoints numbered in order of first use (the diagonals inside quads get none);
     * a + b and b + a round alike, so both sides of an edge give the same point */
    for (i = 0; i < 4 * nc; i++) {
        cvm_index sd = cside[i], e;
        if (sd < 0 || mid[e = W->eid[sd]] >= 0)
            continue;
        {
            const double *a = in->xy + 2 * in->tri[sd], *b = in->xy + 2 * in->tri[next_side(sd)];
            size_t id = np + nc + (size_t)nmid;
            r.xy[2 * id] = 0.5 * (a[0] + b[0]);
            r.xy[2 * id + 1] = 0.5 * (a[1] + b[1]);
            mid[e] = (cvm_index)id;
            nmid++;
        }
    }
    r.npts = np + nc + (size_t)nmid;
    for (c = 0; c < nc; c++) {
        const cvm_index *p = out->conn + out->offsets[c];
        int n = out->offsets[c + 1] - out->offsets[c], k;
        cvm_index cen = (cvm_index)(np + c);
        double g[3], x = 0, y = 0;
        cvm_status st = cell_metric(W, p, n, g);
        if (st) {
            cvm__recombine_out_free(W->ctx, &r);
            return st;
        }
        for (k = 0; k < n; k++) {
            x += in->xy[2 * p[k]];
            y += in->xy[2 * p[k] + 1];
        }
        r.xy[2 * cen] = x / n;
        r.xy[2 * cen + 1] = y / n;
        for (k = 0; k < n; k++) {
            cvm_index *q = r.conn + 4 * sc;
            q[0] = p[k];
            q[1] = mid[W->eid[cside[4 * c + (size_t)k]]];
            q[2] = cen;
            q[3] = mid[W->eid[cside[4 * c + (size_t)(k + n - 1) % (size_t)n]]];
            r.offsets[sc] = (cvm_index)(4 * sc);
            r.types[sc] = CVM_CELL_QUAD;
            r.source[2 * sc] = out->source[2 * c];
            r.source[2 * sc + 1] = out->source[2 * c + 1];
            r.quality[sc] = 0;
            if (cvm__orient2d(r.xy + 2 * q[3], r.xy + 2 * q[0], r.xy + 2 * q[1]) > 0 &&
                cvm__orient2d(r.xy + 2 * q[0], r.xy + 2 * q[1], r.xy + 2 * q[2]) > 0 &&
                cvm__orient2d(r.xy + 2 * q[1], r.xy + 2 * q[2], r.xy + 2 * q[3]) > 0 &&
                cvm__orient2d(r.xy + 2 * q[2], r.xy + 2 * q[3], r.xy + 2 * q[0]) > 0)
                r.quality[sc] = quad_quality(r.xy, q, g);
            r.total_quality += r.quality[sc++];
        }
    }
    r.offsets[sc] = (cvm_index)(4 * sc);
    cvm__recombine_out_free(W->ctx, out);
    *out = r;
    return CVM_OK;
}

static cvm_status emit(work *W, cvm__recombine_out *out)
{
    const cvm__recombine_in *in = W->in;
    cvm_index *cside = W->ord; /* sized 4 per triangle; the sorted sides are done with */
    size_t t, c = 0, o = 0, nq = 0;
    for (t = 0; t < in->ntri; t++)
        nq += W->mate[t] >= 0;
    nq /= 2;
    out->nquad = nq;
    out->ntri = in->ntri - 2 * nq;
    out->ncell = nq + out->ntri;
    out->offsets = cvm__malloc(W->ctx, (out->ncell + 1) * sizeof *out->offsets);
    out->types = cvm__malloc(W->ctx, (out->ncell + 1) * sizeof *out->types);
    out->conn = cvm__malloc(W->ctx, (4 * nq + 3 * out->ntri + 1) * sizeof *out->conn);
    out->source = cvm__malloc(W->ctx, (2 * out->ncell + 1) * sizeof *out->source);
    out->quality = cvm__malloc(W->ctx, (out->ncell + 1) * sizeof *out->quality);
    if (!out->offsets || !out->types || !out->conn || !out->source || !out->quality)
        return CVM_E_NOMEM;
    out->total_quality = 0;
    for (t = 0; t < in->ntri; t++) {
        cvm_index e = W->mate[t];
        out->offsets[c] = (cvm_index)o;
        if (e < 0) {
            memcpy(out->conn + o, in->tri + 3 * t, 3 * sizeof *out->conn);
            o += 3;
            out->types[c] = CVM_CELL_TRIANGLE;
            out->source[2 * c] = (cvm_index)t;
            out->source[2 * c + 1] = -1;
            cside[4 * c] = (cvm_index)(3 * t);
            cside[4 * c + 1] = (cvm_index)(3 * t + 1);
            cside[4 * c + 2] = (cvm_index)(3 * t + 2);
            cside[4 * c + 3] = -1;
            out->quality[c++] = 0;
        } else if (W->pairs[e].t1 == (cvm_index)t) {
            const pair *p = &W->pairs[e];
            out->conn[o++] = p->a;
            out->conn[o++] = p->d;
            out->conn[o++] = p->b;
            out->conn[o++] = p->c;
            out->types[c] = CVM_CELL_QUAD;
            out->source[2 * c] = p->t1;
            out->source[2 * c + 1] = p->t2;
            out->total_quality += p->q;
            cside[4 * c] = next_side(p->s2);             /* a to d */
            cside[4 * c + 1] = next_side(next_side(p->s2)); /* d to b */
            cside[4 * c + 2] = next_side(p->s1);         /* b to c */
            cside[4 * c + 3] = next_side(next_side(p->s1)); /* c to a */
            out->quality[c++] = p->q;
        }
    }
    out->offsets[c] = (cvm_index)o;
    return in->all_quad ? split_all(W, out, cside) : CVM_OK;
}

cvm_status cvm__recombine(cvm__recombine_out *out, cvm__ctx *ctx, const cvm__recombine_in *in)
{
    work W;
    size_t ns;
    cvm_status st;
    if (!out || !in)
        return cvm__error(ctx, CVM_E_NULL_ARG, CVM_ENT_NONE, -1, "recombine: out or in is NULL");
    memset(out, 0, sizeof *out);
    st = check_input(ctx, in);
    if (st)
        return st;
    memset(&W, 0, sizeof W);
    W.ctx = ctx;
    W.in = in;
    ns = 3 * in->ntri;
    W.key = cvm__malloc(ctx, (ns + 1) * sizeof *W.key);
    W.ord = cvm__malloc(ctx, (4 * in->ntri + 1) * sizeof *W.ord);
    W.eid = cvm__malloc(ctx, (ns + 1) * sizeof *W.eid);
    W.tmp = cvm__malloc(ctx, (ns + 1) * sizeof *W.tmp);
    W.pairs = cvm__malloc(ctx, (ns / 2 + 1) * sizeof *W.pairs);
    W.ends = cvm__malloc(ctx, (ns + 1) * sizeof *W.ends);
    W.w = cvm__malloc(ctx, (ns / 2 + 1) * sizeof *W.w);
    st = W.key && W.ord && W.eid && W.tmp && W.pairs && W.ends && W.w ? CVM_OK : CVM_E_NOMEM;
    if (!st)
        st = find_pairs(&W);
    if (!st)
        st = match(&W);
    if (!st)
        st = emit(&W, out);
    cvm__free(ctx, W.key);
    cvm__free(ctx, W.ord);
    cvm__free(ctx, W.tmp);
    cvm__free(ctx, W.eid);
    cvm__free(ctx, W.pairs);
    cvm__free(ctx, W.ends);
    cvm__free(ctx, W.w);
    if (st) {
        cvm__recombine_out_free(ctx, out);
        return st == CVM_E_NOMEM ? cvm__nomem(ctx) : st;
    }
    return CVM_OK;
}

void cvm__recombine_out_free(cvm__ctx *ctx, cvm__recombine_out *out)
{
    cvm__free(ctx, out->offsets);
    cvm__free(ctx, out->types);
    cvm__free(ctx, out->conn);
    cvm__free(ctx, out->source);
    cvm__free(ctx, out->quality);
    cvm__free(ctx, out->xy);
    memset(out, 0, sizeof *out);
}

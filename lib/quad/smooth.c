/* smooth.c - smoothing of a quad-dominant mesh after the recombination: each free vertex moves to
 * the mean of its quad-edge neighbours (which removes the zig-zag rows of the Lp-CVT minimisers
 * where the metric varies) or towards the mean of the points that would make each of its quads a
 * parallelogram (affine invariant: where the metric is locally constant a lattice of metric
 * squares is a fixed point). A move is kept only when every cell around the vertex stays
 * strictly convex (exact orientations) and the metric corner deviation and edge misalignment of
 * its quads drop. */
#include <math.h>
#include <string.h>

#include "geom/geom_internal.h"
#include "geom/measure.h"
#include "quad_internal.h"

typedef struct qs_work {
    const cvm__quad_smooth_in *in;
    double *xy;
    int32_t *vstart, *vcell; /* CSR: the cells of each vertex */
    double *cost;            /* per cell: its quad cost at the current points, when known */
    uint8_t *known;          /* per cell: 1 when cost[c] is that of the current points */
    double *trial;           /* per cell of the vertex being moved: its cost at the trial point */
    uint8_t *dirty;          /* per vertex: 0 when nothing in its cells moved since it last stayed */
} qs_work;

/* 1 when cell c is strictly convex (every corner turns left, exact). */
static int qs_convex(const qs_work *W, int32_t c)
{
    const int32_t *p = W->in->conn + W->in->off[c];
    int n = (int)(W->in->off[c + 1] - W->in->off[c]), i;
    for (i = 0; i < n; i++)
        if (!(cvm__orient2d(W->xy + 2 * p[i], W->xy + 2 * p[(i + 1) % n],
                            W->xy + 2 * p[(i + 2) % n]) > 0))
            return 0;
    return 1;
}

/* The cost of quad c in the metric g at its vertex mean (radians^2): the squared corner
 * deviations from 90 degrees plus each edge's squared angle to the nearer eigenvector of g
 * times the anisotropy of g; HUGE_VAL when the metric fails there. */
static double qs_quad_cost(const qs_work *W, int32_t c)
{
    const int32_t *p = W->in->conn + W->in->off[c];
    double m[2] = {0, 0}, g[3], s = 0, aniso, th;
    int i;
    for (i = 0; i < 4; i++) {
        m[0] += 0.25 * W->xy[2 * p[i]];
        m[1] += 0.25 * W->xy[2 * p[i] + 1];
    }
    if (W->in->metric(m[0], m[1], g, W->in->metric_user))
        return HUGE_VAL;
    {
        double c = g[0] - g[2], r = sqrt(c * c + 4 * g[1] * g[1]);
        aniso = r / (g[0] + g[2]);
        th = 0.5 * atan2(2 * g[1], c);
    }
    for (i = 0; i < 4; i++) {
        const double *a = W->xy + 2 * p[i], *b = W->xy + 2 * p[(i + 1) % 4],
                     *d = W->xy + 2 * p[(i + 3) % 4];
        double u0 = b[0] - a[0], u1 = b[1] - a[1], w0 = d[0] - a[0], w1 = d[1] - a[1];
        double uw = g[0] * u0 * w0 + g[1] * (u0 * w1 + u1 * w0) + g[2] * u1 * w1;
        double uu = g[0] * u0 * u0 + 2 * g[1] * u0 * u1 + g[2] * u1 * u1;
        double ww = g[0] * w0 * w0 + 2 * g[1] * w0 * w1 + g[2] * w1 * w1;
        double t = uw / sqrt(uu * ww), dev = asin(t < -1 ? -1 : t > 1 ? 1 : t); /* 90 - angle */
        s += dev * dev;
        if (aniso > 0) { /* the edge's angle to the nearer eigenvector, weighted by anisotropy */
            double f = fmod(fabs(atan2(u1, u0) - th), 0.5 * CVM__PI);
            f = fmin(f, 0.5 * CVM__PI - f);
            s += aniso * f * f;
        }
    }
    return s;
}

/* The summed cost of v's quads and 1 when every cell of v is strictly convex. cached: the points
 * are the current ones, a quad's known cost serves (the same value, computed when its points
 * last changed) and a computed one is kept; else (a trial point) each is computed into
 * W->trial. */
static int qs_star(const qs_work *W, size_t v, double *cost, int cached)
{
    int32_t k;
    *cost = 0;
    for (k = W->vstart[v]; k < W->vstart[v + 1]; k++) {
        int32_t c = W->vcell[k];
        double q;
        if (!qs_convex(W, c))
            return 0;
        if (W->in->types[c] != CVM_CELL_QUAD)
            continue;
        if (cached && W->known[c]) {
            q = W->cost[c];
        } else {
            q = qs_quad_cost(W, c);
            if (cached) {
                W->cost[c] = q;
                W->known[c] = 1;
            }
        }
        W->trial[k - W->vstart[v]] = q;
        *cost += q;
    }
    return 1;
}

static void qs_free(cvm__ctx *ctx, qs_work *W)
{
    cvm__free(ctx, W->vstart);
    cvm__free(ctx, W->vcell);
    cvm__free(ctx, W->cost);
    cvm__free(ctx, W->known);
    cvm__free(ctx, W->trial);
    cvm__free(ctx, W->dirty);
}

/* The mean of v's parallelogram points into t, and the mean of its neighbours along quad edges
 * into lap; 0 when v has no quad. */
static int qs_target(const qs_work *W, size_t v, double *t, double *lap)
{
    int32_t k, nq = 0;
    t[0] = t[1] = lap[0] = lap[1] = 0;
    for (k = W->vstart[v]; k < W->vstart[v + 1]; k++) {
        int32_t c = W->vcell[k], i;
        const int32_t *p = W->in->conn + W->in->off[c];
        if (W->in->types[c] != CVM_CELL_QUAD)
            continue;
        for (i = 0; i < 4 && p[i] != (int32_t)v; i++)
            ;
        {
            const double *a = W->xy + 2 * p[(i + 1) % 4], *b = W->xy + 2 * p[(i + 2) % 4],
                         *d = W->xy + 2 * p[(i + 3) % 4];
            t[0] += a[0] + d[0] - b[0];
            t[1] += a[1] + d[1] - b[1];
            lap[0] += 0.5 * (a[0] + d[0]);
            lap[1] += 0.5 * (a[1] + d[1]);
            nq++;
        }
    }
    if (nq == 0)
        return 0;
    t[0] /= nq;
    t[1] /= nq;
    lap[0] /= nq;
    lap[1] /= nq;
    return 1;
}

cvm_status cvm__quad_smooth(cvm__ctx *ctx, double *xy, const cvm__quad_smooth_in *in,
                            size_t *moves_out)
{
    qs_work W;
    size_t v, moves = 0, maxstar = 1;
    int32_t c, k;
    int sweep;
    *moves_out = 0;
    memset(&W, 0, sizeof W);
    W.in = in;
    W.xy = xy;
    W.vstart = cvm__calloc(ctx, in->nv + 1, sizeof *W.vstart);
    W.vcell = cvm__malloc(ctx, ((size_t)in->off[in->ncell] + 1) * sizeof *W.vcell);
    W.cost = cvm__malloc(ctx, (in->ncell + 1) * sizeof *W.cost);
    W.known = cvm__calloc(ctx, in->ncell + 1, 1);
    if (!W.vstart || !W.vcell || !W.cost || !W.known) {
        qs_free(ctx, &W);
        return cvm__nomem(ctx);
    }
    for (k = 0; k < in->off[in->ncell]; k++)
        W.vstart[in->conn[k] + 1]++;
    for (v = 0; v < in->nv; v++)
        W.vstart[v + 1] += W.vstart[v];
    for (c = 0; c < (int32_t)in->ncell; c++)
        for (k = in->off[c]; k < in->off[c + 1]; k++)
            W.vcell[W.vstart[in->conn[k]]++] = c;
    for (v = in->nv; v > 0; v--)
        W.vstart[v] = W.vstart[v - 1];
    W.vstart[0] = 0;
    for (v = 0; v < in->nv; v++)
        if ((size_t)(W.vstart[v + 1] - W.vstart[v]) > maxstar)
            maxstar = (size_t)(W.vstart[v + 1] - W.vstart[v]);
    W.trial = cvm__malloc(ctx, maxstar * sizeof *W.trial);
    W.dirty = cvm__malloc(ctx, in->nv + 1);
    if (!W.trial || !W.dirty) {
        qs_free(ctx, &W);
        return cvm__nomem(ctx);
    }
    memset(W.dirty, 1, in->nv + 1);
    for (sweep = 0; sweep < in->sweeps; sweep++) {
        size_t moved = 0;
        for (v = in->first_free; v < in->nv; v++) {
            double t[2], lap[2], old[2], before, after;
            int j;
            /* a vertex that stayed, with every point of its cells where it was then, would stay
             * again: the same targets, costs and tests */
            if (!W.dirty[v])
                continue;
            W.dirty[v] = 0;
            if (!qs_target(&W, v, t, lap) || !qs_star(&W, v, &before, 1))
                continue;
            old[0] = xy[2 * v];
            old[1] = xy[2 * v + 1];
            /* the neighbours' mean (it removes a zig-zag of parallelograms, which is a fixed
             * point of the parallelogram rule), then the parallelogram point at a full, half
             * and quarter step: the first that keeps the star convex and cheaper */
            for (j = -1; j < 3; j++) {
                const double *to = j < 0 ? lap : t;
                double f = j < 0 ? 1 : ldexp(1.0, -j);
                xy[2 * v] = old[0] + f * (to[0] - old[0]);
                xy[2 * v + 1] = old[1] + f * (to[1] - old[1]);
                if (qs_star(&W, v, &after, 0) && after < before)
                    break;
            }
            if (j == 3) {
                xy[2 * v] = old[0];
                xy[2 * v + 1] = old[1];
            } else { /* the trial's costs are those of v's quads now */
                for (k = W.vstart[v]; k < W.vstart[v + 1]; k++) {
                    int32_t c = W.vcell[k], i;
                    if (in->types[c] == CVM_CELL_QUAD) {
                        W.cost[c] = W.trial[k - W.vstart[v]];
                        W.known[c] = 1;
                    }
                    for (i = in->off[c]; i < in->off[c + 1]; i++)
                        W.dirty[in->conn[i]] = 1; /* v itself too: it may move on */
                }
                moved++;
            }
        }
        moves += moved;
        if (moved == 0)
            break;
    }
    qs_free(ctx, &W);
    *moves_out = moves;
    for (c = 0; in->quality && c < (int32_t)in->ncell; c++) {
        const int32_t *p = in->conn + in->off[c];
        double m[2] = {0, 0}, g[3], worst = 0;
        int i;
        if (in->types[c] != CVM_CELL_QUAD)
            continue;
        for (i = 0; i < 4; i++) {
            m[0] += 0.25 * xy[2 * p[i]];
            m[1] += 0.25 * xy[2 * p[i] + 1];
        }
        if (in->metric(m[0], m[1], g, in->metric_user))
            return cvm__error(ctx, CVM_E_ARGUMENT, CVM_ENT_NONE, -1,
                              "smoothing: the metric refused the point (%g, %g)", m[0], m[1]);
        for (i = 0; i < 4; i++)
            worst = fmax(worst, fabs(cvm__metric_angle_deg(g, xy + 2 * p[i], xy + 2 * p[(i + 3) % 4],
                                                           xy + 2 * p[(i + 1) % 4]) - 90));
        in->quality[c] = 1 - worst / 90;
    }
    return CVM_OK;
}

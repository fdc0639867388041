/*
 * sizing_auto.c - the automatic length scale of cvm_sizing_set_automatic():
 *
 *   LS(x) = min over boundary samples q of ( lfs_c(q) / R + |x - q| / G )
 *
 * built once per cvm_mesh_refine() from the domain being refined.
 *
 * Features are the edges bounding the domain or constrained inside it (input
 * segments, their pieces, hull edges) and the input points that lie on none of
 * them. The local feature size lfs(q) at a boundary point q is the distance
 * from q to the nearest feature not incident to q (Ruppert's definition:
 * the radius of the smallest circle centred at q touching two disjoint
 * features): for a vertex, every feature but its own edges; for a point inside
 * an edge, every feature but that edge and the edges sharing its ends.
 * Curved polylines: the edges reached from q along a chain of degree-2
 * vertices before the chain has turned by 60 degrees in total belong to the
 * same smooth curve and are excluded as well, and lfs_c = min(lfs, radius of
 * curvature), with the radius at a chain vertex whose turning angle theta is
 * at most 30 degrees estimated as (l1 + l2) / (2 theta) from its two edges;
 * sharper vertices are corners and carry no curvature.
 *
 * Samples: every feature vertex, and points inside each edge by bisection until
 * a piece is shorter than min(1/2, G/R) x the smaller lfs at its ends (lfs is
 * 1-Lipschitz, so it cannot dip much between samples). The minimum over
 * samples of a cone of slope 1/G is the discrete form of the specified
 * "min over neighbours q of LS(q) + |q - p|/G": it is graded with slope 1/G
 * everywhere, and equals lfs_c/R at a sample unless a smaller size nearby
 * grades it down. Interior points get their size from the boundary through the
 * grading (their own lfs is not sampled).
 *
 * Both the nearest-feature queries and the evaluation use uniform grids with
 * ring searches; nothing here decides topology.
 */
#include <math.h>
#include <string.h>

#include "sizing_internal.h"
#include "geom/measure.h"

#define AUTO_CHAIN_TURN (CVM__PI / 3.0) /* 60 degrees */
#define AUTO_SMOOTH_TURN (CVM__PI / 6.0) /* 30 degrees */
#define AUTO_MAX_DEPTH 24
#define CELLS_PER_SAMPLE 4 /* grid cells per sample (ring searches visit few samples) */


#define AUTO_MAX_CHAIN_STEPS 100000

typedef struct auto_build {
    cvm__ctx *ctx;
    const double *xy;
    /* features: edge k joins fe[2k], fe[2k+1] (equal for a point feature) */
    int32_t *fe;
    size_t nfe, cap_fe;
    /* vertex -> incident edges (CSR over vertices) */
    int32_t *vstart, *vedges;
    double *curv;          /* radius of curvature per vertex (+inf: none) */
    /* feature grid */
    cvm__cell_grid g;
    int32_t *gstart, *gitems;
    /* stamps */
    uint32_t *excl, *seen;
    uint32_t excl_stamp, seen_stamp;
    /* samples, 3 doubles each: x, y, LS */
    double *smp;
    size_t ns, cap_smp;
} auto_build;

static const double *auto_pt(const auto_build *B, int32_t v)
{
    return B->xy + 2 * (size_t)v;
}

static double auto_dist_seg(const double *p, const double *a, const double *b)
{
    double dx = b[0] - a[0], dy = b[1] - a[1], len2 = dx * dx + dy * dy, t = 0;
    if (len2 > 0) {
        t = ((p[0] - a[0]) * dx + (p[1] - a[1]) * dy) / len2;
        t = t < 0 ? 0 : t > 1 ? 1 : t;
    }
    return hypot(a[0] + t * dx - p[0], a[1] + t * dy - p[1]);
}

static cvm_status auto_add_edge(auto_build *B, int32_t a, int32_t b)
{
    if (cvm__grow(B->ctx, (void **)&B->fe, &B->cap_fe, 2 * (B->nfe + 1), sizeof *B->fe))
        return CVM_E_NOMEM;
    B->fe[2 * B->nfe] = a;
    B->fe[2 * B->nfe + 1] = b;
    B->nfe++;
    return CVM_OK;
}

/* Domain boundary and constrained edges, once each; then free input points. */
static cvm_status auto_collect(auto_build *B, const cvm__tri2 *T, const uint8_t *is_input)
{
    size_t t;
    uint8_t *used;
    int j;
    for (t = 0; t < T->nt; t++) {
        if (!cvm__tri2_in_domain(T, (int32_t)t))
            continue;
        for (j = 0; j < 3; j++) {
            int32_t n = T->tn[3 * t + (size_t)j] / 3; /* tn holds 3 u + k */
            int nin = n >= 0 && cvm__tri2_in_domain(T, n);
            int con = T->te && T->te[3 * t + (size_t)j] >= 0;
            if (nin && (!con || (size_t)n < t))
                continue;
            if (auto_add_edge(B, T->tv[3 * t + (size_t)(j + 1) % 3],
                            T->tv[3 * t + (size_t)(j + 2) % 3]))
                return CVM_E_NOMEM;
        }
    }
    used = cvm__malloc(B->ctx, T->nv ? T->nv : 1);
    if (!used)
        return CVM_E_NOMEM;
    memset(used, 0, T->nv);
    for (t = 0; t < 2 * B->nfe; t++)
        used[B->fe[t]] = 1;
    for (t = 0; t < T->nt; t++) {
        if (!cvm__tri2_in_domain(T, (int32_t)t))
            continue;
        for (j = 0; j < 3; j++) {
            int32_t u = T->tv[3 * t + (size_t)j];
            if (used[u] || (is_input && !is_input[u]))
                continue;
            used[u] = 1;
            if (auto_add_edge(B, u, u)) {
                cvm__free(B->ctx, used);
                return CVM_E_NOMEM;
            }
        }
    }
    cvm__free(B->ctx, used);
    return CVM_OK;
}

/* Incident edges per vertex (point features excluded) and curvature radii. */
static cvm_status auto_adjacency(auto_build *B, size_t nv)
{
    size_t k, v;
    B->vstart = cvm__malloc(B->ctx, (nv + 1) * sizeof *B->vstart);
    B->vedges = cvm__malloc(B->ctx, (2 * B->nfe + 1) * sizeof *B->vedges);
    B->curv = cvm__malloc(B->ctx, (nv + 1) * sizeof *B->curv);
    if (!B->vstart || !B->vedges || !B->curv)
        return CVM_E_NOMEM;
    memset(B->vstart, 0, (nv + 1) * sizeof *B->vstart);
    for (k = 0; k < B->nfe; k++)
        if (B->fe[2 * k] != B->fe[2 * k + 1]) {
            B->vstart[B->fe[2 * k] + 1]++;
            B->vstart[B->fe[2 * k + 1] + 1]++;
        }
    for (v = 0; v < nv; v++)
        B->vstart[v + 1] += B->vstart[v];
    {
        int32_t *fill = cvm__malloc(B->ctx, (nv + 1) * sizeof *fill);
        if (!fill)
            return CVM_E_NOMEM;
        memcpy(fill, B->vstart, nv * sizeof *fill);
        for (k = 0; k < B->nfe; k++)
            if (B->fe[2 * k] != B->fe[2 * k + 1]) {
                B->vedges[fill[B->fe[2 * k]]++] = (int32_t)k;
                B->vedges[fill[B->fe[2 * k + 1]]++] = (int32_t)k;
            }
        cvm__free(B->ctx, fill);
    }
    for (v = 0; v < nv; v++) {
        B->curv[v] = HUGE_VAL;
        if (B->vstart[v + 1] - B->vstart[v] == 2) {
            int32_t e0 = B->vedges[B->vstart[v]], e1 = B->vedges[B->vstart[v] + 1];
            int32_t a = B->fe[2 * e0] == (int32_t)v ? B->fe[2 * e0 + 1] : B->fe[2 * e0];
            int32_t c = B->fe[2 * e1] == (int32_t)v ? B->fe[2 * e1 + 1] : B->fe[2 * e1];
            const double *pa = auto_pt(B, a), *pv = auto_pt(B, (int32_t)v), *pc = auto_pt(B, c);
            double ux = pv[0] - pa[0], uy = pv[1] - pa[1], wx = pc[0] - pv[0], wy = pc[1] - pv[1];
            double th = cvm__vec_angle(ux, uy, wx, wy);
            if (th > 0 && th <= AUTO_SMOOTH_TURN)
                B->curv[v] = (hypot(ux, uy) + hypot(wx, wy)) / (2 * th);
        }
    }
    return CVM_OK;
}

/* Visit the cells an edge meets (their circumscribed circle touches it):
 * count them (pos NULL) or append the edge to them. */
static void auto_grid_edge(auto_build *B, size_t k, int32_t *pos)
{
    const double *a = auto_pt(B, B->fe[2 * k]), *b = auto_pt(B, B->fe[2 * k + 1]);
    int i0, j0, i1, j1, i, j;
    cvm__cell_grid_cell(&B->g, fmin(a[0], b[0]), fmin(a[1], b[1]), &i0, &j0);
    cvm__cell_grid_cell(&B->g, fmax(a[0], b[0]), fmax(a[1], b[1]), &i1, &j1);
    for (j = j0; j <= j1; j++)
        for (i = i0; i <= i1; i++) {
            size_t c = (size_t)j * (size_t)B->g.nx + (size_t)i;
            double m[2];
            m[0] = B->g.x0 + (i + 0.5) * B->g.cs;
            m[1] = B->g.y0 + (j + 0.5) * B->g.cs;
            if (auto_dist_seg(m, a, b) > 0.7072 * B->g.cs)
                continue;
            if (pos)
                B->gitems[pos[c]++] = (int32_t)k;
            else
                B->gstart[c + 1]++;
        }
}

/* Grid of features over their bounding box, about one edge per cell. */
static cvm_status auto_grid(auto_build *B)
{
    double xmin = HUGE_VAL, ymin = HUGE_VAL, xmax = -HUGE_VAL, ymax = -HUGE_VAL;
    size_t k, ncell;
    int32_t *pos;
    for (k = 0; k < 2 * B->nfe; k++) {
        const double *p = auto_pt(B, B->fe[k]);
        xmin = fmin(xmin, p[0]);
        xmax = fmax(xmax, p[0]);
        ymin = fmin(ymin, p[1]);
        ymax = fmax(ymax, p[1]);
    }
    cvm__cell_grid_fit(&B->g, xmin, ymin, xmax, ymax, B->nfe);
    ncell = (size_t)B->g.nx * (size_t)B->g.ny;
    B->gstart = cvm__malloc(B->ctx, (ncell + 1) * sizeof *B->gstart);
    B->excl = cvm__malloc(B->ctx, (B->nfe + 1) * sizeof *B->excl);
    B->seen = cvm__malloc(B->ctx, (B->nfe + 1) * sizeof *B->seen);
    if (!B->gstart || !B->excl || !B->seen)
        return CVM_E_NOMEM;
    memset(B->excl, 0, (B->nfe + 1) * sizeof *B->excl);
    memset(B->seen, 0, (B->nfe + 1) * sizeof *B->seen);
    memset(B->gstart, 0, (ncell + 1) * sizeof *B->gstart);
    for (k = 0; k < B->nfe; k++)
        auto_grid_edge(B, k, NULL);
    for (k = 0; k < ncell; k++)
        B->gstart[k + 1] += B->gstart[k];
    B->gitems = cvm__malloc(B->ctx, ((size_t)B->gstart[ncell] + 1) * sizeof *B->gitems);
    pos = cvm__malloc(B->ctx, (ncell + 1) * sizeof *pos);
    if (!B->gitems || !pos) {
        cvm__free(B->ctx, pos);
        return CVM_E_NOMEM;
    }
    memcpy(pos, B->gstart, (ncell + 1) * sizeof *pos);
    for (k = 0; k < B->nfe; k++)
        auto_grid_edge(B, k, pos);
    cvm__free(B->ctx, pos);
    return CVM_OK;
}

/* Next exclusion stamp (a fresh empty set). */
static void auto_excl_new(auto_build *B)
{
    if (++B->excl_stamp == 0) {
        memset(B->excl, 0, (B->nfe + 1) * sizeof *B->excl);
        B->excl_stamp = 1;
    }
}

static int32_t auto_other(const auto_build *B, int32_t e, int32_t v)
{
    return B->fe[2 * e] == v ? B->fe[2 * e + 1] : B->fe[2 * e];
}

/* Exclude the edges of the smooth chain beyond vertex u, arriving along edge e
 * (from the other end of e): while u has degree 2 and the chain has turned by
 * less than AUTO_CHAIN_TURN in total. */
static void auto_excl_chain(auto_build *B, int32_t e, int32_t u)
{
    double acc = 0;
    int steps = 0;
    int32_t from = auto_other(B, e, u);
    while (B->vstart[u + 1] - B->vstart[u] == 2 && steps++ < AUTO_MAX_CHAIN_STEPS) {
        int32_t f = B->vedges[B->vstart[u]] == e ? B->vedges[B->vstart[u] + 1] : B->vedges[B->vstart[u]];
        int32_t next = auto_other(B, f, u);
        const double *pa = auto_pt(B, from), *pu = auto_pt(B, u), *pn = auto_pt(B, next);
        if (B->excl[f] == B->excl_stamp)
            return; /* closed loop */
        acc += cvm__turn_angle(pa, pu, pn);
        if (acc >= AUTO_CHAIN_TURN)
            return;
        B->excl[f] = B->excl_stamp;
        from = u;
        u = next;
        e = f;
    }
}

/* Exclusion set of vertex v: its edges and the smooth chains beyond them. */
static void auto_excl_vertex(auto_build *B, int32_t v)
{
    int32_t k;
    auto_excl_new(B);
    for (k = B->vstart[v]; k < B->vstart[v + 1]; k++)
        B->excl[B->vedges[k]] = B->excl_stamp;
    for (k = B->vstart[v]; k < B->vstart[v + 1]; k++) {
        int32_t e = B->vedges[k];
        auto_excl_chain(B, e, auto_other(B, e, v));
    }
}

/* Exclusion set of the inside of edge e: e, the edges at its ends, and the
 * smooth chains beyond its ends. */
static void auto_excl_edge(auto_build *B, int32_t e)
{
    int end;
    auto_excl_new(B);
    B->excl[e] = B->excl_stamp;
    for (end = 0; end < 2; end++) {
        int32_t u = B->fe[2 * e + end], k;
        for (k = B->vstart[u]; k < B->vstart[u + 1]; k++)
            B->excl[B->vedges[k]] = B->excl_stamp;
        auto_excl_chain(B, e, u);
    }
}

/* Distance from p to the nearest feature outside the current exclusion set
 * (+inf when there is none). */
static double auto_nearest(auto_build *B, const double *p)
{
    double best = HUGE_VAL;
    int ci, cj, r, rmax = B->g.nx > B->g.ny ? B->g.nx : B->g.ny;
    if (++B->seen_stamp == 0) {
        memset(B->seen, 0, (B->nfe + 1) * sizeof *B->seen);
        B->seen_stamp = 1;
    }
    cvm__cell_grid_cell(&B->g, p[0], p[1], &ci, &cj);
    for (r = 0; r <= rmax; r++) {
        int i, j;
        /* every cell of ring r + 1 is at least r cells away */
        if (r > 0 && (double)(r - 1) * B->g.cs >= best)
            break;
        for (j = cj - r; j <= cj + r; j++) {
            int step = (j == cj - r || j == cj + r) ? 1 : 2 * r;
            if (j < 0 || j >= B->g.ny)
                continue;
            for (i = ci - r; i <= ci + r; i += step > 0 ? step : 1) {
                int32_t q;
                size_t c;
                if (i < 0 || i >= B->g.nx)
                    continue;
                c = (size_t)j * (size_t)B->g.nx + (size_t)i;
                for (q = B->gstart[c]; q < B->gstart[c + 1]; q++) {
                    int32_t e = B->gitems[q];
                    double d;
                    if (B->excl[e] == B->excl_stamp || B->seen[e] == B->seen_stamp)
                        continue;
                    B->seen[e] = B->seen_stamp;
                    d = auto_dist_seg(p, auto_pt(B, B->fe[2 * e]), auto_pt(B, B->fe[2 * e + 1]));
                    if (d < best)
                        best = d;
                }
            }
        }
    }
    return best;
}

static cvm_status auto_add_sample(auto_build *B, double x, double y, double ls)
{
    if (cvm__grow(B->ctx, (void **)&B->smp, &B->cap_smp, 3 * (B->ns + 1), sizeof *B->smp))
        return CVM_E_NOMEM;
    B->smp[3 * B->ns] = x;
    B->smp[3 * B->ns + 1] = y;
    B->smp[3 * B->ns + 2] = ls;
    B->ns++;
    return CVM_OK;
}

/* Samples strictly inside edge e between parameters t0 and t1 whose ends have
 * feature sizes l0 and l1 (exclusion set of e current). */
static cvm_status auto_sample_edge(auto_build *B, int32_t e, double t0, double t1, double l0,
                                 double l1, double curv, double R, double G, int depth)
{
    const double *a = auto_pt(B, B->fe[2 * e]), *b = auto_pt(B, B->fe[2 * e + 1]);
    double len = hypot(b[0] - a[0], b[1] - a[1]) * (t1 - t0), tm = 0.5 * (t0 + t1), p[2], lm;
    cvm_status s;
    if (depth >= AUTO_MAX_DEPTH || !(len > fmin(l0, l1) * fmin(0.5, G / R)))
        return CVM_OK;
    p[0] = a[0] + (b[0] - a[0]) * tm;
    p[1] = a[1] + (b[1] - a[1]) * tm;
    lm = auto_nearest(B, p);
    if ((s = auto_add_sample(B, p[0], p[1], fmin(lm, curv) / R)))
        return s;
    if ((s = auto_sample_edge(B, e, t0, tm, l0, lm, curv, R, G, depth + 1)))
        return s;
    return auto_sample_edge(B, e, tm, t1, lm, l1, curv, R, G, depth + 1);
}

static cvm_status auto_samples(auto_build *B, size_t nv, double R, double G, double *vlfs)
{
    size_t k, v;
    cvm_status s;
    double diam = hypot(B->g.nx * B->g.cs, B->g.ny * B->g.cs);
    for (v = 0; v < nv; v++)
        vlfs[v] = -1;
    for (k = 0; k < 2 * B->nfe; k++) {
        int32_t u = B->fe[k];
        double l;
        if (vlfs[u] >= 0)
            continue;
        auto_excl_vertex(B, u);
        if (B->fe[k ^ 1] == u)
            B->excl[k / 2] = B->excl_stamp; /* a point feature: itself */
        l = auto_nearest(B, auto_pt(B, u));
        if (!isfinite(l))
            l = diam > 0 ? diam : 1;
        vlfs[u] = l;
        if ((s = auto_add_sample(B, auto_pt(B, u)[0], auto_pt(B, u)[1], fmin(l, B->curv[u]) / R)))
            return s;
    }
    for (k = 0; k < B->nfe; k++) {
        int32_t a = B->fe[2 * k], b = B->fe[2 * k + 1];
        double curv = fmin(B->curv[a], B->curv[b]);
        if (a == b)
            continue;
        auto_excl_edge(B, (int32_t)k);
        if ((s = auto_sample_edge(B, (int32_t)k, 0, 1, vlfs[a], vlfs[b], curv, R, G, 0)))
            return s;
    }
    return CVM_OK;
}

/* ---- the field: samples in a grid, evaluated by a ring search ---- */

static cvm_status auto_field_grid(cvm__auto_field *F, cvm__ctx *ctx)
{
    double xmin = HUGE_VAL, ymin = HUGE_VAL, xmax = -HUGE_VAL, ymax = -HUGE_VAL;
    size_t k, ncell;
    int32_t *pos;
    for (k = 0; k < F->ns; k++) {
        xmin = fmin(xmin, F->smp[3 * k]);
        xmax = fmax(xmax, F->smp[3 * k]);
        ymin = fmin(ymin, F->smp[3 * k + 1]);
        ymax = fmax(ymax, F->smp[3 * k + 1]);
        F->ls_min = fmin(F->ls_min, F->smp[3 * k + 2]);
    }
    cvm__cell_grid_fit(&F->g, xmin, ymin, xmax, ymax, F->ns * CELLS_PER_SAMPLE);
    ncell = (size_t)F->g.nx * (size_t)F->g.ny;
    F->start = cvm__malloc(ctx, (ncell + 1) * sizeof *F->start);
    F->cmin = cvm__malloc(ctx, (ncell + 1) * sizeof *F->cmin);
    F->items = cvm__malloc(ctx, (F->ns + 1) * sizeof *F->items);
    pos = cvm__malloc(ctx, (ncell + 1) * sizeof *pos);
    if (!F->start || !F->cmin || !F->items || !pos) {
        cvm__free(ctx, pos);
        return CVM_E_NOMEM;
    }
    memset(F->start, 0, (ncell + 1) * sizeof *F->start);
    for (k = 0; k < ncell; k++)
        F->cmin[k] = HUGE_VAL;
    for (k = 0; k < F->ns; k++) {
        int i, j;
        size_t c;
        cvm__cell_grid_cell(&F->g, F->smp[3 * k], F->smp[3 * k + 1], &i, &j);
        c = (size_t)j * (size_t)F->g.nx + (size_t)i;
        F->start[c + 1]++;
        F->cmin[c] = fmin(F->cmin[c], F->smp[3 * k + 2]);
    }
    for (k = 0; k < ncell; k++)
        F->start[k + 1] += F->start[k];
    memcpy(pos, F->start, (ncell + 1) * sizeof *pos);
    for (k = 0; k < F->ns; k++) {
        int i, j;
        cvm__cell_grid_cell(&F->g, F->smp[3 * k], F->smp[3 * k + 1], &i, &j);
        F->items[pos[(size_t)j * (size_t)F->g.nx + (size_t)i]++] = (int32_t)k;
    }
    cvm__free(ctx, pos);
    return CVM_OK;
}

double cvm__auto_field_below(const cvm__auto_field *F, double x, double y, double bound)
{
    double best = bound, inv_g = 1.0 / F->G;
    int ci, cj, r, rmax;
    if (F->ns == 0)
        return bound;
    rmax = F->g.nx > F->g.ny ? F->g.nx : F->g.ny;
    /* outside the grid: count the rings from the nearest cell, the bound below
       still holds because distances only grow */
    cvm__cell_grid_cell(&F->g, x, y, &ci, &cj);
    for (r = 0; r <= rmax + 1; r++) {
        int i, j;
        if (r > 0 && F->ls_min + (double)(r - 1) * F->g.cs * inv_g >= best)
            break;
        for (j = cj - r; j <= cj + r; j++) {
            int step = (j == cj - r || j == cj + r) ? 1 : 2 * r;
            if (j < 0 || j >= F->g.ny)
                continue;
            for (i = ci - r; i <= ci + r; i += step > 0 ? step : 1) {
                size_t c;
                int32_t q;
                double bx, by;
                if (i < 0 || i >= F->g.nx)
                    continue;
                c = (size_t)j * (size_t)F->g.nx + (size_t)i;
                if (F->start[c] == F->start[c + 1])
                    continue;
                /* distance from (x, y) to the cell box */
                bx = fmax(0.0, fmax(F->g.x0 + i * F->g.cs - x, x - (F->g.x0 + (i + 1) * F->g.cs)));
                by = fmax(0.0, fmax(F->g.y0 + j * F->g.cs - y, y - (F->g.y0 + (j + 1) * F->g.cs)));
                if (F->cmin[c] + hypot(bx, by) * inv_g >= best)
                    continue;
                for (q = F->start[c]; q < F->start[c + 1]; q++) {
                    const double *s = F->smp + 3 * (size_t)F->items[q];
                    double d = s[2] + hypot(x - s[0], y - s[1]) * inv_g;
                    if (d < best)
                        best = d;
                }
            }
        }
    }
    return best;
}

static void auto_build_free(auto_build *B)
{
    cvm__free(B->ctx, B->fe);
    cvm__free(B->ctx, B->vstart);
    cvm__free(B->ctx, B->vedges);
    cvm__free(B->ctx, B->curv);
    cvm__free(B->ctx, B->gstart);
    cvm__free(B->ctx, B->gitems);
    cvm__free(B->ctx, B->excl);
    cvm__free(B->ctx, B->seen);
}

/* Hand the samples of B to F, free B, grid the samples; on any failure (s
 * set, or the grid) F is emptied and CVM_E_NOMEM recorded on ctx. */
static cvm_status auto_finish(cvm__auto_field *F, auto_build *B, cvm_status s, cvm__ctx *ctx)
{
    F->smp = B->smp;
    F->ns = B->ns;
    B->smp = NULL;
    auto_build_free(B);
    if (!s && F->ns > 0 && auto_field_grid(F, ctx))
        s = CVM_E_NOMEM;
    if (s) {
        cvm__auto_field_free(F, ctx);
        return cvm__nomem(ctx);
    }
    return CVM_OK;
}

cvm_status cvm__auto_field_build(cvm__auto_field *F, const cvm__tri2 *T, const uint8_t *is_input,
                                 double R, double G, cvm__ctx *ctx)
{
    auto_build B;
    double *vlfs = NULL;
    cvm_status s = CVM_OK;
    memset(F, 0, sizeof *F);
    memset(&B, 0, sizeof B);
    F->G = G;
    F->ls_min = HUGE_VAL;
    B.ctx = ctx;
    B.xy = T->xy;
    if (auto_collect(&B, T, is_input) || auto_adjacency(&B, T->nv))
        s = CVM_E_NOMEM;
    if (!s && B.nfe > 0) {
        vlfs = cvm__malloc(ctx, (T->nv + 1) * sizeof *vlfs);
        if (!vlfs || auto_grid(&B) || auto_samples(&B, T->nv, R, G, vlfs))
            s = CVM_E_NOMEM;
    }
    cvm__free(ctx, vlfs);
    return auto_finish(F, &B, s, ctx);
}

/* ---- the boundary-spacing field of cvm_sizing_set_boundary_grading() ----
 *
 * Samples: every vertex of a feature edge with LS = its shortest feature
 * edge, and points at equal steps inside each edge longer than the LS of its
 * ends (at most BG_MAX_INNER of them, about one per LS) with LS = the edge's
 * length. The field min over samples of LS + g |x - q| is then, to within
 * g x half a step, h(x) = min over feature edges e of l(e) + g dist(x, e). */
#define BG_MAX_INNER 64

cvm_status cvm__spacing_field_build(cvm__auto_field *F, const cvm__tri2 *T, double g,
                                    cvm__ctx *ctx)
{
    auto_build B;
    uint8_t *no_points = NULL;
    double *vmin = NULL;
    size_t k, v;
    cvm_status s = CVM_OK;
    memset(F, 0, sizeof *F);
    memset(&B, 0, sizeof B);
    F->G = 1.0 / g;
    F->ls_min = HUGE_VAL;
    B.ctx = ctx;
    B.xy = T->xy;
    no_points = cvm__calloc(ctx, T->nv + 1, 1); /* edges only: no point features */
    vmin = cvm__malloc(ctx, (T->nv + 1) * sizeof *vmin);
    if (!no_points || !vmin || auto_collect(&B, T, no_points))
        s = CVM_E_NOMEM;
    for (v = 0; !s && v < T->nv; v++)
        vmin[v] = HUGE_VAL;
    for (k = 0; !s && k < B.nfe; k++) {
        const double *a = auto_pt(&B, B.fe[2 * k]), *b = auto_pt(&B, B.fe[2 * k + 1]);
        double len = hypot(b[0] - a[0], b[1] - a[1]);
        vmin[B.fe[2 * k]] = fmin(vmin[B.fe[2 * k]], len);
        vmin[B.fe[2 * k + 1]] = fmin(vmin[B.fe[2 * k + 1]], len);
    }
    for (v = 0; !s && v < T->nv; v++)
        if (isfinite(vmin[v]) && vmin[v] > 0 && auto_add_sample(&B, T->xy[2 * v], T->xy[2 * v + 1], vmin[v]))
            s = CVM_E_NOMEM;
    for (k = 0; !s && k < B.nfe; k++) {
        int32_t ia = B.fe[2 * k], ib = B.fe[2 * k + 1];
        const double *a = auto_pt(&B, ia), *b = auto_pt(&B, ib);
        double len = hypot(b[0] - a[0], b[1] - a[1]), lend = fmin(vmin[ia], vmin[ib]);
        size_t m, i;
        if (!(len > 0) || !(len > lend))
            continue;
        m = len / lend < (double)BG_MAX_INNER ? (size_t)ceil(len / lend) : BG_MAX_INNER;
        for (i = 1; i < m && !s; i++) {
            double t = (double)i / (double)m;
            if (auto_add_sample(&B, a[0] + t * (b[0] - a[0]), a[1] + t * (b[1] - a[1]), len))
                s = CVM_E_NOMEM;
        }
    }
    cvm__free(ctx, no_points);
    cvm__free(ctx, vmin);
    return auto_finish(F, &B, s, ctx);
}

void cvm__auto_field_free(cvm__auto_field *F, cvm__ctx *ctx)
{
    cvm__free(ctx, F->smp);
    cvm__free(ctx, F->start);
    cvm__free(ctx, F->items);
    cvm__free(ctx, F->cmin);
    memset(F, 0, sizeof *F);
}

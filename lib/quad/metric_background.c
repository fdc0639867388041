/* metric_background.c - per-vertex metric tensors on a background triangulation, interpolated
 * log-Euclidean (Arsigny et al. 2006: g = exp(sum_v lambda_v log g_v)), so every interpolant stays
 * symmetric positive definite, with its exact derivative. */
#include <math.h>
#include <string.h>

#include "quad_internal.h"

void cvm__metric_bg_free(cvm__metric_bg *bg)
{
    if (!bg->ctx)
        return;
    cvm__free(bg->ctx, bg->xy);
    cvm__free(bg->ctx, bg->logg);
    cvm__free(bg->ctx, bg->tri);
    cvm__free(bg->ctx, bg->start);
    cvm__free(bg->ctx, bg->items);
    memset(bg, 0, sizeof *bg);
}

/* The cells of the grid that the bounding box of triangle t covers. */
static void tri_cells(const cvm__metric_bg *bg, size_t t, int *i0, int *j0, int *i1, int *j1)
{
    const int32_t *v = bg->tri + 3 * t;
    double lo[2], hi[2];
    int k;
    lo[0] = hi[0] = bg->xy[2 * v[0]];
    lo[1] = hi[1] = bg->xy[2 * v[0] + 1];
    for (k = 1; k < 3; k++) {
        lo[0] = fmin(lo[0], bg->xy[2 * v[k]]);
        hi[0] = fmax(hi[0], bg->xy[2 * v[k]]);
        lo[1] = fmin(lo[1], bg->xy[2 * v[k] + 1]);
        hi[1] = fmax(hi[1], bg->xy[2 * v[k] + 1]);
    }
    cvm__cell_grid_cell(&bg->grid, lo[0], lo[1], i0, j0);
    cvm__cell_grid_cell(&bg->grid, hi[0], hi[1], i1, j1);
}

static cvm_status bucket(cvm__metric_bg *bg)
{
    size_t ncell, t, k;
    double lo[2], hi[2];
    int i, j, i0, j0, i1, j1;
    lo[0] = hi[0] = bg->xy[0];
    lo[1] = hi[1] = bg->xy[1];
    for (k = 1; k < bg->np; k++) {
        lo[0] = fmin(lo[0], bg->xy[2 * k]);
        hi[0] = fmax(hi[0], bg->xy[2 * k]);
        lo[1] = fmin(lo[1], bg->xy[2 * k + 1]);
        hi[1] = fmax(hi[1], bg->xy[2 * k + 1]);
    }
    cvm__cell_grid_fit(&bg->grid, lo[0], lo[1], hi[0], hi[1], bg->nt);
    ncell = (size_t)bg->grid.nx * (size_t)bg->grid.ny;
    bg->start = cvm__calloc(bg->ctx, ncell + 1, sizeof *bg->start);
    if (!bg->start)
        return cvm__nomem(bg->ctx);
    for (t = 0; t < bg->nt; t++) {
        tri_cells(bg, t, &i0, &j0, &i1, &j1);
        for (j = j0; j <= j1; j++)
            for (i = i0; i <= i1; i++)
                bg->start[(size_t)j * (size_t)bg->grid.nx + (size_t)i + 1]++;
    }
    for (k = 0; k < ncell; k++)
        bg->start[k + 1] += bg->start[k];
    bg->items = cvm__malloc(bg->ctx, ((size_t)bg->start[ncell] + 1) * sizeof *bg->items);
    if (!bg->items)
        return cvm__nomem(bg->ctx);
    for (t = 0; t < bg->nt; t++) { /* in triangle order: each cell's list is sorted */
        tri_cells(bg, t, &i0, &j0, &i1, &j1);
        for (j = j0; j <= j1; j++)
            for (i = i0; i <= i1; i++)
                bg->items[bg->start[(size_t)j * (size_t)bg->grid.nx + (size_t)i]++] = (int32_t)t;
    }
    for (k = ncell; k > 0; k--) /* the fill advanced each start to the next cell's */
        bg->start[k] = bg->start[k - 1];
    bg->start[0] = 0;
    return CVM_OK;
}

cvm_status cvm__metric_bg_build(cvm__metric_bg *bg, cvm__ctx *ctx, const double *xy, size_t np,
                                const int32_t *tri, size_t nt, const double *g)
{
    size_t k;
    memset(bg, 0, sizeof *bg);
    bg->ctx = ctx;
    if (np < 3 || nt < 1)
        return cvm__error(ctx, CVM_E_ARGUMENT, CVM_ENT_NONE, -1,
                          "a background needs 3 nodes and a triangle, got %lu and %lu",
                          (unsigned long)np, (unsigned long)nt);
    for (k = 0; k < np; k++) {
        const double *t = g + 3 * k;
        if (!isfinite(xy[2 * k]) || !isfinite(xy[2 * k + 1]) || !isfinite(t[0]) ||
            !isfinite(t[1]) || !isfinite(t[2]) || !(t[0] > 0) || !(t[0] * t[2] - t[1] * t[1] > 0))
            return cvm__error(ctx, CVM_E_ARGUMENT, CVM_ENT_VERTEX, (int64_t)k,
                              "background node %lu (%.17g, %.17g): the tensor (%.17g, %.17g, "
                              "%.17g) is not finite and positive definite, or the node not finite",
                              (unsigned long)k, xy[2 * k], xy[2 * k + 1], t[0], t[1], t[2]);
    }
    for (k = 0; k < nt; k++) {
        const int32_t *v = tri + 3 * k;
        int j;
        for (j = 0; j < 3; j++)
            if (v[j] < 0 || (size_t)v[j] >= np)
                return cvm__error(ctx, CVM_E_ARGUMENT, CVM_ENT_TRIANGLE, (int64_t)k,
                                  "background triangle %lu names node %ld of %lu", (unsigned long)k,
                                  (long)v[j], (unsigned long)np);
        if ((xy[2 * v[1]] - xy[2 * v[0]]) * (xy[2 * v[2] + 1] - xy[2 * v[0] + 1]) -
                (xy[2 * v[1] + 1] - xy[2 * v[0] + 1]) * (xy[2 * v[2]] - xy[2 * v[0]]) == 0)
            return cvm__error(ctx, CVM_E_ARGUMENT, CVM_ENT_TRIANGLE, (int64_t)k,
                              "background triangle %lu (nodes %ld, %ld, %ld) has no area",
                              (unsigned long)k, (long)v[0], (long)v[1], (long)v[2]);
    }
    bg->xy = cvm__malloc(ctx, 2 * np * sizeof *bg->xy);
    bg->logg = cvm__malloc(ctx, 3 * np * sizeof *bg->logg);
    bg->tri = cvm__malloc(ctx, 3 * nt * sizeof *bg->tri);
    if (!bg->xy || !bg->logg || !bg->tri) {
        cvm_status st = cvm__nomem(ctx);
        cvm__metric_bg_free(bg);
        bg->ctx = ctx;
        return st;
    }
    memcpy(bg->xy, xy, 2 * np * sizeof *xy);
    memcpy(bg->tri, tri, 3 * nt * sizeof *tri);
    bg->np = np;
    bg->nt = nt;
    for (k = 0; k < np; k++) {
        cvm__eig2 e;
        double mu[2];
        cvm__eig2_of(&e, g + 3 * k, NULL);
        mu[0] = log(e.lam[0]);
        mu[1] = log(e.lam[1]);
        cvm__eig2_compose(bg->logg + 3 * k, NULL, e.cs, e.sn, mu, NULL, NULL);
    }
    return bucket(bg);
}

int cvm__metric_bg_fn(void *payload, const double *x, int dim, double *g, double *dg)
{
    const cvm__metric_bg *bg = (const cvm__metric_bg *)payload;
    int i, j, k;
    int32_t a, e;
    if (dim != 2 || !bg->start)
        return 1;
    cvm__cell_grid_cell(&bg->grid, x[0], x[1], &i, &j);
    a = bg->start[(size_t)j * (size_t)bg->grid.nx + (size_t)i];
    e = bg->start[(size_t)j * (size_t)bg->grid.nx + (size_t)i + 1];
    for (; a < e; a++) {
        const int32_t *v = bg->tri + 3 * (size_t)bg->items[a];
        const double *p0 = bg->xy + 2 * v[0], *p1 = bg->xy + 2 * v[1], *p2 = bg->xy + 2 * v[2];
        double D = (p1[0] - p0[0]) * (p2[1] - p0[1]) - (p1[1] - p0[1]) * (p2[0] - p0[0]);
        double l[3], gl[6], L[3], dL[6], mu[2], dmu[4];
        cvm__eig2 ev;
        /* barycentric coordinates; an interpolation choice, not a topological one */
        l[0] = ((p1[0] - x[0]) * (p2[1] - x[1]) - (p1[1] - x[1]) * (p2[0] - x[0])) / D;
        l[1] = ((p2[0] - x[0]) * (p0[1] - x[1]) - (p2[1] - x[1]) * (p0[0] - x[0])) / D;
        l[2] = 1 - l[0] - l[1];
        if (l[0] < -1e-12 || l[1] < -1e-12 || l[2] < -1e-12)
            continue;
        gl[0] = (p1[1] - p2[1]) / D; /* d l0 / dx, d l0 / dy, ... */
        gl[1] = (p2[0] - p1[0]) / D;
        gl[2] = (p2[1] - p0[1]) / D;
        gl[3] = (p0[0] - p2[0]) / D;
        gl[4] = (p0[1] - p1[1]) / D;
        gl[5] = (p1[0] - p0[0]) / D;
        for (k = 0; k < 3; k++) {
            int m;
            L[k] = 0;
            for (m = 0; m < 2; m++)
                dL[3 * m + k] = 0;
            for (m = 0; m < 3; m++) {
                double lv = bg->logg[3 * (size_t)v[m] + (size_t)k];
                L[k] += l[m] * lv;
                dL[k] += gl[2 * m] * lv;
                dL[3 + k] += gl[2 * m + 1] * lv;
            }
        }
        cvm__eig2_of(&ev, L, dL);
        for (k = 0; k < 2; k++) {
            mu[k] = exp(ev.lam[k]);
            dmu[2 * k] = mu[k] * ev.dlam[2 * k];
            dmu[2 * k + 1] = mu[k] * ev.dlam[2 * k + 1];
        }
        cvm__eig2_compose(g, dg, ev.cs, ev.sn, mu, dmu, ev.dth);
        return 0;
    }
    return 1;
}

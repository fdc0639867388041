/* sizing_background.c - sizes given at the nodes of a background triangulation, interpolated linearly. */
#include <math.h>
#include <string.h>

#include "sizing_internal.h"
#include "geom/geom_internal.h"

void cvm__background_free(cvm__background *bg, cvm__ctx *ctx)
{
    if (!bg)
        return;
    cvm__free(ctx, bg->xy);
    cvm__free(ctx, bg->h);
    cvm__free(ctx, bg->tri);
    cvm__free(ctx, bg->start);
    cvm__free(ctx, bg->items);
    cvm__free(ctx, bg);
}

static void bg_node(const double *xyh, int32_t v, double *out)
{
    out[0] = xyh[3 * (size_t)v];
    out[1] = xyh[3 * (size_t)v + 1];
}

/* Cells covered by the bounding box of triangle t (a cvm__cell_range_fn). */
static void bg_tri_cells(const void *payload, size_t t, int *i0, int *j0, int *i1, int *j1)
{
    const cvm__background *bg = payload;
    const int32_t *v = bg->tri + 3 * t;
    double xmin = HUGE_VAL, ymin = HUGE_VAL, xmax = -HUGE_VAL, ymax = -HUGE_VAL;
    int k;
    for (k = 0; k < 3; k++) {
        const double *p = bg->xy + 2 * (size_t)v[k];
        xmin = fmin(xmin, p[0]);
        xmax = fmax(xmax, p[0]);
        ymin = fmin(ymin, p[1]);
        ymax = fmax(ymax, p[1]);
    }
    cvm__cell_grid_cell(&bg->g, xmin, ymin, i0, j0);
    cvm__cell_grid_cell(&bg->g, xmax, ymax, i1, j1);
}

static cvm_status bg_grid(cvm__background *bg, cvm__ctx *ctx)
{
    double xmin = HUGE_VAL, ymin = HUGE_VAL, xmax = -HUGE_VAL, ymax = -HUGE_VAL;
    size_t k;
    for (k = 0; k < bg->np; k++) {
        xmin = fmin(xmin, bg->xy[2 * k]);
        xmax = fmax(xmax, bg->xy[2 * k]);
        ymin = fmin(ymin, bg->xy[2 * k + 1]);
        ymax = fmax(ymax, bg->xy[2 * k + 1]);
    }
    cvm__cell_grid_fit(&bg->g, xmin, ymin, xmax, ymax, bg->nt);
    return cvm__cell_grid_bucket(ctx, &bg->g, bg->nt, bg_tri_cells, bg, &bg->start, &bg->items);
}

cvm_status cvm_sizing_set_background(cvm_sizing *s, const double *xyh, size_t npoints,
                                     const cvm_index *tri, size_t ntri)
{
    cvm__background *bg;
    cvm__ctx *ctx;
    size_t k;
    cvm_status st;
    if (!s)
        return CVM_E_NULL_ARG;
    ctx = &s->ctx;
    cvm__clear_error(ctx);
    if (npoints == 0 && ntri == 0) {
        cvm__background_free(s->bg, ctx);
        s->bg = NULL;
        cvm__sizing_recount_dim(s);
        return CVM_OK;
    }
    if ((st = cvm__sizing_check_dim(s, 2, "background mesh")))
        return st;
    if (!xyh || (!tri && ntri > 0))
        return cvm__error(ctx, CVM_E_NULL_ARG, CVM_ENT_NONE, -1,
                          "background mesh: xyh or tri is NULL");
    if (npoints > (size_t)INT32_MAX / 4 || ntri > (size_t)INT32_MAX / 4)
        return cvm__error(ctx, CVM_E_TOO_LARGE, CVM_ENT_NONE, -1,
                          "background mesh: %zu nodes and %zu triangles exceed what cvm_index "
                          "can address",
                          npoints, ntri);
    for (k = 0; k < npoints; k++) {
        double h = xyh[3 * k + 2];
        if (!isfinite(xyh[3 * k]) || !isfinite(xyh[3 * k + 1]))
            return cvm__error(ctx, CVM_E_INPUT_NONFINITE, CVM_ENT_NONE, (int64_t)k,
                              "background node %zu has a non-finite coordinate", k);
        if (!isfinite(h))
            return cvm__error(ctx, CVM_E_INPUT_NONFINITE, CVM_ENT_NONE, (int64_t)k,
                              "background node %zu has a non-finite size (must be positive "
                              "and finite)",
                              k);
        if (!(h > 0))
            return cvm__error(ctx, CVM_E_ARGUMENT, CVM_ENT_NONE, (int64_t)k,
                              "background node %zu has size %.17g (must be positive and finite)",
                              k, h);
    }
    for (k = 0; k < ntri; k++) {
        int j;
        for (j = 0; j < 3; j++)
            if (tri[3 * k + (size_t)j] < 0 || (size_t)tri[3 * k + (size_t)j] >= npoints)
                return cvm__error(ctx, CVM_E_INPUT_INDEX, CVM_ENT_NONE, (int64_t)k,
                                  "background triangle %zu names node %ld, not in [0, %zu)", k,
                                  (long)tri[3 * k + (size_t)j], npoints);
        double a[2], b[2], c[2];
        bg_node(xyh, tri[3 * k], a);
        bg_node(xyh, tri[3 * k + 1], b);
        bg_node(xyh, tri[3 * k + 2], c);
        if (cvm__orient2d(a, b, c) == 0)
            return cvm__error(ctx, CVM_E_INPUT_DEGENERATE, CVM_ENT_NONE, (int64_t)k,
                              "background triangle %zu has zero area", k);
    }
    bg = cvm__malloc(ctx, sizeof *bg);
    if (!bg)
        return cvm__nomem(ctx);
    memset(bg, 0, sizeof *bg);
    bg->np = npoints;
    bg->nt = ntri;
    bg->xy = cvm__malloc(ctx, 2 * npoints * sizeof *bg->xy + 1);
    bg->h = cvm__malloc(ctx, npoints * sizeof *bg->h + 1);
    bg->tri = cvm__malloc(ctx, 3 * ntri * sizeof *bg->tri + 1);
    if (!bg->xy || !bg->h || !bg->tri) {
        cvm__background_free(bg, ctx);
        return cvm__nomem(ctx);
    }
    for (k = 0; k < npoints; k++) {
        bg->xy[2 * k] = xyh[3 * k];
        bg->xy[2 * k + 1] = xyh[3 * k + 1];
        bg->h[k] = xyh[3 * k + 2];
    }
    for (k = 0; k < ntri; k++) {
        int32_t a = tri[3 * k], b = tri[3 * k + 1], c = tri[3 * k + 2];
        if (cvm__orient2d(bg->xy + 2 * (size_t)a, bg->xy + 2 * (size_t)b,
                          bg->xy + 2 * (size_t)c) < 0) {
            int32_t t = b;
            b = c;
            c = t;
        }
        bg->tri[3 * k] = a;
        bg->tri[3 * k + 1] = b;
        bg->tri[3 * k + 2] = c;
    }
    if ((st = bg_grid(bg, ctx)) != CVM_OK) {
        cvm__background_free(bg, ctx);
        if (st == CVM_E_TOO_LARGE)
            return cvm__error(ctx, st, CVM_ENT_NONE, -1,
                              "background mesh: its triangles cover too many grid cells");
        return cvm__nomem(ctx);
    }
    cvm__background_free(s->bg, ctx);
    s->bg = bg;
    s->dim = 2;
    return CVM_OK;
}

double cvm__background_at(const cvm__background *bg, double x, double y)
{
    double best = HUGE_VAL, p[2];
    int i, j;
    size_t c;
    int32_t q;
    if (!bg || bg->nt == 0)
        return HUGE_VAL;
    if (x < bg->g.x0 || y < bg->g.y0 || x > bg->g.x0 + bg->g.nx * bg->g.cs || y > bg->g.y0 + bg->g.ny * bg->g.cs)
        return HUGE_VAL;
    p[0] = x;
    p[1] = y;
    cvm__cell_grid_cell(&bg->g, x, y, &i, &j);
    c = (size_t)j * (size_t)bg->g.nx + (size_t)i;
    for (q = bg->start[c]; q < bg->start[c + 1]; q++) {
        const int32_t *v = bg->tri + 3 * (size_t)bg->items[q];
        const double *a = bg->xy + 2 * (size_t)v[0], *b = bg->xy + 2 * (size_t)v[1],
                     *d = bg->xy + 2 * (size_t)v[2];
        double la, lb, ld, area, val;
        /* containment decided exactly (closed triangle), weights in doubles */
        if (cvm__orient2d(a, b, p) < 0 || cvm__orient2d(b, d, p) < 0 || cvm__orient2d(d, a, p) < 0)
            continue;
        area = (b[0] - a[0]) * (d[1] - a[1]) - (b[1] - a[1]) * (d[0] - a[0]);
        la = ((b[0] - x) * (d[1] - y) - (b[1] - y) * (d[0] - x)) / area;
        lb = ((d[0] - x) * (a[1] - y) - (d[1] - y) * (a[0] - x)) / area;
        ld = 1 - la - lb;
        la = fmax(la, 0);
        lb = fmax(lb, 0);
        ld = fmax(ld, 0);
        val = (la * bg->h[v[0]] + lb * bg->h[v[1]] + ld * bg->h[v[2]]) / (la + lb + ld);
        if (val < best)
            best = val;
    }
    return best;
}

/* sizing_background3.c - sizes given at the nodes of a background tetrahedral mesh, interpolated
 * linearly inside its tetrahedra (the least value where they overlap, no bound outside). */
#include <math.h>
#include <string.h>

#include "sizing_internal.h"
#include "geom/geom_internal.h"

struct cvm__background3 {
    double *xyz, *h;      /* 3 and 1 per node */
    int32_t *tet;         /* 4 per tetrahedron, orient3d(a, b, c, d) > 0 */
    size_t np, nt;
    double lo[3], hi[3], hmin;
    cvm__cell_grid g;     /* tetrahedra bucketed by the x-y extent of their boxes */
    int32_t *start, *items;
};

void cvm__background3_free(cvm__background3 *bg, cvm__ctx *ctx)
{
    if (!bg)
        return;
    cvm__free(ctx, bg->xyz);
    cvm__free(ctx, bg->h);
    cvm__free(ctx, bg->tet);
    cvm__free(ctx, bg->start);
    cvm__free(ctx, bg->items);
    cvm__free(ctx, bg);
}

double cvm__background3_min(const cvm__background3 *bg)
{
    return bg->hmin;
}

void cvm__background3_box(const cvm__background3 *bg, double *lo, double *hi)
{
    int k;
    for (k = 0; k < 3; k++) {
        lo[k] = bg->lo[k];
        hi[k] = bg->hi[k];
    }
}

/* Cells covered by the x-y box of tetrahedron t (a cvm__cell_range_fn). */
static void bg3_tet_cells(const void *payload, size_t t, int *i0, int *j0, int *i1, int *j1)
{
    const cvm__background3 *bg = payload;
    double lo[2] = {HUGE_VAL, HUGE_VAL}, hi[2] = {-HUGE_VAL, -HUGE_VAL};
    int c, k;
    for (c = 0; c < 4; c++)
        for (k = 0; k < 2; k++) {
            double v = bg->xyz[3 * (size_t)bg->tet[4 * t + (size_t)c] + (size_t)k];
            lo[k] = fmin(lo[k], v);
            hi[k] = fmax(hi[k], v);
        }
    cvm__cell_grid_cell(&bg->g, lo[0], lo[1], i0, j0);
    cvm__cell_grid_cell(&bg->g, hi[0], hi[1], i1, j1);
}

static cvm_status bg3_grid(cvm__background3 *bg, cvm__ctx *ctx)
{
    cvm__cell_grid_fit(&bg->g, bg->lo[0], bg->lo[1], bg->hi[0], bg->hi[1], bg->nt);
    return cvm__cell_grid_bucket(ctx, &bg->g, bg->nt, bg3_tet_cells, bg, &bg->start, &bg->items);
}

/* Check the nodes (x, y, z, h each) and tetrahedra of a 3D background. */
static cvm_status bg3_check(cvm__ctx *ctx, const double *xyzh, size_t np, const cvm_index *tet,
                            size_t nt)
{
    size_t k;
    for (k = 0; k < np; k++) {
        const double *v = xyzh + 4 * k;
        if (!isfinite(v[0]) || !isfinite(v[1]) || !isfinite(v[2]))
            return cvm__error(ctx, CVM_E_INPUT_NONFINITE, CVM_ENT_NONE, (int64_t)k,
                              "background node %zu has a non-finite coordinate", k);
        if (!isfinite(v[3]))
            return cvm__error(ctx, CVM_E_INPUT_NONFINITE, CVM_ENT_NONE, (int64_t)k,
                              "background node %zu has a non-finite size (must be positive "
                              "and finite)",
                              k);
        if (!(v[3] > 0))
            return cvm__error(ctx, CVM_E_ARGUMENT, CVM_ENT_NONE, (int64_t)k,
                              "background node %zu has size %.17g (must be positive and finite)",
                              k, v[3]);
    }
    for (k = 0; k < nt; k++) {
        int j;
        for (j = 0; j < 4; j++)
            if (tet[4 * k + (size_t)j] < 0 || (size_t)tet[4 * k + (size_t)j] >= np)
                return cvm__error(ctx, CVM_E_INPUT_INDEX, CVM_ENT_NONE, (int64_t)k,
                                  "background tetrahedron %zu names node %ld, not in [0, %zu)",
                                  k, (long)tet[4 * k + (size_t)j], np);
        if (cvm__orient3d(xyzh + 4 * (size_t)tet[4 * k], xyzh + 4 * (size_t)tet[4 * k + 1],
                          xyzh + 4 * (size_t)tet[4 * k + 2], xyzh + 4 * (size_t)tet[4 * k + 3]) == 0)
            return cvm__error(ctx, CVM_E_INPUT_DEGENERATE, CVM_ENT_NONE, (int64_t)k,
                              "background tetrahedron %zu has zero volume", k);
    }
    return CVM_OK;
}

cvm_status cvm__background3_set(cvm_sizing *s, const double *xyzh, size_t np, const cvm_index *tet,
                                size_t nt)
{
    cvm__ctx *ctx = &s->ctx;
    cvm__background3 *bg;
    size_t k;
    cvm_status st;
    if ((st = bg3_check(ctx, xyzh, np, tet, nt)))
        return st;
    if (!(bg = cvm__calloc(ctx, 1, sizeof *bg)))
        return cvm__nomem(ctx);
    bg->np = np;
    bg->nt = nt;
    bg->xyz = cvm__malloc(ctx, 3 * np * sizeof *bg->xyz + 1);
    bg->h = cvm__malloc(ctx, np * sizeof *bg->h + 1);
    bg->tet = cvm__malloc(ctx, 4 * nt * sizeof *bg->tet + 1);
    if (!bg->xyz || !bg->h || !bg->tet) {
        cvm__background3_free(bg, ctx);
        return cvm__nomem(ctx);
    }
    bg->hmin = HUGE_VAL;
    for (k = 0; k < 3; k++) {
        bg->lo[k] = HUGE_VAL;
        bg->hi[k] = -HUGE_VAL;
    }
    for (k = 0; k < np; k++) {
        int a;
        for (a = 0; a < 3; a++) {
            bg->xyz[3 * k + (size_t)a] = xyzh[4 * k + (size_t)a];
            bg->lo[a] = fmin(bg->lo[a], xyzh[4 * k + (size_t)a]);
            bg->hi[a] = fmax(bg->hi[a], xyzh[4 * k + (size_t)a]);
        }
        bg->h[k] = xyzh[4 * k + 3];
    }
    for (k = 0; k < nt; k++) {
        int32_t v[4];
        int j;
        for (j = 0; j < 4; j++)
            v[j] = tet[4 * k + (size_t)j];
        if (cvm__orient3d(bg->xyz + 3 * (size_t)v[0], bg->xyz + 3 * (size_t)v[1],
                          bg->xyz + 3 * (size_t)v[2], bg->xyz + 3 * (size_t)v[3]) < 0) {
            int32_t t = v[2];
            v[2] = v[3];
            v[3] = t;
        }
        for (j = 0; j < 4; j++) {
            bg->tet[4 * k + (size_t)j] = v[j];
            bg->hmin = fmin(bg->hmin, bg->h[v[j]]);
        }
    }
    if ((st = bg3_grid(bg, ctx)) != CVM_OK) {
        cvm__background3_free(bg, ctx);
        if (st == CVM_E_TOO_LARGE)
            return cvm__error(ctx, st, CVM_ENT_NONE, -1,
                              "background mesh: its tetrahedra cover too many grid cells");
        return cvm__nomem(ctx);
    }
    cvm__background3_free(s->bg3, ctx);
    s->bg3 = bg;
    s->dim = 3;
    return CVM_OK;
}

double cvm__background3_at(const cvm__background3 *bg, const double *x)
{
    double best = HUGE_VAL;
    int i, j, k;
    size_t c;
    int32_t q;
    if (!bg || bg->nt == 0)
        return HUGE_VAL;
    for (k = 0; k < 3; k++)
        if (x[k] < bg->lo[k] || x[k] > bg->hi[k])
            return HUGE_VAL;
    cvm__cell_grid_cell(&bg->g, x[0], x[1], &i, &j);
    c = (size_t)j * (size_t)bg->g.nx + (size_t)i;
    for (q = bg->start[c]; q < bg->start[c + 1]; q++) {
        const int32_t *v = bg->tet + 4 * (size_t)bg->items[q];
        const double *p[4];
        double w[4], sum = 0, val = 0;
        int n;
        for (n = 0; n < 4; n++)
            p[n] = bg->xyz + 3 * (size_t)v[n];
        /* containment decided exactly (closed tetrahedron): x replacing each
         * corner keeps the orientation; the same volumes weigh the sizes */
        w[0] = cvm__orient3d(x, p[1], p[2], p[3]);
        w[1] = cvm__orient3d(p[0], x, p[2], p[3]);
        w[2] = cvm__orient3d(p[0], p[1], x, p[3]);
        w[3] = cvm__orient3d(p[0], p[1], p[2], x);
        if (w[0] < 0 || w[1] < 0 || w[2] < 0 || w[3] < 0)
            continue;
        for (n = 0; n < 4; n++) {
            sum += w[n];
            val += w[n] * bg->h[v[n]];
        }
        val = sum > 0 ? val / sum : bg->h[v[0]];
        best = val < best ? val : best;
    }
    return best;
}

/*
 * g3_trigrid.c - the surface triangles in a uniform grid for "is any triangle
 * within r of x" (r at most the reach the grid was made for): each triangle
 * is listed in every cell its bounding box, grown by the reach, meets, so one
 * cell answers a query. The cell edge is twice the reach, enlarged when the
 * cells would outnumber 8 per triangle.
 */
#include <math.h>

#include "generate3/generate3.h"

struct cvm__g3_trigrid {
    cvm__ctx *ctx;
    const cvm__g3_surface *s;
    double lo[3], cell, reach;
    int64_t dim[3];
    int32_t *start; /* ncell + 1 */
    int32_t *idx;
};

static int64_t tg_axis(const cvm__g3_trigrid *g, double v, int k)
{
    return cvm__g3_cell_at(v, g->lo[k], g->cell, g->dim[k]);
}

static void tg_box(const cvm__g3_trigrid *g, size_t f, int64_t *c0, int64_t *c1)
{
    const int32_t *t = g->s->tri + 3 * f;
    int k, q;
    for (k = 0; k < 3; k++) {
        double lo = g->s->xyz[3 * (size_t)t[0] + (size_t)k], hi = lo;
        for (q = 1; q < 3; q++) {
            double v = g->s->xyz[3 * (size_t)t[q] + (size_t)k];
            lo = v < lo ? v : lo;
            hi = v > hi ? v : hi;
        }
        c0[k] = tg_axis(g, lo - g->reach, k);
        c1[k] = tg_axis(g, hi + g->reach, k);
    }
}

void cvm__g3_trigrid_free(cvm__g3_trigrid *g)
{
    if (!g)
        return;
    cvm__free(g->ctx, g->start);
    cvm__free(g->ctx, g->idx);
    cvm__free(g->ctx, g);
}

cvm_status cvm__g3_trigrid_create(cvm__g3_trigrid **out, cvm__ctx *ctx, const cvm__g3_surface *s,
                                  double reach)
{
    cvm__g3_trigrid *g;
    double hi[3], cells;
    size_t f, ncell, total = 0;
    int k, pass;
    *out = NULL;
    if (!(g = cvm__calloc(ctx, 1, sizeof *g)))
        return cvm__nomem(ctx);
    g->ctx = ctx;
    g->s = s;
    g->reach = reach > 0 ? reach : 0;
    for (k = 0; k < 3; k++)
        g->lo[k] = hi[k] = s->np ? s->xyz[k] : 0;
    for (f = 0; f < s->np; f++)
        for (k = 0; k < 3; k++) {
            double v = s->xyz[3 * f + (size_t)k];
            g->lo[k] = v < g->lo[k] ? v : g->lo[k];
            hi[k] = v > hi[k] ? v : hi[k];
        }
    g->cell = 2 * g->reach;
    for (;;) {
        cells = 1;
        for (k = 0; k < 3; k++)
            cells *= g->cell > 0 ? floor((hi[k] - g->lo[k]) / g->cell) + 1 : 1;
        if (g->cell > 0 && cells <= 8.0 * (double)(s->nt + 1))
            break;
        g->cell = g->cell > 0 ? 2 * g->cell : (hi[0] - g->lo[0]) + (hi[1] - g->lo[1]) +
                                                  (hi[2] - g->lo[2]) + 1;
    }
    for (k = 0; k < 3; k++)
        g->dim[k] = (int64_t)floor((hi[k] - g->lo[k]) / g->cell) + 1;
    ncell = (size_t)(g->dim[0] * g->dim[1] * g->dim[2]);
    if (!(g->start = cvm__calloc(ctx, ncell + 2, sizeof *g->start))) {
        cvm__g3_trigrid_free(g);
        return cvm__nomem(ctx);
    }
    /* pass 0 counts per cell, pass 1 fills */
    for (pass = 0; pass < 2; pass++) {
        for (f = 0; f < s->nt; f++) {
            int64_t c0[3], c1[3], i, j, l;
            tg_box(g, f, c0, c1);
            for (l = c0[2]; l <= c1[2]; l++)
                for (j = c0[1]; j <= c1[1]; j++)
                    for (i = c0[0]; i <= c1[0]; i++) {
                        size_t c = (size_t)((l * g->dim[1] + j) * g->dim[0] + i);
                        if (pass == 0) {
                            g->start[c + 2]++;
                            total++;
                        } else {
                            g->idx[g->start[c + 1]++] = (int32_t)f;
                        }
                    }
        }
        if (pass == 0) {
            size_t c;
            if (total > (size_t)INT32_MAX) {
                cvm__g3_trigrid_free(g);
                return cvm__error(ctx, CVM_E_TOO_LARGE, CVM_ENT_NONE, -1,
                                  "the surface's triangle grid passes 2^31 entries");
            }
            for (c = 2; c < ncell + 2; c++)
                g->start[c] += g->start[c - 1];
            if (!(g->idx = cvm__malloc(ctx, (total + 1) * sizeof *g->idx))) {
                cvm__g3_trigrid_free(g);
                return cvm__nomem(ctx);
            }
        }
    }
    *out = g;
    return CVM_OK;
}

int cvm__g3_trigrid_near(const cvm__g3_trigrid *g, const double *x, double r)
{
    size_t c = (size_t)((tg_axis(g, x[2], 2) * g->dim[1] + tg_axis(g, x[1], 1)) * g->dim[0] +
                        tg_axis(g, x[0], 0)),
           q;
    for (q = (size_t)g->start[c]; q < (size_t)g->start[c + 1]; q++) {
        const int32_t *t = g->s->tri + 3 * (size_t)g->idx[q];
        if (cvm__g3_tri_dist2(x, g->s->xyz + 3 * (size_t)t[0], g->s->xyz + 3 * (size_t)t[1],
                              g->s->xyz + 3 * (size_t)t[2]) < r * r)
            return 1;
    }
    return 0;
}

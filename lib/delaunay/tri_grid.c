/* tri_grid.c - which of a set of triangles holds a point: a uniform grid over
 * them (a mesh file's cells, for the rebuild of rebuild.c). */
#include <math.h>
#include <stdint.h>
#include <string.h>

#include "tri_grid.h"
#include "geom/geom_internal.h"

/* Cell of (v - lo) * s among n; monotone in v, NaN (0 * inf) to cell 0. */
static size_t grid_cell(double v, double lo, double s, size_t n)
{
    double c = (v - lo) * s;
    if (!(c > 0))
        return 0;
    return c < (double)n ? (size_t)c : n - 1;
}

static void grid_box(const cvm__tri_grid *g, size_t k, size_t *box)
{
    const int32_t *t = g->tri + 3 * k;
    double lo[2], hi[2];
    int i, d;
    for (d = 0; d < 2; d++) {
        lo[d] = hi[d] = g->xy[2 * (size_t)t[0] + (size_t)d];
        for (i = 1; i < 3; i++) {
            double v = g->xy[2 * (size_t)t[i] + (size_t)d];
            lo[d] = v < lo[d] ? v : lo[d];
            hi[d] = v > hi[d] ? v : hi[d];
        }
    }
    box[0] = grid_cell(lo[0], g->x0, g->sx, g->side);
    box[1] = grid_cell(hi[0], g->x0, g->sx, g->side);
    box[2] = grid_cell(lo[1], g->y0, g->sy, g->side);
    box[3] = grid_cell(hi[1], g->y0, g->sy, g->side);
}

void cvm__tri_grid_free(cvm__ctx *ctx, cvm__tri_grid *g)
{
    cvm__free(ctx, g->start);
    cvm__free(ctx, g->idx);
    memset(g, 0, sizeof *g);
}

/* The number of listings with side cells per axis, or 0 when it would exceed
 * limit. */
static size_t grid_count(cvm__tri_grid *g, const double *hi, size_t side, size_t limit)
{
    size_t k, n = 0, box[4];
    g->side = side;
    g->sx = hi[0] > g->x0 ? (double)side / (hi[0] - g->x0) : 0;
    g->sy = hi[1] > g->y0 ? (double)side / (hi[1] - g->y0) : 0;
    for (k = 0; k < g->nt; k++) {
        size_t c;
        grid_box(g, k, box);
        c = (box[1] - box[0] + 1) * (box[3] - box[2] + 1);
        if (c > limit - n)
            return 0;
        n += c;
    }
    return n;
}

/* Build g with about one cell per triangle, or fewer cells when the bounding
 * boxes (long thin triangles across the domain) would list the triangles more
 * than 16 times over; one cell lists each triangle once. CVM_OK or
 * CVM_E_NOMEM. */
cvm_status cvm__tri_grid_build(cvm__ctx *ctx, cvm__tri_grid *g, const double *xy, size_t np,
                                const int32_t *tri, size_t nt)
{
    size_t k, c, i, j, box[4], limit = 16 * nt + 1024, side = 1;
    double hi[2];
    memset(g, 0, sizeof *g);
    g->xy = xy;
    g->np = np;
    g->tri = tri;
    g->nt = nt;
    g->x0 = hi[0] = g->np ? g->xy[0] : 0;
    g->y0 = hi[1] = g->np ? g->xy[1] : 0;
    for (k = 1; k < g->np; k++) {
        double x = g->xy[2 * k], y = g->xy[2 * k + 1];
        g->x0 = x < g->x0 ? x : g->x0;
        g->y0 = y < g->y0 ? y : g->y0;
        hi[0] = x > hi[0] ? x : hi[0];
        hi[1] = y > hi[1] ? y : hi[1];
    }
    while (side * side < g->nt && side < 65536)
        side++;
    while ((g->n = grid_count(g, hi, side, limit)) == 0 && side > 1)
        side /= 2;
    g->start = cvm__calloc(ctx, side * side + 1, sizeof *g->start);
    g->idx = cvm__malloc(ctx, (g->n + 1) * sizeof *g->idx);
    if (!g->start || !g->idx) {
        cvm__tri_grid_free(ctx, g);
        return CVM_E_NOMEM;
    }
    for (k = 0; k < g->nt; k++) {
        grid_box(g, k, box);
        for (j = box[2]; j <= box[3]; j++)
            for (i = box[0]; i <= box[1]; i++)
                g->start[j * side + i + 1]++;
    }
    for (c = 0; c < side * side; c++) /* start[c]: where cell c begins */
        g->start[c + 1] += g->start[c];
    for (k = 0; k < g->nt; k++) { /* start[c] advances to the end of cell c ... */
        grid_box(g, k, box);
        for (j = box[2]; j <= box[3]; j++)
            for (i = box[0]; i <= box[1]; i++)
                g->idx[g->start[j * side + i]++] = (int32_t)k;
    }
    for (c = side * side; c > 0; c--) /* ... which is where cell c + 1 begins */
        g->start[c] = g->start[c - 1];
    g->start[0] = 0;
    return CVM_OK;
}

/* 1 when p lies in (or on) triangle k (exact orientation tests). */
static int in_cell(const cvm__tri_grid *g, size_t k, const double *p)
{
    const int32_t *t = g->tri + 3 * k;
    const double *a = g->xy + 2 * (size_t)t[0], *b = g->xy + 2 * (size_t)t[1],
                 *c = g->xy + 2 * (size_t)t[2];
    double o1 = cvm__orient2d(a, b, p), o2 = cvm__orient2d(b, c, p), o3 = cvm__orient2d(c, a, p);
    /* either orientation */
    return (o1 >= 0 && o2 >= 0 && o3 >= 0) || (o1 <= 0 && o2 <= 0 && o3 <= 0);
}

int cvm__tri_grid_contains(const cvm__tri_grid *g, const double *p)
{
    size_t c = grid_cell(p[1], g->y0, g->sy, g->side) * g->side +
               grid_cell(p[0], g->x0, g->sx, g->side), e;
    for (e = g->start[c]; e < g->start[c + 1]; e++)
        if (in_cell(g, (size_t)g->idx[e], p))
            return 1;
    return 0;
}

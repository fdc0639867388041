/*
 * self_intersect.c - finds two faces of a surface that meet other than in
 * their shared corners and edges: a uniform grid over the bounding box (about
 * one cell per triangle) lists the triangles whose bounding boxes touch each
 * cell; each pair of boxes that overlap is tested once, in the lowest cell
 * both occupy, by the exact tests of tri_intersect.c.
 *
 * Cell numbers come from floating-point arithmetic, which is monotone, so two
 * closed boxes that overlap always share a cell; the box overlap test itself
 * compares input coordinates and is exact.
 */
#include <math.h>
#include <stdio.h>
#include <string.h>

#include "surface3_internal.h"

#define MAX_DIM 1024

typedef struct grid {
    double lo[3], inv[3];
    int32_t dim[3];
    size_t *start;     /* ncell+1 */
    int32_t *item;     /* triangles by cell */
} grid;

static int32_t cell_of(const grid *g, int k, double x)
{
    double c = floor((x - g->lo[k]) * g->inv[k]);
    if (!(c > 0))
        return 0;
    if (c >= g->dim[k])
        return g->dim[k] - 1;
    return (int32_t)c;
}

static void tri_box(const cvm__surf3 *s, const int32_t *t, double *lo, double *hi)
{
    int k, j;
    for (k = 0; k < 3; k++) {
        lo[k] = hi[k] = s->xyz[3 * t[0] + k];
        for (j = 1; j < 3; j++) {
            double v = s->xyz[3 * t[j] + k];
            lo[k] = v < lo[k] ? v : lo[k];
            hi[k] = v > hi[k] ? v : hi[k];
        }
    }
}

static void cell_range(const grid *g, const cvm__surf3 *s, const int32_t *t, int32_t *c0, int32_t *c1)
{
    double lo[3], hi[3];
    int k;
    tri_box(s, t, lo, hi);
    for (k = 0; k < 3; k++) {
        c0[k] = cell_of(g, k, lo[k]);
        c1[k] = cell_of(g, k, hi[k]);
    }
}

static void grid_shape(grid *g, const cvm__surf3 *s, const cvm__surf3_tris *t)
{
    double hi[3], ext = 0.0, h;
    size_t i;
    int k;
    for (k = 0; k < 3; k++)
        g->lo[k] = hi[k] = s->np ? s->xyz[k] : 0.0;
    for (i = 0; i < s->np; i++)
        for (k = 0; k < 3; k++) {
            double v = s->xyz[3 * i + k];
            g->lo[k] = v < g->lo[k] ? v : g->lo[k];
            hi[k] = v > hi[k] ? v : hi[k];
        }
    for (k = 0; k < 3; k++)
        ext = hi[k] - g->lo[k] > ext ? hi[k] - g->lo[k] : ext;
    h = ext / ceil(cbrt((double)(t->nt ? t->nt : 1)));
    for (k = 0; k < 3; k++) {
        double n = h > 0 ? ceil((hi[k] - g->lo[k]) / h) : 1.0;
        g->dim[k] = n < 1 ? 1 : n > MAX_DIM ? MAX_DIM : (int32_t)n;
        g->inv[k] = hi[k] > g->lo[k] ? g->dim[k] / (hi[k] - g->lo[k]) : 0.0;
    }
}

static cvm_status grid_fill(cvm__ctx *ctx, grid *g, const cvm__surf3 *s, const cvm__surf3_tris *t)
{
    size_t ncell = (size_t)g->dim[0] * (size_t)g->dim[1] * (size_t)g->dim[2], i, total = 0;
    int pass;
    g->start = cvm__calloc(ctx, ncell + 1, sizeof(size_t));
    if (!g->start)
        return cvm__nomem(ctx);
    for (pass = 0; pass < 2; pass++) {
        for (i = 0; i < t->nt; i++) {
            int32_t c0[3], c1[3], x, y, z;
            cell_range(g, s, t->tri + 3 * i, c0, c1);
            for (z = c0[2]; z <= c1[2]; z++)
                for (y = c0[1]; y <= c1[1]; y++)
                    for (x = c0[0]; x <= c1[0]; x++) {
                        size_t c = ((size_t)z * (size_t)g->dim[1] + (size_t)y) * (size_t)g->dim[0] + (size_t)x;
                        if (pass == 0)
                            g->start[c + 1]++;
                        else
                            g->item[g->start[c]++] = (int32_t)i;
                    }
        }
        if (pass == 0) {
            for (i = 0; i < ncell; i++)
                g->start[i + 1] += g->start[i];
            total = g->start[ncell];
            g->item = cvm__malloc(ctx, (total ? total : 1) * sizeof(int32_t));
            if (!g->item)
                return cvm__nomem(ctx);
        }
    }
    /* the second pass advanced each start to the next cell's: shift back */
    for (i = ncell; i > 0; i--)
        g->start[i] = g->start[i - 1];
    g->start[0] = 0;
    return CVM_OK;
}

static int boxes_overlap(const cvm__surf3 *s, const int32_t *a, const int32_t *b)
{
    double alo[3], ahi[3], blo[3], bhi[3];
    int k;
    tri_box(s, a, alo, ahi);
    tri_box(s, b, blo, bhi);
    for (k = 0; k < 3; k++)
        if (ahi[k] < blo[k] || bhi[k] < alo[k])
            return 0;
    return 1;
}

/* Test the pair (a, b) met in cell (x, y, z) if it is the lowest cell both occupy. */
static int pair_meets(const grid *g, const cvm__surf3 *s, const cvm__surf3_tris *t, int32_t a, int32_t b,
                      const int32_t *cell)
{
    int32_t a0[3], a1[3], b0[3], b1[3];
    const int32_t *ta = t->tri + 3 * a, *tb = t->tri + 3 * b;
    int k;
    cell_range(g, s, ta, a0, a1);
    cell_range(g, s, tb, b0, b1);
    for (k = 0; k < 3; k++)
        if (cell[k] != (a0[k] > b0[k] ? a0[k] : b0[k]))
            return 0;
    if (!boxes_overlap(s, ta, tb))
        return 0;
    return cvm__tri_tri_improper(s->xyz + 3 * ta[0], s->xyz + 3 * ta[1], s->xyz + 3 * ta[2],
                                 s->xyz + 3 * tb[0], s->xyz + 3 * tb[1], s->xyz + 3 * tb[2], ta, tb);
}

static cvm_status report(cvm__ctx *ctx, const cvm__surf3 *s, const cvm__surf3_tris *t, int32_t a, int32_t b)
{
    char na[160], nb[160];
    int32_t lo = a < b ? a : b, hi = a < b ? b : a;
    cvm__surf3_name_poly(s, (size_t)t->tpoly[lo], na, sizeof na);
    cvm__surf3_name_poly(s, (size_t)t->tpoly[hi], nb, sizeof nb);
    return cvm__error(ctx, CVM_E_INPUT_INTERSECTING, CVM_ENT_FACET, s->pfacet[t->tpoly[lo]],
                      "%s%s%s and %s intersect (the surface intersects itself)", s->file ? s->file : "",
                      s->file ? ": " : "", na, nb);
}

cvm_status cvm__surf3_check_intersections(cvm__ctx *ctx, const cvm__surf3 *s, const cvm__surf3_tris *t)
{
    grid g;
    cvm_status st = CVM_OK;
    int32_t cell[3];
    memset(&g, 0, sizeof g);
    grid_shape(&g, s, t);
    if ((st = grid_fill(ctx, &g, s, t)))
        goto done;
    for (cell[2] = 0; cell[2] < g.dim[2]; cell[2]++)
        for (cell[1] = 0; cell[1] < g.dim[1]; cell[1]++)
            for (cell[0] = 0; cell[0] < g.dim[0]; cell[0]++) {
                size_t c = ((size_t)cell[2] * (size_t)g.dim[1] + (size_t)cell[1]) * (size_t)g.dim[0] +
                           (size_t)cell[0], i, j;
                /* pairs in cell order; the first report is the lowest cell's */
                for (i = g.start[c]; i < g.start[c + 1]; i++)
                    for (j = i + 1; j < g.start[c + 1]; j++)
                        if (pair_meets(&g, s, t, g.item[i], g.item[j], cell)) {
                            st = report(ctx, s, t, g.item[i], g.item[j]);
                            goto done;
                        }
            }
done:
    cvm__free(ctx, g.start);
    cvm__free(ctx, g.item);
    return st;
}

/* grid.c - uniform grids of square cells, as the sizing fields use them for ring searches. */
#include <math.h>
#include <string.h>

#include "sizing_internal.h"

void cvm__cell_grid_fit(cvm__cell_grid *g, double xmin, double ymin, double xmax, double ymax, size_t n)
{
    double w = xmax - xmin, h = ymax - ymin;
    if (!(w >= 0) || !(h >= 0)) {
        w = h = 0;
        xmin = ymin = 0;
    }
    g->cs = sqrt(w * h / (double)(n + 1));
    if (!(g->cs > 0))
        g->cs = fmax(w, h) / (double)(n + 1);
    if (!(g->cs > 0))
        g->cs = 1;
    g->cs = fmax(g->cs, fmax(w, h) / 2048);
    g->nx = (int)(w / g->cs) + 1;
    g->ny = (int)(h / g->cs) + 1;
    g->x0 = xmin;
    g->y0 = ymin;
}

void cvm__cell_grid_cell(const cvm__cell_grid *g, double x, double y, int *i, int *j)
{
    double fx = floor((x - g->x0) / g->cs), fy = floor((y - g->y0) / g->cs);
    *i = fx < 0 ? 0 : fx >= g->nx ? g->nx - 1 : (int)fx;
    *j = fy < 0 ? 0 : fy >= g->ny ? g->ny - 1 : (int)fy;
}

cvm_status cvm__cell_grid_bucket(cvm__ctx *ctx, const cvm__cell_grid *g, size_t n,
                                 cvm__cell_range_fn range, const void *payload, int32_t **start,
                                 int32_t **items)
{
    size_t k, ncell = (size_t)g->nx * (size_t)g->ny;
    int32_t *st, *pos = NULL;
    int pass;
    if (!(st = *start = cvm__calloc(ctx, ncell + 1, sizeof *st)))
        return CVM_E_NOMEM;
    for (pass = 0; pass < 2; pass++) {
        if (pass == 1) {
            for (k = 0; k < ncell; k++) {
                if ((size_t)st[k + 1] > (size_t)INT32_MAX - (size_t)st[k])
                    return CVM_E_TOO_LARGE;
                st[k + 1] += st[k];
            }
            *items = cvm__malloc(ctx, ((size_t)st[ncell] + 1) * sizeof **items);
            pos = cvm__malloc(ctx, (ncell + 1) * sizeof *pos);
            if (!*items || !pos) {
                cvm__free(ctx, pos);
                return CVM_E_NOMEM;
            }
            memcpy(pos, st, (ncell + 1) * sizeof *pos);
        }
        for (k = 0; k < n; k++) {
            int i0, j0, i1, j1, i, j;
            range(payload, k, &i0, &j0, &i1, &j1);
            for (j = j0; j <= j1; j++)
                for (i = i0; i <= i1; i++) {
                    size_t c = (size_t)j * (size_t)g->nx + (size_t)i;
                    if (pass == 1)
                        (*items)[pos[c]++] = (int32_t)k;
                    else
                        st[c + 1]++;
                }
        }
    }
    cvm__free(ctx, pos);
    return CVM_OK;
}

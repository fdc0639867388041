/* proximity_grid.c - a uniform grid of vertices answering "is any vertex closer than r to x" without a scan. */
#include <math.h>

#include "refine_internal.h"

cvm_status cvm__vertex_grid_init(cvm__vertex_grid *g, cvm__ctx *ctx, double x0, double y0, double x1,
                           double y1, double cs, size_t max_cells)
{
    double w = x1 - x0, h = y1 - y0, nx, ny;
    size_t n, k;
    g->ctx = ctx;
    g->head = NULL;
    g->next = NULL;
    g->cap_next = 0;
    if (!(w > 0) || !isfinite(w))
        w = 1;
    if (!(h > 0) || !isfinite(h))
        h = 1;
    if (max_cells < 1)
        max_cells = 1;
    if (!(cs > 0) || !isfinite(cs) || (w / cs) * (h / cs) > (double)max_cells)
        cs = sqrt(w * h / (double)max_cells);
    nx = floor(w / cs) + 1;
    ny = floor(h / cs) + 1;
    g->nx = nx > 46340 ? 46340 : (int32_t)nx; /* nx*ny fits an int32 */
    g->ny = ny > 46340 ? 46340 : (int32_t)ny;
    g->x0 = x0;
    g->y0 = y0;
    g->inv = 1 / cs;
    n = (size_t)g->nx * (size_t)g->ny;
    g->head = cvm__malloc(ctx, n * sizeof *g->head);
    if (!g->head)
        return CVM_E_NOMEM;
    for (k = 0; k < n; k++)
        g->head[k] = -1;
    return CVM_OK;
}

void cvm__vertex_grid_destroy(cvm__vertex_grid *g)
{
    if (!g->ctx)
        return; /* never initialised */
    cvm__free(g->ctx, g->head);
    cvm__free(g->ctx, g->next);
    g->head = g->next = NULL;
    g->cap_next = 0;
}

/* Cell coordinate of x along one axis, clamped to [0, n-1]. */
static int32_t pg_cell(double x, double x0, double inv, int32_t n)
{
    double c = floor((x - x0) * inv);
    if (!(c > 0))
        return 0;
    return c >= n - 1 ? n - 1 : (int32_t)c;
}

cvm_status cvm__vertex_grid_add(cvm__vertex_grid *g, int32_t v, const double *p)
{
    size_t c;
    if ((size_t)v >= g->cap_next &&
        cvm__grow(g->ctx, (void **)&g->next, &g->cap_next, (size_t)v + 1, sizeof *g->next))
        return CVM_E_NOMEM;
    c = (size_t)pg_cell(p[1], g->y0, g->inv, g->ny) * (size_t)g->nx +
        (size_t)pg_cell(p[0], g->x0, g->inv, g->nx);
    g->next[v] = g->head[c];
    g->head[c] = v;
    return CVM_OK;
}

void cvm__vertex_grid_move(cvm__vertex_grid *g, int32_t v, const double *old, const double *p)
{
    size_t c0 = (size_t)pg_cell(old[1], g->y0, g->inv, g->ny) * (size_t)g->nx +
                (size_t)pg_cell(old[0], g->x0, g->inv, g->nx);
    size_t c1 = (size_t)pg_cell(p[1], g->y0, g->inv, g->ny) * (size_t)g->nx +
                (size_t)pg_cell(p[0], g->x0, g->inv, g->nx);
    int32_t *link = &g->head[c0];
    if (c0 == c1)
        return;
    while (*link >= 0 && *link != v)
        link = &g->next[*link];
    if (*link != v)
        return; /* not in old's cell: left where it is */
    *link = g->next[v];
    g->next[v] = g->head[c1];
    g->head[c1] = v;
}

int cvm__vertex_grid_any_within(const cvm__vertex_grid *g, const double *xy, const double *x, double r)
{
    int32_t i0 = pg_cell(x[0] - r, g->x0, g->inv, g->nx), i1 = pg_cell(x[0] + r, g->x0, g->inv, g->nx);
    int32_t j0 = pg_cell(x[1] - r, g->y0, g->inv, g->ny), j1 = pg_cell(x[1] + r, g->y0, g->inv, g->ny);
    double r2 = r * r;
    int32_t i, j, v;
    for (j = j0; j <= j1; j++)
        for (i = i0; i <= i1; i++)
            for (v = g->head[(size_t)j * (size_t)g->nx + (size_t)i]; v >= 0; v = g->next[v]) {
                const double *p = xy + 2 * (size_t)v;
                double dx = p[0] - x[0], dy = p[1] - x[1];
                if (dx * dx + dy * dy < r2)
                    return 1;
            }
    return 0;
}

/* grid.c - uniform grids of square cells, as the sizing fields use them for ring searches. */
#include <math.h>

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

/*
 * g3_sizing.c - the size field of 3D generation: uniform h, or the surface's
 * own triangle size growing away from it, size(x) = min(h, min_f l(f) + g
 * |x - centroid(f)|). The triangles' centroids sit in a uniform grid searched
 * ring by ring around x, stopping once no farther ring can lower the minimum.
 */
#include <math.h>

#include "generate3/generate3.h"

struct cvm__g3_size {
    cvm__ctx *ctx;
    const cvm_sizing *user; /* NULL or a 3D sizing */
    double umin;            /* the least size of the user sizing's sources */
    double h, g, lmin;
    int follow;
    size_t nf;
    double *cen;     /* 3 nf centroids */
    double *l;       /* nf mean edge lengths */
    double lo[3], cell;
    int32_t dim[3];
    int32_t *start;  /* ncell + 1: faces of cell c are idx[start[c] .. start[c+1]-1] */
    int32_t *idx;
    double *cmin;    /* ncell: smallest l(f) of the faces of each cell (+inf when empty) */
};

static double dist(const double *a, const double *b)
{
    double x = a[0] - b[0], y = a[1] - b[1], z = a[2] - b[2];
    return sqrt(x * x + y * y + z * z);
}

static int32_t cell_of(const cvm__g3_size *z, const double *x, int k)
{
    return (int32_t)cvm__g3_cell_at(x[k], z->lo[k], z->cell, z->dim[k]);
}

void cvm__g3_size_free(cvm__g3_size *z)
{
    if (!z)
        return;
    cvm__free(z->ctx, z->cen);
    cvm__free(z->ctx, z->l);
    cvm__free(z->ctx, z->start);
    cvm__free(z->ctx, z->idx);
    cvm__free(z->ctx, z->cmin);
    cvm__free(z->ctx, z);
}

cvm_status cvm__g3_size_create(cvm__g3_size **out, cvm__ctx *ctx, const cvm__g3_surface *s,
                               const cvm__g3_params *p)
{
    cvm__g3_size *z;
    double hi[3], ext = 0;
    size_t f, ncell;
    int k;
    *out = NULL;
    if (!(z = cvm__calloc(ctx, 1, sizeof *z)))
        return cvm__nomem(ctx);
    z->ctx = ctx;
    z->h = p->h;
    z->g = p->grading;
    z->follow = p->follow_surface && s->nt > 0;
    z->lmin = p->h;
    z->user = cvm__sizing_is_empty(p->sizing) ? NULL : p->sizing;
    z->umin = cvm__sizing_min3(z->user);
    if (!z->follow) {
        *out = z;
        return CVM_OK;
    }
    z->nf = s->nt;
    z->cen = cvm__malloc(ctx, 3 * s->nt * sizeof *z->cen);
    z->l = cvm__malloc(ctx, s->nt * sizeof *z->l);
    if (!z->cen || !z->l)
        goto nomem;
    for (k = 0; k < 3; k++)
        z->lo[k] = hi[k] = s->xyz[3 * s->tri[0] + k];
    for (f = 0; f < s->nt; f++) {
        const double *a = s->xyz + 3 * s->tri[3 * f], *b = s->xyz + 3 * s->tri[3 * f + 1],
                     *c = s->xyz + 3 * s->tri[3 * f + 2];
        for (k = 0; k < 3; k++) {
            double v = (a[k] + b[k] + c[k]) / 3;
            z->cen[3 * f + k] = v;
            z->lo[k] = v < z->lo[k] ? v : z->lo[k];
            hi[k] = v > hi[k] ? v : hi[k];
        }
        z->l[f] = (dist(a, b) + dist(b, c) + dist(c, a)) / 3;
        if (z->l[f] < z->lmin)
            z->lmin = z->l[f];
    }
    for (k = 0; k < 3; k++)
        ext = hi[k] - z->lo[k] > ext ? hi[k] - z->lo[k] : ext;
    /* about two centroids per cell on a surface spread over a cube's faces */
    z->cell = ext > 0 ? ext / ceil(sqrt((double)s->nt / 12.0) + 1) : 1;
    ncell = 1;
    for (k = 0; k < 3; k++) {
        double d = floor((hi[k] - z->lo[k]) / z->cell) + 1;
        z->dim[k] = d > 1024 ? 1024 : (int32_t)d;
        ncell *= (size_t)z->dim[k];
    }
    z->start = cvm__calloc(ctx, ncell + 1, sizeof *z->start);
    z->idx = cvm__malloc(ctx, s->nt * sizeof *z->idx);
    z->cmin = cvm__malloc(ctx, ncell * sizeof *z->cmin);
    if (!z->start || !z->idx || !z->cmin)
        goto nomem;
    for (f = 0; f < ncell; f++)
        z->cmin[f] = INFINITY;
    for (f = 0; f < s->nt; f++) {
        const double *x = z->cen + 3 * f;
        size_t c = ((size_t)cell_of(z, x, 2) * (size_t)z->dim[1] + (size_t)cell_of(z, x, 1)) *
                       (size_t)z->dim[0] + (size_t)cell_of(z, x, 0);
        z->start[c + 1]++;
    }
    for (f = 0; f < ncell; f++)
        z->start[f + 1] += z->start[f];
    for (f = 0; f < s->nt; f++) {
        const double *x = z->cen + 3 * f;
        size_t c = ((size_t)cell_of(z, x, 2) * (size_t)z->dim[1] + (size_t)cell_of(z, x, 1)) *
                       (size_t)z->dim[0] + (size_t)cell_of(z, x, 0);
        z->idx[z->start[c]++] = (int32_t)f;
        if (z->l[f] < z->cmin[c])
            z->cmin[c] = z->l[f];
    }
    for (f = ncell; f > 0; f--)
        z->start[f] = z->start[f - 1];
    z->start[0] = 0;
    *out = z;
    return CVM_OK;
nomem:
    cvm__g3_size_free(z);
    return cvm__nomem(ctx);
}

double cvm__g3_size_min(const cvm__g3_size *z)
{
    return z->umin < z->lmin ? z->umin : z->lmin;
}

int cvm__g3_size_follows(const cvm__g3_size *z)
{
    return z->follow;
}

const cvm_sizing *cvm__g3_size_user(const cvm__g3_size *z)
{
    return z->user;
}

cvm_status cvm__g3_size_at(const cvm__g3_size *z, const double *x, double *out)
{
    double d;
    cvm_status st;
    *out = cvm__g3_size_eval(z, x);
    if (!z->user)
        return CVM_OK;
    if ((st = cvm__sizing_at3(z->user, x, &d, z->ctx)))
        return st;
    *out = d < *out ? d : *out;
    return CVM_OK;
}

double cvm__g3_size_grading(const cvm__g3_size *z)
{
    return z->g > 0 ? z->g : 1;
}

/* Distance from x to cell (i, j, k) (0 inside it; the outer cells reach to
 * infinity, as cell_of() clamps). */
static double box_dist(const cvm__g3_size *z, int32_t i, int32_t j, int32_t k, const double *x)
{
    int32_t id[3] = {i, j, k};
    double d2 = 0;
    int a;
    for (a = 0; a < 3; a++) {
        double lo = z->lo[a] + z->cell * id[a], hi = lo + z->cell, e = 0;
        if (x[a] < lo && id[a] > 0)
            e = lo - x[a];
        else if (x[a] > hi && id[a] < z->dim[a] - 1)
            e = x[a] - hi;
        d2 += e * e;
    }
    return sqrt(d2);
}

/* The faces of the cells at Chebyshev distance exactly r from cell c0. */
static double ring(const cvm__g3_size *z, const int32_t *c0, int32_t r, const double *x, double best)
{
    int32_t i, j, k;
    for (k = c0[2] - r; k <= c0[2] + r; k++) {
        if (k < 0 || k >= z->dim[2])
            continue;
        for (j = c0[1] - r; j <= c0[1] + r; j++) {
            int edge_jk;
            if (j < 0 || j >= z->dim[1])
                continue;
            edge_jk = (k == c0[2] - r || k == c0[2] + r || j == c0[1] - r || j == c0[1] + r);
            for (i = c0[0] - r; i <= c0[0] + r; i += (edge_jk || r == 0) ? 1 : 2 * r) {
                size_t c, q;
                if (i < 0 || i >= z->dim[0])
                    continue;
                c = ((size_t)k * (size_t)z->dim[1] + (size_t)j) * (size_t)z->dim[0] + (size_t)i;
                /* no face of the cell can beat best: skip it */
                if (z->cmin[c] + z->g * box_dist(z, i, j, k, x) >= best)
                    continue;
                for (q = (size_t)z->start[c]; q < (size_t)z->start[c + 1]; q++) {
                    int32_t f = z->idx[q];
                    double v = z->l[f] + z->g * dist(x, z->cen + 3 * f);
                    best = v < best ? v : best;
                }
            }
        }
    }
    return best;
}

double cvm__g3_size_eval(const cvm__g3_size *z, const double *x)
{
    int32_t c0[3], r, rmax = 0;
    double best = z->h;
    int k;
    if (!z->follow)
        return z->h;
    for (k = 0; k < 3; k++) {
        c0[k] = cell_of(z, x, k);
        rmax = z->dim[k] > rmax ? z->dim[k] : rmax;
    }
    for (r = 0; r <= rmax; r++) {
        best = ring(z, c0, r, x, best);
        /* every face in a farther ring is at least r cells away from x */
        if (z->lmin + z->g * (double)r * z->cell >= best)
            break;
    }
    return best;
}

/*
 * g3_inside.c - exact point-in-domain test: the parity of the surface
 * triangles crossed by a segment from x to a point beyond the surface's
 * bounding box, each crossing decided by exact orient3d. A segment that meets
 * an edge or a vertex exactly, or runs in a triangle's plane, is retried along
 * the next of a few fixed directions; x on the surface is outside.
 *
 * The triangles are bucketed in a 2D grid of their projections on the plane
 * normal to the first direction (bounding boxes widened by 2^-30 of the
 * coordinates and the segment's length, far more than the rounding of the
 * projections and of the segment's far end, so the filter never drops a
 * crossed triangle); retries scan every triangle.
 */
#include <math.h>

#include "generate3/generate3.h"
#include "geom/geom_internal.h"

#define NDIR 4
static const double k_dirs[NDIR][3] = {{1.0, 0.3183098861837907, 0.1591549430918953},
                                       {-0.2718281828459045, 1.0, 0.5772156649015329},
                                       {0.4142135623730950, -0.7320508075688772, 1.0},
                                       {-1.0, -0.6180339887498949, -0.3010299956639812}};

struct cvm__g3_inside {
    cvm__ctx *ctx;
    const cvm__g3_surface *s;
    double span;        /* length that takes any point of the box beyond it */
    double u[3], w[3], d[3]; /* frame of the first direction (d unit) */
    double lo[2], cell;
    int32_t dim[2];
    int32_t *start, *idx;
    double *dmax;       /* nt: largest d-coordinate of each triangle, widened */
};

enum { CROSS_NO = 0, CROSS_YES = 1, CROSS_DEGENERATE = 2, CROSS_ON = 3 };

static double dot(const double *a, const double *b)
{
    return a[0] * b[0] + a[1] * b[1] + a[2] * b[2];
}

static int sgn(double v)
{
    return (v > 0) - (v < 0);
}

/* x in the closed triangle abc of its own plane: orient2d on the first
 * coordinate projection where abc is not degenerate (exact). */
static int in_closed_tri(const double *a, const double *b, const double *c, const double *x)
{
    int ax;
    for (ax = 0; ax < 3; ax++) {
        int i = (ax + 1) % 3, j = (ax + 2) % 3, s, s1, s2, s3;
        double A[2] = {a[i], a[j]}, B[2] = {b[i], b[j]}, C[2] = {c[i], c[j]}, X[2] = {x[i], x[j]};
        s = sgn(cvm__orient2d(A, B, C));
        if (!s)
            continue;
        s1 = sgn(cvm__orient2d(A, B, X));
        s2 = sgn(cvm__orient2d(B, C, X));
        s3 = sgn(cvm__orient2d(C, A, X));
        return s1 != -s && s2 != -s && s3 != -s;
    }
    return 0;
}

static int crossing(const double *a, const double *b, const double *c, const double *p,
                    const double *q)
{
    int sp = sgn(cvm__orient3d(a, b, c, p)), sq = sgn(cvm__orient3d(a, b, c, q)), s1, s2, s3;
    if (!sp) {
        if (in_closed_tri(a, b, c, p))
            return CROSS_ON;
        return sq ? CROSS_NO : CROSS_DEGENERATE;
    }
    if (!sq)
        return CROSS_DEGENERATE;
    if (sp == sq)
        return CROSS_NO;
    s1 = sgn(cvm__orient3d(p, q, a, b));
    s2 = sgn(cvm__orient3d(p, q, b, c));
    s3 = sgn(cvm__orient3d(p, q, c, a));
    if (!s1 || !s2 || !s3)
        return CROSS_DEGENERATE;
    return s1 == s2 && s2 == s3 ? CROSS_YES : CROSS_NO;
}

static void unit(double *v)
{
    double n = sqrt(dot(v, v));
    v[0] /= n;
    v[1] /= n;
    v[2] /= n;
}

static int32_t cell_of(const cvm__g3_inside *in, double v, int k)
{
    return (int32_t)cvm__g3_cell_at(v, in->lo[k], in->cell, in->dim[k]);
}

void cvm__g3_inside_free(cvm__g3_inside *in)
{
    if (!in)
        return;
    cvm__free(in->ctx, in->start);
    cvm__free(in->ctx, in->idx);
    cvm__free(in->ctx, in->dmax);
    cvm__free(in->ctx, in);
}

cvm_status cvm__g3_inside_create(cvm__g3_inside **out, cvm__ctx *ctx, const cvm__g3_surface *s)
{
    cvm__g3_inside *in;
    double bl[3], bh[3], hi[2], ext;
    double *box = NULL; /* 4 per triangle: projected bounding box */
    size_t f, ncell, pass;
    int k;
    *out = NULL;
    if (!(in = cvm__calloc(ctx, 1, sizeof *in)))
        return cvm__nomem(ctx);
    in->ctx = ctx;
    in->s = s;
    for (k = 0; k < 3; k++)
        bl[k] = bh[k] = s->np ? s->xyz[k] : 0;
    for (f = 0; f < s->np; f++)
        for (k = 0; k < 3; k++) {
            double v = s->xyz[3 * f + k];
            bl[k] = v < bl[k] ? v : bl[k];
            bh[k] = v > bh[k] ? v : bh[k];
        }
    in->span = 4 * (fabs(bh[0] - bl[0]) + fabs(bh[1] - bl[1]) + fabs(bh[2] - bl[2])) + 1;
    for (k = 0; k < 3; k++)
        in->d[k] = k_dirs[0][k];
    unit(in->d);
    /* u, w: an orthonormal pair normal to d */
    in->u[0] = -in->d[1];
    in->u[1] = in->d[0];
    in->u[2] = 0;
    unit(in->u);
    in->w[0] = in->d[1] * in->u[2] - in->d[2] * in->u[1];
    in->w[1] = in->d[2] * in->u[0] - in->d[0] * in->u[2];
    in->w[2] = in->d[0] * in->u[1] - in->d[1] * in->u[0];
    box = cvm__malloc(ctx, (4 * s->nt + 1) * sizeof *box);
    in->dmax = cvm__malloc(ctx, (s->nt + 1) * sizeof *in->dmax);
    if (!box || !in->dmax)
        goto nomem;
    in->lo[0] = in->lo[1] = INFINITY;
    hi[0] = hi[1] = -INFINITY;
    for (f = 0; f < s->nt; f++) {
        double *bx = box + 4 * f, mx = -INFINITY;
        int j;
        bx[0] = bx[1] = INFINITY;
        bx[2] = bx[3] = -INFINITY;
        for (j = 0; j < 3; j++) {
            const double *p = s->xyz + 3 * s->tri[3 * f + j];
            double pu = dot(p, in->u), pw = dot(p, in->w), pd = dot(p, in->d);
            bx[0] = pu < bx[0] ? pu : bx[0];
            bx[1] = pw < bx[1] ? pw : bx[1];
            bx[2] = pu > bx[2] ? pu : bx[2];
            bx[3] = pw > bx[3] ? pw : bx[3];
            mx = pd > mx ? pd : mx;
        }
        for (j = 0; j < 2; j++) {
            double e = ldexp(fabs(bx[j]) + fabs(bx[j + 2]) + in->span, -30);
            bx[j] -= e;
            bx[j + 2] += e;
            in->lo[j] = bx[j] < in->lo[j] ? bx[j] : in->lo[j];
            hi[j] = bx[j + 2] > hi[j] ? bx[j + 2] : hi[j];
        }
        in->dmax[f] = mx + ldexp(fabs(mx) + in->span, -30);
    }
    if (s->nt == 0)
        in->lo[0] = in->lo[1] = hi[0] = hi[1] = 0;
    ext = hi[0] - in->lo[0] > hi[1] - in->lo[1] ? hi[0] - in->lo[0] : hi[1] - in->lo[1];
    in->cell = ext > 0 ? ext / (ceil(sqrt((double)s->nt / 4.0)) + 1) : 1;
    ncell = 1;
    for (k = 0; k < 2; k++) {
        double dd = floor((hi[k] - in->lo[k]) / in->cell) + 1;
        in->dim[k] = dd > 4096 ? 4096 : (int32_t)dd;
        ncell *= (size_t)in->dim[k];
    }
    if (!(in->start = cvm__calloc(ctx, ncell + 1, sizeof *in->start)))
        goto nomem;
    /* two passes: count, then fill */
    for (pass = 0; pass < 2; pass++) {
        for (f = 0; f < s->nt; f++) {
            const double *bx = box + 4 * f;
            int32_t i, j;
            for (j = cell_of(in, bx[1], 1); j <= cell_of(in, bx[3], 1); j++)
                for (i = cell_of(in, bx[0], 0); i <= cell_of(in, bx[2], 0); i++) {
                    size_t c = (size_t)j * (size_t)in->dim[0] + (size_t)i;
                    if (pass == 0)
                        in->start[c + 1]++;
                    else
                        in->idx[in->start[c]++] = (int32_t)f;
                }
        }
        if (pass == 0) {
            for (f = 0; f < ncell; f++)
                in->start[f + 1] += in->start[f];
            if (!(in->idx = cvm__malloc(ctx, ((size_t)in->start[ncell] + 1) * sizeof *in->idx)))
                goto nomem;
        }
    }
    for (f = ncell; f > 0; f--)
        in->start[f] = in->start[f - 1];
    in->start[0] = 0;
    cvm__free(ctx, box);
    *out = in;
    return CVM_OK;
nomem:
    cvm__free(ctx, box);
    cvm__g3_inside_free(in);
    return cvm__nomem(ctx);
}

static const double *corner(const cvm__g3_surface *s, size_t f, int j)
{
    return s->xyz + 3 * s->tri[3 * f + j];
}

int cvm__g3_is_inside(const cvm__g3_inside *in, const double *x)
{
    const cvm__g3_surface *s = in->s;
    int dir;
    for (dir = 0; dir < NDIR; dir++) {
        double q[3], d[3];
        int k, parity = 0, r = CROSS_NO;
        size_t f;
        for (k = 0; k < 3; k++)
            d[k] = k_dirs[dir][k];
        unit(d);
        for (k = 0; k < 3; k++)
            q[k] = x[k] + in->span * d[k];
        if (dir == 0) {
            size_t c = (size_t)cell_of(in, dot(x, in->w), 1) * (size_t)in->dim[0] +
                       (size_t)cell_of(in, dot(x, in->u), 0);
            double xd = dot(x, in->d) - ldexp(fabs(dot(x, in->d)) + in->span, -30);
            int32_t q0;
            for (q0 = in->start[c]; q0 < in->start[c + 1]; q0++) {
                f = (size_t)in->idx[q0];
                if (in->dmax[f] < xd)
                    continue;
                r = crossing(corner(s, f, 0), corner(s, f, 1), corner(s, f, 2), x, q);
                if (r == CROSS_YES)
                    parity ^= 1;
                else if (r != CROSS_NO)
                    break;
            }
        } else {
            for (f = 0; f < s->nt; f++) {
                r = crossing(corner(s, f, 0), corner(s, f, 1), corner(s, f, 2), x, q);
                if (r == CROSS_YES)
                    parity ^= 1;
                else if (r != CROSS_NO)
                    break;
            }
        }
        if (r == CROSS_ON)
            return 0;
        if (r != CROSS_DEGENERATE)
            return parity;
    }
    return 0;
}

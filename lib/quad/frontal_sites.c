/* frontal_sites.c - the initial sites of the Lp-CVT placed by an advancing front in metric
 * space: from each placed point, one unit metric step along each of the four directions of a
 * frame (the metric's eigenvectors where it is anisotropic, the nearest domain edge where it is
 * not), kept when inside the domain and not too near a point already placed. The start is then
 * close to a lattice of metric squares, which the energy only has to relax. */
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "geom/measure.h"
#include "quad_internal.h"

/* Metric distance below which a candidate is refused: from the points placed (1 on a lattice,
 * down to about 0.7 where two fronts meet) and from the boundary edges. */
#define FS_NEAR_POINT 0.75
#define FS_NEAR_EDGE 0.6
/* Anisotropy (lam0 - lam1) / (lam0 + lam1) from which the eigenvectors alone set the frame;
 * below it the frame blends towards the nearest edge's direction. */
#define FS_ANISO_FULL 0.05
/* A boundary site seeds the first front when its frame is within this many degrees of the
 * boundary's direction. */
#define FS_SEED_DEG 5.0

typedef struct fs_state {
    const cvm__metric *mt;
    cvm__ctx *ctx;
    const double *cor; /* domain corners, counter-clockwise */
    size_t nc;
    double *xy;        /* placed points: the boundary sites first */
    size_t n, cap;
    int32_t *next;     /* per point: the next in its grid cell */
    size_t cap_next;
    int32_t *head;     /* per grid cell: its first point, or -1 */
    size_t gx, gy;
    double lo[2], hc;
} fs_state;

static size_t fs_cell_of(const fs_state *S, double x, double y, size_t *ix, size_t *iy)
{
    double fx = floor((x - S->lo[0]) / S->hc), fy = floor((y - S->lo[1]) / S->hc);
    *ix = fx < 0 ? 0 : fx >= (double)S->gx ? S->gx - 1 : (size_t)fx;
    *iy = fy < 0 ? 0 : fy >= (double)S->gy ? S->gy - 1 : (size_t)fy;
    return *iy * S->gx + *ix;
}

static cvm_status fs_add(fs_state *S, const double *p)
{
    size_t ix, iy, c;
    if (cvm__grow(S->ctx, (void **)&S->xy, &S->cap, 2 * (S->n + 1), sizeof *S->xy) ||
        cvm__grow(S->ctx, (void **)&S->next, &S->cap_next, S->n + 1, sizeof *S->next))
        return cvm__nomem(S->ctx);
    S->xy[2 * S->n] = p[0];
    S->xy[2 * S->n + 1] = p[1];
    c = fs_cell_of(S, p[0], p[1], &ix, &iy);
    S->next[S->n] = S->head[c];
    S->head[c] = (int32_t)S->n;
    S->n++;
    return CVM_OK;
}

/* 1 when a placed point lies within metric distance r of c, in the metric g of c. */
static int fs_near_point(const fs_state *S, const double *c, const double g[3], double r)
{
    double det = g[0] * g[2] - g[1] * g[1];
    double hx = r * sqrt(g[2] / det), hy = r * sqrt(g[0] / det);
    size_t x0, y0, x1, y1, ix, iy;
    fs_cell_of(S, c[0] - hx, c[1] - hy, &x0, &y0);
    fs_cell_of(S, c[0] + hx, c[1] + hy, &x1, &y1);
    for (iy = y0; iy <= y1; iy++)
        for (ix = x0; ix <= x1; ix++) {
            int32_t q;
            for (q = S->head[iy * S->gx + ix]; q >= 0; q = S->next[q]) {
                double dx = S->xy[2 * q] - c[0], dy = S->xy[2 * q + 1] - c[1];
                if (g[0] * dx * dx + 2 * g[1] * dx * dy + g[2] * dy * dy < r * r)
                    return 1;
            }
        }
    return 0;
}

/* The metric distance from c to the nearest domain edge, in the metric g of c; *ang the
 * direction of that edge. */
static double fs_edge_dist(const fs_state *S, const double *c, const double g[3], double *ang)
{
    double best = HUGE_VAL;
    size_t k;
    *ang = 0;
    for (k = 0; k < S->nc; k++) {
        const double *a = S->cor + 2 * k, *b = S->cor + 2 * ((k + 1) % S->nc);
        double ex = b[0] - a[0], ey = b[1] - a[1], l2 = ex * ex + ey * ey, t, dx, dy, d;
        t = l2 > 0 ? ((c[0] - a[0]) * ex + (c[1] - a[1]) * ey) / l2 : 0;
        t = t < 0 ? 0 : t > 1 ? 1 : t;
        dx = c[0] - (a[0] + t * ex);
        dy = c[1] - (a[1] + t * ey);
        d = g[0] * dx * dx + 2 * g[1] * dx * dy + g[2] * dy * dy;
        if (d < best) {
            best = d;
            *ang = atan2(ey, ex);
        }
    }
    return sqrt(best);
}

/* The two frame directions at p, each of unit metric length in the metric of p, metric
 * orthogonal to each other. */
static cvm_status fs_frame(const fs_state *S, const double *p, double d[2][2])
{
    double g[3], ang, th, vx, vy, w, a, u[2], gu[2];
    cvm__eig2 e;
    cvm_status st = cvm__metric_eval(S->mt, p, g, NULL, S->ctx);
    int k;
    if (st)
        return st;
    cvm__eig2_of(&e, g, NULL);
    a = (e.lam[0] - e.lam[1]) / (e.lam[0] + e.lam[1]);
    w = a >= FS_ANISO_FULL ? 1 : a / FS_ANISO_FULL;
    (void)fs_edge_dist(S, p, g, &ang);
    th = atan2(e.sn, e.cs);
    /* a cross field is an angle modulo 90 degrees: blend its fourfold representatives */
    vx = w * cos(4 * th) + (1 - w) * cos(4 * ang);
    vy = w * sin(4 * th) + (1 - w) * sin(4 * ang);
    th = (vx == 0 && vy == 0) ? th : 0.25 * atan2(vy, vx);
    u[0] = cos(th);
    u[1] = sin(th);
    gu[0] = g[0] * u[0] + g[1] * u[1];
    gu[1] = g[1] * u[0] + g[2] * u[1];
    d[0][0] = u[0];
    d[0][1] = u[1];
    d[1][0] = -gu[1]; /* u^T g d1 = 0 */
    d[1][1] = gu[0];
    for (k = 0; k < 2; k++) {
        double x = d[k][0], y = d[k][1], l = sqrt(g[0] * x * x + 2 * g[1] * x * y + g[2] * y * y);
        d[k][0] = x / l;
        d[k][1] = y / l;
    }
    return CVM_OK;
}

/* One unit metric step from p along dir (unit in the metric of p), rescaled by the metric at
 * the step's midpoint, into c. */
static cvm_status fs_step(const fs_state *S, const double *p, const double *dir, double *c)
{
    double m[2], g[3], l;
    cvm_status st;
    m[0] = p[0] + 0.5 * dir[0];
    m[1] = p[1] + 0.5 * dir[1];
    if (!cvm__lpcvt_inside_polygon(S->cor, S->nc, m)) {
        c[0] = p[0] + dir[0];
        c[1] = p[1] + dir[1];
        return CVM_OK;
    }
    if ((st = cvm__metric_eval(S->mt, m, g, NULL, S->ctx)))
        return st;
    l = sqrt(g[0] * dir[0] * dir[0] + 2 * g[1] * dir[0] * dir[1] + g[2] * dir[1] * dir[1]);
    c[0] = p[0] + dir[0] / l;
    c[1] = p[1] + dir[1] / l;
    return CVM_OK;
}

/* *al = 1 when the frame at boundary site k of bxy is within FS_SEED_DEG of the boundary's
 * direction on both sides of the site (modulo 90 degrees). */
static cvm_status fs_aligned(const fs_state *S, const double *bxy, size_t nb, size_t k, int *al)
{
    const double *p = bxy + 2 * k, *a = bxy + 2 * ((k + nb - 1) % nb), *b = bxy + 2 * ((k + 1) % nb);
    double d[2][2], fr, e1, e2, t1, t2;
    cvm_status st = fs_frame(S, p, d);
    *al = 0;
    if (st)
        return st;
    fr = atan2(d[0][1], d[0][0]);
    e1 = atan2(p[1] - a[1], p[0] - a[0]);
    e2 = atan2(b[1] - p[1], b[0] - p[0]);
    /* the angle between two directions modulo 90 degrees, in [0, 45] */
    t1 = fmod(fabs(fr - e1), 0.5 * CVM__PI);
    t2 = fmod(fabs(fr - e2), 0.5 * CVM__PI);
    t1 = fmin(t1, 0.5 * CVM__PI - t1);
    t2 = fmin(t2, 0.5 * CVM__PI - t2);
    *al = t1 <= FS_SEED_DEG * CVM__PI / 180 && t2 <= FS_SEED_DEG * CVM__PI / 180;
    return CVM_OK;
}

cvm_status cvm__lpcvt_frontal_sites(double **xi_out, size_t *ni_out, const cvm__metric *mt,
                                    const double *bxy, size_t nb, const double *cor, size_t nc,
                                    size_t limit, cvm__ctx *ctx)
{
    fs_state S;
    double hi[2], A, rmax, area = 0;
    size_t k, q, ncell, nq = 0, qcap;
    int32_t *qu = NULL;
    uint8_t *aligned = NULL;
    int phase;
    cvm_status st;
    *xi_out = NULL;
    *ni_out = 0;
    if ((st = cvm__metric_area(&A, &rmax, mt, cor, nc, ctx)))
        return st;
    if (!(A < 1e9))
        return cvm__error(ctx, CVM_E_TOO_LARGE, CVM_ENT_NONE, -1,
                          "the metric asks for %.6g interior sites", A);
    memset(&S, 0, sizeof S);
    S.mt = mt;
    S.ctx = ctx;
    S.cor = cor;
    S.nc = nc;
    S.lo[0] = hi[0] = cor[0];
    S.lo[1] = hi[1] = cor[1];
    for (k = 0; k < nc; k++) {
        const double *a = cor + 2 * k, *b = cor + 2 * ((k + 1) % nc);
        S.lo[0] = fmin(S.lo[0], a[0]);
        hi[0] = fmax(hi[0], a[0]);
        S.lo[1] = fmin(S.lo[1], a[1]);
        hi[1] = fmax(hi[1], a[1]);
        area += a[0] * b[1] - a[1] * b[0];
    }
    /* about one point per cell where the density is its mean */
    S.hc = sqrt(0.5 * fabs(area) / (A + (double)nb + 1));
    if (!(S.hc > 0))
        S.hc = fmax(hi[0] - S.lo[0], hi[1] - S.lo[1]) + 1;
    S.gx = (size_t)fmin(4096, floor((hi[0] - S.lo[0]) / S.hc) + 1);
    S.gy = (size_t)fmin(4096, floor((hi[1] - S.lo[1]) / S.hc) + 1);
    S.hc = fmax(S.hc, fmax((hi[0] - S.lo[0]) / (double)S.gx, (hi[1] - S.lo[1]) / (double)S.gy));
    ncell = S.gx * S.gy;
    S.head = cvm__malloc(ctx, ncell * sizeof *S.head);
    if (!S.head)
        return cvm__nomem(ctx);
    for (k = 0; k < ncell; k++)
        S.head[k] = -1;
    for (k = 0; k < nb && !st; k++)
        st = fs_add(&S, bxy + 2 * k);
    /* breadth first: from the boundary sites where the frame follows the boundary first, so
     * the lattice grows along the frame field instead of copying the boundary's direction
     * where the two disagree; then from the other boundary sites, into what is left */
    qcap = 0;
    aligned = cvm__malloc(ctx, nb + 1);
    if (!st && (!aligned || cvm__grow(ctx, (void **)&qu, &qcap, nb + 1, sizeof *qu)))
        st = cvm__nomem(ctx);
    for (k = 0; k < nb && !st; k++) {
        int al;
        if ((st = fs_aligned(&S, bxy, nb, k, &al)))
            break;
        aligned[k] = (uint8_t)al;
        if (al)
            qu[nq++] = (int32_t)k;
    }
    phase = 0;
    for (q = 0; !st; q++) {
        double d[2][2], p[2];
        int j;
        if (q == nq) {
            if (phase == 1)
                break;
            phase = 1; /* the boundary sites not taken yet */
            for (k = 0; k < nb && !st; k++) {
                if (aligned[k])
                    continue;
                if (cvm__grow(ctx, (void **)&qu, &qcap, nq + 1, sizeof *qu))
                    st = cvm__nomem(ctx);
                else
                    qu[nq++] = (int32_t)k;
            }
            if (st || q == nq)
                break;
        }
        p[0] = S.xy[2 * (size_t)qu[q]];
        p[1] = S.xy[2 * (size_t)qu[q] + 1];
        if ((st = fs_frame(&S, p, d)))
            break;
        for (j = 0; j < 4 && !st; j++) {
            double dir[2], c[2], g[3], ang;
            dir[0] = (j & 1 ? -1 : 1) * d[j >> 1][0];
            dir[1] = (j & 1 ? -1 : 1) * d[j >> 1][1];
            if ((st = fs_step(&S, p, dir, c)))
                break;
            if (!cvm__lpcvt_inside_polygon(S.cor, S.nc, c))
                continue;
            if ((st = cvm__metric_eval(mt, c, g, NULL, ctx)))
                break;
            if (fs_edge_dist(&S, c, g, &ang) < FS_NEAR_EDGE || fs_near_point(&S, c, g, FS_NEAR_POINT))
                continue;
            if (S.n - nb >= limit)
                break;
            if (cvm__grow(ctx, (void **)&qu, &qcap, nq + 1, sizeof *qu)) {
                st = cvm__nomem(ctx);
                break;
            }
            qu[nq++] = (int32_t)S.n;
            st = fs_add(&S, c);
        }
    }
    cvm__free(ctx, qu);
    cvm__free(ctx, aligned);
    cvm__free(ctx, S.head);
    cvm__free(ctx, S.next);
    if (st) {
        cvm__free(ctx, S.xy);
        return st;
    }
    /* the interior points only, moved to the front of the array */
    memmove(S.xy, S.xy + 2 * nb, 2 * (S.n - nb) * sizeof *S.xy);
    *xi_out = S.xy;
    *ni_out = S.n - nb;
    return CVM_OK;
}

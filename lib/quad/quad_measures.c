/* quad_measures.c - the quality report of a quad-dominant mesh in the space of its metric:
 * quad share, corner angles (metric and Euclidean), alignment with the eigenvectors, metric
 * edge lengths and the scaled Jacobian. */
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "geom/measure.h"
#include "quad_internal.h"

#define DEG (180.0 / CVM__PI)
#define HALF_PI (CVM__PI / 2)

static int cmp_double(const void *a, const void *b)
{
    double x = *(const double *)a, y = *(const double *)b;
    return x < y ? -1 : x > y;
}

static int cmp_u64(const void *a, const void *b)
{
    uint64_t x = *(const uint64_t *)a, y = *(const uint64_t *)b;
    return x < y ? -1 : x > y;
}

/* Mean, 95th percentile (the value at rank ceil(0.95 n)) and maximum of v (sorted in place). */
static void stats(double *mean, double *p95, double *max, double *v, size_t n)
{
    double s = 0;
    size_t k, r;
    *mean = *p95 = 0;
    if (max)
        *max = 0;
    if (n == 0)
        return;
    qsort(v, n, sizeof *v, cmp_double);
    for (k = 0; k < n; k++)
        s += v[k];
    r = (size_t)ceil(0.95 * (double)n);
    *mean = s / (double)n;
    *p95 = v[r > 0 ? r - 1 : 0];
    if (max)
        *max = v[n - 1];
}

cvm_status cvm__quad_measures(double *out, const cvm__metric *mt, const double *xy, size_t ncell,
                              const int32_t *off, const int32_t *types, const int32_t *conn,
                              cvm__ctx *ctx)
{
    static const double I[3] = {1, 0, 1};
    size_t c, nq = 0, ncorner = 0, nedge = 0, ne = 0, nal = 0, k, in_range = 0, good = 0;
    double area_all = 0, area_q = 0, sj_min = 1, dev_sum = 0;
    double *dev = NULL, *edev = NULL, *al = NULL;
    uint64_t *edges = NULL;
    cvm_status st = CVM_OK;
    memset(out, 0, CVM__QUAD_NMEASURES * sizeof *out);
    for (c = 0; c < ncell; c++) {
        nq += types[c] == CVM_CELL_QUAD;
        nedge += (size_t)(off[c + 1] - off[c]);
    }
    dev = cvm__malloc(ctx, (4 * nq + 1) * sizeof *dev);
    edev = cvm__malloc(ctx, (4 * nq + 1) * sizeof *edev);
    al = cvm__malloc(ctx, (4 * nq + 1) * sizeof *al);
    edges = cvm__malloc(ctx, (nedge + 1) * sizeof *edges);
    if (!dev || !edev || !al || !edges) {
        st = cvm__nomem(ctx);
        goto done;
    }
    for (c = 0; c < ncell; c++) {
        const int32_t *p = conn + off[c];
        int n = off[c + 1] - off[c], j, all_in = 1;
        double a = 0, cen[2] = {0, 0}, g[3];
        for (j = 0; j < n; j++) {
            const double *u = xy + 2 * p[j], *v = xy + 2 * p[(j + 1) % n];
            uint32_t lo = (uint32_t)(p[j] < p[(j + 1) % n] ? p[j] : p[(j + 1) % n]);
            uint32_t hi = (uint32_t)(p[j] < p[(j + 1) % n] ? p[(j + 1) % n] : p[j]);
            a += 0.5 * (u[0] * v[1] - u[1] * v[0]);
            cen[0] += u[0] / n;
            cen[1] += u[1] / n;
            edges[ne++] = (uint64_t)lo << 32 | hi;
        }
        area_all += a;
        if (types[c] != CVM_CELL_QUAD)
            continue;
        area_q += a;
        if ((st = cvm__metric_eval(mt, cen, g, NULL, ctx)))
            goto done;
        for (j = 0; j < 4; j++) {
            const double *q = xy + 2 * p[j], *nx = xy + 2 * p[(j + 1) % 4];
            const double *pv = xy + 2 * p[(j + 3) % 4];
            double d = fabs(cvm__metric_angle_deg(g, q, nx, pv) - 90);
            double e[2], m[2], gm[3], th, phi, f, sj, u[2], v[2];
            dev[ncorner] = d;
            edev[ncorner] = fabs(cvm__metric_angle_deg(I, q, nx, pv) - 90);
            all_in &= d <= 10;
            u[0] = nx[0] - q[0];
            u[1] = nx[1] - q[1];
            v[0] = pv[0] - q[0];
            v[1] = pv[1] - q[1];
            sj = (u[0] * v[1] - u[1] * v[0]) / (hypot(u[0], u[1]) * hypot(v[0], v[1]));
            sj_min = fmin(sj_min, sj);
            /* alignment of the edge q->nx with the nearest eigenvector of g at its midpoint */
            e[0] = u[0];
            e[1] = u[1];
            m[0] = 0.5 * (q[0] + nx[0]);
            m[1] = 0.5 * (q[1] + nx[1]);
            if ((st = cvm__metric_eval(mt, m, gm, NULL, ctx)))
                goto done;
            th = 0.5 * atan2(2 * gm[1], gm[0] - gm[2]);
            phi = atan2(e[1], e[0]);
            f = fmod(fabs(phi - th), HALF_PI);
            al[nal++] = fmin(f, HALF_PI - f) * DEG;
            ncorner++;
        }
        good += (size_t)all_in;
    }
    /* metric lengths of the unique edges, g at each midpoint */
    qsort(edges, ne, sizeof *edges, cmp_u64);
    nedge = 0;
    for (k = 0; k < ne; k++) {
        const double *u, *v;
        double m[2], g[3], e[2], l;
        if (k > 0 && edges[k] == edges[k - 1])
            continue;
        u = xy + 2 * (size_t)(edges[k] >> 32);
        v = xy + 2 * (size_t)(edges[k] & 0xffffffffu);
        m[0] = 0.5 * (u[0] + v[0]);
        m[1] = 0.5 * (u[1] + v[1]);
        if ((st = cvm__metric_eval(mt, m, g, NULL, ctx)))
            goto done;
        e[0] = v[0] - u[0];
        e[1] = v[1] - u[1];
        l = sqrt(e[0] * e[0] * g[0] + 2 * e[0] * e[1] * g[1] + e[1] * e[1] * g[2]);
        in_range += l >= sqrt(0.5) && l <= sqrt(2.0);
        dev_sum += fabs(l - 1);
        nedge++;
    }
    out[0] = ncell ? 100.0 * (double)nq / (double)ncell : 0;
    out[1] = area_all > 0 ? 100.0 * area_q / area_all : 0;
    stats(out + 2, out + 3, out + 4, dev, ncorner);
    stats(out + 5, out + 6, NULL, edev, ncorner);
    out[7] = nq ? 100.0 * (double)good / (double)nq : 0;
    stats(out + 8, out + 9, NULL, al, nal);
    out[10] = nedge ? 100.0 * (double)in_range / (double)nedge : 0;
    out[11] = nedge ? dev_sum / (double)nedge : 0;
    out[12] = nq ? sj_min : 0;
done:
    cvm__free(ctx, dev);
    cvm__free(ctx, edev);
    cvm__free(ctx, al);
    cvm__free(ctx, edges);
    return st;
}

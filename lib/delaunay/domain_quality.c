/*
 * domain_quality.c - measures of the domain triangles of a triangulation:
 * angles, edge lengths, areas and the degrees of interior vertices, as
 * extremes, counts and histograms (cvm_mesh_get_measure and
 * cvm_mesh_copy_histogram report them).
 *
 * These are measures, not topology: plain doubles, no exact arithmetic.
 * Angles come from atan2(|cross|, dot), which is accurate for small and
 * large angles alike. Near the limits of the double range (an edge vector
 * beyond 2^500 or below 2^-500, or one whose difference overflows) each edge
 * vector is scaled by a power of two before the products, so angles stay
 * right where plain products would give inf - inf, and areas are scaled back
 * (inf only when the true area exceeds the largest double). Inside that
 * range nothing is scaled, so the values there are as before. A triangle is
 * "obtuse" (not well-centred: its circumcentre lies outside it) when the dot
 * product of the two edges at one of its corners is negative; a right
 * triangle, whose circumcentre lies on its edge, is not counted. Interior
 * vertices are vertices of domain triangles that lie on no boundary edge of
 * the domain.
 */
#include <float.h>
#include <math.h>
#include <string.h>

#include "domain.h"
#include "geom/measure.h"

typedef cvm__tri_quality qstats;

#define NBIN_ANGLE CVM__NBIN_ANGLE
#define NBIN_DEGREE CVM__NBIN_DEGREE

static void add_area(qstats *q, double x)
{
    double t = q->area + x;
    if (!(fabs(t) <= DBL_MAX)) {
        q->area = t; /* overflow: the compensation would be inf - inf */
        return;
    }
    if (fabs(q->area) >= fabs(x))
        q->area_c += (q->area - t) + x;
    else
        q->area_c += (x - t) + q->area;
    q->area = t;
}

void cvm__domain_triangle_stats(const cvm__tri2 *T, cvm__tri_quality *q)
{
    size_t t;
    memset(q, 0, sizeof *q);
    q->min_angle = q->min_edge = q->min_area = HUGE_VAL;
    for (t = 0; t < T->nt; t++) {
        const double *p[3];
        double obtuse = 0, area;
        int k;
        if (!cvm__tri2_in_domain(T, (int32_t)t))
            continue;
        for (k = 0; k < 3; k++)
            p[k] = T->xy + 2 * (size_t)T->tv[3 * t + (size_t)k];
        for (k = 0; k < 3; k++) {
            double dot, a = cvm__corner_angle_deg_safe(p[k], p[(k + 1) % 3], p[(k + 2) % 3], &dot);
            double len = hypot(p[(k + 1) % 3][0] - p[k][0], p[(k + 1) % 3][1] - p[k][1]);
            int bin = a >= 0 && a < 10.0 * NBIN_ANGLE ? (int)(a / 10.0) : a >= 0 ? NBIN_ANGLE - 1 : 0;
            q->min_angle = a < q->min_angle ? a : q->min_angle;
            q->max_angle = a > q->max_angle ? a : q->max_angle;
            q->n_regular += a >= 55.0 && a <= 65.0;
            q->angle_hist[bin < 0 ? 0 : bin >= NBIN_ANGLE ? NBIN_ANGLE - 1 : bin] += 1.0;
            q->min_edge = len < q->min_edge ? len : q->min_edge;
            q->max_edge = len > q->max_edge ? len : q->max_edge;
            if (dot < 0)
                obtuse = 1;
        }
        q->n_obtuse += obtuse != 0;
        area = cvm__tri_area_safe(p[0], p[1], p[2]);
        add_area(q, area);
        q->min_area = area < q->min_area ? area : q->min_area;
        q->nt++;
    }
}

cvm_status cvm__domain_degree_stats(cvm__ctx *ctx, const cvm__tri2 *T, double *hist,
                                    size_t *n_interior)
{
    int32_t *deg = cvm__calloc(ctx, T->nv + 1, sizeof *deg);
    uint8_t *on_bnd = cvm__calloc(ctx, T->nv + 1, 1);
    size_t t, v;
    int j;
    if (!deg || !on_bnd) {
        cvm__free(ctx, deg);
        cvm__free(ctx, on_bnd);
        return CVM_E_NOMEM;
    }
    for (t = 0; t < T->nt; t++) {
        if (!cvm__tri2_in_domain(T, (int32_t)t))
            continue;
        for (j = 0; j < 3; j++) {
            int32_t a = T->tn[3 * t + (size_t)j], u = a < 0 ? -1 : a / 3;
            int32_t v1 = T->tv[3 * t + (size_t)(j + 1) % 3], v2 = T->tv[3 * t + (size_t)(j + 2) % 3];
            int bnd = u < 0 || !cvm__tri2_in_domain(T, u);
            if (!bnd && (size_t)u < t)
                continue; /* counted from u */
            deg[v1]++;
            deg[v2]++;
            if (bnd)
                on_bnd[v1] = on_bnd[v2] = 1;
        }
    }
    memset(hist, 0, NBIN_DEGREE * sizeof *hist);
    *n_interior = 0;
    for (v = 0; v < T->nv; v++) {
        if (deg[v] == 0 || on_bnd[v])
            continue;
        hist[deg[v] < NBIN_DEGREE - 1 ? deg[v] : NBIN_DEGREE - 1] += 1.0;
        (*n_interior)++;
    }
    cvm__free(ctx, deg);
    cvm__free(ctx, on_bnd);
    return CVM_OK;
}

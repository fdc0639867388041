/*
 * mesh3_quality.c - the 3D measures 720-724 and histograms of a 3D handle:
 * dual edges against their faces, vertex valence, radius-edge ratio and
 * dihedral angles (plain doubles; only the dual's ties are exact decisions).
 */
#include <math.h>
#include <string.h>

#include "api/mesh3_dual.h"
#include "api/store.h"
#include "geom/measure3.h"

#define NBIN_DIHEDRAL 18
#define NBIN_VALENCE 32

/* The dual-edge minima over interior faces: [0] dual length, [1] min(dual,
 * shortest face edge), [2] dual length / mean face edge; all 0 without any. */
static void dual_edge_minima(const cvm__mesh3 *g, const cvm__dual3 *d, double out[3])
{
    size_t i;
    int any = 0;
    out[0] = out[1] = out[2] = INFINITY;
    for (i = 0; i < 4 * d->ntet; i++) {
        int32_t s = d->nbr[i], f[3];
        double len, e0, e1, e2, emin;
        if (s < 0 || (int32_t)i > s || d->dvert[i / 4] == d->dvert[s / 4])
            continue;
        len = sqrt(cvm__dist2_3(d->pv + 3 * (i / 4), d->pv + 3 * (s / 4)));
        cvm__mesh3_face_corners(g->tet + 4 * (i / 4), (int)(i % 4), f);
        e0 = sqrt(cvm__dist2_3(g->xyz + 3 * f[0], g->xyz + 3 * f[1]));
        e1 = sqrt(cvm__dist2_3(g->xyz + 3 * f[1], g->xyz + 3 * f[2]));
        e2 = sqrt(cvm__dist2_3(g->xyz + 3 * f[2], g->xyz + 3 * f[0]));
        emin = e0 < e1 ? (e0 < e2 ? e0 : e2) : (e1 < e2 ? e1 : e2);
        any = 1;
        out[0] = len < out[0] ? len : out[0];
        emin = len < emin ? len : emin;
        out[1] = emin < out[1] ? emin : out[1];
        len /= (e0 + e1 + e2) / 3;
        out[2] = len < out[2] ? len : out[2];
    }
    if (!any)
        out[0] = out[1] = out[2] = 0;
}

/* The valence histogram of the interior vertices; their count. */
static size_t valence_hist(const cvm__dual3 *d, double *hist)
{
    size_t i, n = 0;
    memset(hist, 0, NBIN_VALENCE * sizeof *hist);
    for (i = 0; i < d->nv; i++) {
        int32_t k = d->vedge_off[i + 1] - d->vedge_off[i];
        if (d->vbnd[i])
            continue;
        hist[k < NBIN_VALENCE - 1 ? k : NBIN_VALENCE - 1] += 1;
        n++;
    }
    return n;
}

static cvm_status need_mesh(cvm_mesh *m)
{
    if (!m->m3->have)
        return cvm__error(&m->ctx, CVM_E_STATE, CVM_ENT_NONE, -1,
                          "no mesh to measure: call cvm_mesh_triangulate() first");
    return CVM_OK;
}

cvm_status cvm__mesh3_quality(double *out, cvm_mesh *m, cvm_measure which)
{
    const cvm__mesh3 *g = m->m3;
    cvm__dual3 d;
    double r[3], hist[NBIN_VALENCE];
    size_t t, n;
    cvm_status s;
    if ((s = need_mesh(m)))
        return s;
    if (which == CVM_MEASURE_MEAN_RADIUS_EDGE) {
        double sum = 0;
        for (t = 0; t < cvm__store_nslots(m); t++) {
            const int32_t *v = cvm__store_cell(m, t);
            sum += cvm__tet_radius_edge(cvm__store_point(m, v[0]), cvm__store_point(m, v[1]),
                                        cvm__store_point(m, v[2]), cvm__store_point(m, v[3]));
        }
        *out = g->ntet ? sum / (double)g->ntet : 0;
        return CVM_OK;
    }
    if ((s = cvm__dual3_build(&m->ctx, g, &d)))
        return s;
    if (which == CVM_MEASURE_VALENCE14_PCT) {
        n = valence_hist(&d, hist);
        *out = n ? 100.0 * hist[14] / (double)n : 0;
    } else {
        dual_edge_minima(g, &d, r);
        *out = which == CVM_MEASURE_MIN_DUAL_EDGE_3D ? r[0]
               : which == CVM_MEASURE_TIME_STEP_PROXY_3D ? r[1] : r[2];
    }
    cvm__dual3_free(&m->ctx, &d);
    return CVM_OK;
}

cvm_status cvm__mesh3_histogram(double *dst, size_t dst_len, cvm_mesh *m, cvm_histogram which)
{
    const cvm__mesh3 *g = m->m3;
    size_t need, t;
    cvm_status s;
    if (which != CVM_HIST_DIHEDRAL_DEG && which != CVM_HIST_VALENCE_3D)
        return cvm__error(&m->ctx, CVM_E_ARGUMENT, CVM_ENT_NONE, -1,
                          "histogram %d is not defined for a 3D mesh", (int)which);
    if ((s = need_mesh(m)))
        return s;
    need = which == CVM_HIST_DIHEDRAL_DEG ? NBIN_DIHEDRAL : NBIN_VALENCE;
    if (dst_len < need)
        return cvm__error(&m->ctx, CVM_E_BUFFER_TOO_SMALL, CVM_ENT_NONE, -1,
                          "dst has %lu entries, the histogram needs %lu", (unsigned long)dst_len,
                          (unsigned long)need);
    if (which == CVM_HIST_VALENCE_3D) {
        cvm__dual3 d;
        if ((s = cvm__dual3_build(&m->ctx, g, &d)))
            return s;
        valence_hist(&d, dst);
        cvm__dual3_free(&m->ctx, &d);
        return CVM_OK;
    }
    memset(dst, 0, NBIN_DIHEDRAL * sizeof *dst);
    for (t = 0; t < cvm__store_nslots(m); t++) {
        const int32_t *v = cvm__store_cell(m, t);
        double a[6];
        int k;
        cvm__tet_dihedrals_deg(cvm__store_point(m, v[0]), cvm__store_point(m, v[1]),
                               cvm__store_point(m, v[2]), cvm__store_point(m, v[3]), a);
        for (k = 0; k < 6; k++) {
            int b = (int)(a[k] / 10);
            dst[b < 0 ? 0 : b > NBIN_DIHEDRAL - 1 ? NBIN_DIHEDRAL - 1 : b] += 1;
        }
    }
    return CVM_OK;
}

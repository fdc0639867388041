/* surf3.c - growth and release of the arrays of a cvm__surf3. */
#include <string.h>

#include "common/surf3.h"

void cvm__surf3_init(cvm__surf3 *s)
{
    memset(s, 0, sizeof *s);
    s->facet_word = "facet";
    s->points_numbered = 1;
}

void cvm__surf3_free(cvm__ctx *ctx, cvm__surf3 *s)
{
    cvm__free(ctx, s->xyz);
    cvm__free(ctx, s->poff);
    cvm__free(ctx, s->pidx);
    cvm__free(ctx, s->pfacet);
    cvm__free(ctx, s->fmark);
    cvm__free(ctx, s->fhole_off);
    cvm__free(ctx, s->fhole);
    cvm__free(ctx, s->holes);
    cvm__free(ctx, s->regions);
    cvm__free(ctx, s->file);
    cvm__surf3_init(s);
}

static cvm_status grow(cvm__ctx *ctx, void *pp, size_t *cap, size_t need, size_t elem)
{
    if (cvm__grow(ctx, (void **)pp, cap, need, elem))
        return cvm__nomem(ctx);
    return CVM_OK;
}

cvm_status cvm__surf3_add_point(cvm__ctx *ctx, cvm__surf3 *s, double x, double y, double z)
{
    if (grow(ctx, &s->xyz, &s->cap_xyz, 3 * (s->np + 1), sizeof(double)))
        return CVM_E_NOMEM;
    s->xyz[3 * s->np] = x;
    s->xyz[3 * s->np + 1] = y;
    s->xyz[3 * s->np + 2] = z;
    s->np++;
    return CVM_OK;
}

cvm_status cvm__surf3_add_facet(cvm__ctx *ctx, cvm__surf3 *s, int32_t marker)
{
    size_t f = s->nfacet;
    if (grow(ctx, &s->fmark, &s->cap_fmark, f + 1, sizeof(int32_t)) ||
        grow(ctx, &s->fhole_off, &s->cap_fhole_off, f + 2, sizeof(int32_t)))
        return CVM_E_NOMEM;
    if (f == 0)
        s->fhole_off[0] = 0;
    s->fhole_off[f + 1] = s->fhole_off[f];
    s->fmark[f] = marker;
    s->nfacet = f + 1;
    return CVM_OK;
}

cvm_status cvm__surf3_add_polygon(cvm__ctx *ctx, cvm__surf3 *s, const int32_t *idx, size_t n)
{
    size_t k = s->npoly, at;
    if (grow(ctx, &s->poff, &s->cap_poff, k + 2, sizeof(int32_t)) ||
        grow(ctx, &s->pfacet, &s->cap_pfacet, k + 1, sizeof(int32_t)))
        return CVM_E_NOMEM;
    if (k == 0)
        s->poff[0] = 0;
    at = (size_t)s->poff[k];
    if (grow(ctx, &s->pidx, &s->cap_pidx, at + n, sizeof(int32_t)))
        return CVM_E_NOMEM;
    if (n)
        memcpy(s->pidx + at, idx, n * sizeof(int32_t));
    s->poff[k + 1] = (int32_t)(at + n);
    s->pfacet[k] = (int32_t)(s->nfacet ? s->nfacet - 1 : 0);
    s->npoly = k + 1;
    return CVM_OK;
}

cvm_status cvm__surf3_add_facet_hole(cvm__ctx *ctx, cvm__surf3 *s, const double *xyz)
{
    size_t n = s->nfacet ? (size_t)s->fhole_off[s->nfacet] : 0;
    if (!s->nfacet)
        return CVM_OK;
    if (grow(ctx, &s->fhole, &s->cap_fhole, 3 * (n + 1), sizeof(double)))
        return CVM_E_NOMEM;
    memcpy(s->fhole + 3 * n, xyz, 3 * sizeof(double));
    s->fhole_off[s->nfacet]++;
    return CVM_OK;
}

cvm_status cvm__surf3_add_hole(cvm__ctx *ctx, cvm__surf3 *s, const double *xyz)
{
    if (grow(ctx, &s->holes, &s->cap_holes, 3 * (s->nholes + 1), sizeof(double)))
        return CVM_E_NOMEM;
    memcpy(s->holes + 3 * s->nholes, xyz, 3 * sizeof(double));
    s->nholes++;
    return CVM_OK;
}

cvm_status cvm__surf3_add_region(cvm__ctx *ctx, cvm__surf3 *s, const double *r)
{
    if (grow(ctx, &s->regions, &s->cap_regions, 5 * (s->nregions + 1), sizeof(double)))
        return CVM_E_NOMEM;
    memcpy(s->regions + 5 * s->nregions, r, 5 * sizeof(double));
    s->nregions++;
    return CVM_OK;
}

cvm_status cvm__surf3_set_file(cvm__ctx *ctx, cvm__surf3 *s, const char *file)
{
    size_t n = strlen(file) + 1;
    char *copy = cvm__malloc(ctx, n);
    if (!copy)
        return cvm__nomem(ctx);
    memcpy(copy, file, n);
    cvm__free(ctx, s->file);
    s->file = copy;
    return CVM_OK;
}

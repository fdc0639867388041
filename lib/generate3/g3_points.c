/* g3_points.c - the growing point list of a generation run (shared by the near field,
 * the lattice and the driver). */
#include <string.h>

#include "generate3/generate3.h"

cvm_status cvm__g3_points_push(cvm__ctx *ctx, cvm__g3_points *P, const double *x, double dm)
{
    if (P->n == P->cap) {
        size_t cap = P->cap ? 2 * P->cap : 1024;
        double *xyz = cvm__realloc(ctx, P->xyz, 3 * cap * sizeof *xyz), *d;
        if (!xyz)
            return cvm__nomem(ctx);
        P->xyz = xyz;
        if (!(d = cvm__realloc(ctx, P->dm, cap * sizeof *d)))
            return cvm__nomem(ctx);
        P->dm = d;
        P->cap = cap;
    }
    memcpy(P->xyz + 3 * P->n, x, 3 * sizeof *x);
    P->dm[P->n++] = dm;
    return CVM_OK;
}

void cvm__g3_points_free(cvm__ctx *ctx, cvm__g3_points *P)
{
    cvm__free(ctx, P->xyz);
    cvm__free(ctx, P->dm);
    memset(P, 0, sizeof *P);
}
